// Writing and reading the results database: round trips, NaN, atomic batches, deletion, the
// end of a run, and a kill in the middle of writing.

#include "db_test_support.hpp"
#include "synthetic.hpp"

#include "db/results_db.hpp"

#include <catch2/catch.hpp>
#include <sqlite3.h>

#include <chrono>
#include <cmath>
#include <signal.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace rockfall::db;
using rockfall::db::test::ScratchDir;

namespace {

std::vector<SampleRecord> synthetic_batch(std::int64_t first, std::int64_t count,
                                          std::size_t trajectory_points = 0) {
    testing::SyntheticOptions options;
    options.trajectory_points = trajectory_points;
    std::vector<SampleRecord> batch;
    for (std::int64_t i = first; i < first + count; ++i) {
        batch.push_back(testing::synthetic_record(options, i));
    }
    return batch;
}

std::int64_t count_rows(const ResultsDb& db, const std::string& sql) {
    sqlite3_stmt* statement = nullptr;
    REQUIRE(sqlite3_prepare_v2(db.handle(), sql.c_str(), -1, &statement, nullptr) == SQLITE_OK);
    REQUIRE(sqlite3_step(statement) == SQLITE_ROW);
    const std::int64_t n = sqlite3_column_int64(statement, 0);
    sqlite3_finalize(statement);
    return n;
}

}  // namespace

TEST_CASE("a batch round-trips through the database", "[db]") {
    ScratchDir dir;
    const auto batch = synthetic_batch(0, 40, 5);
    const testing::SyntheticOptions options;
    RunRecord run = testing::synthetic_run(options, 40);
    run.seed = 0xfedcba9876543210ULL;  // above 2^63: stored as its int64 bit pattern
    {
        ResultsDb db = ResultsDb::create(dir / "run.db", run);
        db.write_batch(batch);
    }
    const ResultsDb db = ResultsDb::open(dir / "run.db", false);
    const RunRecord read = db.run();
    CHECK(read.seed == run.seed);
    CHECK(read.scenario_name == run.scenario_name);
    CHECK(read.scenario_text == run.scenario_text);
    CHECK(read.method == run.method);
    CHECK(read.samples_planned == 40);
    CHECK(read.status == "running");
    CHECK(read.finished_at.empty());
    CHECK(read.zones == run.zones);
    std::vector<std::int64_t> expected_indices(40);
    for (std::size_t i = 0; i < 40; ++i) expected_indices[i] = static_cast<std::int64_t>(i);
    CHECK(db.stored_samples() == expected_indices);
    // The synthetic set has rocks that hit the wall twice and stations not reached.
    CHECK(count_rows(db, "SELECT COUNT(*) FROM wall_impacts WHERE hit = 2") > 0);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM stations WHERE reached = 0") > 0);
    for (const SampleRecord& expected : batch) {
        INFO("sample " << expected.inputs.index);
        const auto actual = db.sample(expected.inputs.index);
        REQUIRE(actual.has_value());
        rockfall::db::test::check_same(expected, *actual);
    }
    CHECK_FALSE(db.sample(40).has_value());
}

TEST_CASE("NaN is stored as NULL and read back as NaN", "[db]") {
    ScratchDir dir;
    SampleRecord record = rockfall::db::test::hand_record(0, std::nan(""), {5.0e4});
    record.rocks.at(0).outcome.wall_hits[0].peak_normal_force = std::nan("");
    ResultsDb db = rockfall::db::test::make_database(dir / "nan.db", {record});
    CHECK(count_rows(db, "SELECT COUNT(*) FROM outcomes WHERE reach_m IS NULL") == 1);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM outcomes WHERE velocity_change IS NULL") == 1);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM wall_impacts WHERE peak_force_N IS NULL") == 1);
    const auto read = db.sample(0);
    REQUIRE(read.has_value());
    CHECK(std::isnan(read->rocks.at(0).outcome.reach));
    CHECK(std::isnan(read->rocks.at(0).outcome.velocity_change));
    CHECK(std::isnan(read->rocks.at(0).outcome.wall_hits.at(0).peak_normal_force));
    CHECK(read->rocks.at(0).outcome.wall_hits.at(0).energy_before == 500.0);
}

