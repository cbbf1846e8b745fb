// Output of the percentiles, exceed, curve and worst queries (the summary is in query_summary.cpp).

#include "query_report.hpp"

#include "text_format.hpp"

#include <cmath>

namespace rockfall::app {
namespace {

// The group's leading columns: none without grouping; the size class also as numbers so that
// CSV and JSON readers need not parse "[0.2, 0.3)".
std::vector<std::string> group_columns(db::GroupBy by) {
    switch (by) {
        case db::GroupBy::none:
            return {};
        case db::GroupBy::kind:
            return {"kind"};
        case db::GroupBy::shape:
            return {"shape"};
        case db::GroupBy::zone:
            return {"zone"};
        case db::GroupBy::size:
            return {"size_class_m", "size_min_m", "size_max_m"};
    }
    return {};
}

std::vector<Cell> group_cells(db::GroupBy by, const db::GroupId& id) {
    if (by == db::GroupBy::none) return {};
    if (by != db::GroupBy::size) return {id.label};
    return {id.label, id.size_min, std::isinf(id.size_max) ? Cell{} : Cell{id.size_max}};
}

void write(std::ostream& out, QueryFormat format, const std::vector<std::string>& lines,
           nlohmann::ordered_json meta, const Table& table) {
    switch (format) {
        case QueryFormat::text:
            for (const std::string& line : lines) out << line << '\n';
            if (!table.rows.empty()) print_text(out, table);
            return;
        case QueryFormat::csv:
            print_csv(out, table);
            return;
        case QueryFormat::json:
            meta["rows"] = rows_json(table);
            out << meta.dump(2) << '\n';
            return;
    }
}

}  // namespace

std::string quantity_column(db::Quantity quantity) {
    return std::string(db::to_string(quantity)) + "_" +
           unit_suffix(std::string(db::unit_of(quantity)));
}

std::string population_of(db::Quantity quantity) {
    return db::needs_wall_hit(quantity)
               ? "the samples that hit the wall (conditional on a hit; each sample's largest "
                 "value over its hits)"
               : "all samples that have a value";
}

void write_percentiles(std::ostream& out, QueryFormat format, const std::string& database,
                       const db::PercentileTable& table, db::GroupBy by) {
    const std::string name(db::to_string(table.quantity));
    const std::string unit(db::unit_of(table.quantity));
    const std::string column = quantity_column(table.quantity);
    const std::string suffix = unit_suffix(unit);
    Table rows;
    rows.columns = group_columns(by);
    for (const char* c : {"samples", "n", "percentile"}) rows.columns.emplace_back(c);
    rows.columns.insert(rows.columns.end(),
                        {column, name + "_ci_lower_" + suffix, name + "_ci_upper_" + suffix});
    for (const db::PercentileGroup& group : table.groups) {
        for (const db::PercentileRow& row : group.rows) {
            std::vector<Cell> cells = group_cells(by, group.id);
            cells.insert(cells.end(),
                         {group.samples, group.n, 100.0 * row.p, row.value, row.lower, row.upper});
            rows.rows.push_back(std::move(cells));
        }
    }
    const std::string interval = "distribution-free (binomial order statistics)";
    std::vector<std::string> lines = {database + ": percentiles of " + name + " (" + unit +
                                          ") over " + population_of(table.quantity),
                                      percent_text(table.confidence) +
                                          " % confidence intervals: " + interval +
                                          "; - where the sample is too small for a bound"};
    for (const db::PercentileGroup& group : table.groups) {
        if (group.n == 0) {
            lines.push_back((by == db::GroupBy::none ? "" : group.id.label + ": ") +
                            "no sample of " + std::to_string(group.samples) + " has a value");
        }
    }
    if (table.groups.empty()) lines.emplace_back("no samples stored");
    nlohmann::ordered_json meta = {{"database", database},
                                   {"query", "percentiles"},
                                   {"quantity", name},
                                   {"unit", unit},
                                   {"population", population_of(table.quantity)},
                                   {"group_by", db::to_string(by)},
                                   {"confidence", table.confidence},
                                   {"interval", interval}};
    write(out, format, lines, std::move(meta), rows);
}

void write_exceedance(std::ostream& out, QueryFormat format, const std::string& database,
                      const db::ExceedanceTable& table, db::GroupBy by) {
    const std::string name(db::to_string(table.quantity));
    const std::string unit(db::unit_of(table.quantity));
    const std::string threshold_column = name + "_at_least_" + unit_suffix(unit);
    Table rows;
    rows.columns = group_columns(by);
    rows.columns.insert(rows.columns.end(), {threshold_column, "samples", "trials", "exceeding",
                                             "probability", "ci_lower", "ci_upper"});
    for (const db::ExceedanceGroup& group : table.groups) {
        std::vector<Cell> cells = group_cells(by, group.id);
        cells.insert(cells.end(), {table.threshold, group.samples, group.trials, group.exceeding,
                                   group.probability, group.interval.lower, group.interval.upper});
        rows.rows.push_back(std::move(cells));
    }
    const std::string method(db::to_string(table.method));
    const std::string trials = exceedance_trials(table.quantity);
    std::vector<std::string> lines = {
        database + ": probability that " + name + " >= " + fmt("%g", table.threshold) + " " + unit +
            (table.quantity == db::Quantity::reach ? " (horizontal distance past the toe)" : ""),
        percent_text(table.confidence) + " % " + method + " interval; " + trials};
    if (table.groups.empty()) lines.emplace_back("no samples stored");
    nlohmann::ordered_json meta = {{"database", database},
                                   {"query", "exceed"},
                                   {"quantity", name},
                                   {"unit", unit},
                                   {"threshold", table.threshold},
                                   {"group_by", db::to_string(by)},
                                   {"interval", method},
                                   {"confidence", table.confidence},
                                   {"trials", trials}};
    write(out, format, lines, std::move(meta), rows);
}

std::string exceedance_trials(db::Quantity quantity) {
    return db::needs_wall_hit(quantity)
               ? "every sample is a trial; a rock that misses the wall does not exceed"
               : "trials are the samples with a value";
}

void write_curve(std::ostream& out, QueryFormat format, const std::string& database,
                 const db::ExceedanceCurve& curve, db::GroupBy by) {
    const std::string name(db::to_string(curve.quantity));
    const std::string unit(db::unit_of(curve.quantity));
    Table rows;
    rows.columns = group_columns(by);
    rows.columns.insert(rows.columns.end(),
                        {name + "_at_least_" + unit_suffix(unit), "samples", "trials", "exceeding",
                         "probability", "ci_lower", "ci_upper"});
    for (const db::CurveGroup& group : curve.groups) {
        for (const db::CurvePoint& p : group.points) {
            std::vector<Cell> cells = group_cells(by, group.id);
            cells.insert(cells.end(), {p.threshold, group.samples, group.trials, p.exceeding,
                                       p.probability, p.interval.lower, p.interval.upper});
            rows.rows.push_back(std::move(cells));
        }
    }
    const std::string method(db::to_string(curve.method));
    std::vector<std::string> lines = {
        database + ": exceedance curve, probability that " + name + " >= x (" + unit + ")" +
            (curve.quantity == db::Quantity::reach ? ", x past the toe" : ""),
        percent_text(curve.confidence) + " % " + method + " interval; " +
            exceedance_trials(curve.quantity)};
    if (curve.groups.empty()) lines.emplace_back("no samples stored");
    nlohmann::ordered_json meta = {{"database", database},
                                   {"query", "curve"},
                                   {"quantity", name},
                                   {"unit", unit},
                                   {"group_by", db::to_string(by)},
                                   {"interval", method},
                                   {"confidence", curve.confidence},
                                   {"trials", exceedance_trials(curve.quantity)}};
    write(out, format, lines, std::move(meta), rows);
}

void write_worst(std::ostream& out, QueryFormat format, const std::string& database,
                 db::Quantity by, const std::vector<db::WorstSample>& worst) {
    Table rows;
    rows.columns = {"rank",
                    "sample",
                    "seed",
                    "kind",
                    "size_m",
                    "mass_kg",
                    "zone",
                    "reach_m",
                    "max_speed_m_s",
                    "bounce_height_m",
                    "wall_hits",
                    "peak_force_N",
                    "impact_energy_J",
                    "impulse_N_s",
                    "impact_speed_m_s"};
    std::int64_t rank = 0;
    for (const db::WorstSample& w : worst) {
        rows.rows.push_back({++rank, w.sample, w.seed, w.kind, w.size, w.mass, w.zone, w.reach,
                             w.max_speed, w.bounce_height, w.wall_hits, w.peak_force,
                             w.impact_energy, w.impulse, w.impact_speed});
    }
    const std::string name(db::to_string(by));
    std::vector<std::string> lines = {
        database + ": the " + std::to_string(worst.size()) + " samples with the largest " + name +
            " (" + std::string(db::unit_of(by)) + ")" +
            (db::needs_wall_hit(by) ? ", among the samples that hit the wall" : ""),
        "wall columns are each sample's largest over its hits; replay one with `rockfall "
        "simulate --from " +
            database + " --sample SAMPLE`"};
    nlohmann::ordered_json meta = {
        {"database", database}, {"query", "worst"}, {"by", name}, {"unit", db::unit_of(by)}};
    write(out, format, lines, std::move(meta), rows);
}

}  // namespace rockfall::app
