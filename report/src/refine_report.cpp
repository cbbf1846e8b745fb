#include "report/refine_report.hpp"

#include "report/query_table.hpp"
#include "report/text_format.hpp"

#include <algorithm>
#include <cmath>

namespace rockfall::report {
namespace {

// Text loads in kN (kN/m for a plane-strain section); JSON keys in N with a `_per_m` suffix.
struct LoadUnits {
    const char* text;
    bool per_metre;
    std::string key(const std::string& base) const { return per_metre ? base + "_per_m" : base; }
};

LoadUnits load_units(int dimension) { return {dimension == 2 ? "kN/m" : "kN", dimension == 2}; }

// One extrapolated quantity: name, unit in the text, key of its value in JSON, scale from the
// study's unit to the text's (1e-3 for N to kN).
struct Quantity {
    const char* name;
    std::string unit;
    std::string key;
    double scale;
    const mpm::RichardsonEstimate mpm::RefinementStudy::*estimate;
    double mpm::RefinementLevel::*value;
    mpm::ValueRange mpm::RefinementLevel::*range;
};

std::vector<Quantity> quantities(int dimension) {
    const LoadUnits u = load_units(dimension);
    return {
        {"peak wall load", u.text, u.key("peak_wall_force_N"), 1e-3,
         &mpm::RefinementStudy::peak_wall_force, &mpm::RefinementLevel::peak_wall_force,
         &mpm::RefinementLevel::peak_wall_force_range},
        {"time of peak", "s", "peak_time_s", 1.0, &mpm::RefinementStudy::peak_time,
         &mpm::RefinementLevel::peak_time, &mpm::RefinementLevel::peak_time_range},
        {"filtered peak", u.text, u.key("peak_wall_force_filtered_N"), 1e-3,
         &mpm::RefinementStudy::peak_wall_force_filtered,
         &mpm::RefinementLevel::peak_wall_force_filtered,
         &mpm::RefinementLevel::peak_wall_force_filtered_range},
        {"steady wall load", u.text, u.key("steady_wall_force_N"), 1e-3,
         &mpm::RefinementStudy::steady_wall_force, &mpm::RefinementLevel::steady_wall_force,
         &mpm::RefinementLevel::steady_wall_force_range},
        {"runout past toe", "m", "runout_past_toe_m", 1.0, &mpm::RefinementStudy::runout_past_toe,
         &mpm::RefinementLevel::runout_past_toe, &mpm::RefinementLevel::runout_past_toe_range},
    };
}

std::string status_note(const mpm::RefinementLevel& level) {
    return level.status == mpm::SoilStatus::completed
               ? ""
               : std::string(" (") + mpm::status_name(level.status) + ")";
}

// (largest - smallest) / |mean| over a level's runs, in %.
double spread_percent(const mpm::RefinementLevel& level, const Quantity& q) {
    const mpm::ValueRange& r = level.*q.range;
    const double mean = level.*q.value;
    return mean != 0.0 ? 100.0 * (r.max - r.min) / std::abs(mean) : 0.0;
}

// With several runs per level: how far the runs of each level spread.
void print_spread(std::ostream& out, const mpm::RefinementStudy& study, int dimension) {
    int runs = 1;
    for (const mpm::RefinementLevel& l : study.levels) runs = std::max(runs, l.runs);
    if (runs == 1) return;
    out << "each level is the mean of " << runs << " runs, run k with numerics.cfl times (1 - k "
        << fmt("%g", mpm::kRepeatTimeStepChange)
        << "); spread between the runs, (largest - smallest) / mean:\n";
    char line[256];
    std::snprintf(line, sizeof line, "%10s %12s %10s %16s %13s %10s", "cell (m)", "peak (%)",
                  "t peak (%)", "filtered (%)", "steady (%)", "runout (%)");
    out << line << '\n';
    const std::vector<Quantity> q = quantities(dimension);
    for (const mpm::RefinementLevel& l : study.levels) {
        std::snprintf(line, sizeof line, "%10.4f %12.1f %10.1f %16.1f %13.1f %10.1f", l.cell_size,
                      spread_percent(l, q[0]), spread_percent(l, q[1]), spread_percent(l, q[2]),
                      spread_percent(l, q[3]), spread_percent(l, q[4]));
        out << line << '\n';
    }
}

}  // namespace

std::string refinement_progress_line(const mpm::RefinementLevel& level, int index, int count,
                                     int dimension, double runtime) {
    const LoadUnits u = load_units(dimension);
    return "refinement level " + std::to_string(index + 1) + " of " + std::to_string(count) +
           ": cell " + fmt("%g m", level.cell_size) + ", " + std::to_string(level.particles) +
           " particles, peak " + fmt("%.2f ", 1e-3 * level.peak_wall_force) + u.text + ", steady " +
           fmt("%.2f ", 1e-3 * level.steady_wall_force) + u.text +
           (level.runs > 1 ? " (means of " + std::to_string(level.runs) + " runs)" : "") + ", " +
           fmt("%.1f s", runtime) + status_note(level);
}

void print_refinement(std::ostream& out, const mpm::RefinementStudy& study,
                      const RefinementContext& context) {
    const LoadUnits u = load_units(context.dimension);
    const bool timed = context.runtime.size() == study.levels.size();
    out << "refinement study of " << context.scenario << ": "
        << (u.per_metre ? "2D plane strain, loads per metre of width" : "3D") << ", "
        << fmt("%g s", context.duration) << " of flow; steady load = mean over the last "
        << fmt("%g s", context.steady_window)
        << "; peak = largest mean over any window of one sample interval, "
        << "filtered = over any window of " << fmt("%g s", context.filter_window) << '\n';
    const std::string load = std::string("(") + u.text + ")";
    char line[256];
    std::snprintf(line, sizeof line, "%10s %9s %8s %12s %10s %16s %13s %10s", "cell (m)",
                  "particles", "steps", ("peak " + load).c_str(), "t peak (s)",
                  ("filtered " + load).c_str(), ("steady " + load).c_str(), "runout (m)");
    out << line << (timed ? "    run (s)" : "") << '\n';
    for (std::size_t i = 0; i < study.levels.size(); ++i) {
        const mpm::RefinementLevel& l = study.levels[i];
        std::snprintf(line, sizeof line, "%10.4f %9ld %8ld %12.3f %10.3f %16.3f %13.3f %10.3f",
                      l.cell_size, l.particles, l.steps, 1e-3 * l.peak_wall_force, l.peak_time,
                      1e-3 * l.peak_wall_force_filtered, 1e-3 * l.steady_wall_force,
                      l.runout_past_toe);
        out << line << (timed ? fmt(" %10.1f", context.runtime[i]) : "") << status_note(l) << '\n';
    }
    print_spread(out, study, context.dimension);
    if (!study.extrapolated) {
        out << (study.levels.size() < 3
                    ? "no extrapolation: it needs three levels\n"
                    : "no extrapolation: one of the three finest levels did not complete\n");
        return;
    }
    out << "Richardson extrapolation from the three finest levels (refinement ratio "
        << fmt("%.3f", study.ratio) << "):\n";
    for (const Quantity& q : quantities(context.dimension)) {
        const mpm::RichardsonEstimate& e = study.*q.estimate;
        std::snprintf(line, sizeof line, "  %-17s", q.name);
        out << line;
        if (!e.monotone) {
            out << "not converging monotonically: no extrapolation; finest change "
                << fmt("%.1f %%", 100.0 * e.finest_change) << '\n';
            continue;
        }
        out << fmt("%.4g ", q.scale * e.extrapolated) << q.unit << ", observed order "
            << (std::isnan(e.order) ? std::string("undefined (two finest equal)")
                                    : fmt("%.2f", e.order))
            << ", finest change " << fmt("%.1f %%", 100.0 * e.finest_change) << ", GCI "
            << fmt("%.1f %%", 100.0 * e.gci_fine) << '\n';
    }
}

nlohmann::ordered_json refinement_json(const mpm::RefinementStudy& study,
                                       const RefinementContext& context) {
    const LoadUnits u = load_units(context.dimension);
    const bool timed = context.runtime.size() == study.levels.size();
    nlohmann::ordered_json levels = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < study.levels.size(); ++i) {
        const mpm::RefinementLevel& l = study.levels[i];
        nlohmann::ordered_json level = {
            {"cell_size_m", l.cell_size},
            {"particles", l.particles},
            {"steps", l.steps},
            {"status", mpm::status_name(l.status)},
            {u.key("peak_wall_force_N"), l.peak_wall_force},
            {"peak_time_s", l.peak_time},
            {u.key("peak_wall_force_filtered_N"), l.peak_wall_force_filtered},
            {u.key("steady_wall_force_N"), l.steady_wall_force},
            {"runout_past_toe_m", l.runout_past_toe},
        };
        level["runs"] = l.runs;
        nlohmann::ordered_json ranges;
        for (const Quantity& q : quantities(context.dimension)) {
            const mpm::ValueRange& r = l.*q.range;
            ranges[q.key] = {{"min", r.min}, {"max", r.max}};
        }
        level["range"] = std::move(ranges);
        if (timed) level["runtime_s"] = context.runtime[i];
        levels.push_back(std::move(level));
    }
    nlohmann::ordered_json extrapolation;
    if (study.extrapolated) {
        extrapolation = {{"refinement_ratio", study.ratio}};
        for (const Quantity& q : quantities(context.dimension)) {
            const mpm::RichardsonEstimate& e = study.*q.estimate;
            extrapolation[q.key] = {
                {"monotone", e.monotone},
                {"extrapolated", json_number(e.extrapolated)},
                {"observed_order", json_number(e.order)},
                {"finest_change", json_number(e.finest_change)},
                {"gci_fine", json_number(e.gci_fine)},
            };
        }
    }
    return {
        {"scenario_file", context.scenario},
        {"dimension", context.dimension},
        {"per_metre_of_width", u.per_metre},
        {"duration_s", context.duration},
        {"steady_window_s", context.steady_window},
        {"filter_window_s", context.filter_window},
        {"levels", std::move(levels)},
        {"extrapolation", std::move(extrapolation)},
    };
}

}  // namespace rockfall::report
