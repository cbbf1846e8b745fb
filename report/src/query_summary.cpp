// Output of `rockfall query DB summary`: readable text, a JSON document, or CSV in long form
// (one row per item; the item name carries the unit).

#include "report/query_report.hpp"
#include "report/text_format.hpp"

#include <cmath>

namespace rockfall::report {
namespace {

struct Item {
    std::string name;
    Cell value;
    double lower = std::nan("");
    double upper = std::nan("");
};

double share_value(const db::Share& s) {
    return s.trials == 0 ? std::nan("")
                         : static_cast<double>(s.count) / static_cast<double>(s.trials);
}

std::string bound(double value, const char* unit) {
    return std::isnan(value) ? std::string("-") : fmt("%.4g", value) + " " + unit;
}

// Items of a percentile table of one group ("peak_force_p95_N").
void add_percentiles(std::vector<Item>& items, const db::PercentileTable& table) {
    if (table.groups.empty()) return;
    const std::string name(db::to_string(table.quantity));
    const std::string suffix = unit_suffix(std::string(db::unit_of(table.quantity)));
    for (const db::PercentileRow& row : table.groups[0].rows) {
        items.push_back({name + "_p" + fmt("%g", 100.0 * row.p) + "_" + suffix, row.value,
                         row.lower, row.upper});
    }
}

std::vector<Item> items_of(const db::Summary& s) {
    const db::RunRecord& run = s.run;
    std::vector<Item> items = {
        {"scenario_name", run.scenario_name},
        {"scenario_hash", run.scenario_hash},
        {"seed", run.seed},
        {"method", run.method},
        {"samples_done", s.samples},
        {"rocks_done", s.rocks},
        {"samples_planned", run.samples_planned},
        {"status", run.status},
        {"started_at", run.started_at},
        {"finished_at", run.finished_at},
        {"tool_version", run.tool_version},
        {"build", run.build},
        {"stop_rule", run.stop_rule},
        {"confidence", s.confidence},
    };
    for (const auto& [reason, count] : s.stop_reasons) {
        items.push_back({"stop_" + reason + "_rocks", count});
    }
    add_percentiles(items, s.reach);
    items.push_back({"reach_max_m", s.max_reach});
    items.push_back({"wall_hit_rocks", s.wall.count});
    items.push_back(
        {"wall_hit_share", share_value(s.wall), s.wall.interval.lower, s.wall.interval.upper});
    items.push_back({"wall_hit_samples", s.wall_samples.count});
    items.push_back({"wall_hit_sample_share", share_value(s.wall_samples),
                     s.wall_samples.interval.lower, s.wall_samples.interval.upper});
    items.push_back({"wall_impacts", s.wall_impacts});
    for (const db::StationShare& st : s.stations) {
        const std::string prefix = "station_" + std::to_string(st.station) + "_";
        items.push_back({prefix + "distance_from_toe_m", st.distance_from_toe});
        items.push_back({prefix + "reached_rocks", st.reached.count});
        items.push_back({prefix + "reached_share", share_value(st.reached),
                         st.reached.interval.lower, st.reached.interval.upper});
    }
    add_percentiles(items, s.peak_force);
    add_percentiles(items, s.impact_energy);
    return items;
}

void print_load(std::ostream& out, const db::PercentileTable& table, const std::string& label,
                const std::string& confidence) {
    if (table.groups.empty() || table.groups[0].n == 0) return;
    const db::PercentileGroup& g = table.groups[0];
    const std::string unit(db::unit_of(table.quantity));
    out << label << " over the " << g.n << " rocks that hit the wall (largest per rock):\n";
    for (const db::PercentileRow& row : g.rows) {
        out << "  p" << fmt("%g", 100.0 * row.p) << ": " << fmt("%.4g", row.value) << ' ' << unit
            << " (" << confidence << " % CI " << bound(row.lower, unit.c_str()) << " to "
            << bound(row.upper, unit.c_str()) << ")\n";
    }
}

void print_summary_text(std::ostream& out, const std::string& database, const db::Summary& s) {
    const db::RunRecord& run = s.run;
    const std::string confidence = percent_text(s.confidence);
    out << "database: " << database << '\n'
        << "scenario: " << run.scenario_name << " (hash " << run.scenario_hash << ")\n"
        << "run: seed " << run.seed << ", " << run.method << ", " << s.samples << " of "
        << run.samples_planned << " samples"
        << (s.rocks != s.samples ? " (" + std::to_string(s.rocks) + " rocks)" : "") << ", "
        << run.status << '\n'
        << "stop rule: " << run.stop_rule << '\n'
        << "started " << run.started_at << ", finished "
        << (run.finished_at.empty() ? "-" : run.finished_at) << '\n'
        << "tool: rockfall " << run.tool_version << " (" << run.build << ")\n";
    if (s.samples == 0) {
        out << "no samples stored yet\n";
        return;
    }
    out << "stop reasons:";
    for (const auto& [reason, count] : s.stop_reasons) {
        out << (reason == s.stop_reasons.front().first ? " " : ", ") << reason << ' ' << count
            << " (" << percent_text(static_cast<double>(count) / static_cast<double>(s.rocks))
            << " %)";
    }
    out << '\n';
    if (!s.reach.groups.empty() && !s.reach.groups[0].rows.empty()) {
        const db::PercentileRow& median = s.reach.groups[0].rows[0];
        out << "reach past the toe: median " << fmt("%.4g", median.value) << " m (" << confidence
            << " % CI " << bound(median.lower, "m") << " to " << bound(median.upper, "m")
            << "), maximum " << fmt("%.4g", s.max_reach) << " m\n";
    }
    out << "wall hit by: " << share_text(s.wall, confidence) << " rocks; " << s.wall_impacts
        << " impacts\n"
        << "samples with a rock on the wall: " << share_text(s.wall_samples, confidence) << '\n';
    for (const db::StationShare& st : s.stations) {
        out << "past station " << st.station << " (" << fmt("%g", st.distance_from_toe)
            << " m from the toe): " << share_text(st.reached, confidence) << '\n';
    }
    print_load(out, s.peak_force, "peak force", confidence);
    print_load(out, s.impact_energy, "impact energy", confidence);
}

nlohmann::ordered_json percentiles_json(const db::PercentileTable& table) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    if (table.groups.empty()) return rows;
    for (const db::PercentileRow& row : table.groups[0].rows) {
        rows.push_back({{"percentile", 100.0 * row.p},
                        {"value", row.value},
                        {"ci_lower", json_number(row.lower)},
                        {"ci_upper", json_number(row.upper)}});
    }
    return rows;
}

nlohmann::ordered_json share_json(const db::Share& s) {
    return {{"count", s.count},
            {"of", s.trials},
            {"share", json_number(share_value(s))},
            {"ci_lower", s.interval.lower},
            {"ci_upper", s.interval.upper}};
}

nlohmann::ordered_json summary_json(const std::string& database, const db::Summary& s) {
    const db::RunRecord& run = s.run;
    nlohmann::ordered_json stops = nlohmann::ordered_json::object();
    for (const auto& [reason, count] : s.stop_reasons) stops[reason] = count;
    nlohmann::ordered_json stations = nlohmann::ordered_json::array();
    for (const db::StationShare& st : s.stations) {
        nlohmann::ordered_json entry = {{"station", st.station},
                                        {"distance_from_toe_m", st.distance_from_toe}};
        entry["reached"] = share_json(st.reached);
        stations.push_back(std::move(entry));
    }
    nlohmann::ordered_json reach = {{"median", nullptr},
                                    {"ci_lower", nullptr},
                                    {"ci_upper", nullptr},
                                    {"max", json_number(s.max_reach)}};
    if (!s.reach.groups.empty() && !s.reach.groups[0].rows.empty()) {
        const db::PercentileRow& median = s.reach.groups[0].rows[0];
        reach["median"] = median.value;
        reach["ci_lower"] = json_number(median.lower);
        reach["ci_upper"] = json_number(median.upper);
    }
    nlohmann::ordered_json wall = share_json(s.wall);
    wall["impacts"] = s.wall_impacts;
    wall["samples"] = share_json(s.wall_samples);
    return {{"database", database},
            {"query", "summary"},
            {"run",
             {{"scenario_name", run.scenario_name},
              {"scenario_hash", run.scenario_hash},
              {"seed", run.seed},
              {"method", run.method},
              {"samples_done", s.samples},
              {"rocks_done", s.rocks},
              {"samples_planned", run.samples_planned},
              {"status", run.status},
              {"stop_rule", run.stop_rule},
              {"started_at", run.started_at},
              {"finished_at", run.finished_at},
              {"tool_version", run.tool_version},
              {"build", run.build}}},
            {"confidence", s.confidence},
            {"stop_reasons", stops},
            {"reach_m", reach},
            {"wall", wall},
            {"stations", stations},
            {"peak_force_N", percentiles_json(s.peak_force)},
            {"impact_energy_J", percentiles_json(s.impact_energy)}};
}

}  // namespace

std::string share_text(const db::Share& s, const std::string& confidence) {
    if (s.trials == 0) return "none";
    return std::to_string(s.count) + " of " + std::to_string(s.trials) + ", " +
           percent_text(static_cast<double>(s.count) / static_cast<double>(s.trials)) + " % (" +
           confidence + " % CI " + percent_text(s.interval.lower) + " to " +
           percent_text(s.interval.upper) + " %)";
}

void write_summary(std::ostream& out, QueryFormat format, const std::string& database,
                   const db::Summary& summary) {
    switch (format) {
        case QueryFormat::text:
            print_summary_text(out, database, summary);
            return;
        case QueryFormat::json:
            out << summary_json(database, summary).dump(2) << '\n';
            return;
        case QueryFormat::csv:
            break;
    }
    Table table{{"item", "value", "ci_lower", "ci_upper"}, {}};
    for (const Item& item : items_of(summary)) {
        table.rows.push_back({item.name, item.value, item.lower, item.upper});
    }
    print_csv(out, table);
}

}  // namespace rockfall::report
