// A soil flow in a results database: written whole and read back field for field, 2D loads in
// the per-metre columns, and each kind of database refused where the other is expected.

#include "db_test_support.hpp"

#include "db/results_db.hpp"
#include "db/soil_run.hpp"

#include <catch2/catch.hpp>
#include <sqlite3.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

using namespace rockfall::db;
using rockfall::db::test::make_database;
using rockfall::db::test::read_bytes;
using rockfall::db::test::same_value;
using rockfall::db::test::ScratchDir;
using rockfall::db::test::write_bytes;
namespace fs = std::filesystem;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A soil run of `dimension` with every field set to a distinct value and short histories; in
// 2D the y components are NaN, as a plane-strain run has none.
SoilRunRecord hand_soil_run(int dimension) {
    SoilRunRecord r;
    r.run.tool_version = "0.1.0";
    r.run.build = "test";
    r.run.scenario_name = "quick soil";
    r.run.scenario_text = "name = \"quick soil\"\n";
    r.run.scenario_hash = "0123456789abcdef";
    r.run.seed = 0;
    r.run.method = "mpm";
    r.run.samples_planned = 1;
    r.run.stop_rule = "duration 5 s";
    r.run.settings_json = R"({"dimension":2})";
    r.run.started_at = "2026-11-22T10:00:00Z";
    r.run.finished_at = "2026-11-22T10:00:01Z";
    r.run.status = "complete";
    r.dimension = dimension;
    r.outcome = "left_domain";
    r.message = "particles reached the grid's edge";
    r.particles = 105;
    r.steps = 2583;
    r.cell_size = 0.2;
    r.mass = 755.6;
    r.simulated_time = 5.0;
    r.runtime = 0.43;
    r.wall_distance_from_toe = 0.5;
    r.sample_interval = 0.01;
    r.filter_window = 0.05;
    r.peak_force = 5705.25;
    r.peak_time = 3.28;
    r.peak_force_filtered = 4934.2;
    r.peak_force_step = 5775.1;
    r.impulse = 8123.4;
    r.runout_x = 11.9;
    r.runout_past_toe = 0.48;
    const double y = dimension == 2 ? nan : 1.0;
    for (int k = 1; k <= 4; ++k) {
        const double t = 0.01 * k;
        r.load.push_back({t, {100.0 * k, y * k, -10.0 * k}, {90.0 * k, y * 0.5 * k, -9.0 * k}});
        r.motion.push_back({t, {1.0 + t, y * t, 5.0 - t}, 2.0 + t, 300.0 / k});
        r.step_load.push_back({0.004 * k, 0.004, {50.0 * k, y * 2.0 * k, -5.0 * k}});
    }
    r.deposit = {{10.1, 0.3}, {10.3, 0.25}, {10.5, 0.0}};
    return r;
}

bool same_vector(const SceneVector& a, const SceneVector& b) {
    return same_value(a[0], b[0]) && same_value(a[1], b[1]) && same_value(a[2], b[2]);
}

void check_same(const SoilRunRecord& a, const SoilRunRecord& b) {
    CHECK(b.run.scenario_text == a.run.scenario_text);
    CHECK(b.run.method == a.run.method);
    CHECK(b.run.status == a.run.status);
    CHECK(b.run.finished_at == a.run.finished_at);
    CHECK(b.dimension == a.dimension);
    CHECK(b.outcome == a.outcome);
    CHECK(b.message == a.message);
    CHECK(b.particles == a.particles);
    CHECK(b.steps == a.steps);
    for (const auto& [x, y] : {std::pair{a.cell_size, b.cell_size},
                               {a.mass, b.mass},
                               {a.simulated_time, b.simulated_time},
                               {a.runtime, b.runtime},
                               {a.wall_distance_from_toe, b.wall_distance_from_toe},
                               {a.sample_interval, b.sample_interval},
                               {a.filter_window, b.filter_window},
                               {a.peak_force, b.peak_force},
                               {a.peak_time, b.peak_time},
                               {a.peak_force_filtered, b.peak_force_filtered},
                               {a.peak_force_step, b.peak_force_step},
                               {a.impulse, b.impulse},
                               {a.runout_x, b.runout_x},
                               {a.runout_past_toe, b.runout_past_toe}}) {
        CHECK(same_value(x, y));
    }
    REQUIRE(b.load.size() == a.load.size());
    for (std::size_t k = 0; k < a.load.size(); ++k) {
        CHECK(b.load[k].time == a.load[k].time);
        CHECK(same_vector(b.load[k].force, a.load[k].force));
        CHECK(same_vector(b.load[k].force_filtered, a.load[k].force_filtered));
    }
    REQUIRE(b.step_load.size() == a.step_load.size());
    for (std::size_t k = 0; k < a.step_load.size(); ++k) {
        CHECK(b.step_load[k].time == a.step_load[k].time);
        CHECK(b.step_load[k].dt == a.step_load[k].dt);
        CHECK(same_vector(b.step_load[k].force, a.step_load[k].force));
    }
    REQUIRE(b.motion.size() == a.motion.size());
    for (std::size_t k = 0; k < a.motion.size(); ++k) {
        CHECK(b.motion[k].time == a.motion[k].time);
        CHECK(same_vector(b.motion[k].centre_of_mass, a.motion[k].centre_of_mass));
        CHECK(b.motion[k].front_x == a.motion[k].front_x);
        CHECK(b.motion[k].kinetic_energy == a.motion[k].kinetic_energy);
    }
    REQUIRE(b.deposit.size() == a.deposit.size());
    for (std::size_t k = 0; k < a.deposit.size(); ++k) {
        CHECK(b.deposit[k].x == a.deposit[k].x);
        CHECK(b.deposit[k].height == a.deposit[k].height);
    }
}

