// The marked rocks tracked one by one (see marked_rocks.hpp).

#include "report/marked_rocks.hpp"

#include "report/text_format.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rockfall::report {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

nlohmann::json number_or_null(double value) {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json series_json(const RockSeries& series) {
    nlohmann::json rows = nlohmann::json::array();
    for (const SeriesPoint& p : series.points) rows.push_back({p.time, p.distance, p.speed});
    return {{"columns", {"time_s", "distance_m", "speed_m_s"}}, {"rows", rows}};
}

// "3.12" or "-" for a speed not reached.
std::string speed_text(double speed) {
    return std::isfinite(speed) ? fmt("%.2f", speed) : std::string("-");
}

}  // namespace

engine::Vec3 position_at_time(const RockSeries& series, double t) {
    const std::vector<SeriesPoint>& p = series.points;
    assert(!p.empty());
    const auto after = std::upper_bound(
        p.begin(), p.end(), t, [](double value, const SeriesPoint& q) { return value < q.time; });
    if (after == p.begin()) return p.front().position;
    if (after == p.end()) return p.back().position;
    const SeriesPoint& a = *(after - 1);
    const SeriesPoint& b = *after;
    const double f = (t - a.time) / (b.time - a.time);
    return a.position + f * (b.position - a.position);
}

RockSeries camera_series(const RockSeries& series, double interval) {
    assert(interval > 0.0);
    RockSeries camera;
    if (series.points.size() < 2) return camera;
    // Frames at whole multiples of the interval inside the samples' span (a relative slack keeps
    // a frame that round-off puts a hair outside).
    const double slack = 1e-9;
    const auto first = static_cast<long>(std::ceil(series.points.front().time / interval - slack));
    const auto last = static_cast<long>(std::floor(series.points.back().time / interval + slack));
    double travelled = 0.0;
    for (long k = std::max(first, 0L); k < last; ++k) {
        const double t = static_cast<double>(k) * interval;
        const engine::Vec3 from = position_at_time(series, t);
        const engine::Vec3 to = position_at_time(series, t + interval);
        const double chord = (to - from).norm();
        camera.points.push_back(
            {t + 0.5 * interval, travelled + 0.5 * chord, chord / interval, 0.5 * (from + to)});
        travelled += chord;
    }
    return camera;
}

double speed_at_distance(const RockSeries& series, double s) {
    if (series.points.empty() || s > series.distance()) return kNaN;
    return point_at_distance(series, s).speed;
}

MarkedRocks marked_rocks(const engine::Outcome& outcome, const std::vector<RockSeries>& series,
                         const engine::PressureMap* cells, double camera_interval,
                         const std::vector<double>& distances) {
    assert(camera_interval > 0.0);
    MarkedRocks marked;
    marked.camera_interval = camera_interval;
    marked.distances = distances;
    marked.has_cells = cells != nullptr;
    marked.columns = cells ? cells->spec.columns : 0;
    for (std::size_t i = 0; i < outcome.rocks.size(); ++i) {
        const engine::RockOutcome& outcome_rock = outcome.rocks[i];
        if (outcome_rock.name.empty()) continue;
        MarkedRock rock;
        rock.rock = i;
        rock.name = outcome_rock.name;
        if (i < series.size()) rock.fine = series[i];
        rock.camera = camera_series(rock.fine, camera_interval);
        for (const double d : distances) {
            rock.fine_speed.push_back(speed_at_distance(rock.fine, d));
            rock.camera_speed.push_back(speed_at_distance(rock.camera, d));
        }
        rock.wall_hits = outcome_rock.wall_hits.size();
        for (const engine::WallHit& hit : outcome_rock.wall_hits) {
            if (hit.peak_normal_force > rock.peak_force) {
                rock.peak_force = hit.peak_normal_force;
                rock.peak_time = hit.peak_time;
            }
        }
        if (cells) {
            const auto load =
                std::find_if(cells->rocks.begin(), cells->rocks.end(),
                             [i](const engine::RockCellLoad& l) { return l.rock == i; });
            if (load != cells->rocks.end()) {
                rock.cells = load->cells;
                if (!load->cells.empty()) {
                    rock.sampled_peak_force = load->sampled_peak_force;
                    rock.sampled_peak_time = load->sampled_peak_time;
                }
            }
        }
        marked.rocks.push_back(std::move(rock));
    }
    return marked;
}

