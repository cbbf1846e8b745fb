#include "synthetic.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

namespace rockfall::db::testing {
namespace {

constexpr double gravity = 9.81;

// SplitMix64 (Steele, Lea and Flood 2014): decorrelates the seeds of neighbouring indices.
std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30U)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27U)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31U);
}

std::string zone_name(std::size_t zone) {
    if (zone == 0) return "upper";
    if (zone == 1) return "lower";
    return "zone " + std::to_string(zone + 1);
}

}  // namespace

RunRecord synthetic_run(const SyntheticOptions& options, std::int64_t samples_planned) {
    RunRecord run;
    run.tool_version = "synthetic";
    run.build = "test data";
    run.scenario_name = "synthetic slope";
    run.scenario_text = "# synthetic records, no scenario\n";
    run.scenario_hash = "0000000000000000";
    run.seed = options.seed;
    run.method = "monte_carlo";
    run.samples_planned = samples_planned;
    run.stop_rule = "samples " + std::to_string(samples_planned);
    run.settings_json = "{\"synthetic\": true}";
    run.started_at = "2024-01-01T00:00:00Z";
    for (std::size_t z = 0; z < options.zones; ++z) run.zones.push_back(zone_name(z));
    return run;
}

SampleRecord synthetic_record(const SyntheticOptions& options, std::int64_t index) {
    const std::uint64_t seed =
        splitmix64(options.seed ^ splitmix64(static_cast<std::uint64_t>(index)));
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit(random); };

    SampleRecord record;
    risk::SampleInputs& in = record.inputs;
    in.index = index;
    in.seed = seed;
    in.zone = options.zones > 1 && unit(random) < 0.4 ? 1 : 0;
    in.kind =
        std::array{shapes::RockKind::sphere, shapes::RockKind::massive,
                   shapes::RockKind::planar}[static_cast<std::size_t>(unit(random) * 3.0) % 3];
    in.size = std::clamp(0.3 * std::exp(0.4 * normal(random)), 0.05, 2.0);
    in.density = 2600.0 + 100.0 * normal(random);
    in.mass = in.density * std::numbers::pi / 6.0 * in.size * in.size * in.size;
    in.material = {uniform(0.4, 0.8), uniform(0.2, 0.5), uniform(0.01, 0.05)};
    in.release_distance = uniform(0.5, 10.0);
    in.release_lateral = uniform(-1.0, 1.0);
    in.orientation_deg = {uniform(0.0, 360.0), uniform(0.0, 360.0), uniform(0.0, 360.0)};

    // Travel past the toe: about N(2.5 m, 3 m), longer for bouncier rocks, so that roughly
    // 30 % reach a wall 4 m out.
    const double travel = 2.5 + 3.0 * normal(random) + 4.0 * (in.material.restitution - 0.35);
    const bool hits_wall = travel >= options.wall_distance;
    record.rocks.push_back({risk::rock_inputs(in), {}, {}});
    engine::RockOutcome& out = record.rocks.front().outcome;
    out.size = in.size;
    out.reach = hits_wall ? options.wall_distance - 0.5 * in.size : travel;
    const double toe_speed = std::sqrt(2.0 * gravity * (0.3 * in.release_distance + 1.0));
    out.max_speed = toe_speed * (1.0 + 0.1 * unit(random));
    out.max_kinetic_energy = 0.55 * in.mass * out.max_speed * out.max_speed;
    out.max_bounce_height = 0.2 * std::exp(0.5 * normal(random));
    const double u = unit(random);
    out.stop = u < 0.85   ? engine::StopReason::at_rest
               : u < 0.95 ? engine::StopReason::left_domain
               : u < 0.99 ? engine::StopReason::time_limit
                          : engine::StopReason::numerical_failure;
    out.stop_time = 3.0 + 0.5 * in.release_distance + unit(random);
    out.final_state.time = out.stop_time;
    out.final_state.position = {out.reach, in.release_lateral, 0.5 * in.size};

    for (std::size_t s = 0; s < options.stations; ++s) {
        engine::StationCrossing& c = out.stations.emplace_back();
        c.distance_from_toe = 3.0 * static_cast<double>(s);
        c.reached = travel >= c.distance_from_toe;
        if (!c.reached) continue;
        const double fraction = c.distance_from_toe / std::max(travel, 1e-3);
        c.speed = toe_speed * std::sqrt(std::max(0.0, 1.0 - fraction));
        c.time = 2.0 + 0.3 * static_cast<double>(s);
        c.parallel_speed = 0.95 * c.speed;
        c.angular_speed = c.speed / (0.5 * in.size);
        c.bounce_height = 0.05 * unit(random);
        c.rolling_coefficient = c.angular_speed * 0.5 * in.size / std::max(c.speed, 1e-9);
        c.translational_energy = 0.5 * in.mass * c.speed * c.speed;
        c.rotational_energy = 0.4 * c.translational_energy;
    }
    const bool two_stations = out.stations.size() >= 2 && out.stations[1].reached;
    out.velocity_change =
        two_stations ? (out.stations[1].speed - out.stations[0].speed) / out.stations[0].speed
                     : std::nan("");

    if (hits_wall) {
        const int hits = unit(random) < 0.3 ? 2 : 1;
        double speed = std::sqrt(2.0 * gravity * (travel - options.wall_distance + 0.5)) + 1.0;
        for (int h = 0; h < hits; ++h) {
            engine::WallHit& w = out.wall_hits.emplace_back();
            w.start_time = 2.5 + 0.4 * h;
            w.end_time = w.start_time + 0.004;
            w.point = {options.wall_distance, in.release_lateral, 0.5 * in.size};
            w.velocity_before = {speed, 0.1 * normal(random), -0.3 * speed};
            w.velocity_after = {-in.material.restitution * speed, 0.0, -0.2 * speed};
            w.angular_velocity_before = {0.0, speed / (0.5 * in.size), 0.0};
            w.angular_velocity_after = {0.0, 0.2 * speed / (0.5 * in.size), 0.0};
            w.normal_speed = speed;
            w.normal_impulse = in.mass * speed * (1.0 + in.material.restitution);
            w.tangential_impulse = {0.0, 0.1 * w.normal_impulse, 0.2 * w.normal_impulse};
            w.energy_before = 0.55 * in.mass * speed * speed;
            w.energy_after = w.energy_before * in.material.restitution * in.material.restitution;
            // Hertz-like growth with mass and speed (F ~ m^(3/5) v^(6/5)) and a 30 % scatter.
            w.peak_normal_force = 2.5e3 * std::pow(in.mass, 0.6) * std::pow(speed, 1.2) *
                                  std::exp(0.3 * normal(random));
            w.peak_time = w.start_time + 0.002;
            speed *= 0.3;
        }
    }

    for (std::size_t k = 0; k < options.trajectory_points; ++k) {
        engine::RockState& s = record.rocks.front().trajectory.emplace_back();
        const double t =
            out.stop_time * static_cast<double>(k) /
            static_cast<double>(std::max<std::size_t>(options.trajectory_points - 1, 1));
        s.time = t;
        s.position = {out.reach * t / out.stop_time, in.release_lateral, 0.5 * in.size};
        s.velocity = {toe_speed * (1.0 - t / out.stop_time), 0.0, 0.0};
        s.angular_velocity = {0.0, s.velocity.x() / (0.5 * in.size), 0.0};
        s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(t, Eigen::Vector3d::UnitY()));
        s.translational_energy = 0.5 * in.mass * s.velocity.squaredNorm();
        s.rotational_energy = 0.4 * s.translational_energy;
    }
    return record;
}

}  // namespace rockfall::db::testing
