#include "report/simulation_report.hpp"

#include "report/text_format.hpp"

#include "shapes/rocks.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace rockfall::report {
namespace {

nlohmann::json vec_json(const engine::Vec3& v) { return {v.x(), v.y(), v.z()}; }

double rock_mass(const engine::RockSpec& rock) {
    return rock.geometry().properties.volume * rock.density;
}

// "massive", or "custom 'cube'" for a mesh, catalogue or generated shape.
std::string rock_label(const engine::RockSpec& rock) {
    const std::string kind(shapes::to_string(rock.kind));
    return rock.shape ? kind + " '" + rock.shape->name + "'" : kind;
}

std::string hex(std::uint64_t value) {
    char buffer[20];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(value));
    return buffer;
}

void print_stations(std::ostream& out, const engine::RockOutcome& rock) {
    if (rock.stations.empty()) return;
    out << "  stations (horizontal distance from the toe):\n";
    for (const auto& s : rock.stations) {
        out << "    " << fmt("%6.2f m", s.distance_from_toe);
        if (!s.reached) {
            out << "  not reached\n";
            continue;
        }
        out << "  t " << fmt("%.3f s", s.time) << "  v " << fmt("%.2f m/s", s.speed) << "  v_par "
            << fmt("%.2f m/s", s.parallel_speed) << "  w " << fmt("%.1f rad/s", s.angular_speed)
            << "  bounce " << fmt("%.3f m", s.bounce_height) << "  Cr "
            << fmt("%.2f", s.rolling_coefficient) << '\n';
    }
    if (std::isfinite(rock.velocity_change)) {
        out << "  V' = (b - a) / a = " << fmt("%.3f", rock.velocity_change)
            << " between the first two stations\n";
    }
}

void print_hits(std::ostream& out, const engine::RockOutcome& rock) {
    out << "  wall hits: " << rock.wall_hits.size() << '\n';
    int n = 1;
    for (const auto& h : rock.wall_hits) {
        out << "    #" << n++ << " t " << fmt("%.4f s", h.start_time) << " at y "
            << fmt("%.3f m", h.point.y()) << ", z " << fmt("%.3f m", h.point.z()) << ": v_n "
            << fmt("%.2f m/s", h.normal_speed) << ", normal impulse "
            << fmt("%.1f N s", h.normal_impulse) << ", peak normal force "
            << fmt("%.1f kN", h.peak_normal_force / 1e3) << ", duration "
            << fmt("%.3f ms", (h.end_time - h.start_time) * 1e3) << ", kinetic energy "
            << fmt("%.1f J", h.energy_before) << " -> " << fmt("%.1f J", h.energy_after) << '\n';
    }
}

// The rock as simulated: the scenario's, or a cluster rock with its drawn size.
engine::RockSpec rock_spec(const engine::Scenario& scenario, const engine::RockOutcome& rock,
                           std::size_t index) {
    if (index < scenario.rocks.size()) return scenario.rocks[index].rock;
    engine::RockSpec spec = scenario.cluster->rock;
    spec.size = rock.size;
    return spec;
}

}  // namespace

void print_summary(std::ostream& out, const engine::Scenario& scenario,
                   const engine::Outcome& outcome, const RunInfo& info) {
    out << "scenario " << scenario.name << " (" << info.scenario_path << "), seed " << info.seed
        << ", " << outcome.rocks.size() << (outcome.rocks.size() == 1 ? " rock" : " rocks") << '\n';
    for (std::size_t i = 0; i < outcome.rocks.size(); ++i) {
        const auto& rock = outcome.rocks[i];
        const engine::RockSpec spec = rock_spec(scenario, rock, i);
        out << "rock " << i + 1 << ": " << rock_label(spec) << ' ' << fmt("%.3f m", spec.size)
            << ", " << fmt("%.0f kg/m3", spec.density) << ", " << fmt("%.2f kg", rock_mass(spec))
            << '\n';
        out << "  stopped: " << engine::to_string(rock.stop) << " at "
            << fmt("%.3f s", rock.stop_time) << '\n';
        const auto& p = rock.final_state.position;
        out << "  reach: " << fmt("%.2f m", rock.reach) << " past the toe; final position x "
            << fmt("%.2f m", p.x()) << ", y " << fmt("%.2f m", p.y()) << ", z "
            << fmt("%.2f m", p.z()) << '\n';
        out << "  max speed " << fmt("%.2f m/s", rock.max_speed) << ", max kinetic energy "
            << fmt("%.1f J", rock.max_kinetic_energy) << ", max bounce height "
            << fmt("%.3f m", rock.max_bounce_height) << '\n';
        print_stations(out, rock);
        print_hits(out, rock);
    }
    out << "simulated " << fmt("%.3f s", outcome.simulated_time) << " in " << outcome.coarse_steps
        << " coarse + " << outcome.fine_steps << " fine (near-wall) steps; runtime "
        << fmt("%.3f s", info.runtime) << '\n';
}

