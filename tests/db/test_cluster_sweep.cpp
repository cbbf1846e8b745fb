// A sweep over a cluster scenario (issue 13): each sample is one cluster release drawn by the
// sample's seed; the database keeps every rock's outcome, stations and wall hits with its
// sample; queries work per rock and per sample; a stored sample replays.

#include "db_test_support.hpp"
#include "scenario/scenario_file.hpp"

#include "db/queries.hpp"
#include "db/results_db.hpp"
#include "db/wall_impacts.hpp"
#include "engine/simulation.hpp"
#include "risk/sweep_runner.hpp"

#include <catch2/catch.hpp>
#include <sqlite3.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

using namespace rockfall;
using rockfall::db::test::ScratchDir;

namespace {

constexpr int rocks_per_sample = 5;

// tests/db/data/cluster_sweep.toml: a shortened, unlined 45 deg flume, the wall 0.3 m past
// the toe, a 5-rock cluster of C2's grading; two samples.
std::string cluster_sweep_text() {
    std::ifstream in(std::filesystem::path(ROCKFALL_TEST_DATA_DIR) / "cluster_sweep.toml");
    REQUIRE(in);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

scenario::ScenarioFile cluster_file() {
    return scenario::parse_scenario_file(cluster_sweep_text(), "cluster_sweep.toml");
}

std::int64_t count_rows(const db::ResultsDb& db, const std::string& sql) {
    sqlite3_stmt* statement = nullptr;
    REQUIRE(sqlite3_prepare_v2(db.handle(), sql.c_str(), -1, &statement, nullptr) == SQLITE_OK);
    REQUIRE(sqlite3_step(statement) == SQLITE_ROW);
    const std::int64_t count = sqlite3_column_int64(statement, 0);
    sqlite3_finalize(statement);
    return count;
}

std::vector<double> values_of(const db::ResultsDb& db, db::Quantity quantity, db::Per per) {
    db::Grouping grouping;
    grouping.per = per;
    const std::vector<db::Group> groups = db::read_groups(db, quantity, grouping);
    REQUIRE(groups.size() == 1);
    return groups.front().values;
}

double largest(const std::vector<engine::WallHit>& hits, double engine::WallHit::*member) {
    double value = -1.0;
    for (const engine::WallHit& hit : hits) value = std::max(value, hit.*member);
    return value;
}

}  // namespace

TEST_CASE(
    "a cluster sweep stores every rock of every sample and queries them per rock and "
    "per sample",
    "[db][cluster][sweep]") {
    const scenario::ScenarioFile file = cluster_file();
    REQUIRE(file.scenario.cluster);
    const risk::SweepSpec& spec = file.sweep;
    REQUIRE(spec.samples == 2);

    std::vector<risk::SampleResult> results;
    for (std::int64_t i = 0; i < spec.samples; ++i) {
        results.push_back(risk::run_sample(spec, file.scenario, i));
    }
    for (const risk::SampleResult& result : results) {
        REQUIRE(result.rocks.size() == rocks_per_sample);
        double mass = 0.0;
        for (const risk::RockResult& rock : result.rocks) {
            CHECK(rock.inputs.cluster);
            CHECK(rock.inputs.kind == shapes::RockKind::massive);
            CHECK(rock.inputs.size == rock.outcome.size);
            CHECK(rock.inputs.mass == Approx(2620.0 * M_PI / 6.0 * std::pow(rock.inputs.size, 3)));
            mass += rock.inputs.mass;
        }
        CHECK(result.inputs.mass == Approx(mass));
        CHECK(std::isnan(result.inputs.size));
    }
    // The samples' seeds draw different clusters.
    CHECK(results[0].rocks[0].inputs.size != results[1].rocks[0].inputs.size);

    ScratchDir dir;
    {
        db::ResultsDb db = db::test::make_database(dir / "cluster.db", results, 1);
        CHECK(db.stored_samples() == std::vector<std::int64_t>{0, 1});
    }
    const db::ResultsDb db = db::ResultsDb::open(dir / "cluster.db", false);

    // One row per rock in outcomes and rocks, one per rock and station, one per rock's hit.
    std::int64_t hits = 0;
    for (const risk::SampleResult& result : results) {
        for (const risk::RockResult& rock : result.rocks) {
            hits += static_cast<std::int64_t>(rock.outcome.wall_hits.size());
        }
    }
    CHECK(count_rows(db, "SELECT COUNT(*) FROM outcomes WHERE sample = 1") == rocks_per_sample);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM rocks WHERE sample = 0") == rocks_per_sample);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM stations") == 2 * rocks_per_sample * 2);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM wall_impacts") == hits);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM sample_results") == 2 * rocks_per_sample);
    CHECK(count_rows(db, "SELECT MAX(rocks) FROM samples") == rocks_per_sample);

    // Every rock comes back as stored.
    for (const risk::SampleResult& result : results) {
        const std::optional<db::SampleRecord> stored = db.sample(result.inputs.index);
        REQUIRE(stored);
        REQUIRE(stored->rocks.size() == result.rocks.size());
        for (std::size_t r = 0; r < result.rocks.size(); ++r) {
            db::test::check_same_rock(result.rocks[r], stored->rocks[r]);
        }
    }

    // Queries: per rock, one value per rock; per sample, the sample's largest reach and its
    // total impulse.
    std::vector<double> reach_rock;
    std::vector<double> reach_sample;
    std::vector<double> force_rock;
    std::vector<double> impulse_sample;
    std::int64_t rocks_hitting = 0;
    std::int64_t samples_hitting = 0;
    for (const risk::SampleResult& result : results) {
        double furthest = -1e9;
        double impulse = 0.0;
        bool hit = false;
        for (const risk::RockResult& rock : result.rocks) {
            reach_rock.push_back(rock.outcome.reach);
            furthest = std::max(furthest, rock.outcome.reach);
            for (const engine::WallHit& h : rock.outcome.wall_hits) impulse += h.normal_impulse;
            if (!rock.outcome.wall_hits.empty()) {
                ++rocks_hitting;
                hit = true;
                force_rock.push_back(
                    largest(rock.outcome.wall_hits, &engine::WallHit::peak_normal_force));
            }
        }
        reach_sample.push_back(furthest);
        if (hit) impulse_sample.push_back(impulse);
        samples_hitting += hit ? 1 : 0;
    }
    // The front hits the wall, so the wall queries have values to compare.
    REQUIRE_FALSE(force_rock.empty());
    REQUIRE(rocks_hitting < 2 * rocks_per_sample);
    std::sort(reach_rock.begin(), reach_rock.end());
    const std::vector<double> reach_by_sample = reach_sample;  // in sample order
    std::sort(reach_sample.begin(), reach_sample.end());
    std::sort(force_rock.begin(), force_rock.end());
    std::sort(impulse_sample.begin(), impulse_sample.end());
    CHECK(values_of(db, db::Quantity::reach, db::Per::rock) == reach_rock);
    CHECK(values_of(db, db::Quantity::reach, db::Per::sample) == reach_sample);
    CHECK(values_of(db, db::Quantity::peak_force, db::Per::rock) == force_rock);
    const std::vector<double> impulses = values_of(db, db::Quantity::impulse, db::Per::sample);
    REQUIRE(impulses.size() == impulse_sample.size());
    for (std::size_t i = 0; i < impulses.size(); ++i) {
        CHECK(impulses[i] == Approx(impulse_sample[i]).epsilon(1e-12));
    }
    // The worst sample by total impulse is the one with the largest sum over its rocks' hits;
    // the worst rock by peak force has the largest force of any rock.
    const std::vector<db::WorstSample> worst_sample =
        db::worst_samples(db, db::Quantity::impulse, 1, db::Per::sample);
    REQUIRE(worst_sample.size() == 1);
    CHECK(worst_sample[0].rock == -1);
    CHECK(worst_sample[0].impulse == Approx(impulse_sample.back()).epsilon(1e-12));
    CHECK(worst_sample[0].mass == Approx(results[worst_sample[0].sample].inputs.mass));
    const std::vector<db::WorstSample> worst_rock =
        db::worst_samples(db, db::Quantity::peak_force, 1);
    REQUIRE(worst_rock.size() == 1);
    CHECK(worst_rock[0].peak_force == force_rock.back());
    CHECK(results[worst_rock[0].sample]
              .rocks[static_cast<std::size_t>(worst_rock[0].rock)]
              .inputs.mass == worst_rock[0].mass);
    // A cluster release has no size of its own: grouping samples by size says so.
    db::Grouping by_size;
    by_size.by = db::GroupBy::size;
    by_size.per = db::Per::sample;
    CHECK_THROWS_WITH(db::read_groups(db, db::Quantity::reach, by_size),
                      Catch::Contains("--per rock"));
    by_size.per = db::Per::rock;
    CHECK_FALSE(db::read_groups(db, db::Quantity::reach, by_size).empty());
    const db::Summary summary = db::summarize(db);
    CHECK(summary.samples == 2);
    CHECK(summary.rocks == 2 * rocks_per_sample);
    CHECK(summary.wall.count == rocks_hitting);
    CHECK(summary.wall_samples.count == samples_hitting);
    // Exceedance per sample: a sample exceeds when its furthest rock does.
    db::Grouping per_sample;
    per_sample.per = db::Per::sample;
    const double threshold = reach_rock[reach_rock.size() / 2];
    const db::ExceedanceTable exceed =
        db::exceedance(db, db::Quantity::reach, threshold, per_sample, db::IntervalMethod::wilson);
    REQUIRE(exceed.groups.size() == 1);
    CHECK(exceed.groups[0].trials == 2);
    CHECK(exceed.groups[0].exceeding == std::count_if(reach_sample.begin(), reach_sample.end(),
                                                      [&](double r) { return r >= threshold; }));

    // The stop rule counts a sample as a success when any of its rocks is one, and so does
    // what --resume reads back.
    risk::UntilRule rule;
    rule.statistic = risk::UntilRule::Statistic::exceed;
    rule.distance = threshold;
    const std::vector<db::StoredOutcome> stored = db::stored_outcomes(db);
    REQUIRE(stored.size() == 2);
    for (std::size_t i = 0; i < results.size(); ++i) {
        CHECK(rule.success(results[i].rocks) == (reach_by_sample[i] >= threshold));
        CHECK(stored[i].sample == static_cast<std::int64_t>(i));
        CHECK(stored[i].reach == reach_by_sample[i]);
    }

    // Replay: sample 1 from what the database stores gives every rock's outcome again.
    const std::optional<db::SampleRecord> record = db.sample(1);
    REQUIRE(record);
    const engine::Outcome replay = engine::simulate(
        risk::sample_scenario(spec, file.scenario, record->inputs), record->inputs.seed);
    REQUIRE(replay.rocks.size() == rocks_per_sample);
    for (std::size_t r = 0; r < replay.rocks.size(); ++r) {
        CHECK(replay.rocks[r].reach == record->rocks[r].outcome.reach);
        CHECK(replay.rocks[r].stop_time == record->rocks[r].outcome.stop_time);
        CHECK(replay.rocks[r].wall_hits.size() == record->rocks[r].outcome.wall_hits.size());
    }
}

TEST_CASE("a cluster scenario's [sweep] table sets only method, samples and seed",
          "[db][cluster][sweep]") {
    const std::string text = cluster_sweep_text() + "\n[sweep.rock]\nsize = 0.2\n";
    try {
        scenario::parse_scenario_file(text, "cluster_sweep.toml");
        FAIL("a swept rock size was accepted on a cluster scenario");
    } catch (const scenario::ScenarioError& error) {
        CHECK_THAT(error.what(), Catch::Contains("sweep.rock") &&
                                     Catch::Contains("cannot be swept over a cluster"));
    }
}
