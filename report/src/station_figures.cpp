// Seed 000's Figures 5 and 6 from the stations of a sweep (see station_figures.hpp).

#include "report/station_figures.hpp"

#include "report/text_format.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace rockfall::report {
namespace {

// Stations are written at the scenario's distances; 1 mm tells them apart from any other.
constexpr double station_tolerance_m = 1.0e-3;

constexpr std::array<const char*, 3> seed_shapes{"sphere", "massive", "planar"};
constexpr std::array<const char*, 6> set_colors{"#1f77b4", "#d62728", "#2ca02c",
                                                "#ff7f0e", "#9467bd", "#8c564b"};

// The seed's shapes first, in the paper's order, then the others by name.
bool shape_before(const std::string& a, const std::string& b) {
    const auto rank = [](const std::string& s) {
        return std::find(seed_shapes.begin(), seed_shapes.end(), s) - seed_shapes.begin();
    };
    return rank(a) != rank(b) ? rank(a) < rank(b) : a < b;
}

Marker marker_of(const std::string& shape) {
    if (shape == "massive") return Marker::square;
    if (shape == "planar") return Marker::triangle;
    return Marker::circle;
}

// Colour by shape (one set; the colours of `rockfall fit`) or by set (several).
const char* color_of(const std::string& shape, std::size_t set, std::size_t sets,
                     std::size_t shape_index) {
    if (sets > 1) return set_colors[set % set_colors.size()];
    const std::size_t seed = static_cast<std::size_t>(
        std::find(seed_shapes.begin(), seed_shapes.end(), shape) - seed_shapes.begin());
    return set_colors[(seed < seed_shapes.size() ? seed : shape_index) % set_colors.size()];
}

ShapePoints& points_of(MotionTrend& trend, const std::string& shape) {
    for (ShapePoints& p : trend.shapes) {
        if (p.shape == shape) return p;
    }
    trend.shapes.push_back({shape, {}, {}, {}});
    return trend.shapes.back();
}

// Every shape of the set, also one whose rocks give no point (its legend entry and table row
// then say n = 0 rather than leave the shape out), in shapes_of's order.
void add_shapes(MotionTrend& trend, const StationSet& set) {
    for (const std::string& shape : shapes_of(set)) points_of(trend, shape);
}

void add_point(MotionTrend& trend, const std::string& shape, double x, double y) {
    ShapePoints& p = points_of(trend, shape);
    p.x.push_back(x);
    p.y.push_back(y);
    trend.all.x.push_back(x);
    trend.all.y.push_back(y);
}

std::optional<risk::LineFit> line_of(const ShapePoints& p) {
    const auto [low, high] = std::minmax_element(p.x.begin(), p.x.end());
    if (p.x.size() < 2 || *low == *high) return std::nullopt;
    return risk::fit_line(p.x, p.y);
}

void finish(MotionTrend& trend) {
    std::sort(
        trend.shapes.begin(), trend.shapes.end(),
        [](const ShapePoints& a, const ShapePoints& b) { return shape_before(a.shape, b.shape); });
    for (ShapePoints& p : trend.shapes) p.fit = line_of(p);
    trend.all.shape = "all";
    trend.all.fit = line_of(trend.all);
}

// The third of the points (ordered by Cr) from `begin` to `end`.
CrThird third_of(const std::vector<std::pair<double, double>>& by_cr, std::size_t begin,
                 std::size_t end) {
    CrThird t;
    t.rocks = static_cast<std::int64_t>(end - begin);
    if (t.rocks == 0) return t;
    t.cr_min = by_cr[begin].first;
    t.cr_max = by_cr[end - 1].first;
    double sum = 0.0;
    for (std::size_t i = begin; i < end; ++i) {
        sum += by_cr[i].second;
        if (by_cr[i].second < 0.0) ++t.negative;
    }
    t.mean_velocity_change = sum / static_cast<double>(t.rocks);
    return t;
}

std::string distance_list(const std::vector<double>& distances) {
    std::string text;
    for (const double d : distances) text += (text.empty() ? "" : ", ") + fmt("%g", d);
    return text + " m past the toe";
}

// The legend text of a series: the shape, after the set's label when there are several.
std::string series_label(const MotionTrend& trend, const std::string& shape, std::size_t n,
                         std::size_t sets) {
    return (sets > 1 ? trend.label + ": " : "") + shape + " (n = " + std::to_string(n) + ")";
}

Series scatter(const ShapePoints& p, std::string label, const char* color) {
    Series s;
    s.label = std::move(label);
    s.color = color;
    s.x = p.x;
    s.y = p.y;
    s.line = false;
    s.marker = marker_of(p.shape);
    s.opacity = 0.8;
    return s;
}

// The least-squares line over the points' range of x.
Series fitted(const ShapePoints& p, std::string label, const char* color) {
    Series s;
    s.label = std::move(label);
    s.color = color;
    const auto [low, high] = std::minmax_element(p.x.begin(), p.x.end());
    for (const double x : {*low, *high}) {
        s.x.push_back(x);
        s.y.push_back(p.fit->intercept + p.fit->slope * x);
    }
    s.line_width = 2.0;
    return s;
}

// Both figures: speeds and Cr start at 0; room for the legend beside the plot area.
Plot motion_plot(const std::string& title, std::string x_label, std::string y_label) {
    Plot plot;
    plot.title = title;
    plot.x_label = std::move(x_label);
    plot.y_label = std::move(y_label);
    plot.x_min = 0.0;
    plot.width = 1080.0;
    return plot;
}

std::string slope_text(const risk::LineFit& fit) {
    return "least squares, slope " + fmt("%.3g", fit.slope) + " rad/m";
}

}  // namespace

