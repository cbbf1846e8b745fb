// Output of the stations query: the station table and the Figure 5 and 6 trends (see
// station_figures.hpp).

#include "report/station_figures.hpp"
#include "report/text_format.hpp"

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace rockfall::report {
namespace {

struct Means {
    std::int64_t rocks = 0;
    std::int64_t reached = 0;
    // Sums and counts of speed, parallel speed, angular speed, Cr, bounce height.
    std::array<double, 5> sum{};
    std::array<std::int64_t, 5> count{};
};

Cell mean_cell(const Means& m, std::size_t i) {
    return m.count[i] > 0 ? Cell{m.sum[i] / static_cast<double>(m.count[i])} : Cell{};
}

// A trend, or the reason it is missing (a station the scenario lacks).
template <typename F>
std::optional<MotionTrend> trend_or_note(F&& make, const StationSet& set,
                                         std::vector<std::string>& notes) {
    try {
        return make(set);
    } catch (const std::invalid_argument& e) {
        notes.push_back(e.what());
        return std::nullopt;
    }
}

std::string third_text(const char* which, const CrThird& t) {
    if (t.rocks == 0) return std::string("  ") + which + " third of Cr: no rocks";
    return std::string("  ") + which + " third of Cr (" + fmt("%.3g", t.cr_min) + " to " +
           fmt("%.3g", t.cr_max) + ", " + std::to_string(t.rocks) + " rocks): mean V' " +
           fmt("%.3g", t.mean_velocity_change) + ", V' < 0 for " + std::to_string(t.negative) +
           " of " + std::to_string(t.rocks) + " (" +
           percent_text(static_cast<double>(t.negative) / static_cast<double>(t.rocks)) + " %)";
}

nlohmann::ordered_json third_json(const CrThird& t) {
    return {
        {"rocks", t.rocks},
        {"cr_min", json_number(t.cr_min)},
        {"cr_max", json_number(t.cr_max)},
        {"mean_velocity_change", json_number(t.mean_velocity_change)},
        {"negative", t.negative},
        {"negative_share", t.rocks > 0 ? nlohmann::ordered_json(static_cast<double>(t.negative) /
                                                                static_cast<double>(t.rocks))
                                       : nlohmann::ordered_json()}};
}

// The least-squares line through the origin, w = s v: s = sum v w / sum v^2 (Cr / r of rocks
// that roll, seed 000's "inclination ... i.e. the rolling coefficient").
Cell origin_slope(const ShapePoints& p) {
    double vw = 0.0;
    double vv = 0.0;
    for (std::size_t i = 0; i < p.x.size(); ++i) {
        vw += p.x[i] * p.y[i];
        vv += p.x[i] * p.x[i];
    }
    return vv > 0.0 ? Cell{vw / vv} : Cell{};
}

// One row per shape and one over all shapes: the least-squares line of w on v.
Table slope_table(const std::vector<MotionTrend>& trends) {
    Table t;
    t.columns = {"database",          "shape",           "rocks",
                 "slope_rad_m",       "intercept_rad_s", "correlation",
                 "origin_slope_rad_m"};
    for (const MotionTrend& trend : trends) {
        std::vector<const ShapePoints*> rows;
        for (const ShapePoints& p : trend.shapes) rows.push_back(&p);
        rows.push_back(&trend.all);
        for (const ShapePoints* p : rows) {
            const auto& f = p->fit;
            t.rows.push_back({trend.label, p->shape, static_cast<std::int64_t>(p->x.size()),
                              f ? Cell{f->slope} : Cell{}, f ? Cell{f->intercept} : Cell{},
                              f ? Cell{f->correlation()} : Cell{}, origin_slope(*p)});
        }
    }
    return t;
}

}  // namespace

Table station_table(const std::vector<StationSet>& sets) {
    Table t;
    t.columns = {"database",
                 "shape",
                 "station",
                 "distance_from_toe_m",
                 "rocks",
                 "reached",
                 "mean_speed_m_s",
                 "mean_parallel_speed_m_s",
                 "mean_angular_speed_rad_s",
                 "mean_rolling_coefficient",
                 "mean_bounce_height_m"};
    for (const StationSet& set : sets) {
        const std::vector<double> distances = station_distances(set);
        std::map<std::string, std::vector<Means>> by_shape;
        for (const db::RockStations& rock : set.rocks) {
            std::vector<Means>& means = by_shape[rock.shape];
            means.resize(distances.size());
            for (std::size_t i = 0; i < rock.stations.size() && i < means.size(); ++i) {
                const engine::StationCrossing& s = rock.stations[i];
                Means& m = means[i];
                ++m.rocks;
                if (!s.reached) continue;
                ++m.reached;
                const std::array<double, 5> values{s.speed, s.parallel_speed, s.angular_speed,
                                                   s.rolling_coefficient, s.bounce_height};
                for (std::size_t v = 0; v < values.size(); ++v) {
                    if (!std::isfinite(values[v])) continue;
                    m.sum[v] += values[v];
                    ++m.count[v];
                }
            }
        }
        for (const std::string& shape : shapes_of(set)) {
            const std::vector<Means>& means = by_shape[shape];
            for (std::size_t i = 0; i < means.size(); ++i) {
                const Means& m = means[i];
                t.rows.push_back({set.label, shape, static_cast<std::int64_t>(i + 1), distances[i],
                                  m.rocks, m.reached, mean_cell(m, 0), mean_cell(m, 1),
                                  mean_cell(m, 2), mean_cell(m, 3), mean_cell(m, 4)});
            }
        }
    }
    return t;
}

void write_stations(std::ostream& out, QueryFormat format, const std::vector<StationSet>& sets) {
    const Table stations = station_table(sets);
    if (format == QueryFormat::csv) {
        print_csv(out, stations);
        return;
    }
    std::vector<std::string> notes;
    std::vector<MotionTrend> changes;
    std::vector<MotionTrend> spins;
    for (const StationSet& set : sets) {
        if (auto t = trend_or_note(velocity_change_trend, set, notes)) changes.push_back(*t);
        if (auto t = trend_or_note(spin_speed_trend, set, notes)) spins.push_back(*t);
    }
    if (format == QueryFormat::json) {
        nlohmann::ordered_json doc = {{"query", "stations"}};
        nlohmann::ordered_json databases = nlohmann::ordered_json::array();
        for (const StationSet& set : sets) {
            databases.push_back(
                {{"label", set.label}, {"database", set.database}, {"scenario", set.scenario}});
        }
        doc["databases"] = databases;
        doc["stations"] = rows_json(stations);
        nlohmann::ordered_json velocity = nlohmann::ordered_json::array();
        for (const MotionTrend& t : changes) {
            velocity.push_back({{"database", t.label},
                                {"from_m", t.toe},
                                {"to_m", t.far},
                                {"rocks", static_cast<std::int64_t>(t.all.x.size())},
                                {"correlation", t.all.fit ? json_number(t.all.fit->correlation())
                                                          : nlohmann::ordered_json()},
                                {"lower_cr_third", third_json(t.lower)},
                                {"upper_cr_third", third_json(t.upper)}});
        }
        doc["velocity_change_vs_cr"] = velocity;
        doc["angular_speed_vs_speed"] = rows_json(slope_table(spins));
        doc["notes"] = notes;
        out << doc.dump(2) << '\n';
        return;
    }
    for (const StationSet& set : sets) {
        out << set.label << ": " << set.database << ", scenario \"" << set.scenario << "\", "
            << set.rocks.size() << " rocks\n";
    }
    out << "\nrocks at each station (means over the rocks that crossed it):\n";
    print_text(out, stations);
    for (const MotionTrend& t : changes) {
        out << '\n'
            << t.label << ": V' = (b - a) / a from the toe to " << fmt("%g m", t.far)
            << " against Cr at " << fmt("%g m", t.far) << " (seed 000 Fig. 5), " << t.all.x.size()
            << " rocks crossed both\n";
        out << "  correlation of Cr and V': "
            << (t.all.fit ? fmt("%.3f", t.all.fit->correlation()) : std::string("-")) << '\n'
            << third_text("lowest", t.lower) << '\n'
            << third_text("highest", t.upper) << '\n';
    }
    if (!spins.empty()) {
        out << "\nangular speed w (rad/s) against speed v (m/s) at the toe (seed 000 Fig. 6): "
               "least squares w = intercept + slope v, and w = origin_slope v\n";
        print_text(out, slope_table(spins));
    }
    for (const std::string& note : notes) out << "\nnot shown: " << note << '\n';
}

}  // namespace rockfall::report
