// Output of the percentiles, exceed, curve and worst queries (the summary is in query_summary.cpp).

#include "report/query_report.hpp"

#include "report/text_format.hpp"

#include <cmath>

namespace rockfall::report {
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

// The column counting a group's observations.
std::string observations(db::Per per) { return per == db::Per::rock ? "rocks" : "samples"; }

}  // namespace

std::string quantity_column(db::Quantity quantity) {
    return std::string(db::to_string(quantity)) + "_" +
           unit_suffix(std::string(db::unit_of(quantity)));
}

std::string population_of(db::Quantity quantity, db::Per per) {
    if (per == db::Per::sample) {
        if (!db::needs_wall_hit(quantity)) {
            return "all samples that have a value (each sample's largest over its rocks)";
        }
        return std::string("the samples with a rock that hit the wall (conditional on a hit; ") +
               (quantity == db::Quantity::impulse
                    ? "each sample's total over all its rocks' hits)"
                    : "each sample's largest value over all its rocks' hits)");
    }
    return db::needs_wall_hit(quantity)
               ? "the rocks that hit the wall (conditional on a hit; each rock's largest "
                 "value over its hits)"
               : "all rocks that have a value";
}

void write_percentiles(std::ostream& out, QueryFormat format, const std::string& database,
                       const db::PercentileTable& table, db::GroupBy by, db::Per per) {
    const std::string name(db::to_string(table.quantity));
    const std::string unit(db::unit_of(table.quantity));
    const std::string column = quantity_column(table.quantity);
    const std::string suffix = unit_suffix(unit);
    Table rows;
    rows.columns = group_columns(by);
    for (const std::string& c : {observations(per), std::string("n"), std::string("percentile")})
        rows.columns.push_back(c);
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
                                          ") over " + population_of(table.quantity, per),
                                      percent_text(table.confidence) +
                                          " % confidence intervals: " + interval +
                                          "; - where the sample is too small for a bound"};
    for (const db::PercentileGroup& group : table.groups) {
        if (group.n == 0) {
            lines.push_back((by == db::GroupBy::none ? "" : group.id.label + ": ") + "none of " +
                            std::to_string(group.samples) + " " + observations(per) +
                            " has a value");
        }
    }
    if (table.groups.empty()) lines.emplace_back("no samples stored");
    nlohmann::ordered_json meta = {{"database", database},
                                   {"query", "percentiles"},
                                   {"quantity", name},
                                   {"unit", unit},
                                   {"population", population_of(table.quantity, per)},
                                   {"group_by", db::to_string(by)},
                                   {"per", db::to_string(per)},
                                   {"confidence", table.confidence},
                                   {"interval", interval}};
    write(out, format, lines, std::move(meta), rows);
}

std::string exceedance_trials(db::Quantity quantity, db::Per per) {
    if (per == db::Per::sample) {
        return db::needs_wall_hit(quantity)
                   ? "every sample is a trial; a sample none of whose rocks hits the wall does "
                     "not exceed"
                   : "trials are the samples with a value (each sample's largest over its rocks)";
    }
    return db::needs_wall_hit(quantity)
               ? "every rock is a trial; a rock that misses the wall does not exceed"
               : "trials are the rocks with a value";
}

namespace {

// What `exceed` and `curve` share: one row per group and threshold, the interval line and
// the JSON metadata.
struct ExceedanceReport {
    db::Quantity quantity;
    db::GroupBy by;
    db::Per per;
    Table rows;
    std::string name;
    std::string unit;

    ExceedanceReport(db::Quantity q, db::GroupBy group_by, db::Per observation)
        : quantity(q),
          by(group_by),
          per(observation),
          name(db::to_string(q)),
          unit(db::unit_of(q)) {
        rows.columns = group_columns(by);
        rows.columns.insert(rows.columns.end(),
                            {name + "_at_least_" + unit_suffix(unit), observations(per), "trials",
                             "exceeding", "probability", "ci_lower", "ci_upper"});
    }

    void add(const db::GroupId& id, std::int64_t samples, std::int64_t trials,
             const db::CurvePoint& p) {
        std::vector<Cell> cells = group_cells(by, id);
        cells.insert(cells.end(), {p.threshold, samples, trials, p.exceeding, p.probability,
                                   p.interval.lower, p.interval.upper});
        rows.rows.push_back(std::move(cells));
    }

