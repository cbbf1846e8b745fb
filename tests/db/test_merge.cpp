// db::merge_runs (`rockfall merge`): every sample row of the shards in one new file, built
// under a temporary name and published whole, or nothing at all.

#include "db_test_support.hpp"

#include "db/merge.hpp"
#include "db/results_db.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace rockfall;
using db::test::ScratchDir;
namespace fs = std::filesystem;

namespace {

// Synthetic samples `first`, `first + step`, ... below `end`, with trajectories and wall hits.
std::vector<db::SampleRecord> records(std::int64_t first, std::int64_t step, std::int64_t end) {
    db::testing::SyntheticOptions options;
    options.trajectory_points = 3;
    std::vector<db::SampleRecord> out;
    for (std::int64_t i = first; i < end; i += step)
        out.push_back(db::testing::synthetic_record(options, i));
    return out;
}

// A shard as `rockfall sweep --shard` leaves it: finished, one file (no -wal).
void make_shard(const fs::path& path, const std::vector<db::SampleRecord>& samples) {
    db::test::make_database(path, samples).finish("complete", "2026-01-01T00:00:00Z");
}

db::RunRecord run_of(const fs::path& path) { return db::ResultsDb::open(path, false).run(); }

}  // namespace

TEST_CASE("merged shards hold every sample row of each, unchanged", "[db][merge]") {
    ScratchDir dir;
    make_shard(dir / "a.db", records(0, 2, 60));
    make_shard(dir / "b.db", records(1, 2, 60));
    db::RunRecord run = run_of(dir / "a.db");
    run.status = "complete";
    db::merge_runs(dir / "merged.db", run, {dir / "a.db", dir / "b.db"});

    const db::ResultsDb merged = db::ResultsDb::open(dir / "merged.db", false);
    CHECK(merged.run().status == "complete");
    CHECK(merged.run().zones == run.zones);
    std::vector<std::int64_t> expected(60);
    for (std::int64_t i = 0; i < 60; ++i) expected[static_cast<std::size_t>(i)] = i;
    CHECK(merged.stored_samples() == expected);
    const db::ResultsDb a = db::ResultsDb::open(dir / "a.db", false);
    const db::ResultsDb b = db::ResultsDb::open(dir / "b.db", false);
    for (std::int64_t i = 0; i < 60; ++i) {
        const auto from = (i % 2 == 0 ? a : b).sample(i);
        const auto copied = merged.sample(i);
        REQUIRE(from);
        REQUIRE(copied);
        db::test::check_same(*from, *copied);
        CHECK(copied->rocks[0].trajectory.size() == 3);
    }
    // Nothing but the merged file appears beside the shards.
    CHECK(dir.files() == std::vector<std::string>{"a.db", "b.db", "merged.db"});
}

TEST_CASE("a merge refused or failing leaves no output and no temporary file", "[db][merge]") {
    ScratchDir dir;
    make_shard(dir / "a.db", records(0, 2, 20));
    make_shard(dir / "b.db", records(1, 2, 20));
    const db::RunRecord run = run_of(dir / "a.db");

    SECTION("a shard of schema version 1") {
        std::ifstream in(fs::path(ROCKFALL_TEST_DATA_DIR) / "schema_v1.sql");
        REQUIRE(in);
        std::stringstream sql;
        sql << in.rdbuf();
        db::test::run_sql(dir / "v1.db", sql.str());
        CHECK_THROWS_WITH(db::merge_runs(dir / "out.db", run, {dir / "a.db", dir / "v1.db"}),
                          Catch::Contains("v1.db has schema version 1; merge copies rows of "
                                          "version 2 only"));
        CHECK_FALSE(fs::exists(dir / "out.db"));
        CHECK(dir.files() == std::vector<std::string>{"a.db", "b.db", "v1.db"});
    }
    SECTION("samples in both shards (the caller's check bypassed)") {
        CHECK_THROWS_AS(db::merge_runs(dir / "out.db", run, {dir / "a.db", dir / "a.db"}),
                        db::DatabaseError);
        CHECK(dir.files() == std::vector<std::string>{"a.db", "b.db"});
    }
    SECTION("an output that exists is never replaced") {
        const std::string bytes = db::test::read_bytes(dir / "b.db");
        CHECK_THROWS_WITH(db::merge_runs(dir / "b.db", run, {dir / "a.db"}),
                          Catch::Contains("exists already"));
        CHECK(db::test::read_bytes(dir / "b.db") == bytes);
    }
}