std::vector<std::string> shapes_of(const StationSet& set) {
    std::vector<std::string> shapes;
    for (const db::RockStations& rock : set.rocks) {
        if (std::find(shapes.begin(), shapes.end(), rock.shape) == shapes.end()) {
            shapes.push_back(rock.shape);
        }
    }
    std::sort(shapes.begin(), shapes.end(), shape_before);
    return shapes;
}

std::vector<double> station_distances(const StationSet& set) {
    for (const db::RockStations& rock : set.rocks) {
        if (rock.stations.empty()) continue;
        std::vector<double> distances;
        for (const engine::StationCrossing& s : rock.stations) {
            distances.push_back(s.distance_from_toe);
        }
        return distances;
    }
    throw std::invalid_argument(set.database +
                                ": no station rows (the scenario has no stations, or the "
                                "sweep no samples): add `stations = [0.0, 4.0]` to the scenario");
}

std::size_t station_at(const StationSet& set, double distance, const std::string& purpose) {
    const std::vector<double> distances = station_distances(set);
    for (std::size_t i = 0; i < distances.size(); ++i) {
        if (std::abs(distances[i] - distance) <= station_tolerance_m) return i;
    }
    throw std::invalid_argument(set.database + ": " + purpose + " needs a station " +
                                fmt("%g", distance) + " m past the toe; the scenario's stations " +
                                "are at " + distance_list(distances));
}

