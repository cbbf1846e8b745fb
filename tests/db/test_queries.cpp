// Queries against hand computations on a database whose values are known exactly:
// 1000 samples, sample i reaching i / 100 m, every third kind, alternate zones, sizes rising
// with i, and the samples with i % 10 < 3 hitting the wall with peak force 1000 (i + 1) N.

#include "db_test_support.hpp"

#include "db/queries.hpp"
#include "risk/statistics.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace rockfall::db;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr int sample_count = 1000;

SampleRecord known_record(int i) {
    std::vector<double> forces;
    if (i % 10 < 3) forces.push_back(1000.0 * (i + 1));
    if (i % 10 == 0) forces.push_back(500.0 * (i + 1));  // a second, weaker hit
    SampleRecord r = rockfall::db::test::hand_record(i, i / 100.0, forces);
    r.inputs.kind =
        std::array{rockfall::shapes::RockKind::sphere, rockfall::shapes::RockKind::massive,
                   rockfall::shapes::RockKind::planar}[static_cast<std::size_t>(i % 3)];
    r.inputs.zone = static_cast<std::size_t>(i % 2);
    r.inputs.size = 0.1005 + 0.0004 * i;
    r.rocks.at(0).inputs = rockfall::risk::rock_inputs(r.inputs);
    r.rocks.at(0).outcome.stop = i % 100 == 0 ? rockfall::engine::StopReason::left_domain
                                              : rockfall::engine::StopReason::at_rest;
    for (const double distance : {0.0, 5.0}) {
        rockfall::engine::StationCrossing& s = r.rocks.at(0).outcome.stations.emplace_back();
        s.distance_from_toe = distance;
        s.reached = r.rocks.at(0).outcome.reach >= distance;
    }
    return r;
}

// The database is written once for all the tests of this file.
const ResultsDb& known_database() {
    static rockfall::db::test::ScratchDir dir;
    static const ResultsDb db = [] {
        std::vector<SampleRecord> records;
        for (int i = 0; i < sample_count; ++i) records.push_back(known_record(i));
        return rockfall::db::test::make_database(dir / "known.db", records);
    }();
    return db;
}

std::vector<double> wall_forces() {
    std::vector<double> forces;
    for (int i = 0; i < sample_count; ++i) {
        if (i % 10 < 3) forces.push_back(1000.0 * (i + 1));
    }
    return forces;
}

}  // namespace

TEST_CASE("exceedance of 50 in 1000 has the Wilson interval [0.0381, 0.0653]", "[db][query]") {
    const ExceedanceTable table =
        exceedance(known_database(), Quantity::reach, 9.5, {}, IntervalMethod::wilson, 0.95);
    REQUIRE(table.groups.size() == 1);
    const ExceedanceGroup& all = table.groups[0];
    CHECK(all.id.label == "all");
    CHECK(all.trials == 1000);
    CHECK(all.exceeding == 50);
    CHECK(all.probability == 0.05);
    CHECK_THAT(all.interval.lower, WithinAbs(0.0381, 5e-5));
    CHECK_THAT(all.interval.upper, WithinAbs(0.0653, 5e-5));

    const ExceedanceTable exact = exceedance(known_database(), Quantity::reach, 9.5, {},
                                             IntervalMethod::clopper_pearson, 0.99);
    const rockfall::risk::Interval expected =
        rockfall::risk::clopper_pearson_interval(50, 1000, 0.99);
    CHECK(exact.groups[0].interval.lower == expected.lower);
    CHECK(exact.groups[0].interval.upper == expected.upper);
}

