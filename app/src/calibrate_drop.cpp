#include "calibrate_drop.hpp"

#include "calibrate_common.hpp"
#include "report/text_format.hpp"

#include <algorithm>
#include <sstream>

namespace rockfall::app {
namespace {

using report::fmt;
using risk::SampleSummary;

engine::Material contact(const risk::DropTestSpec& spec) {
    const engine::Material& a = spec.rock.material;
    const engine::Material& b = spec.surface;
    return {0.5 * (a.friction + b.friction), 0.5 * (a.restitution + b.restitution),
            0.5 * (a.rolling_resistance + b.rolling_resistance)};
}

nlohmann::json curve_json(const std::vector<risk::CurvePoint>& points) {
    nlohmann::json rows = nlohmann::json::array();
    for (const risk::CurvePoint& p : points) {
        rows.push_back({{"surface_restitution", p.surface_restitution},
                        {"contact_restitution", p.contact_restitution},
                        {"cor", summary_json(p.cor)}});
    }
    return rows;
}

// Curve and refinement points in restitution order.
std::vector<risk::CurvePoint> all_points(const risk::RestitutionIdentification& id) {
    std::vector<risk::CurvePoint> points = id.curve;
    points.insert(points.end(), id.refinements.begin(), id.refinements.end());
    std::stable_sort(points.begin(), points.end(), [](const auto& a, const auto& b) {
        return a.surface_restitution < b.surface_restitution;
    });
    return points;
}

std::string coefficient_name(risk::CorDefinition definition) {
    return definition == risk::CorDefinition::height ? "kinematic COR from heights sqrt(H_r/H_i)"
                                                     : "kinematic COR from speeds v_out/v_in";
}

void print_identification(std::ostream& out, const DropShapeRun& run,
                          risk::CorDefinition definition) {
    const risk::RestitutionIdentification& id = *run.identification;
    out << "  identification: surface restitution for a mean " << coefficient_name(definition)
        << " of " << report::short_number(id.target) << "\n";
    out << "    surface restitution  contact restitution  mean COR  95% CI of mean\n";
    for (const risk::CurvePoint& p : all_points(id)) {
        out << "    " << fmt("%19.4f", p.surface_restitution) << "  "
            << fmt("%19.4f", p.contact_restitution) << "  " << fmt("%8.4f", p.cor.mean) << "  ["
            << fmt("%.4f", p.cor.mean_interval.lower) << ", "
            << fmt("%.4f", p.cor.mean_interval.upper) << "]\n";
    }
    out << "  identified: surface restitution " << fmt("%.4f", id.surface_restitution)
        << " (contact restitution " << fmt("%.4f", id.contact_restitution) << " with the rock's "
        << report::short_number(run.spec.rock.material.restitution) << "): mean COR "
        << fmt("%.4f", id.achieved.mean) << " [" << fmt("%.4f", id.achieved.mean_interval.lower)
        << ", " << fmt("%.4f", id.achieved.mean_interval.upper) << "], target "
        << report::short_number(id.target) << "; " << id.curve.size() << " curve points, "
        << id.refinements.size()
        << (id.refinements.size() == 1 ? " refinement\n" : " refinements\n");
    out << "  consistent with the target (95 % CI of the mean contains it): surface restitution "
        << fmt("%.3f", id.consistent.lower) << " to " << fmt("%.3f", id.consistent.upper) << '\n';
}

}  // namespace

std::string to_string(risk::CorDefinition definition) {
    return definition == risk::CorDefinition::height ? "height" : "speed";
}

void print_drop_text(std::ostream& out, const DropReport& report) {
    for (const DropShapeRun& run : report.shapes) {
        const risk::DropTestSpec& spec = run.spec;
        const risk::DropTestResult& r = run.result;
        out << "drop test: " << run.label << ", size " << report::short_number(spec.rock.size)
            << " m, mass " << fmt("%.4g", r.drops.front().mass) << " kg, sphericity "
            << fmt("%.3f", run.sphericity) << '\n';
        out << "  surface: " << material_text(spec.surface)
            << "\n  rock:    " << material_text(spec.rock.material)
            << "\n  contact: " << material_text(contact(spec)) << " (mean of the two)\n";
        out << "  " << r.drops.size() << " drops from " << report::short_number(spec.height)
            << " m (rock's lowest point above the surface), random orientations from seed "
            << spec.seed << ", time step " << report::short_number(spec.time_step) << " s; "
            << r.no_rebound << " without rebound (coefficients 0)\n";
        out << "  first bounce                                   mean      sd      p5     p50     "
               "p95  95% CI of mean (Student t)\n";
        print_summary_row(out, "kinematic COR, heights sqrt(H_r/H_i)", r.cor_height, "%7.4f");
        print_summary_row(out, "kinematic COR, speeds v_out/v_in", r.cor_speed, "%7.4f");
        print_summary_row(out, "kinetic COR, impulses P_r/P_c (1st contact)", r.cor_kinetic,
                          "%7.4f");
        print_summary_row(out, "energetic COR, sqrt(E_after/E_before)", r.cor_energy, "%7.4f");
        print_summary_row(out, "approach speed v_in (m/s)", r.approach_speed, "%7.4g");
        print_summary_row(out, "rebound speed v_out (m/s)", r.rebound_speed, "%7.4g");
        print_summary_row(out, "rebound height H_r (m)", r.rebound_height, "%7.4g");
        print_summary_row(out, "normal impulse (N s)", r.normal_impulse, "%7.4g");
        if (run.identification) print_identification(out, run, report.definition);
    }
    out << "runtime: " << fmt("%.2f", report.runtime) << " s on " << report.threads << " thread"
        << (report.threads == 1 ? "" : "s") << '\n';
}

nlohmann::json drop_json(const DropReport& report) {
    nlohmann::json shapes = nlohmann::json::array();
    for (const DropShapeRun& run : report.shapes) {
        const risk::DropTestSpec& spec = run.spec;
        const risk::DropTestResult& r = run.result;
        nlohmann::json shape = {{"label", run.label},
                                {"size_m", spec.rock.size},
                                {"density_kg_m3", spec.rock.density},
                                {"mass_kg", r.drops.front().mass},
                                {"sphericity", run.sphericity},
                                {"rock_material", material_json(spec.rock.material)},
                                {"surface_material", material_json(spec.surface)},
                                {"contact_material", material_json(contact(spec))},
                                {"height_m", spec.height},
                                {"count", spec.count},
                                {"seed", spec.seed},
                                {"time_step_s", spec.time_step},
                                {"no_rebound", r.no_rebound},
                                {"cor_height", summary_json(r.cor_height)},
                                {"cor_speed", summary_json(r.cor_speed)},
                                {"cor_kinetic", summary_json(r.cor_kinetic)},
                                {"cor_energy", summary_json(r.cor_energy)},
                                {"approach_speed_m_s", summary_json(r.approach_speed)},
                                {"rebound_speed_m_s", summary_json(r.rebound_speed)},
                                {"rebound_height_m", summary_json(r.rebound_height)},
                                {"normal_impulse_N_s", summary_json(r.normal_impulse)}};
        if (run.identification) {
            const risk::RestitutionIdentification& id = *run.identification;
            shape["identification"] = {
                {"matched", "cor_" + to_string(report.definition)},
                {"target", id.target},
                {"surface_restitution", id.surface_restitution},
                {"contact_restitution", id.contact_restitution},
                {"achieved", summary_json(id.achieved)},
                {"consistent_surface_restitution", {id.consistent.lower, id.consistent.upper}},
                {"curve", curve_json(id.curve)},
                {"refinements", curve_json(id.refinements)}};
        }
        shapes.push_back(shape);
    }
    return {{"command", "calibrate drop"},    {"confidence", 0.95},
            {"interval_method", "student_t"}, {"shapes", shapes},
            {"threads", report.threads},      {"runtime_s", report.runtime}};
}

void write_drop_csv(std::ostream& out, const DropReport& report) {
    out << "shape,drop,seed,rebounded,mass_kg,drop_height_m,rebound_height_m,approach_speed_m_s,"
           "rebound_speed_m_s,normal_impulse_N_s,first_impulse_N_s,compression_impulse_N_s,"
           "restitution_impulse_N_s,energy_before_J,energy_after_J,cor_height,cor_speed,"
           "cor_kinetic,cor_energy\n";
    out.precision(9);
    for (const DropShapeRun& run : report.shapes) {
        std::string label = run.label;
        std::replace(label.begin(), label.end(), ',', ';');
        std::replace(label.begin(), label.end(), '"', '\'');
        for (const risk::DropMeasurement& m : run.result.drops) {
            out << '"' << label << "\"," << m.index << ',' << m.seed << ',' << (m.rebounded ? 1 : 0)
                << ',' << m.mass << ',' << m.drop_height << ',' << m.rebound_height << ','
                << m.approach_speed << ',' << m.rebound_speed << ',' << m.normal_impulse << ','
                << m.first_impulse << ',' << m.compression_impulse << ',' << m.restitution_impulse
                << ',' << m.energy_before << ',' << m.energy_after << ',' << m.cor_height << ','
                << m.cor_speed << ',' << m.cor_kinetic << ',' << m.cor_energy << '\n';
        }
    }
}

report::Plot drop_figure(const DropReport& report) {
    report::Plot plot;
    plot.title =
        "Drop test: mean " + coefficient_name(report.definition) + " against surface restitution";
    plot.x_label = "surface restitution (materials.slope.restitution)";
    plot.y_label = "mean kinematic COR (-)";
    plot.x_min = 0.0;
    plot.x_max = 1.0;
    plot.y_min = 0.0;
    std::vector<FigureCurve> curves;
    double target = 0.0;
    for (const DropShapeRun& run : report.shapes) {
        if (!run.identification) continue;
        const risk::RestitutionIdentification& id = *run.identification;
        FigureCurve& curve = curves.emplace_back();
        curve.label = run.label;
        for (const risk::CurvePoint& p : all_points(id))
            curve.points.push_back({p.surface_restitution, p.cor});
        curve.identified = {id.surface_restitution, id.achieved};
        target = id.target;
    }
    add_calibration_curves(plot, curves, target, "target " + report::short_number(target));
    return plot;
}

std::string drop_fragment(const DropShapeRun& run, risk::CorDefinition definition) {
    const risk::RestitutionIdentification& id = *run.identification;
    const risk::DropTestSpec& spec = run.spec;
    std::ostringstream out;
    out << "# Surface material identified by `rockfall calibrate drop` (docs/calibration.md):\n"
        << "# the restitution at which " << run.label << " dropped " << exact(spec.height)
        << " m in " << spec.count << " orientations (seed " << spec.seed << ") has a mean "
        << coefficient_name(definition) << " of " << exact(id.target) << "\n"
        << "# (achieved " << fmt("%.4f", id.achieved.mean) << ", 95 % CI ["
        << fmt("%.4f", id.achieved.mean_interval.lower) << ", "
        << fmt("%.4f", id.achieved.mean_interval.upper) << "]). The contact uses the mean with "
        << "the rock's restitution\n# (" << exact(spec.rock.material.restitution)
        << " here), giving a contact restitution of " << fmt("%.4f", id.contact_restitution)
        << ": give the scenario's rocks the same material.\n"
        << "# Use it with extends = \"THIS_FILE.toml\" in a scenario.\n"
        << "[materials.slope]\n"
        << "friction = " << exact(spec.surface.friction) << '\n'
        << "restitution = " << exact(id.surface_restitution) << '\n'
        << "rolling_resistance = " << exact(spec.surface.rolling_resistance) << '\n';
    return out.str();
}

}  // namespace rockfall::app
