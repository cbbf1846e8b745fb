// A results database of schema version 1 (one rock per sample, before per-rock rows) opens and
// answers every query as version 2 with rock 0; it is not written to.

#include "db_test_support.hpp"

#include "db/queries.hpp"
#include "db/results_db.hpp"
#include "db/wall_impacts.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace rockfall::db;
using rockfall::db::test::ScratchDir;
namespace fs = std::filesystem;

namespace {

// tests/db/data/schema_v1.sql: the version-1 schema with three samples. Sample 0 reaches
// 1.5 m and hits the wall twice (300 N s at 1000 N, then 100 N s at 3000 N), sample 1 reaches
// 0.5 m without a hit, sample 2 reaches 2.5 m with one hit (600 N s, 2000 N).
fs::path version1_file(const ScratchDir& dir) {
    std::ifstream in(fs::path(ROCKFALL_TEST_DATA_DIR) / "schema_v1.sql");
    REQUIRE(in);
    std::stringstream sql;
    sql << in.rdbuf();
    const fs::path path = dir / "v1.db";
    rockfall::db::test::run_sql(path, sql.str());
    return path;
}

std::vector<double> values_of(const ResultsDb& db, Quantity quantity, Per per) {
    Grouping grouping;
    grouping.per = per;
    const std::vector<Group> groups = read_groups(db, quantity, grouping);
    REQUIRE(groups.size() == 1);
    return groups.front().values;
}

}  // namespace

TEST_CASE("a version-1 database reads as one rock per sample", "[db][schema]") {
    ScratchDir dir;
    const fs::path path = version1_file(dir);
    const std::string before = rockfall::db::test::read_bytes(path);
    {
        const ResultsDb db = ResultsDb::open(path, false);
        CHECK(db.stored_samples() == std::vector<std::int64_t>{0, 1, 2});

        const Summary summary = summarize(db);
        CHECK(summary.samples == 3);
        CHECK(summary.rocks == 3);
        CHECK(summary.wall.count == 2);
        CHECK(summary.wall_samples.count == 2);
        CHECK(summary.wall_impacts == 3);
        CHECK(summary.max_reach == 2.5);

        CHECK(values_of(db, Quantity::reach, Per::rock) == std::vector<double>{0.5, 1.5, 2.5});
        CHECK(values_of(db, Quantity::peak_force, Per::rock) == std::vector<double>{2000, 3000});
        // Per rock the largest impulse of a rock's hits, per sample the sum over its hits.
        CHECK(values_of(db, Quantity::impulse, Per::rock) == std::vector<double>{300, 600});
        CHECK(values_of(db, Quantity::impulse, Per::sample) == std::vector<double>{400, 600});

        const std::vector<WorstSample> worst = worst_samples(db, Quantity::reach, 1);
        REQUIRE(worst.size() == 1);
        CHECK(worst[0].sample == 2);
        CHECK(worst[0].rock == 0);
        CHECK(worst[0].mass == 87.1);

        const std::optional<SampleRecord> sample = db.sample(0);
        REQUIRE(sample);
        REQUIRE(sample->rocks.size() == 1);
        CHECK(sample->rocks[0].inputs.mass == 36.8);
        CHECK(sample->rocks[0].outcome.reach == 1.5);
        CHECK(sample->rocks[0].outcome.wall_hits.size() == 2);

        const std::vector<WallImpact> impacts = read_wall_impacts(db);
        REQUIRE(impacts.size() == 3);
        CHECK(impacts[1].rock == 0);
        CHECK(impacts[1].hit == 2);
        CHECK(impacts[1].mass == 36.8);
        CHECK(impacts[2].kind == "sphere");
    }
    // Writing (a --resume) is refused, and nothing about the file changed.
    try {
        ResultsDb::open(path, true);
        FAIL("a version-1 file was opened for writing");
    } catch (const DatabaseError& error) {
        CHECK(error.kind() == DatabaseError::Kind::bad_file);
        CHECK_THAT(error.what(), Catch::Contains("schema version 1"));
    }
    CHECK(rockfall::db::test::read_bytes(path) == before);
}