TEST_CASE("exceedance by zone and of a wall quantity", "[db][query]") {
    // Reach >= 9.5 m: samples 950..999, 25 even (upper) and 25 odd (lower).
    const ExceedanceTable by_zone = exceedance(known_database(), Quantity::reach, 9.5,
                                               {GroupBy::zone, {}}, IntervalMethod::wilson);
    REQUIRE(by_zone.groups.size() == 2);
    CHECK(by_zone.groups[0].id.label == "upper");
    CHECK(by_zone.groups[1].id.label == "lower");
    for (const ExceedanceGroup& g : by_zone.groups) {
        CHECK(g.trials == 500);
        CHECK(g.exceeding == 25);
    }
    // Peak force >= 500 kN: i >= 499 with i % 10 < 3, i.e. 3 of each ten from 500 to 999;
    // the 700 rocks that miss the wall are trials that do not exceed.
    const ExceedanceTable force =
        exceedance(known_database(), Quantity::peak_force, 5.0e5, {}, IntervalMethod::wilson);
    CHECK(force.groups.at(0).trials == 1000);
    CHECK(force.groups.at(0).exceeding == 150);
    CHECK_THROWS_AS(
        exceedance(known_database(), Quantity::reach, std::nan(""), {}, IntervalMethod::wilson),
        std::invalid_argument);
}

TEST_CASE("exceedance curve: evenly spaced thresholds over the stored range", "[db][query]") {
    // Reach i / 100 m for i = 0..999: thresholds 0, 3.33, 6.66, 9.99 m over 4 points; reach
    // >= x for x = k * 9.99 / 3 is the samples i >= ceil(100 x).
    const ExceedanceCurve curve =
        exceedance_curve(known_database(), Quantity::reach, 4, {}, IntervalMethod::wilson);
    REQUIRE(curve.groups.size() == 1);
    const CurveGroup& all = curve.groups[0];
    CHECK(all.trials == 1000);
    REQUIRE(all.points.size() == 4);
    const std::array<std::int64_t, 4> exceeding{1000, 667, 334, 1};
    for (std::size_t k = 0; k < 4; ++k) {
        CHECK_THAT(all.points[k].threshold, WithinRel(9.99 * static_cast<double>(k) / 3.0, 1e-12));
        CHECK(all.points[k].exceeding == exceeding[k]);
        CHECK_THAT(all.points[k].probability,
                   WithinRel(static_cast<double>(exceeding[k]) / 1000.0, 1e-12));
        // Each point is the single-threshold query at that threshold.
        const ExceedanceTable single = exceedance(
            known_database(), Quantity::reach, all.points[k].threshold, {}, IntervalMethod::wilson);
        CHECK(single.groups[0].exceeding == all.points[k].exceeding);
        CHECK(single.groups[0].interval.lower == all.points[k].interval.lower);
        CHECK(single.groups[0].interval.upper == all.points[k].interval.upper);
    }
    // Wall quantities: every sample is a trial; by kind, the same thresholds for each group.
    const ExceedanceCurve force =
        exceedance_curve(known_database(), Quantity::peak_force, 3, {GroupBy::kind, {}},
                         IntervalMethod::clopper_pearson);
    REQUIRE(force.groups.size() == 3);
    for (const CurveGroup& g : force.groups) {
        CHECK(g.trials == g.samples);
        REQUIRE(g.points.size() == 3);
        CHECK(g.points[0].threshold == force.groups[0].points[0].threshold);
        CHECK(g.points[2].threshold == force.groups[0].points[2].threshold);
    }
    CHECK_THROWS_AS(
        exceedance_curve(known_database(), Quantity::reach, 1, {}, IntervalMethod::wilson),
        std::invalid_argument);
}

TEST_CASE("percentiles of the reach with order-statistic intervals", "[db][query]") {
    const PercentileTable table =
        percentiles(known_database(), Quantity::reach, {0.5, 0.9}, {}, 0.95);
    REQUIRE(table.groups.size() == 1);
    const PercentileGroup& all = table.groups[0];
    CHECK(all.n == 1000);
    CHECK(all.samples == 1000);
    REQUIRE(all.rows.size() == 2);
    // Type 7: h = 999 p. Median: (4.99 + 5.00) / 2; bounds x(469), x(532) (exact binomial).
    CHECK_THAT(all.rows[0].value, WithinRel(4.995, 1e-12));
    CHECK(all.rows[0].lower == 4.68);
    CHECK(all.rows[0].upper == 5.31);
    // 90th: h = 899.1; bounds at ranks quantile_confidence_ranks(1000, 0.9) gives.
    CHECK_THAT(all.rows[1].value, WithinRel(8.991, 1e-12));
    const rockfall::risk::QuantileRanks ranks =
        rockfall::risk::quantile_confidence_ranks(1000, 0.9);
    CHECK(all.rows[1].lower == static_cast<double>(ranks.lower - 1) / 100.0);
    CHECK(all.rows[1].upper == static_cast<double>(ranks.upper - 1) / 100.0);
    CHECK_THROWS_AS(percentiles(known_database(), Quantity::reach, {1.0}, {}),
                    std::invalid_argument);
}