MotionTrend velocity_change_trend(const StationSet& set) {
    const std::string purpose = "V' between the toe and " + fmt("%g m", far_station_m);
    const std::size_t toe = station_at(set, toe_station_m, purpose);
    const std::size_t far = station_at(set, far_station_m, purpose);
    MotionTrend trend;
    trend.label = set.label;
    trend.toe = toe_station_m;
    trend.far = far_station_m;
    add_shapes(trend, set);
    std::vector<std::pair<double, double>> by_cr;
    for (const db::RockStations& rock : set.rocks) {
        if (std::max(toe, far) >= rock.stations.size()) continue;
        const engine::StationCrossing& a = rock.stations[toe];
        const engine::StationCrossing& b = rock.stations[far];
        if (!a.reached || !b.reached || !(a.speed > 0.0) || !std::isfinite(b.speed) ||
            !std::isfinite(b.rolling_coefficient)) {
            continue;
        }
        // V' = (b - a) / a (seed 000, eq. 1), speeds as the engine's own V' (recorders.cpp).
        const double change = (b.speed - a.speed) / a.speed;
        add_point(trend, rock.shape, b.rolling_coefficient, change);
        by_cr.emplace_back(b.rolling_coefficient, change);
    }
    finish(trend);
    std::sort(by_cr.begin(), by_cr.end());
    const std::size_t third = by_cr.size() / 3;
    trend.lower = third_of(by_cr, 0, third);
    trend.upper = third_of(by_cr, by_cr.size() - third, by_cr.size());
    return trend;
}

MotionTrend spin_speed_trend(const StationSet& set) {
    const std::size_t toe = station_at(set, toe_station_m, "angular speed against speed");
    MotionTrend trend;
    trend.label = set.label;
    trend.toe = trend.far = toe_station_m;
    add_shapes(trend, set);
    for (const db::RockStations& rock : set.rocks) {
        if (toe >= rock.stations.size()) continue;
        const engine::StationCrossing& a = rock.stations[toe];
        if (!a.reached || !std::isfinite(a.speed) || !std::isfinite(a.angular_speed)) continue;
        add_point(trend, rock.shape, a.speed, a.angular_speed);
    }
    finish(trend);
    return trend;
}

Plot velocity_change_figure(const std::vector<MotionTrend>& trends, const std::string& title) {
    const std::string far = fmt("%g m", far_station_m);
    Plot plot =
        motion_plot(title, "rolling coefficient Cr = \u03c9 r / v at " + far + " past the toe (-)",
                    "rate of velocity change V' = (b - a) / a, toe to " + far + " (-)");
    double cr_max = 0.0;
    for (std::size_t t = 0; t < trends.size(); ++t) {
        for (std::size_t s = 0; s < trends[t].shapes.size(); ++s) {
            const ShapePoints& p = trends[t].shapes[s];
            plot.series.push_back(
                scatter(p, series_label(trends[t], p.shape, p.x.size(), trends.size()),
                        color_of(p.shape, t, trends.size(), s)));
            for (const double cr : p.x) cr_max = std::max(cr_max, cr);
        }
    }
    Series zero;
    zero.color = "#555555";
    zero.dash = "4 3";
    zero.line_width = 1.0;
    zero.x = {0.0, nice_ticks(0.0, std::max(cr_max, 1.0)).upper};
    zero.y = {0.0, 0.0};
    plot.series.insert(plot.series.begin(), zero);
    return plot;
}

Plot spin_speed_figure(const std::vector<MotionTrend>& trends, const std::string& title) {
    Plot plot =
        motion_plot(title, "speed at the toe v (m/s)", "angular speed at the toe \u03c9 (rad/s)");
    plot.y_min = 0.0;
    std::vector<Series> lines;
    for (std::size_t t = 0; t < trends.size(); ++t) {
        const MotionTrend& trend = trends[t];
        for (std::size_t s = 0; s < trend.shapes.size(); ++s) {
            const ShapePoints& p = trend.shapes[s];
            const char* color = color_of(p.shape, t, trends.size(), s);
            plot.series.push_back(
                scatter(p, series_label(trend, p.shape, p.x.size(), trends.size()), color));
            if (trends.size() == 1 && p.fit) {
                lines.push_back(fitted(p, p.shape + ": " + slope_text(*p.fit), color));
            }
        }
        if (trends.size() > 1 && trend.all.fit) {
            lines.push_back(fitted(trend.all, trend.label + ": " + slope_text(*trend.all.fit),
                                   color_of("", t, trends.size(), 0)));
        }
    }
    plot.series.insert(plot.series.end(), lines.begin(), lines.end());
    return plot;
}

}  // namespace rockfall::report
