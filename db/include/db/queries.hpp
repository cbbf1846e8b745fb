#pragma once
/// The questions a results database answers, for `rockfall query`, the tests and the
/// benchmarks: a quantity's values broken down by shape kind, size class or release zone; its
/// percentiles with distribution-free confidence intervals; the probability of exceeding a
/// value with a Wilson or Clopper-Pearson interval; the worst samples; a summary of the run.
/// Every function only reads; each throws DatabaseError for a damaged file.

#include "db/results_db.hpp"
#include "risk/statistics.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rockfall::db {

/// A quantity the queries read, per rock (Per::rock) or per sample (Per::sample: over all of
/// the sample's rocks).
enum class Quantity {
    reach,          ///< furthest horizontal distance past the toe, m; per sample the largest
    max_speed,      ///< highest speed, m/s; per sample the largest
    bounce_height,  ///< highest gap between a rock and the surface, m; per sample the largest
    impact_energy,  ///< kinetic energy at first touch of the wall, J; largest over the hits
    impact_speed,   ///< speed at first touch of the wall, m/s; largest over the hits
    impulse,        ///< normal impulse on the wall, N s; per rock the largest over its hits,
                    ///< per sample the sum over all hits of all its rocks (total impulse)
    peak_force,     ///< peak normal force on the wall, N; largest over the hits
};

/// Every quantity, in the order above.
inline constexpr Quantity all_quantities[] = {
    Quantity::reach,        Quantity::max_speed, Quantity::bounce_height, Quantity::impact_energy,
    Quantity::impact_speed, Quantity::impulse,   Quantity::peak_force};

/// Name on the command line ("reach", "peak_force", ...).
std::string_view to_string(Quantity quantity);
/// The quantity of a name; throws std::invalid_argument listing the names.
Quantity parse_quantity(std::string_view name);
/// Column name with its unit, as in the views ("reach_m", "peak_force_N").
std::string_view column_of(Quantity quantity);
/// Unit ("m", "m/s", "J", "N s", "N").
std::string_view unit_of(Quantity quantity);
/// True for the wall quantities: only rocks (samples) that hit the wall have them, and a rock's
/// value is the largest over its hits (view sample_impacts).

/// What one observation is: a rock of a sample, or a whole sample (a cluster release).
enum class Per {
    rock,    ///< every rock of every sample (a one-rock sample: the sample)
    sample,  ///< every sample, its value made of all its rocks (see Quantity)
};
/// Name on the command line ("rock", "sample").
std::string_view to_string(Per per);
/// The observation of a name; throws std::invalid_argument naming the choices.
Per parse_per(std::string_view name);
bool needs_wall_hit(Quantity quantity);

/// What results are broken down by.
enum class GroupBy {
    none,   ///< one group of all samples
    kind,   ///< shape family (samples.kind)
    size,   ///< size class of the nominal size (samples.size_m)
    zone,   ///< release zone (zones.name)
    shape,  ///< rock shape: the family, custom, a named shape or generated (samples.shape)
};
/// Name on the command line ("none", "kind", "size", "zone", "shape").
std::string_view to_string(GroupBy by);
/// The grouping of a name; throws std::invalid_argument listing the names.
GroupBy parse_group_by(std::string_view name);

/// A breakdown: by what and, for size classes, where the classes change; and what one
/// observation is.
struct Grouping {
    /// What to group by. Per rock, kind, shape and size are the rock's (table rocks); per
    /// sample the sample's (table samples; a cluster release has no size).
    GroupBy by = GroupBy::none;
    /// Size class edges, m, strictly ascending and > 0: classes [0, e1), [e1, e2), ...,
    /// [en, inf). Empty with by = size: edges at the quartiles of the stored sizes, rounded
    /// to two significant digits.
    std::vector<double> size_edges;
    /// Observations: rocks (default) or samples.
    Per per = Per::rock;
};

/// Throws std::invalid_argument naming the edge unless the edges are finite, > 0 and
/// strictly ascending.
void validate_size_edges(const std::vector<double>& edges);

/// Which group a result belongs to.
struct GroupId {
    /// "all", the kind, the shape, the zone name, or the size class ("[0.2, 0.3)", m).
    std::string label;
    /// Size class bounds, m; NaN unless grouped by size; the last class ends at +infinity.
    double size_min = std::numeric_limits<double>::quiet_NaN();
    double size_max = std::numeric_limits<double>::quiet_NaN();
};

/// One group's values of a quantity.
struct Group {
    /// The group.
    GroupId id;
    /// Observations (rocks or samples, Grouping::per) in the group.
    std::int64_t samples = 0;
    /// The values, ascending: one per observation that has one (for the wall quantities those
    /// that hit the wall; NULLs are skipped).
    std::vector<double> values;
};