TEST_CASE("wall quantities are per-sample maxima over the samples that hit", "[db][query]") {
    const PercentileTable table =
        percentiles(known_database(), Quantity::peak_force, {0.5, 0.99}, {}, 0.95);
    const PercentileGroup& all = table.groups.at(0);
    CHECK(all.samples == 1000);
    CHECK(all.n == 300);
    const std::vector<double> forces = wall_forces();  // ascending already
    CHECK(all.rows.at(0).value == rockfall::risk::quantile(forces, 0.5));
    CHECK(all.rows.at(1).value == rockfall::risk::quantile(forces, 0.99));
    // n = 300 is too few to bound the 99th percentile from above at 95 %.
    CHECK(std::isnan(all.rows.at(1).upper));
    CHECK_FALSE(std::isnan(all.rows.at(1).lower));
}

TEST_CASE("groups by kind, zone and size class", "[db][query]") {
    const auto labels_and_counts = [](const std::vector<Group>& groups) {
        std::vector<std::pair<std::string, std::int64_t>> out;
        for (const Group& g : groups) out.emplace_back(g.id.label, g.samples);
        return out;
    };
    using Counts = std::vector<std::pair<std::string, std::int64_t>>;
    CHECK(labels_and_counts(read_groups(known_database(), Quantity::reach, {GroupBy::kind, {}})) ==
          Counts{{"massive", 333}, {"planar", 333}, {"sphere", 334}});
    CHECK(labels_and_counts(read_groups(known_database(), Quantity::reach, {GroupBy::zone, {}})) ==
          Counts{{"upper", 500}, {"lower", 500}});
    // size = 0.1005 + 0.0004 i m.
    const auto sizes = read_groups(known_database(), Quantity::reach, {GroupBy::size, {0.2, 0.4}});
    CHECK(labels_and_counts(sizes) ==
          Counts{{"[0, 0.2)", 249}, {"[0.2, 0.4)", 500}, {"[0.4, inf)", 251}});
    CHECK(sizes[1].id.size_min == 0.2);
    CHECK(sizes[1].id.size_max == 0.4);
    CHECK(std::isinf(sizes[2].id.size_max));
    // Default: quartiles (order statistics 250, 500, 750: 0.2001, 0.3001, 0.4001 m) rounded.
    CHECK(labels_and_counts(read_groups(known_database(), Quantity::reach, {GroupBy::size, {}})) ==
          Counts{{"[0, 0.2)", 249}, {"[0.2, 0.3)", 250}, {"[0.3, 0.4)", 250}, {"[0.4, inf)", 251}});
    // Wall quantity by kind: every kind has 100 of the 300 hits.
    for (const Group& g :
         read_groups(known_database(), Quantity::peak_force, {GroupBy::kind, {}})) {
        CHECK(g.values.size() == 100);
        CHECK(std::is_sorted(g.values.begin(), g.values.end()));
    }
    CHECK_THROWS_AS(read_groups(known_database(), Quantity::reach, {GroupBy::size, {0.3, 0.2}}),
                    std::invalid_argument);
}

