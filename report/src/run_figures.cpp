// The figures of one run (see run_figures.hpp).

#include "report/run_figures.hpp"

#include "report/text_format.hpp"

#include "shapes/slope.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <utility>

namespace rockfall::report {
namespace {

constexpr double kPascalPerKilopascal = 1e3;
constexpr double kNewtonPerKilonewton = 1e3;
// Above this the wall force is drawn in kN, N.
constexpr double kilonewton_threshold = 1e4;

std::string lower_case(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

// The axes, orientation and legend of a pressure map over the grid.
HeatMap grid_map(const engine::PressureMap& map) {
    const engine::PressureCells& spec = map.spec;
    HeatMap heat;
    heat.columns = spec.columns;
    heat.rows = spec.rows;
    heat.x_min = -0.5 * spec.width;
    heat.x_max = 0.5 * spec.width;
    heat.y_min = 0.0;
    heat.y_max = spec.height;
    // Seen from the slope (looking downslope along +x, z up), +y is on the left.
    heat.mirror_x = true;
    heat.x_label = "across the wall, y (m), seen from the slope: column 1 (y = " +
                   fmt("%.2f m", -0.5 * spec.width) + ") on the right";
    heat.y_label = "up the wall from its foot (m)";
    heat.empty_label = "grey: no load";
    heat.mark = spec.capacity / kPascalPerKilopascal;
    heat.mark_label =
        "red line on the colour bar: capacity " + fmt("%.0f kPa", spec.capacity / 1e3);
    heat.values.resize(map.cells.size());
    heat.flagged.resize(map.cells.size());
    return heat;
}

std::string saturated_label(const HeatMap& heat, double capacity) {
    const auto count = std::count(heat.flagged.begin(), heat.flagged.end(), true);
    const std::string rule = "sampled pressure > " + fmt("%.0f kPa", capacity / 1e3);
    if (count == 0) return "hatched, red outline: saturated (" + rule + "): none";
    return "hatched, red outline: saturated (" + rule + "): " + std::to_string(count) +
           (count == 1 ? " cell" : " cells");
}

// The samples of a history worth drawing: every non-zero one, the zeros next to them and the
// two ends (a long run of zeros is one straight segment).
std::vector<std::size_t> drawn_samples(const std::vector<double>& force) {
    std::vector<std::size_t> kept;
    for (std::size_t k = 0; k < force.size(); ++k) {
        const bool edge = k == 0 || k + 1 == force.size();
        const bool near = force[k] != 0.0 || (k > 0 && force[k - 1] != 0.0) ||
                          (k + 1 < force.size() && force[k + 1] != 0.0);
        if (edge || near) kept.push_back(k);
    }
    return kept;
}

bool any_wall_hit(const engine::Outcome& outcome) {
    return std::any_of(outcome.rocks.begin(), outcome.rocks.end(), [](const auto& rock) {
        return std::any_of(rock.wall_hits.begin(), rock.wall_hits.end(),
                           [](const engine::WallHit& h) { return !h.history.empty(); });
    });
}

}  // namespace

HeatMap pressure_peak_map(const engine::PressureMap& map) {
    HeatMap heat = grid_map(map);
    for (std::size_t i = 0; i < map.cells.size(); ++i) {
        const engine::PressureCellRecord& cell = map.cells[i];
        heat.values[i] = cell.sampled_peak_force > 0.0
                             ? cell.sampled_peak_force / map.cell_area / kPascalPerKilopascal
                             : std::numeric_limits<double>::quiet_NaN();
        heat.flagged[i] = cell.saturated;
    }
    heat.title =
        "Peak pressure per cell (sampled every " + fmt("%.3g s", map.spec.sample_interval) + ")";
    heat.value_label = "peak sampled pressure (kPa)";
    heat.flagged_label = saturated_label(heat, map.spec.capacity);
    return heat;
}

HeatMap pressure_sample_map(const engine::PressureMap& map, std::size_t sample) {
    HeatMap heat = grid_map(map);
    double on_grid = 0.0;
    for (std::size_t i = 0; i < map.cells.size(); ++i) {
        const double force = map.cells[i].force.at(sample);
        on_grid += force;
        const double pressure = force / map.cell_area;
        heat.values[i] = force > 0.0 ? pressure / kPascalPerKilopascal
                                     : std::numeric_limits<double>::quiet_NaN();
        heat.flagged[i] = pressure > map.spec.capacity;
    }
    heat.title = "Pressure at t = " + fmt("%.3f s", map.sample_time(sample)) + " (mean over " +
                 fmt("%.3g s", map.spec.sample_interval) + "): " + fmt("%.1f N", on_grid) +
                 " on the grid";
    heat.value_label = "sampled pressure (kPa)";
    heat.flagged_label = saturated_label(heat, map.spec.capacity);
    return heat;
}

Plot wall_force_plot(const engine::PressureMap& map, bool grid) {
    const double largest =
        map.total.empty() ? 0.0 : *std::max_element(map.total.begin(), map.total.end());
    const bool kilo = largest > kilonewton_threshold;
    const double scale = kilo ? 1.0 / kNewtonPerKilonewton : 1.0;
    auto series = [&](const std::vector<double>& force, std::string label, std::string colour) {
        Series s;
        s.label = std::move(label);
        s.color = std::move(colour);
        s.line_width = 1.2;
        for (const std::size_t k : drawn_samples(force)) {
            s.x.push_back(map.sample_time(k));
            s.y.push_back(force[k] * scale);
        }
        return s;
    };
    Plot plot;
    plot.title = "Normal force on the wall (mean over each " +
                 fmt("%.3g s", map.spec.sample_interval) + " sample)";
    plot.x_label = "time since gate opening (s)";
    plot.y_label = std::string("normal force on the wall (") + (kilo ? "kN" : "N") + ")";
    // The whole wall broad and light, the grid's part thin and dark on top: where the grid takes
    // all of it, both show.
    Series wall = series(map.total, "whole wall", "#6baed6");
    wall.line_width = 3.0;
    plot.series.push_back(std::move(wall));
    if (grid) {
        std::vector<double> on_grid(map.samples);
        double grid_impulse = 0.0;
        double wall_impulse = 0.0;
        for (std::size_t k = 0; k < map.samples; ++k) {
            on_grid[k] = map.total[k] - map.outside[k];
            grid_impulse += on_grid[k];
            wall_impulse += map.total[k];
        }
        const double share = wall_impulse > 0.0 ? 100.0 * grid_impulse / wall_impulse : 0.0;
        Series cells = series(
            on_grid, "on the cells (" + fmt("%.0f %%", share) + " of the impulse)", "#b35806");
        cells.line_width = 1.0;
        plot.series.push_back(std::move(cells));
    }
    plot.y_min = 0.0;
    return plot;
}

std::string rock_colour(const std::string& name, std::size_t index) {
    static const std::array<std::pair<const char*, const char*>, 13> named{{
        {"red", "#d62728"},
        {"blue", "#1f77b4"},
        {"green", "#2ca02c"},
        {"yellow", "#d4a900"},
        {"orange", "#ff7f0e"},
        {"purple", "#9467bd"},
        {"brown", "#8c564b"},
        {"pink", "#e377c2"},
        {"grey", "#7f7f7f"},
        {"gray", "#7f7f7f"},
        {"black", "#000000"},
        {"cyan", "#17becf"},
        {"magenta", "#c51b8a"},
    }};
    // Tableau 10, matplotlib's default cycle.
    static const std::array<const char*, 10> palette{"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                                     "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
                                                     "#bcbd22", "#17becf"};
    const std::string key = lower_case(name);
    for (const auto& [colour_name, hex] : named) {
        if (key == colour_name) return hex;
    }
    return palette[index % palette.size()];
}

Plot marked_speeds_plot(const MarkedRocks& marked) {
    Plot plot;
    plot.title = "Marked rocks: speed against distance travelled";
    plot.x_label = "distance travelled by the centre of mass since gate opening (m)";
    plot.y_label = "speed of the centre of mass (m/s)";
    double top = 0.0;
    for (std::size_t i = 0; i < marked.rocks.size(); ++i) {
        const MarkedRock& rock = marked.rocks[i];
        if (rock.fine.points.size() < 2) continue;
        const std::string colour = rock_colour(rock.name, i);
        Series fine;
        fine.label = rock.name + " (engine samples)";
        fine.color = colour;
        for (const SeriesPoint& p : rock.fine.points) {
            fine.x.push_back(p.distance);
            fine.y.push_back(p.speed);
            top = std::max(top, p.speed);
        }
        plot.series.push_back(std::move(fine));
        Series camera;
        camera.label = rock.name + " (camera, every " + fmt("%.3g s", marked.camera_interval) + ")";
        camera.color = colour;
        camera.line = false;
        camera.marker = Marker::circle;
        camera.marker_size = 3.0;
        camera.opacity = 0.8;
        for (const SeriesPoint& p : rock.camera.points) {
            camera.x.push_back(p.distance);
            camera.y.push_back(p.speed);
            top = std::max(top, p.speed);
        }
        if (!camera.x.empty()) plot.series.push_back(std::move(camera));
    }
    for (std::size_t k = 0; k < marked.distances.size() && !plot.series.empty(); ++k) {
        Series at;
        at.label = k == 0 ? "speed readings at " + fmt("%.1f m", marked.distances.front()) +
                                (marked.distances.size() > 1
                                     ? " and " + fmt("%.1f m", marked.distances.back())
                                     : std::string())
                          : std::string();
        at.color = "#555555";
        at.dash = "4 4";
        at.line_width = 1.0;
        at.x = {marked.distances[k], marked.distances[k]};
        at.y = {0.0, top};
        plot.series.push_back(std::move(at));
    }
    plot.x_min = 0.0;
    plot.y_min = 0.0;
    return plot;
}

std::vector<Figure> run_figures(const engine::Scenario& scenario, const engine::Outcome& outcome,
                                const RunSeries& series) {
    std::vector<Figure> figures;
    const bool hits = any_wall_hit(outcome);
    std::optional<engine::PressureMap> map;
    if (hits || scenario.wall_cells) {
        // Without [wall_cells] a default grid still gives the whole wall's sampled force.
        const shapes::Slope slope(scenario.slope);
        map = engine::pressure_map(scenario.wall_cells.value_or(engine::PressureCells{}), slope,
                                   outcome);
    }
    const bool loaded =
        map && scenario.wall_cells &&
        std::any_of(map->cells.begin(), map->cells.end(),
                    [](const engine::PressureCellRecord& c) { return c.sampled_peak_force > 0.0; });
    if (loaded) {
        figures.push_back({"pressure_peak.svg", "peak sampled pressure per cell (kPa)",
                           render_heat_map_svg(pressure_peak_map(*map))});
        figures.push_back({"pressure_at_peak.svg",
                           "pressure per cell at the grid's peak sample, t = " +
                               fmt("%.3f s", map->sample_time(map->peak_sample)) + " (kPa)",
                           render_heat_map_svg(pressure_sample_map(*map, map->peak_sample))});
    }
    if (hits) {
        figures.push_back({"wall_force.svg",
                           scenario.wall_cells
                               ? "normal force on the wall and on the pressure cells against time"
                               : "normal force on the wall against time",
                           render_svg(wall_force_plot(*map, scenario.wall_cells.has_value()))});
    }
    const MarkedRocks marked = marked_rocks(
        outcome, series.rocks, scenario.wall_cells ? &*map : nullptr, series.camera_interval);
    const bool tracked = std::any_of(marked.rocks.begin(), marked.rocks.end(),
                                     [](const MarkedRock& r) { return r.fine.points.size() >= 2; });
    if (tracked) {
        figures.push_back({"marked_speeds.svg",
                           "marked rocks' speed against distance travelled (m/s, m)",
                           render_svg(marked_speeds_plot(marked))});
    }
    return figures;
}

}  // namespace rockfall::report
