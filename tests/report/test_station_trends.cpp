// Seed 000's trends about motion ("ANALYSIS OF ROCK BEHAVIOR", Figures 5 and 6) on real small
// sweeps of the seed slope, bars on (samples/seed_sweep.toml) and off
// (samples/seed_sweep_bars_off.toml), through the database as `rockfall query DB stations`
// reads it. About 5 s per sweep of 300 samples on one core (150 left too few rocks past the 4 m
// station without bars once the blocks and slabs slid on their whole face, 54).

#include "report/station_figures.hpp"
#include "scenario/scenario_file.hpp"
#include "synthetic.hpp"

#include "db/results_db.hpp"
#include "db/station_values.hpp"
#include "risk/sweep_runner.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>

namespace rockfall::report {
namespace {

constexpr std::int64_t samples = 300;

// The sweep's first `samples` samples, stored and read back as the query reads them.
StationSet swept(const std::string& file) {
    const scenario::ScenarioFile scenario =
        scenario::load_scenario(std::filesystem::path(ROCKFALL_SAMPLES_DIR) / file);
    std::vector<db::SampleRecord> records;
    for (std::int64_t i = 0; i < samples; ++i) {
        records.push_back(risk::run_sample(scenario.sweep, scenario.scenario, i));
    }
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("rockfall_trends_" + std::to_string(std::random_device{}()) + ".db");
    StationSet set{file, path.string(), scenario.scenario.name, {}};
    {
        db::ResultsDb database =
            db::ResultsDb::create(path, db::testing::synthetic_run({}, samples));
        database.write_batch(records);
        set.rocks = db::read_rock_stations(database);
    }
    for (const char* suffix : {"", "-wal", "-shm"}) {
        std::filesystem::remove(path.string() + suffix);
    }
    return set;
}

}  // namespace

namespace {

MotionTrend velocity_trend_of(const char* file) {
    const MotionTrend trend = velocity_change_trend(swept(file));
    UNSCOPED_INFO(file << ": " << trend.all.x.size() << " rocks; lowest Cr third ("
                       << trend.lower.cr_min << " to " << trend.lower.cr_max << ") mean V' "
                       << trend.lower.mean_velocity_change << ", highest (" << trend.upper.cr_min
                       << " to " << trend.upper.cr_max << ") mean V' "
                       << trend.upper.mean_velocity_change);
    return trend;
}

}  // namespace

TEST_CASE("seed 000 Fig. 5: small Cr goes with a more negative V' (bars on)",
          "[report][stations][validation]") {
    const MotionTrend trend = velocity_trend_of("seed_sweep.toml");
    REQUIRE(trend.lower.rocks >= 20);
    CHECK(trend.lower.mean_velocity_change < trend.upper.mean_velocity_change);
    // Sliding rocks slow down on the run-out: most of the lowest third has V' < 0.
    CHECK(trend.lower.negative * 2 > trend.lower.rocks);
}

// A documented miss (docs/validation.md, "Seed 000: motion on the slope"): without bars the
// rocks past 4 m are nearly all rolling spheres, and the thirds by Cr differ by less than their
// scatter: the lowest third was below the highest by a hair (-0.1360 against -0.1346), above it
// from the day resting contacts stopped jittering (-0.131 against -0.143 on 2026-12-07) and is
// below it again since the rolling rows per contact patch (-0.136 against -0.103).
// [!mayfail] keeps the check running and reported without failing the suite.
TEST_CASE("seed 000 Fig. 5 without bars: small Cr goes with a more negative V'",
          "[report][stations][validation][!mayfail]") {
    const MotionTrend trend = velocity_trend_of("seed_sweep_bars_off.toml");
    REQUIRE(trend.lower.rocks >= 20);
    CHECK(trend.lower.negative * 2 > trend.lower.rocks);
    CHECK(trend.lower.mean_velocity_change < trend.upper.mean_velocity_change);
}

// A documented miss (docs/validation.md, "Seed 000: motion on the slope"): the simulated slope of w
// on v at the toe is less than half as large with bars as without (3.70 against 8.03 rad/m over
// all shapes, 2026-12-07), where the paper finds it larger with bars. Without bars the spheres roll
// without slipping and reach the toe at nearly one speed with w = v / r, so the spheres' spread of
// sizes makes the steep part of the line; the blocks and slabs slide slowly. [!mayfail] keeps the
// check running and reported without failing the suite; the rolling-resistance fault of issue 16 is
// fixed and did not change it.
TEST_CASE("seed 000 Fig. 6: the slope of angular speed on speed is larger with bars",
          "[report][stations][validation][!mayfail]") {
    const MotionTrend on = spin_speed_trend(swept("seed_sweep.toml"));
    const MotionTrend off = spin_speed_trend(swept("seed_sweep_bars_off.toml"));
    REQUIRE(on.all.fit);
    REQUIRE(off.all.fit);
    WARN("slope of w on v at the toe: bars on "
         << on.all.fit->slope << " rad/m (" << on.all.x.size() << " rocks), bars off "
         << off.all.fit->slope << " rad/m (" << off.all.x.size() << " rocks)");
    CHECK(on.all.fit->slope > off.all.fit->slope);
}

}  // namespace rockfall::report