    void write(std::ostream& out, QueryFormat format, const std::string& database,
               const char* query, std::string headline, bool no_groups, db::IntervalMethod method,
               double confidence, nlohmann::ordered_json extra) const {
        const std::string interval(db::to_string(method));
        std::vector<std::string> lines = {
            std::move(headline), percent_text(confidence) + " % " + interval + " interval; " +
                                     exceedance_trials(quantity, per)};
        if (no_groups) lines.emplace_back("no samples stored");
        nlohmann::ordered_json meta = {
            {"database", database}, {"query", query}, {"quantity", name}, {"unit", unit}};
        meta.update(extra);
        meta.update(nlohmann::ordered_json{{"group_by", db::to_string(by)},
                                           {"per", db::to_string(per)},
                                           {"interval", interval},
                                           {"confidence", confidence},
                                           {"trials", exceedance_trials(quantity, per)}});
        report::write(out, format, lines, std::move(meta), rows);
    }
};

}  // namespace

void write_exceedance(std::ostream& out, QueryFormat format, const std::string& database,
                      const db::ExceedanceTable& table, db::GroupBy by, db::Per per) {
    ExceedanceReport report(table.quantity, by, per);
    for (const db::ExceedanceGroup& g : table.groups) {
        report.add(g.id, g.samples, g.trials,
                   {table.threshold, g.exceeding, g.probability, g.interval});
    }
    report.write(
        out, format, database, "exceed",
        database + ": probability that " + report.name + " >= " + fmt("%g", table.threshold) + " " +
            report.unit +
            (table.quantity == db::Quantity::reach ? " (horizontal distance past the toe)" : ""),
        table.groups.empty(), table.method, table.confidence, {{"threshold", table.threshold}});
}

void write_curve(std::ostream& out, QueryFormat format, const std::string& database,
                 const db::ExceedanceCurve& curve, db::GroupBy by, db::Per per) {
    ExceedanceReport report(curve.quantity, by, per);
    for (const db::CurveGroup& g : curve.groups) {
        for (const db::CurvePoint& p : g.points) report.add(g.id, g.samples, g.trials, p);
    }
    report.write(
        out, format, database, "curve",
        database + ": exceedance curve, probability that " + report.name + " >= x (" + report.unit +
            ")" + (curve.quantity == db::Quantity::reach ? ", x past the toe" : ""),
        curve.groups.empty(), curve.method, curve.confidence, nlohmann::ordered_json::object());
}

void write_worst(std::ostream& out, QueryFormat format, const std::string& database,
                 db::Quantity by, const std::vector<db::WorstSample>& worst, db::Per per) {
    Table rows;
    rows.columns = {"rank",
                    "sample",
                    "rock",
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
        rows.rows.push_back({++rank, w.sample, w.rock >= 0 ? Cell{w.rock} : Cell{}, w.seed, w.kind,
                             w.size, w.mass, w.zone, w.reach, w.max_speed, w.bounce_height,
                             w.wall_hits, w.peak_force, w.impact_energy, w.impulse,
                             w.impact_speed});
    }
    const std::string name(db::to_string(by));
    const std::string what = observations(per);
    std::vector<std::string> lines = {
        database + ": the " + std::to_string(worst.size()) + " " + what + " with the largest " +
            name + " (" + std::string(db::unit_of(by)) + ")" +
            (db::needs_wall_hit(by) ? ", among the " + what + " that hit the wall" : ""),
        (per == db::Per::rock
             ? "wall columns are each rock's largest over its hits"
             : "rows are whole samples (no rock index): reach, speed and bounce height their "
               "largest over the rocks, wall columns over all their rocks' hits (impulse the "
               "total), mass the total") +
            std::string("; replay a sample with `rockfall simulate --from ") + database +
            " --sample SAMPLE`"};
    nlohmann::ordered_json meta = {{"database", database},
                                   {"query", "worst"},
                                   {"by", name},
                                   {"unit", db::unit_of(by)},
                                   {"per", db::to_string(per)}};
    write(out, format, lines, std::move(meta), rows);
}

}  // namespace rockfall::report