void print_marked_rocks(std::ostream& out, const MarkedRocks& marked) {
    if (marked.rocks.empty()) return;
    const std::string interval = fmt("%.3g s", marked.camera_interval);
    out << "marked rocks (named rocks, tracked one by one):\n"
           "  s: distance travelled by the centre of mass from t = 0; v(d): speed at d of travel, "
           "camera / fine\n"
           "  (camera: displacement between frames "
        << interval << " apart / " << interval << ", frames at t = 0, " << interval
        << ", ... from gate opening; fine: the engine's trajectory samples)\n"
           "  peak: the load cell's largest normal force"
        << (marked.has_cells ? "; sampled: the pressure cells' reading; cells: cells loaded" : "")
        << '\n';
    char row[160];
    std::snprintf(row, sizeof row, "  %4s  %-10s %7s", "rock", "name", "s m");
    out << row;
    for (const double d : marked.distances) {
        std::snprintf(row, sizeof row, "  %15s", ("v(" + fmt("%.1f m", d) + ") m/s").c_str());
        out << row;
    }
    std::snprintf(row, sizeof row, "  %4s  %9s", "hits", "peak N");
    out << row;
    if (marked.has_cells) {
        std::snprintf(row, sizeof row, "  %9s  %5s", "sampled N", "cells");
        out << row;
    }
    out << '\n';
    for (const MarkedRock& rock : marked.rocks) {
        std::snprintf(row, sizeof row, "  %4zu  %-10s %7s", rock.rock + 1, rock.name.c_str(),
                      rock.fine.points.empty() ? "-" : fmt("%.3f", rock.fine.distance()).c_str());
        out << row;
        for (std::size_t k = 0; k < marked.distances.size(); ++k) {
            const std::string speeds =
                speed_text(rock.camera_speed[k]) + " / " + speed_text(rock.fine_speed[k]);
            std::snprintf(row, sizeof row, "  %15s", speeds.c_str());
            out << row;
        }
        std::snprintf(row, sizeof row, "  %4zu  %9.1f", rock.wall_hits, rock.peak_force);
        out << row;
        if (marked.has_cells) {
            const std::string sampled =
                rock.sampled_peak_force ? fmt("%.1f", *rock.sampled_peak_force) : "-";
            std::snprintf(row, sizeof row, "  %9s  %5zu", sampled.c_str(), rock.cells.size());
            out << row;
        }
        out << '\n';
    }
}

nlohmann::json marked_rocks_json(const MarkedRocks& marked) {
    nlohmann::json rocks = nlohmann::json::array();
    for (const MarkedRock& rock : marked.rocks) {
        nlohmann::json speeds = nlohmann::json::array();
        for (std::size_t k = 0; k < marked.distances.size(); ++k) {
            speeds.push_back({{"distance_m", marked.distances[k]},
                              {"camera_speed_m_s", number_or_null(rock.camera_speed[k])},
                              {"fine_speed_m_s", number_or_null(rock.fine_speed[k])}});
        }
        nlohmann::json cells = nullptr;
        if (marked.has_cells) {
            cells = nlohmann::json::array();
            for (const int c : rock.cells) {
                cells.push_back({{"column", c % marked.columns}, {"row", c / marked.columns}});
            }
        }
        rocks.push_back(
            {{"rock", rock.rock + 1},
             {"name", rock.name},
             {"distance_travelled_m", rock.fine.points.empty()
                                          ? nlohmann::json(nullptr)
                                          : nlohmann::json(rock.fine.distance())},
             {"speed_at_distance", speeds},
             {"wall_hit_count", rock.wall_hits},
             {"peak_wall_force_N", rock.peak_force},
             {"peak_wall_force_time_s", number_or_null(rock.peak_time)},
             {"sampled_peak_wall_force_N",
              rock.sampled_peak_force ? nlohmann::json(*rock.sampled_peak_force) : nullptr},
             {"sampled_peak_time_s",
              rock.sampled_peak_time ? nlohmann::json(*rock.sampled_peak_time) : nullptr},
             {"cells_loaded", cells},
             {"camera", series_json(rock.camera)},
             {"fine", series_json(rock.fine)}});
    }
    return {{"camera_interval_s", marked.camera_interval},
            {"note",
             "distance: path of the centre of mass from t = 0 (gate opening); camera speed: "
             "displacement between frames camera_interval_s apart (frames at t = k "
             "camera_interval_s) over camera_interval_s, at the middle of the step; fine: the "
             "engine's trajectory samples (speed of the centre of mass); cells: 0-based, column "
             "0 at y = -width / 2, row 0 at the wall's foot"},
            {"distances_m", marked.distances},
            {"rocks", rocks}};
}

}  // namespace rockfall::report
