#include "report/simulation_report.hpp"

#include "report/marked_rocks.hpp"
#include "report/pressure_report.hpp"
#include "report/text_format.hpp"

#include "engine/simulation.hpp"
#include "shapes/rocks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
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

// The hits' count, largest peak normal force (N) and total normal impulse (N s).
struct HitTotals {
    std::size_t count = 0;
    double peak = 0.0;
    double impulse = 0.0;
};

HitTotals hit_totals(const engine::RockOutcome& rock) {
    HitTotals totals;
    totals.count = rock.wall_hits.size();
    for (const auto& h : rock.wall_hits) {
        totals.peak = std::max(totals.peak, h.peak_normal_force);
        totals.impulse += h.normal_impulse;
    }
    return totals;
}

const RockSeries* series_of(const RunSeries& series, std::size_t index) {
    if (index >= series.rocks.size() || series.rocks[index].points.empty()) return nullptr;
    return &series.rocks[index];
}

void print_distance_table(std::ostream& out, const RockSeries& series) {
    out << "  distance travelled (centre of mass path): " << fmt("%.3f m", series.distance())
        << "; speed against distance travelled:\n";
    for (const SeriesPoint& p : sampled_by_distance(series, summary_distance_rows)) {
        out << "    s " << fmt("%7.3f m", p.distance) << "  t " << fmt("%7.3f s", p.time) << "  v "
            << fmt("%6.2f m/s", p.speed) << "  x " << fmt("%7.3f m", p.position.x()) << '\n';
    }
}

void print_rock_table(std::ostream& out, const engine::Scenario& scenario,
                      const engine::Outcome& outcome, const RunSeries& series) {
    out << "rocks (s: distance travelled by the centre of mass; hits: wall hits, largest peak "
           "normal force, total normal impulse):\n";
    out << "  rock  size m  mass kg  stop               at s  reach m     s m  v_max m/s  hits"
           "  peak kN  impulse N s\n";
    for (std::size_t i = 0; i < outcome.rocks.size(); ++i) {
        const auto& rock = outcome.rocks[i];
        const engine::RockSpec spec =
            engine::simulated_rock(scenario, i, outcome.rocks.size(), rock.size);
        const HitTotals hits = hit_totals(rock);
        const RockSeries* s = series_of(series, i);
        char row[200];
        std::snprintf(row, sizeof row,
                      "  %4zu  %6.3f  %7.3f  %-17s %6.2f  %7.3f  %6s  %9.2f  %4zu  %7.2f  %11.2f\n",
                      i + 1, spec.size, rock_mass(spec),
                      std::string(engine::to_string(rock.stop)).c_str(), rock.stop_time, rock.reach,
                      s ? fmt("%6.3f", s->distance()).c_str() : "-", rock.max_speed, hits.count,
                      hits.peak / 1e3, hits.impulse);
        out << row;
    }
}

// The front at `rows` times evenly spaced over the run (the latest point at or before each),
// and when it first passed the toe and each station.
void print_front(std::ostream& out, const engine::Scenario& scenario,
                 const std::vector<FrontPoint>& front) {
    if (front.empty()) return;
    out << "front (the rock furthest downslope; x past the toe, distance along the surface from "
           "the crown, travel since t = 0):\n";
    const double end = front.back().time;
    std::size_t j = 0;
    for (std::size_t k = 0; k < summary_front_rows; ++k) {
        const double t = end * static_cast<double>(k) / static_cast<double>(summary_front_rows - 1);
        while (j + 1 < front.size() && front[j + 1].time <= t) ++j;
        const FrontPoint& p = front[j];
        out << "    t " << fmt("%7.3f s", p.time) << "  past toe " << fmt("%7.3f m", p.past_toe)
            << "  along surface " << fmt("%7.3f m", p.along_surface) << "  travel "
            << fmt("%7.3f m", p.travel) << "  rock " << p.rock + 1 << '\n';
    }
    std::vector<double> marks = scenario.stations;
    marks.insert(marks.begin(), 0.0);
    std::sort(marks.begin(), marks.end());
    marks.erase(std::unique(marks.begin(), marks.end()), marks.end());
    for (const double d : marks) {
        const auto hit = std::find_if(front.begin(), front.end(),
                                      [d](const FrontPoint& p) { return p.past_toe >= d; });
        out << "  front at " << fmt("%.2f m", d) << " past the toe: ";
        if (hit == front.end()) {
            out << "not reached\n";
        } else {
            out << "t " << fmt("%.3f s", hit->time) << " (rock " << hit->rock + 1 << ")\n";
        }
    }
}

// The scenario's own rocks and every named rock (marked cluster rocks) are always in full.
bool in_full(const engine::Scenario& scenario, const engine::Outcome& outcome,
             const RockDetail& detail, std::size_t index) {
    return detail.all || index < scenario.rocks.size() || !outcome.rocks[index].name.empty() ||
           std::find(detail.rocks.begin(), detail.rocks.end(), index) != detail.rocks.end();
}

nlohmann::json distance_json(const RockSeries* series) {
    nlohmann::json rows = nlohmann::json::array();
    if (series) {
        for (const SeriesPoint& p : series->points) {
            rows.push_back(
                {p.time, p.distance, p.speed, p.position.x(), p.position.y(), p.position.z()});
        }
    }
    return {{"columns", {"time_s", "distance_m", "speed_m_s", "x_m", "y_m", "z_m"}},
            {"rows", rows}};
}

