// Statistics on the values read by queries.cpp: percentiles, exceedance, the run summary.

#include "sqlite.hpp"

#include "db/queries.hpp"
#include "risk/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rockfall::db {

using risk::number_text;

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

// Percentiles of one group's sorted values with their distribution-free intervals.
// Trials for an exceedance: a rock that misses the wall puts no load on it, so for the wall
// quantities every sample is a trial that does not exceed; otherwise the samples with a value.
std::int64_t trials_of(const Group& group, Quantity quantity) {
    return needs_wall_hit(quantity) ? group.samples : count_of(group.values);
}

// P(value >= threshold) over `trials` (group.values ascending).
CurvePoint exceedance_point(const Group& group, std::int64_t trials, double threshold,
                            IntervalMethod method, double confidence) {
    CurvePoint point;
    point.threshold = threshold;
    const auto first = std::lower_bound(group.values.begin(), group.values.end(), threshold);
    point.exceeding = group.values.end() - first;
    point.probability = static_cast<double>(point.exceeding) / static_cast<double>(trials);
    point.interval = proportion_interval(point.exceeding, trials, method, confidence);
    return point;
}

PercentileGroup percentile_group(const Group& group, const std::vector<double>& ps,
                                 double confidence) {
    PercentileGroup out{group.id, group.samples, count_of(group.values), {}};
    if (group.values.empty()) return out;
    for (const double p : ps) {
        PercentileRow& row = out.rows.emplace_back();
        row.p = p;
        row.value = risk::quantile(group.values, p);
        const risk::QuantileRanks ranks = risk::quantile_confidence_ranks(out.n, p, confidence);
        if (ranks.lower >= 1) row.lower = group.values[static_cast<std::size_t>(ranks.lower - 1)];
        if (ranks.upper <= out.n) {
            row.upper = group.values[static_cast<std::size_t>(ranks.upper - 1)];
        }
    }
    return out;
}

void require_levels(const std::vector<double>& ps, double confidence) {
    require_confidence(confidence);
    for (const double p : ps) {
        if (!(p > 0.0 && p < 1.0)) {
            throw std::invalid_argument("percentile " + number_text(100.0 * p) +
                                        ": must be in (0, 100)");
        }
    }
}

}  // namespace

PercentileGroup percentiles_of(const Group& group, const std::vector<double>& ps,
                               double confidence) {
    require_levels(ps, confidence);
    return percentile_group(group, ps, confidence);
}

PercentileTable percentiles(const ResultsDb& db, Quantity quantity, const std::vector<double>& ps,
                            const Grouping& grouping, double confidence) {
    require_levels(ps, confidence);
    PercentileTable table{quantity, confidence, {}};
    for (const Group& group : read_groups(db, quantity, grouping)) {
        table.groups.push_back(percentile_group(group, ps, confidence));
    }
    return table;
}

std::string_view to_string(IntervalMethod method) {
    return method == IntervalMethod::wilson ? "wilson" : "clopper-pearson";
}

std::string_view display_name(IntervalMethod method) {
    return method == IntervalMethod::wilson ? "Wilson score interval"
                                            : "Clopper-Pearson exact interval";
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
        const std::int64_t trials = trials_of(group, quantity);
        if (trials == 0) continue;
        const CurvePoint point = exceedance_point(group, trials, threshold, method, confidence);
        table.groups.push_back(
            {group.id, group.samples, trials, point.exceeding, point.probability, point.interval});
    }
    return table;
}

ExceedanceCurve exceedance_curve(const ResultsDb& db, Quantity quantity, int points,
                                 const Grouping& grouping, IntervalMethod method,
                                 double confidence) {
    require_confidence(confidence);
    if (points < 2 || points > 10000) {
        throw std::invalid_argument("points = " + std::to_string(points) +
                                    ": must be in [2, 10000]");
    }
    ExceedanceCurve curve{quantity, method, confidence, {}};
    const std::vector<Group> groups = read_groups(db, quantity, grouping);
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    for (const Group& group : groups) {
        if (group.values.empty()) continue;
        lo = std::min(lo, group.values.front());
        hi = std::max(hi, group.values.back());
    }
    for (const Group& group : groups) {
        const std::int64_t trials = trials_of(group, quantity);
        if (trials == 0) continue;
        CurveGroup out{group.id, group.samples, trials, {}};
        // No stored value anywhere (every rock missed the wall): no thresholds to draw.
        for (int k = 0; k < points && lo <= hi; ++k) {
            const double x = k == points - 1 ? hi : lo + (hi - lo) * k / (points - 1);
            out.points.push_back(exceedance_point(group, trials, x, method, confidence));
        }
        curve.groups.push_back(std::move(out));
    }
    return curve;
}

Summary summarize(const ResultsDb& db, double confidence) {
    require_confidence(confidence);
    Summary summary;
    summary.run = db.run();
    summary.confidence = confidence;
    sqlite3* handle = db.handle();
    const std::filesystem::path& path = db.path();

    // One pass over the outcomes for the counts and the reach: a COUNT/SUM query and a
    // GROUP BY stop_reason would each scan the table again (and the GROUP BY sort it).
    // Rows come in (sample, rock) order: the primary key's.
    sql::Statement outcomes(handle, path,
                            "SELECT stop_reason, wall_hits, reach_m, sample FROM outcomes");
    Group reach{{"all"}, 0, {}};
    std::int64_t hitting = 0;
    std::int64_t samples_hitting = 0;
    std::int64_t sample_rows = 0;
    std::int64_t last_sample = -1;
    bool last_hit = false;
    while (outcomes.step()) {
        ++reach.samples;
        const std::int64_t sample = outcomes.integer(3);
        if (sample != last_sample || sample_rows == 0) {
            ++sample_rows;
            last_sample = sample;
            last_hit = false;
        }
        const std::string_view reason = outcomes.text_view(0);
        auto known = std::find_if(summary.stop_reasons.begin(), summary.stop_reasons.end(),
                                  [&](const auto& entry) { return entry.first == reason; });
        if (known == summary.stop_reasons.end()) {
            known = summary.stop_reasons.emplace(known, std::string(reason), 0);
        }
        ++known->second;
        const std::int64_t hits = outcomes.integer(1);
        hitting += hits > 0 ? 1 : 0;
        if (hits > 0 && !last_hit) {
            ++samples_hitting;
            last_hit = true;
        }
        summary.wall_impacts += hits;
        if (!outcomes.is_null(2)) reach.values.push_back(outcomes.real(2));
    }
    std::sort(summary.stop_reasons.begin(), summary.stop_reasons.end(),
              [](const auto& a, const auto& b) {
                  return a.second != b.second ? a.second > b.second : a.first < b.first;
              });
    std::sort(reach.values.begin(), reach.values.end());
    summary.samples = sample_rows;
    summary.rocks = reach.samples;
    summary.wall = share(hitting, summary.rocks, confidence);
    summary.wall_samples = share(samples_hitting, summary.samples, confidence);
    if (!reach.values.empty()) summary.max_reach = reach.values.back();
    summary.reach = {Quantity::reach, confidence, {}};
    if (reach.samples > 0)
        summary.reach.groups.push_back(percentile_group(reach, {0.5}, confidence));

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
    const std::vector<double> levels = {0.5, 0.9, 0.95, 0.99};
    summary.peak_force = percentiles(db, Quantity::peak_force, levels, all, confidence);
    summary.impact_energy = percentiles(db, Quantity::impact_energy, levels, all, confidence);
    return summary;
}

}  // namespace rockfall::db