// One value of a query on the file (NaN for NULL), through SQLite directly.
double sql_value(const fs::path& path, const std::string& query) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* statement = nullptr;
    REQUIRE(sqlite3_prepare_v2(db, query.c_str(), -1, &statement, nullptr) == SQLITE_OK);
    REQUIRE(sqlite3_step(statement) == SQLITE_ROW);
    const double value = sqlite3_column_type(statement, 0) == SQLITE_NULL
                             ? nan
                             : sqlite3_column_double(statement, 0);
    sqlite3_finalize(statement);
    sqlite3_close(db);
    return value;
}

}  // namespace

TEST_CASE("a 3D soil run reads back field for field", "[db]") {
    ScratchDir dir;
    const SoilRunRecord written = hand_soil_run(3);
    write_soil_run(dir / "soil.db", written);
    CHECK(dir.files() == std::vector<std::string>{"soil.db"});
    const ResultsDb db = ResultsDb::open_any(dir / "soil.db", false);
    CHECK(db.kind() == RunKind::soil_flow);
    check_same(written, read_soil_run(db));
    CHECK(sql_value(dir / "soil.db", "SELECT force_x_N FROM soil_load WHERE time_s = 0.02") ==
          200.0);
    CHECK(std::isnan(
        sql_value(dir / "soil.db", "SELECT force_x_N_per_m FROM soil_load WHERE time_s = 0.02")));
    CHECK(sql_value(dir / "soil.db", "SELECT count(*) FROM soil_load_steps") == 4.0);
}

TEST_CASE("a 2D soil run keeps its loads per metre of width", "[db]") {
    ScratchDir dir;
    const SoilRunRecord written = hand_soil_run(2);
    write_soil_run(dir / "soil.db", written);
    check_same(written, read_soil_run(ResultsDb::open_any(dir / "soil.db", false)));
    const fs::path file = dir / "soil.db";
    CHECK(std::isnan(sql_value(file, "SELECT force_x_N FROM soil_load WHERE time_s = 0.02")));
    CHECK(sql_value(file, "SELECT force_x_N_per_m FROM soil_load WHERE time_s = 0.02") == 200.0);
    CHECK(sql_value(file, "SELECT force_z_filtered_N_per_m FROM soil_load WHERE time_s = 0.02") ==
          -18.0);
    CHECK(std::isnan(sql_value(file, "SELECT peak_force_x_N FROM soil_run")));
    CHECK(sql_value(file, "SELECT peak_force_x_N_per_m FROM soil_run") == 5705.25);
    CHECK(sql_value(file, "SELECT mass_kg_per_m FROM soil_run") == 755.6);
    CHECK(std::isnan(sql_value(file, "SELECT max(centre_y_m) FROM soil_motion")));
}

TEST_CASE("rock-sweep opens refuse a soil database and leave it unchanged", "[db]") {
    ScratchDir dir;
    write_soil_run(dir / "soil.db", hand_soil_run(3));
    const std::string before = read_bytes(dir / "soil.db");
    for (const bool writable : {false, true}) {
        try {
            ResultsDb::open(dir / "soil.db", writable);
            FAIL("opened a soil database as a rock sweep");
        } catch (const DatabaseError& e) {
            CHECK_THAT(e.what(), Catch::Contains("soil.db holds a soil flow") &&
                                     Catch::Contains("not a rock sweep"));
            CHECK(e.kind() == DatabaseError::Kind::bad_file);
        }
    }
    CHECK(read_bytes(dir / "soil.db") == before);
    CHECK(dir.files() == std::vector<std::string>{"soil.db"});
}

TEST_CASE("soil reads refuse a rock-sweep database", "[db]") {
    ScratchDir dir;
    { make_database(dir / "sweep.db", {}); }
    const ResultsDb db = ResultsDb::open_any(dir / "sweep.db", false);
    CHECK(db.kind() == RunKind::rock_sweep);
    try {
        read_soil_run(db);
        FAIL("read a soil run from a rock sweep");
    } catch (const DatabaseError& e) {
        CHECK_THAT(e.what(), Catch::Contains("sweep.db holds a rock sweep") &&
                                 Catch::Contains("not a soil flow"));
        CHECK(e.kind() == DatabaseError::Kind::bad_file);
    }
}

TEST_CASE("writing a soil run never replaces a file and leaves nothing when it fails", "[db]") {
    ScratchDir dir;
    SECTION("an existing file") {
        write_bytes(dir / "soil.db", "last year's flow");
        CHECK_THROWS_WITH(write_soil_run(dir / "soil.db", hand_soil_run(3)),
                          Catch::Contains("soil.db exists already"));
        CHECK(read_bytes(dir / "soil.db") == "last year's flow");
        CHECK_THROWS_WITH(check_new_database(dir / "soil.db"),
                          Catch::Contains("soil.db exists already"));
        CHECK(dir.files() == std::vector<std::string>{"soil.db"});
    }
    SECTION("a record the schema rejects, after most rows are written") {
        SoilRunRecord bad = hand_soil_run(3);
        bad.deposit.push_back(bad.deposit.front());  // a repeated bin: PRIMARY KEY violated
        CHECK_THROWS_AS(write_soil_run(dir / "soil.db", bad), DatabaseError);
        CHECK(dir.files().empty());
    }
    SECTION("a read-only directory") {
        fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
        CHECK_THROWS_WITH(check_new_database(dir / "soil.db"), Catch::Contains("read-only"));
        CHECK_THROWS_WITH(write_soil_run(dir / "soil.db", hand_soil_run(2)),
                          Catch::Contains("read-only"));
        fs::permissions(dir.path(), fs::perms::owner_all);
        CHECK(dir.files().empty());
    }
}