/// The values of `quantity` per group: groups with samples only, in kind or shape order
/// (alphabetical), zone order or size order.
std::vector<Group> read_groups(const ResultsDb& db, Quantity quantity, const Grouping& grouping);

/// One percentile of one group.
struct PercentileRow {
    /// Probability level p in (0, 1) (the 95th percentile has p = 0.95).
    double p = 0.5;
    /// Type 7 quantile (risk::quantile), in the quantity's unit.
    double value = 0.0;
    /// Distribution-free confidence bounds (risk::quantile_confidence_ranks); NaN where the
    /// group is too small for a bound on that side.
    double lower = std::numeric_limits<double>::quiet_NaN();
    double upper = std::numeric_limits<double>::quiet_NaN();
};

/// Percentiles of one group.
struct PercentileGroup {
    /// The group, its samples and how many of them have the quantity.
    GroupId id;
    std::int64_t samples = 0;
    std::int64_t n = 0;
    /// One row per requested p; empty when n = 0.
    std::vector<PercentileRow> rows;
};

/// Percentiles of a quantity per group.
struct PercentileTable {
    /// The quantity and the confidence of the intervals.
    Quantity quantity = Quantity::reach;
    double confidence = 0.95;
    std::vector<PercentileGroup> groups;
};

/// Percentiles `ps` (each in (0, 1)) of `quantity` with confidence intervals at `confidence`
/// (in (0, 1)); throws std::invalid_argument for a bad p or confidence.
PercentileTable percentiles(const ResultsDb& db, Quantity quantity, const std::vector<double>& ps,
                            const Grouping& grouping, double confidence = 0.95);

/// Percentiles `ps` of one group's values (ascending) with their intervals, as `percentiles`
/// gives them for each group: for values read elsewhere (the stations). Throws
/// std::invalid_argument for a bad p or confidence.
PercentileGroup percentiles_of(const Group& group, const std::vector<double>& ps,
                               double confidence = 0.95);

/// Interval for a proportion.
enum class IntervalMethod {
    wilson,           ///< Wilson score interval
    clopper_pearson,  ///< Clopper-Pearson exact interval
};
/// Name on the command line ("wilson", "clopper-pearson").
std::string_view to_string(IntervalMethod method);
/// Name in reports ("Wilson score interval", "Clopper-Pearson exact interval").
std::string_view display_name(IntervalMethod method);
/// The method of a name; throws std::invalid_argument listing the names.
IntervalMethod parse_interval_method(std::string_view name);

/// Exceedance in one group.
struct ExceedanceGroup {
    /// The group and its samples.
    GroupId id;
    std::int64_t samples = 0;
    /// Trials: samples with a value of the quantity; for the wall quantities every sample
    /// (a rock that misses the wall exceeds no load).
    std::int64_t trials = 0;
    /// Trials whose value is >= the threshold.
    std::int64_t exceeding = 0;
    /// exceeding / trials, and its interval.
    double probability = 0.0;
    risk::Interval interval;
};

/// Probability that a sample's quantity is >= a threshold, per group.
struct ExceedanceTable {
    /// The quantity, the threshold in its unit, the interval method and confidence.
    Quantity quantity = Quantity::reach;
    double threshold = 0.0;
    IntervalMethod method = IntervalMethod::wilson;
    double confidence = 0.95;
    /// Groups with at least one trial.
    std::vector<ExceedanceGroup> groups;
};

/// P(quantity >= threshold) per group with its interval; throws std::invalid_argument for a
/// non-finite threshold or a confidence outside (0, 1).
ExceedanceTable exceedance(const ResultsDb& db, Quantity quantity, double threshold,
                           const Grouping& grouping, IntervalMethod method,
                           double confidence = 0.95);

/// One point of an exceedance curve: P(quantity >= threshold) with its interval.
struct CurvePoint {
    /// The threshold, in the quantity's unit.
    double threshold = 0.0;
    /// Trials whose value is >= the threshold, their share and its interval.
    std::int64_t exceeding = 0;
    double probability = 0.0;
    risk::Interval interval;
};

/// One group's exceedance curve.
struct CurveGroup {
    /// The group, its samples and trials (as ExceedanceGroup).
    GroupId id;
    std::int64_t samples = 0;
    std::int64_t trials = 0;
    /// One point per threshold, ascending.
    std::vector<CurvePoint> points;
};