nlohmann::json front_json(const std::vector<FrontPoint>& front) {
    nlohmann::json rows = nlohmann::json::array();
    for (const FrontPoint& p : front) {
        rows.push_back({p.time, p.past_toe, p.along_surface, p.travel, p.rock + 1});
    }
    return {{"columns", {"time_s", "past_toe_m", "along_surface_m", "travel_m", "rock_number"}},
            {"rows", rows}};
}

}  // namespace

void print_summary(std::ostream& out, const engine::Scenario& scenario,
                   const engine::Outcome& outcome, const RunInfo& info, const RunSeries& series,
                   const RockDetail& detail) {
    out << "scenario " << scenario.name << " (" << info.scenario_path << "), seed " << info.seed
        << ", " << outcome.rocks.size() << (outcome.rocks.size() == 1 ? " rock" : " rocks") << '\n';
    const bool several = outcome.rocks.size() > 1;
    if (several) print_rock_table(out, scenario, outcome, series);
    std::size_t brief = 0;
    for (std::size_t i = 0; i < outcome.rocks.size(); ++i) {
        if (!in_full(scenario, outcome, detail, i)) {
            ++brief;
            continue;
        }
        const auto& rock = outcome.rocks[i];
        const engine::RockSpec spec =
            engine::simulated_rock(scenario, i, outcome.rocks.size(), rock.size);
        out << "rock " << i + 1 << (rock.name.empty() ? "" : " \"" + rock.name + "\"") << ": "
            << rock_label(spec) << ' ' << fmt("%.3f m", spec.size) << ", "
            << fmt("%.0f kg/m3", spec.density) << ", " << fmt("%.2f kg", rock_mass(spec)) << '\n';
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
        if (const RockSeries* s = series_of(series, i)) print_distance_table(out, *s);
    }
    if (brief > 0) {
        out << brief << " of " << outcome.rocks.size()
            << " rocks in the table only (--rock N prints rock N in full, --all-rocks every one)\n";
    }
    if (several) print_front(out, scenario, series.front);
    std::optional<engine::PressureMap> cells;
    if (scenario.wall_cells) {
        cells = engine::pressure_map(*scenario.wall_cells, shapes::Slope(scenario.slope), outcome);
        print_pressure_cells(out, *cells, outcome);
    }
    print_marked_rocks(out, marked_rocks(outcome, series.rocks, cells ? &*cells : nullptr,
                                         series.camera_interval));
    const bool per_rock = scenario.numerics.wall_stepping == engine::WallStepping::per_rock;
    out << "simulated " << fmt("%.3f s", outcome.simulated_time) << " in " << outcome.coarse_steps
        << " coarse + " << outcome.fine_steps
        << (per_rock ? " wall sub-steps (of single rocks)" : " fine (near-wall) steps")
        << "; runtime " << fmt("%.3f s", info.runtime) << '\n';
}

nlohmann::json outcome_json(const engine::Scenario& scenario, const engine::Outcome& outcome,
                            const RunInfo& info, const RunSeries& series) {
    nlohmann::json rocks = nlohmann::json::array();
    for (std::size_t i = 0; i < outcome.rocks.size(); ++i) {
        const auto& rock = outcome.rocks[i];
        const engine::RockSpec spec =
            engine::simulated_rock(scenario, i, outcome.rocks.size(), rock.size);
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
        rocks.push_back(
            {{"name", rock.name.empty() ? nlohmann::json(nullptr) : nlohmann::json(rock.name)},
             {"kind", shapes::to_string(spec.kind)},
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
        const HitTotals totals = hit_totals(rock);
        nlohmann::json& entry = rocks.back();
        entry["wall_hit_count"] = totals.count;
        entry["max_peak_normal_force_N"] = totals.peak;
        entry["total_normal_impulse_N_s"] = totals.impulse;
        const RockSeries* s = series_of(series, i);
        entry["distance_travelled_m"] = s ? nlohmann::json(s->distance()) : nullptr;
        entry["speed_by_distance"] = distance_json(s);
    }
    std::optional<engine::PressureMap> map;
    nlohmann::json cells = nullptr;
    if (scenario.wall_cells) {
        map = engine::pressure_map(*scenario.wall_cells, shapes::Slope(scenario.slope), outcome);
        cells = pressure_cells_json(*map, outcome);
    }
    const MarkedRocks marked =
        marked_rocks(outcome, series.rocks, map ? &*map : nullptr, series.camera_interval);
    return {{"scenario", scenario.name},
            {"scenario_file", info.scenario_path},
            {"pressure_cells", cells},
            {"marked_rocks",
             marked.rocks.empty() ? nlohmann::json(nullptr) : marked_rocks_json(marked)},
            {"seed", info.seed},
            {"runtime_s", info.runtime},
            {"simulated_time_s", outcome.simulated_time},
            {"coarse_steps", outcome.coarse_steps},
            {"fine_steps", outcome.fine_steps},
            {"body_steps", outcome.body_steps},
            {"state_hash", hex(outcome.state_hash)},
            {"rocks", rocks},
            {"front", front_json(series.front)}};
}

}  // namespace rockfall::report
