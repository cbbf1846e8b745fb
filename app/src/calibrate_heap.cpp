#include "calibrate_heap.hpp"

#include "calibrate_common.hpp"
#include "report/text_format.hpp"

#include <algorithm>
#include <sstream>

namespace rockfall::app {
namespace {

using report::fmt;
using report::short_number;

std::vector<risk::FrictionPoint> all_points(const risk::FrictionIdentification& id) {
    std::vector<risk::FrictionPoint> points = id.curve;
    points.insert(points.end(), id.refinements.begin(), id.refinements.end());
    std::stable_sort(points.begin(), points.end(),
                     [](const auto& a, const auto& b) { return a.friction < b.friction; });
    return points;
}

std::string grading_text(const shapes::Grading& g) {
    return std::to_string(g.count) + " rocks, d50 " + short_number(1000.0 * g.d50) + " mm, Cu " +
           short_number(g.cu) + ", " + short_number(1000.0 * g.d_min) + " to " +
           short_number(1000.0 * g.d_max) + " mm";
}

void print_identification(std::ostream& out, const risk::FrictionIdentification& id) {
    out << "  identification: rock friction for a mean angle of repose of "
        << short_number(id.target_deg) << " deg\n";
    out << "    rock friction  mean angle (deg)  95% CI of mean     sd over planes  heaps\n";
    for (const risk::FrictionPoint& p : all_points(id)) {
        const risk::SampleSummary& a = p.result.angle_deg;
        out << "    " << fmt("%13.4f", p.friction) << "  " << fmt("%16.2f", a.mean) << "  ["
            << fmt("%6.2f", a.mean_interval.lower) << ", " << fmt("%6.2f", a.mean_interval.upper)
            << "]  " << fmt("%14.2f", p.result.plane_angle_deg.standard_deviation) << "  "
            << fmt("%5.0f", static_cast<double>(a.count)) << '\n';
    }
    out << "  identified: rock friction " << fmt("%.4f", id.identified.friction) << ": mean angle "
        << fmt("%.2f", id.identified.result.angle_deg.mean) << " deg, target "
        << short_number(id.target_deg) << " deg; " << id.curve.size() << " curve points, "
        << id.refinements.size()
        << (id.refinements.size() == 1 ? " refinement\n" : " refinements\n");
    out << "  consistent with the target (95 % CI of the mean contains it): rock friction "
        << fmt("%.3f", id.consistent.lower) << " to " << fmt("%.3f", id.consistent.upper) << '\n';
}

nlohmann::json result_json(const risk::HeapTestResult& r) {
    nlohmann::json heaps = nlohmann::json::array();
    for (const risk::HeapMeasurement& m : r.heaps) {
        nlohmann::json planes = nlohmann::json::array();
        for (const risk::HeapProfile& p : m.planes) {
            planes.push_back({{"azimuth_deg", p.azimuth_deg},
                              {"valid", p.valid},
                              {"angle_deg", p.angle_deg},
                              {"heap_height_m", p.heap_height},
                              {"foot_radius_m", p.foot_radius},
                              {"fitted_points", p.fitted_points}});
        }
        heaps.push_back({{"index", m.index},
                         {"seed", m.seed},
                         {"status", engine::to_string(m.status)},
                         {"rocks", m.rocks},
                         {"rolled_off", m.rolled_off},
                         {"fill_height_m", m.fill_height},
                         {"fill_time_s", m.fill_time},
                         {"fill_at_rest", m.fill_at_rest},
                         {"lift_time_s", m.lift_time},
                         {"settle_time_s", m.settle_time},
                         {"heap_height_m", m.heap_height},
                         {"foot_radius_m", m.foot_radius},
                         {"angle_deg", m.angle_deg},
                         {"angle_sd_deg", m.angle_sd_deg},
                         {"valid_planes", m.valid_planes},
                         {"planes", planes}});
    }
    return {{"angle_deg", summary_json(r.angle_deg)},
            {"plane_angle_deg", summary_json(r.plane_angle_deg)},
            {"heap_height_m", summary_json(r.heap_height)},
            {"fill_height_m", summary_json(r.fill_height)},
            {"not_at_rest", r.not_at_rest},
            {"fills_not_at_rest", r.fills_not_at_rest},
            {"heaps", heaps}};
}

nlohmann::json points_json(const std::vector<risk::FrictionPoint>& points) {
    nlohmann::json rows = nlohmann::json::array();
    for (const risk::FrictionPoint& p : points) {
        rows.push_back({{"friction", p.friction},
                        {"angle_deg", summary_json(p.result.angle_deg)},
                        {"plane_angle_deg", summary_json(p.result.plane_angle_deg)}});
    }
    return rows;
}

void write_rows(std::ostream& out, const std::string& label, const char* role, double friction,
                const risk::HeapTestResult& r) {
    for (const risk::HeapMeasurement& m : r.heaps) {
        for (const risk::HeapProfile& p : m.planes) {
            out << '"' << label << "\"," << role << ',' << friction << ',' << m.index << ','
                << m.seed << ',' << engine::to_string(m.status) << ',' << m.rocks << ','
                << m.rolled_off << ',' << m.fill_height << ',' << m.lift_time << ','
                << p.azimuth_deg << ',' << (p.valid ? 1 : 0) << ',' << p.angle_deg << ','
                << p.heap_height << ',' << p.foot_radius << ',' << p.fitted_points << '\n';
        }
    }
}

}  // namespace

void print_heap_text(std::ostream& out, const HeapReport& report) {
    for (const HeapShapeRun& run : report.shapes) {
        const engine::HeapScenario& h = run.spec.heap;
        const risk::HeapTestResult& r = run.result;
        out << "heap test: " << run.label << ", sphericity " << fmt("%.3f", run.sphericity)
            << ", density " << short_number(h.rock.density) << " kg/m3; " << grading_text(h.grading)
            << '\n';
        out << "  funnel: " << short_number(1000.0 * h.funnel.inner_diameter) << " mm inside, "
            << short_number(h.funnel.height) << " m high, lifted at "
            << short_number(1000.0 * h.funnel.lift_speed) << " mm/s; wall "
            << material_text(h.funnel.material) << '\n';
        out << "  surface: " << material_text(h.surface)
            << (h.sheet ? ", perforated sheet" : ", flat")
            << "\n  rock:    " << material_text(h.rock.material)
            << " (rock-rock contacts; with the surface and the wall the mean)\n";
        out << "  " << r.heaps.size() << " heap" << (r.heaps.size() == 1 ? "" : "s")
            << " from seed " << run.spec.seed << ", time step " << short_number(h.time_step)
            << " s (lift " << short_number(engine::effective_lift_step(h)) << " s), "
            << h.solver_iterations << " solver iterations (lift "
            << engine::effective_lift_iterations(h) << "), angle from " << run.spec.method.planes
            << " planes through the axis; " << r.not_at_rest << " not at rest after "
            << short_number(h.max_settle_time) << " s\n";
        if (r.fills_not_at_rest > 0) {
            out << "  warning: " << r.fills_not_at_rest << " fill"
                << (r.fills_not_at_rest == 1 ? " was" : "s were") << " still moving after "
                << short_number(h.max_fill_time)
                << " s and lifted so: give it a longer --max-fill-time, or more --iterations; "
                   "rocks wedged between walls a few rocks apart may never rest "
                   "(docs/calibration.md, Deep fills)\n";
        }
        for (const risk::HeapMeasurement& m : r.heaps) {
            out << "    heap " << m.index << ": fill " << fmt("%.3f", m.fill_height) << " m, lift "
                << fmt("%.1f", m.lift_time) << " s, height " << fmt("%.3f", m.heap_height)
                << " m, foot radius " << fmt("%.3f", m.foot_radius) << " m, " << m.rolled_off
                << " rolled off, angle " << fmt("%.2f", m.angle_deg) << " deg (sd "
                << fmt("%.2f", m.angle_sd_deg) << " over " << m.valid_planes << " planes)\n";
        }
        out << "                                                 mean      sd      p5     p50     "
               "p95  95% CI of mean (Student t)\n";
        print_summary_row(out, "angle of repose, heap means (deg)", r.angle_deg, "%7.2f");
        print_summary_row(out, "angle of repose, every plane (deg)", r.plane_angle_deg, "%7.2f");
        print_summary_row(out, "heap height (m)", r.heap_height, "%7.4f");
        print_summary_row(out, "fill height (m)", r.fill_height, "%7.4f");
        if (run.identification) print_identification(out, *run.identification);
    }
    out << "runtime: " << fmt("%.2f", report.runtime) << " s on " << report.threads << " thread"
        << (report.threads == 1 ? "" : "s") << '\n';
}

nlohmann::json heap_json(const HeapReport& report) {
    nlohmann::json shapes = nlohmann::json::array();
    for (const HeapShapeRun& run : report.shapes) {
        const engine::HeapScenario& h = run.spec.heap;
        nlohmann::json shape = {{"label", run.label},
                                {"sphericity", run.sphericity},
                                {"density_kg_m3", h.rock.density},
                                {"grading",
                                 {{"count", h.grading.count},
                                  {"d50_m", h.grading.d50},
                                  {"cu", h.grading.cu},
                                  {"d_min_m", h.grading.d_min},
                                  {"d_max_m", h.grading.d_max}}},
                                {"rock_material", material_json(h.rock.material)},
                                {"surface_material", material_json(h.surface)},
                                {"sheet", h.sheet.has_value()},
                                {"funnel",
                                 {{"inner_diameter_m", h.funnel.inner_diameter},
                                  {"height_m", h.funnel.height},
                                  {"lift_speed_m_s", h.funnel.lift_speed},
                                  {"material", material_json(h.funnel.material)}}},
                                {"count", run.spec.count},
                                {"seed", run.spec.seed},
                                {"time_step_s", h.time_step},
                                {"lift_time_step_s", engine::effective_lift_step(h)},
                                {"solver_iterations", h.solver_iterations},
                                {"lift_solver_iterations", engine::effective_lift_iterations(h)},
                                {"planes", run.spec.method.planes},
                                {"result", result_json(run.result)}};
        if (run.identification) {
            const risk::FrictionIdentification& id = *run.identification;
            shape["identification"] = {
                {"target_deg", id.target_deg},
                {"friction", id.identified.friction},
                {"achieved_angle_deg", summary_json(id.identified.result.angle_deg)},
                {"consistent_friction", {id.consistent.lower, id.consistent.upper}},
                {"curve", points_json(id.curve)},
                {"refinements", points_json(id.refinements)}};
        }
        shapes.push_back(shape);
    }
    return {{"command", "calibrate heap"},    {"confidence", 0.95},
            {"interval_method", "student_t"}, {"shapes", shapes},
            {"threads", report.threads},      {"runtime_s", report.runtime}};
}

void write_heap_csv(std::ostream& out, const HeapReport& report) {
    out << "shape,role,rock_friction,heap,seed,status,rocks,rolled_off,fill_height_m,lift_time_s,"
           "azimuth_deg,valid,angle_deg,heap_height_m,foot_radius_m,fitted_points\n";
    out.precision(9);
    for (const HeapShapeRun& run : report.shapes) {
        std::string label = run.label;
        std::replace(label.begin(), label.end(), ',', ';');
        std::replace(label.begin(), label.end(), '"', '\'');
        write_rows(out, label, "test", run.spec.heap.rock.material.friction, run.result);
        if (!run.identification) continue;
        for (const risk::FrictionPoint& p : all_points(*run.identification))
            write_rows(out, label, "curve", p.friction, p.result);
    }
}

report::Plot heap_figure(const HeapReport& report) {
    report::Plot plot;
    plot.title = "Heap test: mean angle of repose against rock friction";
    plot.x_label = "rock friction (cluster.material.friction)";
    plot.y_label = "mean angle of repose (deg)";
    plot.y_min = 0.0;
    std::vector<FigureCurve> curves;
    double target = 0.0;
    for (const HeapShapeRun& run : report.shapes) {
        if (!run.identification) continue;
        const risk::FrictionIdentification& id = *run.identification;
        FigureCurve& curve = curves.emplace_back();
        curve.label = run.label;
        for (const risk::FrictionPoint& p : all_points(id))
            curve.points.push_back({p.friction, p.result.angle_deg});
        curve.identified = {id.identified.friction, id.identified.result.angle_deg};
        plot.x_min = std::min(plot.x_min.value_or(1e9), id.curve.front().friction);
        plot.x_max = std::max(plot.x_max.value_or(-1e9), id.curve.back().friction);
        target = id.target_deg;
    }
    add_calibration_curves(plot, curves, target, "target " + short_number(target) + " deg");
    return plot;
}

std::string heap_fragment(const HeapShapeRun& run) {
    const risk::FrictionIdentification& id = *run.identification;
    const engine::HeapScenario& h = run.spec.heap;
    std::ostringstream out;
    out << "# Rock material identified by `rockfall calibrate heap` (docs/calibration.md): the\n"
        << "# friction at which heaps of " << run.label << " (" << grading_text(h.grading)
        << ",\n# " << run.spec.count << " heap" << (run.spec.count == 1 ? "" : "s") << " from seed "
        << run.spec.seed << ", funnel " << exact(h.funnel.inner_diameter) << " m lifted at "
        << exact(h.funnel.lift_speed) << " m/s) have a mean angle of repose of "
        << exact(id.target_deg) << " deg\n# (achieved "
        << fmt("%.2f", id.identified.result.angle_deg.mean) << " deg; consistent friction "
        << fmt("%.3f", id.consistent.lower) << " to " << fmt("%.3f", id.consistent.upper)
        << "). Rock-rock contacts use it as it is; a\n# rock-surface contact uses the mean with "
           "the "
           "surface's friction. For [[rocks]] entries copy\n# these keys into each rock's "
           "`material` table.\n"
        << "# Use it with extends = \"THIS_FILE.toml\" in a scenario with a [cluster].\n"
        << "[cluster.material]\n"
        << "friction = " << exact(id.identified.friction) << '\n'
        << "restitution = " << exact(h.rock.material.restitution) << '\n'
        << "rolling_resistance = " << exact(h.rock.material.rolling_resistance) << '\n';
    return out.str();
}

}  // namespace rockfall::app