TEST_CASE("the worst samples come with their seeds", "[db][query]") {
    const auto by_reach = worst_samples(known_database(), Quantity::reach, 3);
    REQUIRE(by_reach.size() == 3);
    CHECK(by_reach[0].sample == 999);
    CHECK(by_reach[0].seed == 1999);
    CHECK(by_reach[0].reach == 9.99);
    CHECK(by_reach[2].sample == 997);
    CHECK(by_reach[0].zone == "lower");
    CHECK(std::isnan(by_reach[0].peak_force));  // 999 % 10 = 9: no wall hit
    const auto by_force = worst_samples(known_database(), Quantity::peak_force, 2);
    REQUIRE(by_force.size() == 2);
    CHECK(by_force[0].sample == 992);
    CHECK(by_force[0].peak_force == 993000.0);
    CHECK(by_force[0].wall_hits == 1);
    CHECK(by_force[1].sample == 991);
    const auto everything = worst_samples(known_database(), Quantity::impulse, 5000);
    CHECK(everything.size() == 300);  // only the samples that hit
    CHECK_THROWS_AS(worst_samples(known_database(), Quantity::reach, 0), std::invalid_argument);
}

TEST_CASE("the summary counts stops, wall hits and stations", "[db][query]") {
    const Summary s = summarize(known_database(), 0.95);
    CHECK(s.samples == 1000);
    CHECK(s.run.scenario_name == "synthetic slope");
    REQUIRE(s.stop_reasons.size() == 2);
    CHECK(s.stop_reasons[0] == std::pair<std::string, std::int64_t>{"at_rest", 990});
    CHECK(s.stop_reasons[1] == std::pair<std::string, std::int64_t>{"left_domain", 10});
    CHECK(s.wall.count == 300);
    CHECK(s.wall.trials == 1000);
    CHECK(s.wall.interval.lower == rockfall::risk::wilson_interval(300, 1000).lower);
    CHECK(s.wall_impacts == 400);  // 300 first hits and 100 second ones
    CHECK(s.max_reach == 9.99);
    REQUIRE(s.stations.size() == 2);
    CHECK(s.stations[0].reached.count == 1000);
    CHECK(s.stations[1].distance_from_toe == 5.0);
    CHECK(s.stations[1].reached.count == 500);
    CHECK(s.reach.groups.at(0).rows.at(0).lower == 4.68);
    CHECK(s.peak_force.groups.at(0).n == 300);
    CHECK(s.impact_energy.groups.at(0).rows.size() == 4);
}

TEST_CASE("queries on a database without samples", "[db][query]") {
    rockfall::db::test::ScratchDir dir;
    const ResultsDb db = rockfall::db::test::make_database(dir / "empty.db", {});
    CHECK(percentiles(db, Quantity::reach, {0.5}, {}).groups.empty());
    CHECK(exceedance(db, Quantity::reach, 1.0, {}, IntervalMethod::wilson).groups.empty());
    CHECK(worst_samples(db, Quantity::reach, 3).empty());
    const Summary s = summarize(db);
    CHECK(s.samples == 0);
    CHECK(s.wall.trials == 0);
    CHECK(std::isnan(s.max_reach));
}

TEST_CASE("quantity, grouping and interval names", "[db][query]") {
    for (const Quantity q : all_quantities) CHECK(parse_quantity(to_string(q)) == q);
    CHECK(column_of(Quantity::impact_energy) == "energy_before_J");
    CHECK(unit_of(Quantity::impulse) == "N s");
    CHECK(needs_wall_hit(Quantity::peak_force));
    CHECK_FALSE(needs_wall_hit(Quantity::bounce_height));
    CHECK_THROWS_WITH(parse_quantity("speed"), Catch::Contains("choose reach"));
    CHECK(parse_group_by("zone") == GroupBy::zone);
    CHECK_THROWS_AS(parse_group_by("colour"), std::invalid_argument);
    CHECK(parse_interval_method("clopper-pearson") == IntervalMethod::clopper_pearson);
    CHECK_THROWS_AS(parse_interval_method("wald"), std::invalid_argument);
}

TEST_CASE("stored outcomes for the stop rule", "[db][query]") {
    const std::vector<StoredOutcome> outcomes = stored_outcomes(known_database());
    REQUIRE(outcomes.size() == 1000);
    CHECK(outcomes[950].sample == 950);
    CHECK(outcomes[950].reach == 9.5);
    CHECK(outcomes[950].wall_hits == 2);  // 950 % 10 = 0: two hits
    CHECK(outcomes[951].wall_hits == 1);
    CHECK(outcomes[959].wall_hits == 0);
}
