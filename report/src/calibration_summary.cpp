#include "report/calibration_summary.hpp"

#include "risk/sample_summary.hpp"

#include <vector>

namespace rockfall::report {
namespace {

// The measure of each drop or heap at the configured parameter: the kinematic COR from heights
// (what the paper measured) or the heap's angle of repose over its valid planes.
std::vector<double> configured_measure(const db::CalibrationShape& shape) {
    std::vector<double> values;
    for (const risk::DropMeasurement& d : shape.drops) values.push_back(d.cor_height);
    if (shape.heaps.empty()) return values;
    const double configured = shape.rock.friction;
    for (const db::CalibrationHeap& h : shape.heaps) {
        if (h.rock_friction == configured && h.heap.valid_planes > 0) {
            values.push_back(h.heap.angle_deg);
        }
    }
    return values;
}

bool is_drop(const db::CalibrationRecord& record) { return record.kind == db::RunKind::drop_test; }

}  // namespace

Table calibration_shapes_table(const db::CalibrationRecord& record) {
    const std::string measure = is_drop(record) ? "cor_height" : "angle_deg";
    Table table;
    table.columns = {"shape",
                     "label",
                     "kind",
                     "sphericity",
                     is_drop(record) ? "surface_restitution" : "rock_friction",
                     is_drop(record) ? "drops" : "heaps",
                     measure + "_mean",
                     measure + "_sd",
                     measure + "_mean_lower_95",
                     measure + "_mean_upper_95",
                     "target",
                     "identified_value",
                     "consistent_lower",
                     "consistent_upper"};
    for (std::size_t k = 0; k < record.shapes.size(); ++k) {
        const db::CalibrationShape& s = record.shapes[k];
        const std::vector<double> values = configured_measure(s);
        const risk::SampleSummary m = risk::sample_summary(values);
        std::vector<Cell> row = {static_cast<std::int64_t>(k),
                                 s.label,
                                 s.kind,
                                 s.sphericity,
                                 is_drop(record) ? s.surface.restitution : s.rock.friction,
                                 static_cast<std::int64_t>(values.size()),
                                 values.empty() ? Cell{} : Cell{m.mean},
                                 values.size() < 2 ? Cell{} : Cell{m.standard_deviation},
                                 values.size() < 2 ? Cell{} : Cell{m.mean_interval.lower},
                                 values.size() < 2 ? Cell{} : Cell{m.mean_interval.upper}};
        if (s.identified) {
            row.insert(row.end(), {s.identified->target, s.identified->value,
                                   s.identified->consistent.lower, s.identified->consistent.upper});
        } else {
            row.insert(row.end(), 4, Cell{});
        }
        table.rows.push_back(std::move(row));
    }
    return table;
}

void write_calibration_summary(std::ostream& out, QueryFormat format, const std::string& database,
                               const db::CalibrationRecord& record) {
    const Table table = calibration_shapes_table(record);
    const db::RunRecord& run = record.run;
    switch (format) {
        case QueryFormat::text:
            out << "database: " << database << " (" << (is_drop(record) ? "drop test" : "heap test")
                << ", `rockfall " << run.scenario_name << "`)\n"
                << "run: " << run.samples_planned << (is_drop(record) ? " drop" : " heap")
                << (run.samples_planned == 1 ? "" : "s") << " per shape from seed " << run.seed
                << ", started " << run.started_at << ", finished " << run.finished_at
                << ", rockfall " << run.tool_version << " (" << run.build << ")\n"
                << "measure: "
                << (is_drop(record) ? "kinematic COR from heights sqrt(H_r/H_i) (-)"
                                    : "angle of repose (deg), heaps with a valid plane")
                << " at the configured "
                << (is_drop(record) ? "surface restitution" : "rock friction")
                << "; interval: 95 % Student t of the mean\n";
            print_text(out, table);
            return;
        case QueryFormat::json: {
            nlohmann::json settings = nlohmann::json::parse(run.settings_json, nullptr, false);
            if (settings.is_discarded()) settings = run.settings_json;
            out << nlohmann::ordered_json{{"database", database},
                                          {"query", "summary"},
                                          {"kind", db::to_string(record.kind)},
                                          {"command", run.scenario_name},
                                          {"seed", run.seed},
                                          {"count_per_shape", run.samples_planned},
                                          {"started_at", run.started_at},
                                          {"finished_at", run.finished_at},
                                          {"tool_version", run.tool_version},
                                          {"settings", settings},
                                          {"shapes", rows_json(table)}}
                       .dump(2)
                << '\n';
            return;
        }
        case QueryFormat::csv:
            print_csv(out, table);
            return;
    }
}

}  // namespace rockfall::report