nlohmann::json outcome_json(const engine::Scenario& scenario, const engine::Outcome& outcome,
                            const RunInfo& info) {
    nlohmann::json rocks = nlohmann::json::array();
    for (std::size_t i = 0; i < outcome.rocks.size(); ++i) {
        const auto& rock = outcome.rocks[i];
        const engine::RockSpec spec = rock_spec(scenario, rock, i);
        nlohmann::json stations = nlohmann::json::array();
        for (const auto& s : rock.stations) {
            stations.push_back({{"distance_from_toe_m", s.distance_from_toe},
                                {"reached", s.reached},
                                {"time_s", s.time},
                                {"speed_m_s", s.speed},
                                {"parallel_speed_m_s", s.parallel_speed},
                                {"angular_speed_rad_s", s.angular_speed},
                                {"bounce_height_m", s.bounce_height},
                                {"rolling_coefficient", s.rolling_coefficient},
                                {"translational_energy_J", s.translational_energy},
                                {"rotational_energy_J", s.rotational_energy}});
        }
        nlohmann::json hits = nlohmann::json::array();
        for (const auto& h : rock.wall_hits) {
            nlohmann::json history = nlohmann::json::array();
            for (const auto& f : h.history) history.push_back({f.time, f.normal, f.tangential});
            hits.push_back(
                {{"start_time_s", h.start_time},
                 {"end_time_s", h.end_time},
                 {"point_m", vec_json(h.point)},
                 {"normal_speed_m_s", h.normal_speed},
                 {"normal_impulse_N_s", h.normal_impulse},
                 {"tangential_impulse_N_s", vec_json(h.tangential_impulse)},
                 {"velocity_before_m_s", vec_json(h.velocity_before)},
                 {"velocity_after_m_s", vec_json(h.velocity_after)},
                 {"angular_velocity_before_rad_s", vec_json(h.angular_velocity_before)},
                 {"angular_velocity_after_rad_s", vec_json(h.angular_velocity_after)},
                 {"energy_before_J", h.energy_before},
                 {"energy_after_J", h.energy_after},
                 {"peak_normal_force_N", h.peak_normal_force},
                 {"peak_time_s", h.peak_time},
                 {"force_history",
                  {{"columns", {"time_s", "normal_N", "tangential_N"}}, {"rows", history}}}});
        }
        rocks.push_back({{"kind", shapes::to_string(spec.kind)},
                         {"shape_name", spec.shape ? nlohmann::json(spec.shape->name) : nullptr},
                         {"size_m", spec.size},
                         {"density_kg_m3", spec.density},
                         {"mass_kg", rock_mass(spec)},
                         {"stop_reason", engine::to_string(rock.stop)},
                         {"stop_time_s", rock.stop_time},
                         {"reach_m", rock.reach},
                         {"final_position_m", vec_json(rock.final_state.position)},
                         {"max_speed_m_s", rock.max_speed},
                         {"max_kinetic_energy_J", rock.max_kinetic_energy},
                         {"max_bounce_height_m", rock.max_bounce_height},
                         {"velocity_change", rock.velocity_change},
                         {"stations", stations},
                         {"wall_hits", hits}});
    }
    return {{"scenario", scenario.name},
            {"scenario_file", info.scenario_path},
            {"seed", info.seed},
            {"runtime_s", info.runtime},
            {"simulated_time_s", outcome.simulated_time},
            {"coarse_steps", outcome.coarse_steps},
            {"fine_steps", outcome.fine_steps},
            {"state_hash", hex(outcome.state_hash)},
            {"rocks", rocks}};
}

}  // namespace rockfall::report
