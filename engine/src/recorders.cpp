#include "recorders.hpp"

#include "release.hpp"

#include "shapes/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rockfall::engine {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double surface_gap(const shapes::Slope& slope, const shapes::RockGeometry& rock,
                   const BodyState& state) {
    // The ground is the terrain mesh where the slope has one (shapes::ground_at), else the
    // profile.
    const Vec3 down = -shapes::ground_at(slope, state.position.x(), state.position.y()).normal;
    const Vec3 lowest = state.position + extent_along(rock, state.orientation, down) * down;
    // Height above a plane times the cosine of its inclination is the normal distance.
    const shapes::Ground ground = shapes::ground_at(slope, lowest.x(), lowest.y());
    return (lowest.z() - ground.height) * ground.normal.z();
}

RockState rock_state(const BodyState& body, double time, double mass,
                     const Vec3& principal_inertia) {
    RockState state;
    state.time = time;
    state.position = body.position;
    state.orientation = body.orientation;
    state.velocity = body.velocity;
    state.angular_velocity = body.angular_velocity;
    state.translational_energy = 0.5 * mass * body.velocity.squaredNorm();
    const Vec3 omega_body = body.orientation.conjugate() * body.angular_velocity;
    state.rotational_energy = 0.5 * omega_body.dot(principal_inertia.cwiseProduct(omega_body));
    return state;
}

RockRecorder::RockRecorder(const Scenario& scenario, const shapes::Slope& slope, int rock_index,
                           double rolling_radius, const RunOptions& options)
    : slope_(slope),
      rock_index_(rock_index),
      rolling_radius_(rolling_radius),
      options_(options),
      toe_x_(slope.toe_x()) {
    stations_.reserve(scenario.stations.size());
    for (const double distance : scenario.stations) {
        StationCrossing station;
        station.distance_from_toe = distance;
        stations_.push_back(station);
    }
}

void RockRecorder::start(const RockState& state, double gap) {
    reach_ = state.position.x() - toe_x_;
    max_speed_ = state.velocity.norm();
    max_energy_ = state.translational_energy + state.rotational_energy;
    max_gap_ = std::max(0.0, gap);
    sample(state);
}

void RockRecorder::after_step(const RockState& before, double gap_before, const RockState& after,
                              double gap_after) {
    reach_ = std::max(reach_, after.position.x() - toe_x_);
    max_speed_ = std::max(max_speed_, after.velocity.norm());
    max_energy_ = std::max(max_energy_, after.translational_energy + after.rotational_energy);
    max_gap_ = std::max(max_gap_, gap_after);
    for (StationCrossing& station : stations_) {
        const double x = toe_x_ + station.distance_from_toe;
        if (!station.reached && before.position.x() < x && after.position.x() >= x) {
            station = crossing(station.distance_from_toe, before, gap_before, after, gap_after);
        }
    }
    if (options_.trajectory &&
        after.time >= static_cast<double>(next_sample_) * options_.trajectory_interval) {
        sample(after);
    }
}

void RockRecorder::finish(const RockState& final_state, RockOutcome& outcome) {
    if (options_.trajectory && last_sample_time_ != final_state.time) {
        options_.trajectory(rock_index_, final_state);
    }
    outcome.reach = reach_;
    outcome.max_speed = max_speed_;
    outcome.max_kinetic_energy = max_energy_;
    outcome.max_bounce_height = max_gap_;
    outcome.stations = stations_;
    // V' = (b - a) / a between the first two stations (seed 000, eq. 1).
    outcome.velocity_change = kNaN;
    if (stations_.size() >= 2 && stations_[0].reached && stations_[1].reached) {
        const double a = stations_[0].speed;
        outcome.velocity_change = (stations_[1].speed - a) / a;
    }
}

void RockRecorder::sample(const RockState& state) {
    if (!options_.trajectory) {
        return;
    }
    options_.trajectory(rock_index_, state);
    last_sample_time_ = state.time;
    // The next sample is the first multiple of the interval after this time.
    next_sample_ = static_cast<long>(std::floor(state.time / options_.trajectory_interval)) + 1;
}

StationCrossing RockRecorder::crossing(double distance, const RockState& before, double gap_before,
                                       const RockState& after, double gap_after) const {
    const double x = toe_x_ + distance;
    // Linear interpolation between the two steps' states at the crossing.
    const double f = (x - before.position.x()) / (after.position.x() - before.position.x());
    const auto lerp = [f](const auto& a, const auto& b) { return a + f * (b - a); };
    const Vec3 velocity = lerp(before.velocity, after.velocity);
    const Vec3 omega = lerp(before.angular_velocity, after.angular_velocity);

    StationCrossing station;
    station.distance_from_toe = distance;
    station.reached = true;
    station.time = lerp(before.time, after.time);
    station.speed = velocity.norm();
    station.parallel_speed = velocity.dot(slope_.surface_tangent(x));
    station.angular_speed = omega.norm();
    station.bounce_height = std::max(0.0, lerp(gap_before, gap_after));
    station.translational_energy = lerp(before.translational_energy, after.translational_energy);
    station.rotational_energy = lerp(before.rotational_energy, after.rotational_energy);
    // Cr = w r / v (seed 000, eq. 2): ~0 sliding, ~1 rolling.
    station.rolling_coefficient =
        station.parallel_speed > 0.0
            ? station.angular_speed * rolling_radius_ / station.parallel_speed
            : kNaN;
    return station;
}

}  // namespace rockfall::engine
