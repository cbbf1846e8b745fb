// Statistics on the values read by queries.cpp: percentiles, exceedance, the run summary.

#include "number_text.hpp"
#include "sqlite.hpp"

#include "db/queries.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rockfall::db {
namespace {

void require_confidence(double confidence) {
    if (!(confidence > 0.0 && confidence < 1.0)) {
        throw std::invalid_argument("confidence = " + number_text(confidence) +
                                    ": must be in (0, 1), e.g. 0.95");
    }
}

risk::Interval proportion_interval(std::int64_t count, std::int64_t trials, IntervalMethod method,
                                   double confidence) {
    if (trials == 0) return {0.0, 1.0};
    return method == IntervalMethod::wilson
               ? risk::wilson_interval(count, trials, confidence)
               : risk::clopper_pearson_interval(count, trials, confidence);
}

Share share(std::int64_t count, std::int64_t trials, double confidence) {
    return {count, trials, proportion_interval(count, trials, IntervalMethod::wilson, confidence)};
}

std::int64_t count_of(const std::vector<double>& values) {
    return static_cast<std::int64_t>(values.size());
}

}  // namespace

PercentileTable percentiles(const ResultsDb& db, Quantity quantity, const std::vector<double>& ps,
                            const Grouping& grouping, double confidence) {
    require_confidence(confidence);
    for (const double p : ps) {
        if (!(p > 0.0 && p < 1.0)) {
            throw std::invalid_argument("percentile " + number_text(100.0 * p) +
                                        ": must be in (0, 100)");
        }
    }
    PercentileTable table{quantity, confidence, {}};
    for (const Group& group : read_groups(db, quantity, grouping)) {
        PercentileGroup& out = table.groups.emplace_back();
        out.id = group.id;
        out.samples = group.samples;
        out.n = count_of(group.values);
        if (group.values.empty()) continue;
        for (const double p : ps) {
            PercentileRow& row = out.rows.emplace_back();
            row.p = p;
            row.value = risk::quantile(group.values, p);
            const risk::QuantileRanks ranks = risk::quantile_confidence_ranks(out.n, p, confidence);
            if (ranks.lower >= 1)
                row.lower = group.values[static_cast<std::size_t>(ranks.lower - 1)];
            if (ranks.upper <= out.n) {
                row.upper = group.values[static_cast<std::size_t>(ranks.upper - 1)];
            }
        }
    }
    return table;
}

std::string_view to_string(IntervalMethod method) {
    return method == IntervalMethod::wilson ? "wilson" : "clopper-pearson";
}

IntervalMethod parse_interval_method(std::string_view name) {
    if (name == "wilson") return IntervalMethod::wilson;
    if (name == "clopper-pearson") return IntervalMethod::clopper_pearson;
    throw std::invalid_argument("unknown interval '" + std::string(name) +
                                "': choose wilson or clopper-pearson");
}

ExceedanceTable exceedance(const ResultsDb& db, Quantity quantity, double threshold,
                           const Grouping& grouping, IntervalMethod method, double confidence) {
    require_confidence(confidence);
    if (!std::isfinite(threshold)) {
        throw std::invalid_argument("threshold = " + number_text(threshold) + " " +
                                    std::string(unit_of(quantity)) + ": must be finite");
    }
    ExceedanceTable table{quantity, threshold, method, confidence, {}};
    for (const Group& group : read_groups(db, quantity, grouping)) {
        ExceedanceGroup out;
        out.id = group.id;
        out.samples = group.samples;
        // A rock that misses the wall puts no load on it: it is a trial that does not exceed.
        out.trials = needs_wall_hit(quantity) ? group.samples : count_of(group.values);
        if (out.trials == 0) continue;
        const auto first = std::lower_bound(group.values.begin(), group.values.end(), threshold);
        out.exceeding = group.values.end() - first;
        out.probability = static_cast<double>(out.exceeding) / static_cast<double>(out.trials);
        out.interval = proportion_interval(out.exceeding, out.trials, method, confidence);
        table.groups.push_back(std::move(out));
    }
    return table;
}

Summary summarize(const ResultsDb& db, double confidence) {
    require_confidence(confidence);
    Summary summary;
    summary.run = db.run();
    summary.confidence = confidence;
    sqlite3* handle = db.handle();
    const std::filesystem::path& path = db.path();

    sql::Statement totals(handle, path,
                          "SELECT COUNT(*), COALESCE(SUM(wall_hits > 0), 0), "
                          "COALESCE(SUM(wall_hits), 0), MAX(reach_m) FROM outcomes");
    totals.step();
    summary.samples = totals.integer(0);
    summary.wall = share(totals.integer(1), summary.samples, confidence);
    summary.wall_impacts = totals.integer(2);
    summary.max_reach = totals.real(3);

    sql::Statement reasons(handle, path,
                           "SELECT stop_reason, COUNT(*) AS n FROM outcomes GROUP BY stop_reason "
                           "ORDER BY n DESC, stop_reason");
    while (reasons.step()) summary.stop_reasons.emplace_back(reasons.text(0), reasons.integer(1));

    // One pass over the stations in storage order; GROUP BY station would sort every row.
    sql::Statement stations(handle, path,
                            "SELECT station, distance_from_toe_m, reached FROM stations");
    while (stations.step()) {
        const std::int64_t station = stations.integer(0);
        if (station < 1) continue;
        const auto index = static_cast<std::size_t>(station - 1);
        if (index >= summary.stations.size()) summary.stations.resize(index + 1);
        StationShare& s = summary.stations[index];
        s.station = station;
        s.distance_from_toe = stations.real(1);
        ++s.reached.trials;
        s.reached.count += stations.integer(2);
    }
    for (StationShare& s : summary.stations) {
        s.reached = share(s.reached.count, s.reached.trials, confidence);
    }

    const Grouping all;
    summary.reach = percentiles(db, Quantity::reach, {0.5}, all, confidence);
    const std::vector<double> levels = {0.5, 0.9, 0.95, 0.99};
    summary.peak_force = percentiles(db, Quantity::peak_force, levels, all, confidence);
    summary.impact_energy = percentiles(db, Quantity::impact_energy, levels, all, confidence);
    return summary;
}

}  // namespace rockfall::db