TEST_CASE("a failing batch leaves nothing of itself", "[db]") {
    ScratchDir dir;
    ResultsDb db = rockfall::db::test::make_database(dir / "r.db", synthetic_batch(0, 10));
    const std::int64_t stations_before = count_rows(db, "SELECT COUNT(*) FROM stations");

    SECTION("a record violating a constraint in the middle of the batch") {
        // Samples 10 and 11 are fine; the third repeats sample 5, already stored.
        auto batch = synthetic_batch(10, 2);
        batch.push_back(testing::synthetic_record({}, 5));
        batch.push_back(testing::synthetic_record({}, 12));
        CHECK_THROWS_AS(db.write_batch(batch), DatabaseError);
    }
    SECTION("a zone that the run does not have") {
        auto batch = synthetic_batch(10, 3);
        batch[1].inputs.zone = 7;
        CHECK_THROWS_AS(db.write_batch(batch), DatabaseError);
    }
    SECTION("a full disk") {
        // SQLite reports SQLITE_FULL when the file may not grow: what a full disk looks like.
        const std::int64_t pages = count_rows(db, "PRAGMA page_count");
        REQUIRE(sqlite3_exec(db.handle(),
                             ("PRAGMA max_page_count = " + std::to_string(pages + 2)).c_str(),
                             nullptr, nullptr, nullptr) == SQLITE_OK);
        try {
            db.write_batch(synthetic_batch(10, 2000, 20));
            FAIL("the batch fitted in two pages");
        } catch (const DatabaseError& e) {
            CHECK_THAT(e.what(), Catch::Contains("disk full") && Catch::Contains("r.db"));
            CHECK(e.kind() == DatabaseError::Kind::failure);
        }
    }
    std::vector<std::int64_t> first_ten(10);
    for (std::size_t i = 0; i < 10; ++i) first_ten[i] = static_cast<std::int64_t>(i);
    CHECK(db.stored_samples() == first_ten);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM samples") == 10);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM stations") == stations_before);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM wall_impacts WHERE sample >= 10") == 0);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM trajectories") == 0);
    // The connection stays usable: the next batch (the statements reused) goes in whole.
    db.write_batch(synthetic_batch(10, 5));
    CHECK(db.stored_samples().size() == 15);
}

TEST_CASE("delete_samples_from removes those samples and all their rows", "[db]") {
    ScratchDir dir;
    ResultsDb db = rockfall::db::test::make_database(dir / "d.db", synthetic_batch(0, 50, 3));
    db.delete_samples_from(20);
    CHECK(db.stored_samples().size() == 20);
    CHECK(db.stored_samples().back() == 19);
    for (const char* table :
         {"samples", "rocks", "outcomes", "stations", "wall_impacts", "trajectories"}) {
        INFO(table);
        CHECK(count_rows(
                  db, std::string("SELECT COUNT(*) FROM ") + table + " WHERE sample >= 20") == 0);
    }
    CHECK(count_rows(db, "SELECT COUNT(*) FROM trajectories") == 20 * 3);
    // The deleted samples can be written again, as --resume does.
    db.write_batch(synthetic_batch(20, 30, 3));
    CHECK(db.stored_samples().size() == 50);
}

TEST_CASE("finish records the end and leaves one self-contained file", "[db]") {
    ScratchDir dir;
    {
        ResultsDb db = rockfall::db::test::make_database(dir / "f.db", synthetic_batch(0, 5));
        CHECK(std::filesystem::exists(dir / "f.db-wal"));
        db.finish("complete", "2024-01-01T01:00:00Z");
        CHECK_FALSE(std::filesystem::exists(dir / "f.db-wal"));
        CHECK_THROWS_AS(db.finish("done", "2024-01-01T01:00:00Z"), DatabaseError);
    }
    ResultsDb db = ResultsDb::open(dir / "f.db", true);
    CHECK(db.run().status == "complete");
    CHECK(db.run().finished_at == "2024-01-01T01:00:00Z");
    // Reopened for writing, the file is back in WAL mode.
    db.write_batch(synthetic_batch(5, 1));
    CHECK(std::filesystem::exists(dir / "f.db-wal"));
}

TEST_CASE("a read-only handle refuses to write", "[db]") {
    ScratchDir dir;
    rockfall::db::test::make_database(dir / "ro.db", {});
    ResultsDb db = ResultsDb::open(dir / "ro.db", false);
    CHECK_FALSE(db.writable());
    CHECK_THROWS_WITH(db.write_batch(synthetic_batch(0, 1)), Catch::Contains("read-only"));
    CHECK_THROWS_AS(db.delete_samples_from(0), DatabaseError);
}

TEST_CASE("a kill in the middle of writing leaves whole batches only", "[db]") {
    ScratchDir dir;
    const auto path = dir / "killed.db";
    rockfall::db::test::make_database(path, {});
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        // The child writes batches of 100 until it is killed; it never returns to Catch.
        try {
            ResultsDb db = ResultsDb::open(path, true);
            for (std::int64_t first = 0;; first += 100) {
                db.write_batch(synthetic_batch(first, 100, 4));
            }
        } catch (...) {
            _exit(1);
        }
    }
    // Wait until some batches are in, then kill without warning.
    for (int i = 0; i < 400; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        if (std::filesystem::exists(path.string() + "-wal") &&
            std::filesystem::file_size(path.string() + "-wal") > 200000) {
            break;
        }
    }
    REQUIRE(kill(child, SIGKILL) == 0);
    int status = 0;
    waitpid(child, &status, 0);
    REQUIRE(WIFSIGNALED(status));

    ResultsDb db = ResultsDb::open(path, true);  // runs quick_check
    const auto stored = db.stored_samples();
    INFO(stored.size() << " samples survived the kill");
    CHECK(stored.size() >= 100);
    CHECK(stored.size() % 100 == 0);
    CHECK(stored.back() == static_cast<std::int64_t>(stored.size()) - 1);
    CHECK(count_rows(db, "SELECT COUNT(*) FROM samples") ==
          static_cast<std::int64_t>(stored.size()));
    CHECK(count_rows(db, "SELECT COUNT(*) FROM stations") ==
          2 * static_cast<std::int64_t>(stored.size()));
    CHECK(count_rows(db, "SELECT COUNT(*) FROM trajectories") ==
          4 * static_cast<std::int64_t>(stored.size()));
}