/// Exceedance curves of a quantity per group, at the same thresholds for every group.
struct ExceedanceCurve {
    Quantity quantity = Quantity::reach;
    IntervalMethod method = IntervalMethod::wilson;
    double confidence = 0.95;
    /// Groups with at least one trial.
    std::vector<CurveGroup> groups;
};

/// P(quantity >= x) per group at `points` (in [2, 10000]) thresholds evenly spaced from the
/// smallest to the largest stored value over all groups, each with its interval (the same
/// trials and method as `exceedance`). Throws std::invalid_argument for a bad point count or
/// confidence.
ExceedanceCurve exceedance_curve(const ResultsDb& db, Quantity quantity, int points,
                                 const Grouping& grouping, IntervalMethod method,
                                 double confidence = 0.95);

/// A sample among the worst by some quantity, with what identifies and replays it.
struct WorstSample {
    /// Sample index (for `rockfall simulate --from DB --sample i`), rock index (0-based; -1
    /// for a whole sample) and the sample's engine seed.
    std::int64_t sample = 0;
    std::int64_t rock = 0;
    std::uint64_t seed = 0;
    /// Shape kind, nominal size (m), mass (kg) and release zone name.
    std::string kind;
    double size = 0.0;
    double mass = 0.0;
    std::string zone;
    /// Outcome: reach (m), highest speed (m/s), highest bounce height (m), wall hits.
    double reach = 0.0;
    double max_speed = 0.0;
    double bounce_height = 0.0;
    std::int64_t wall_hits = 0;
    /// Largest over the wall hits (NaN without a hit): peak force (N), impact energy (J),
    /// normal impulse (N s), impact speed (m/s).
    double peak_force = 0.0;
    double impact_energy = 0.0;
    double impulse = 0.0;
    double impact_speed = 0.0;
};

/// Per rock: the `count` rocks with the largest `by` (each rock of each sample), largest first
/// (ties by sample and rock index), each with its own inputs and outcome. Per sample: the
/// `count` samples with the largest value made of all their rocks (see Quantity), rock = -1,
/// the sample's kind, size and (total) mass, its largest reach, speed and bounce height, its
/// wall hits summed, and its wall quantities as in Quantity (impulse: the total). Those
/// without a value (NULL, no wall hit) are never among them. count >= 1.
std::vector<WorstSample> worst_samples(const ResultsDb& db, Quantity by, std::int64_t count,
                                       Per per = Per::rock);

/// What a stop rule needs of a stored sample's outcome.
struct StoredOutcome {
    /// Sample index.
    std::int64_t sample = 0;
    /// Largest reach past the toe over its rocks, m (NaN when not stored), and the number of
    /// wall hits of all its rocks.
    double reach = 0.0;
    std::int64_t wall_hits = 0;
};

/// Every stored sample's reach and wall hits, by ascending sample index (for `--until` after
/// `--resume`).
std::vector<StoredOutcome> stored_outcomes(const ResultsDb& db);

/// A proportion of samples with its interval.
struct Share {
    /// Samples counted and trials.
    std::int64_t count = 0;
    std::int64_t trials = 0;
    /// Wilson interval of count / trials at the summary's confidence; [0, 1] when trials = 0.
    risk::Interval interval{0.0, 1.0};
};

/// Samples past one station.
struct StationShare {
    /// Station number (1-based, scenario order) and its horizontal distance from the toe, m.
    std::int64_t station = 0;
    double distance_from_toe = 0.0;
    /// Samples that crossed it, of all samples.
    Share reached;
};

/// What `rockfall query DB summary` reports.
struct Summary {
    /// The run record, the samples stored and their rocks (equal for one-rock samples).
    RunRecord run;
    std::int64_t samples = 0;
    std::int64_t rocks = 0;
    /// Confidence of every interval below.
    double confidence = 0.95;
    /// Rocks per stop reason, most frequent first.
    std::vector<std::pair<std::string, std::int64_t>> stop_reasons;
    /// Reach median over the rocks with its interval, and the largest reach (m; NaN without
    /// samples).
    PercentileTable reach;
    double max_reach = std::numeric_limits<double>::quiet_NaN();
    /// Rocks that hit the wall (of all rocks), samples with a rock that did (of all samples),
    /// and the number of hits over all rocks.
    Share wall;
    Share wall_samples;
    std::int64_t wall_impacts = 0;
    /// Rocks past each station.
    std::vector<StationShare> stations;
    /// Percentiles 50, 90, 95, 99 of the peak force and impact energy over the rocks that hit
    /// the wall (each rock's largest).
    PercentileTable peak_force;
    PercentileTable impact_energy;
};

/// The summary of a run at `confidence` in (0, 1).
Summary summarize(const ResultsDb& db, double confidence = 0.95);

}  // namespace rockfall::db
