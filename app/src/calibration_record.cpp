#include "calibration_record.hpp"

#include "sweep_record.hpp"

#include <algorithm>
#include <limits>

namespace rockfall::app {
namespace {

db::RunRecord run_record(const CalibrationRun& run, const char* command, const char* method,
                         std::uint64_t seed, std::int64_t count) {
    db::RunRecord r;
    r.tool_version = ROCKFALL_VERSION;
    r.build = ROCKFALL_BUILD;
    r.scenario_name = command;
    r.scenario_text = run.scenario_text;
    r.scenario_hash = identity_hash({run.scenario_text, run.settings, ""});
    r.seed = seed;
    r.method = method;
    r.samples_planned = count;
    r.stop_rule = "count " + std::to_string(count);
    r.settings_json = run.settings.dump();
    r.started_at = run.started_at;
    r.finished_at = run.finished_at;
    r.status = "complete";
    return r;
}

db::CalibrationShape shape_record(const std::string& label, const engine::RockSpec& rock,
                                  double sphericity, const engine::Material& surface) {
    db::CalibrationShape s;
    s.label = label;
    s.kind = std::string(shapes::to_string(rock.kind));
    s.density = rock.density;
    s.sphericity = sphericity;
    s.rock = rock.material;
    s.surface = surface;
    return s;
}

// Sorted by parameter with repeated values dropped (a refinement may land on a curve point).
void sort_curve(std::vector<db::CalibrationCurvePoint>& curve) {
    std::stable_sort(curve.begin(), curve.end(),
                     [](const auto& a, const auto& b) { return a.parameter < b.parameter; });
    curve.erase(
        std::unique(curve.begin(), curve.end(),
                    [](const auto& a, const auto& b) { return a.parameter == b.parameter; }),
        curve.end());
}

}  // namespace

db::CalibrationRecord drop_record(const DropReport& report, const CalibrationRun& run) {
    const risk::DropTestSpec& first = report.shapes.front().spec;
    db::CalibrationRecord record;
    record.kind = db::RunKind::drop_test;
    record.run = run_record(run, "calibrate drop", "drop_test", first.seed, first.count);
    for (const DropShapeRun& shape : report.shapes) {
        db::CalibrationShape& s = record.shapes.emplace_back(
            shape_record(shape.label, shape.spec.rock, shape.sphericity, shape.spec.surface));
        s.size = shape.spec.rock.size;
        s.drops = shape.result.drops;
        if (!shape.identification) continue;
        const risk::RestitutionIdentification& id = *shape.identification;
        db::CalibrationIdentified& out = s.identified.emplace();
        out.parameter = "surface_restitution";
        out.measure = "cor_" + to_string(report.definition);
        out.target = id.target;
        out.value = id.surface_restitution;
        out.contact_value = id.contact_restitution;
        out.achieved = id.achieved;
        out.consistent = id.consistent;
        for (const auto* points : {&id.curve, &id.refinements}) {
            for (const risk::CurvePoint& p : *points) {
                out.curve.push_back({p.surface_restitution, p.contact_restitution,
                                     points == &id.refinements, p.cor});
            }
        }
        sort_curve(out.curve);
    }
    return record;
}

db::CalibrationRecord heap_record(const HeapReport& report, const CalibrationRun& run) {
    const risk::HeapTestSpec& first = report.shapes.front().spec;
    db::CalibrationRecord record;
    record.kind = db::RunKind::heap_test;
    record.run = run_record(run, "calibrate heap", "heap_test", first.seed, first.count);
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    for (const HeapShapeRun& shape : report.shapes) {
        const engine::HeapScenario& heap = shape.spec.heap;
        db::CalibrationShape& s = record.shapes.emplace_back(
            shape_record(shape.label, heap.rock, shape.sphericity, heap.surface));
        // Heaps run at a friction already stored (a curve point at the configured friction)
        // are the same heaps, drawn from the same seeds: stored once.
        std::vector<double> stored;
        const auto add_heaps = [&](double friction, const risk::HeapTestResult& result) {
            if (std::find(stored.begin(), stored.end(), friction) != stored.end()) return;
            stored.push_back(friction);
            for (const risk::HeapMeasurement& m : result.heaps) s.heaps.push_back({friction, m});
        };
        add_heaps(heap.rock.material.friction, shape.result);
        if (!shape.identification) continue;
        const risk::FrictionIdentification& id = *shape.identification;
        db::CalibrationIdentified& out = s.identified.emplace();
        out.parameter = "rock_friction";
        out.measure = "angle_deg";
        out.target = id.target_deg;
        out.value = id.identified.friction;
        out.achieved = id.identified.result.angle_deg;
        out.consistent = id.consistent;
        for (const auto* points : {&id.curve, &id.refinements}) {
            for (const risk::FrictionPoint& p : *points) {
                out.curve.push_back(
                    {p.friction, nan, points == &id.refinements, p.result.angle_deg});
                add_heaps(p.friction, p.result);
            }
        }
        add_heaps(id.identified.friction, id.identified.result);
        sort_curve(out.curve);
    }
    return record;
}

}  // namespace rockfall::app
