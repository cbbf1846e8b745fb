// A calibration experiment in a results database: written whole and read back field for
// field, refused where a rock sweep or a soil flow is expected and the reverse, and never
// replacing a file.

#include "db_test_support.hpp"

#include "db/calibration_run.hpp"
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
namespace fs = std::filesystem;
namespace risk = rockfall::risk;

namespace {

RunRecord hand_run(const char* command, const char* method) {
    RunRecord r;
    r.tool_version = "0.1.0";
    r.build = "test";
    r.scenario_name = command;
    r.scenario_hash = "00000000000000ff";
    r.seed = 0xfedcba9876543210ULL;  // above INT64_MAX: stored as its bit pattern
    r.method = method;
    r.samples_planned = 2;
    r.stop_rule = "count 2";
    r.settings_json = R"({"count":"2"})";
    r.started_at = "2026-12-02T20:00:00Z";
    r.finished_at = "2026-12-02T20:00:05Z";
    r.status = "complete";
    return r;
}

risk::SampleSummary summary(double base) {
    return {2, base, 0.01 * base, 0.9 * base, base, 1.1 * base, {0.95 * base, 1.05 * base}};
}

CalibrationShape hand_shape(const char* label, double scale) {
    CalibrationShape s;
    s.label = label;
    s.kind = "custom";
    s.density = 2620.0;
    s.sphericity = 0.8 * scale;
    s.rock = {0.4 * scale, 0.3, 0.02};
    s.surface = {0.5, 0.25 * scale, 0.0};
    return s;
}

CalibrationRecord hand_drop_record() {
    CalibrationRecord r;
    r.kind = RunKind::drop_test;
    r.run = hand_run("calibrate drop", "drop_test");
    for (int k = 0; k < 2; ++k) {
        CalibrationShape s = hand_shape(k == 0 ? "catalogue entry 'cube'" : "sphere 0.2 m", 1 + k);
        s.size = 0.2 + k;
        for (int d = 0; d < 2; ++d) {
            risk::DropMeasurement& m = s.drops.emplace_back();
            m.index = d;
            m.seed = 0xffffffff00000000ULL + static_cast<unsigned>(d);
            m.rebounded = d == 0;
            double value = 1.0 + d + 10 * k;
            for (double* field :
                 {&m.mass, &m.drop_height, &m.rebound_height, &m.approach_speed, &m.rebound_speed,
                  &m.normal_impulse, &m.first_impulse, &m.compression_impulse,
                  &m.restitution_impulse, &m.energy_before, &m.energy_after, &m.cor_height,
                  &m.cor_speed, &m.cor_kinetic, &m.cor_energy}) {
                *field = (value += 0.125);
            }
        }
        if (k == 0) {
            CalibrationIdentified& id = s.identified.emplace();
            id.parameter = "surface_restitution";
            id.measure = "cor_height";
            id.target = 0.3;
            id.value = 0.21;
            id.contact_value = 0.255;
            id.achieved = summary(0.3);
            id.consistent = {0.18, 0.24};
            id.curve = {{0.0, 0.15, false, summary(0.1)},
                        {0.21, 0.255, true, summary(0.3)},
                        {0.5, 0.4, false, summary(0.4)}};
        }
        r.shapes.push_back(s);
    }
    return r;
}

CalibrationRecord hand_heap_record() {
    CalibrationRecord r;
    r.kind = RunKind::heap_test;
    r.run = hand_run("calibrate heap", "heap_test");
    CalibrationShape s = hand_shape("cube", 1.0);
    for (const double friction : {0.4, 0.1, 1.0}) {
        for (int h = 0; h < 2; ++h) {
            risk::HeapMeasurement m;
            m.index = h;
            m.seed = 7 + h;
            m.status = h == 0 ? rockfall::engine::HeapStatus::at_rest
                              : rockfall::engine::HeapStatus::time_limit;
            m.rocks = 300;
            m.rolled_off = h;
            m.fill_height = 0.1;
            m.fill_time = 3.0;
            m.lift_time = 13.0 + friction;
            m.settle_time = 1.5;
            m.heap_height = 0.09;
            m.foot_radius = 0.2;
            m.angle_deg = 20.0 + 10 * friction + h;
            m.angle_sd_deg = 3.0;
            m.valid_planes = 2;
            for (int p = 0; p < 2; ++p) {
                risk::HeapProfile& plane = m.planes.emplace_back();
                plane.azimuth_deg = 180.0 * p;
                plane.valid = p == 0;
                plane.angle_deg = p == 0 ? m.angle_deg : 0.0;
                plane.fitted_points = 5 - p;
                plane.heap_height = 0.09;
                plane.foot_radius = 0.2 + 0.01 * p;
            }
            s.heaps.push_back({friction, m});
        }
    }
    CalibrationIdentified& id = s.identified.emplace();
    id.parameter = "rock_friction";
    id.measure = "angle_deg";
    id.target = 25.2;
    id.value = 0.52;
    id.achieved = summary(25.1);
    id.consistent = {0.45, 0.6};
    id.curve = {{0.1, std::numeric_limits<double>::quiet_NaN(), false, summary(21.0)},
                {1.0, std::numeric_limits<double>::quiet_NaN(), false, summary(30.0)}};
    r.shapes.push_back(s);
    return r;
}

void check_summary(const risk::SampleSummary& a, const risk::SampleSummary& b, bool percentiles) {
    CHECK(a.count == b.count);
    CHECK(a.mean == b.mean);
    CHECK(a.standard_deviation == b.standard_deviation);
    CHECK(a.mean_interval.lower == b.mean_interval.lower);
    CHECK(a.mean_interval.upper == b.mean_interval.upper);
    if (!percentiles) return;
    CHECK(a.p5 == b.p5);
    CHECK(a.p50 == b.p50);
    CHECK(a.p95 == b.p95);
}

void check_shape(const CalibrationShape& a, const CalibrationShape& b) {
    CHECK(a.label == b.label);
    CHECK(a.kind == b.kind);
    CHECK(same_value(a.size, b.size));
    CHECK(a.density == b.density);
    CHECK(a.sphericity == b.sphericity);
    CHECK(a.rock.friction == b.rock.friction);
    CHECK(a.surface.restitution == b.surface.restitution);
    REQUIRE(a.drops.size() == b.drops.size());
    for (std::size_t k = 0; k < a.drops.size(); ++k) {
        const risk::DropMeasurement& x = a.drops[k];
        const risk::DropMeasurement& y = b.drops[k];
        CHECK(x.index == y.index);
        CHECK(x.seed == y.seed);
        CHECK(x.rebounded == y.rebounded);
        CHECK(x.mass == y.mass);
        CHECK(x.restitution_impulse == y.restitution_impulse);
        CHECK(x.cor_energy == y.cor_energy);
    }
    REQUIRE(a.heaps.size() == b.heaps.size());
    for (std::size_t k = 0; k < a.heaps.size(); ++k) {
        const CalibrationHeap& x = a.heaps[k];
        const CalibrationHeap& y = b.heaps[k];
        CHECK(x.rock_friction == y.rock_friction);
        CHECK(x.heap.seed == y.heap.seed);
        CHECK(x.heap.status == y.heap.status);
        CHECK(x.heap.lift_time == y.heap.lift_time);
        CHECK(x.heap.angle_deg == y.heap.angle_deg);
        REQUIRE(x.heap.planes.size() == y.heap.planes.size());
        for (std::size_t p = 0; p < x.heap.planes.size(); ++p) {
            CHECK(x.heap.planes[p].valid == y.heap.planes[p].valid);
            CHECK(x.heap.planes[p].fitted_points == y.heap.planes[p].fitted_points);
            CHECK(x.heap.planes[p].foot_radius == y.heap.planes[p].foot_radius);
        }
    }
    REQUIRE(a.identified.has_value() == b.identified.has_value());
    if (!a.identified) return;
    const CalibrationIdentified& x = *a.identified;
    const CalibrationIdentified& y = *b.identified;
    CHECK(x.parameter == y.parameter);
    CHECK(x.measure == y.measure);
    CHECK(x.target == y.target);
    CHECK(x.value == y.value);
    CHECK(same_value(x.contact_value, y.contact_value));
    check_summary(x.achieved, y.achieved, false);
    CHECK(x.consistent.lower == y.consistent.lower);
    CHECK(x.consistent.upper == y.consistent.upper);
    REQUIRE(x.curve.size() == y.curve.size());
    for (std::size_t k = 0; k < x.curve.size(); ++k) {
        CHECK(x.curve[k].parameter == y.curve[k].parameter);
        CHECK(same_value(x.curve[k].contact_value, y.curve[k].contact_value));
        CHECK(x.curve[k].refinement == y.curve[k].refinement);
        check_summary(x.curve[k].measure, y.curve[k].measure, true);
    }
}

}  // namespace

TEST_CASE("a calibration experiment reads back as written", "[db]") {
    ScratchDir dir;
    const CalibrationRecord written = GENERATE(hand_drop_record(), hand_heap_record());
    write_calibration(dir / "calibration.db", written);
    CHECK(dir.files() == std::vector<std::string>{"calibration.db"});
    const ResultsDb db = ResultsDb::open_any(dir / "calibration.db", false);
    CHECK(db.kind() == written.kind);
    const CalibrationRecord read = read_calibration(db);
    CHECK(read.kind == written.kind);
    CHECK(read.run.seed == written.run.seed);
    CHECK(read.run.method == written.run.method);
    CHECK(read.run.settings_json == written.run.settings_json);
    CHECK(read.run.status == "complete");
    REQUIRE(read.shapes.size() == written.shapes.size());
    // Heaps come back in friction order, as a query would list them.
    CalibrationRecord expected = written;
    for (CalibrationShape& s : expected.shapes) {
        std::stable_sort(s.heaps.begin(), s.heaps.end(), [](const auto& a, const auto& b) {
            return a.rock_friction < b.rock_friction;
        });
    }
    for (std::size_t k = 0; k < read.shapes.size(); ++k) {
        check_shape(read.shapes[k], expected.shapes[k]);
    }
}

TEST_CASE("calibration databases and the others refuse each other's reads", "[db]") {
    ScratchDir dir;
    write_calibration(dir / "drop.db", hand_drop_record());
    const std::string before = read_bytes(dir / "drop.db");
    for (const bool writable : {false, true}) {
        try {
            ResultsDb::open(dir / "drop.db", writable);
            FAIL("opened a drop test as a rock sweep");
        } catch (const DatabaseError& e) {
            CHECK_THAT(e.what(), Catch::Contains("drop.db holds a drop test") &&
                                     Catch::Contains("not a rock sweep"));
            CHECK(e.kind() == DatabaseError::Kind::bad_file);
        }
    }
    CHECK(read_bytes(dir / "drop.db") == before);
    const ResultsDb drop = ResultsDb::open_any(dir / "drop.db", false);
    CHECK_THROWS_WITH(read_soil_run(drop),
                      Catch::Contains("holds a drop test") && Catch::Contains("not a soil flow"));
    { make_database(dir / "sweep.db", {}); }
    const ResultsDb sweep = ResultsDb::open_any(dir / "sweep.db", false);
    CHECK_THROWS_WITH(read_calibration(sweep), Catch::Contains("holds a rock sweep") &&
                                                   Catch::Contains("not a calibration"));
    CHECK_THROWS_AS(write_calibration(dir / "x.db",
                                      {hand_run("sweep", "monte_carlo"), RunKind::rock_sweep, {}}),
                    std::invalid_argument);
}

TEST_CASE("a calibration database never replaces a file", "[db]") {
    ScratchDir dir;
    write_calibration(dir / "heap.db", hand_heap_record());
    const std::string before = read_bytes(dir / "heap.db");
    try {
        write_calibration(dir / "heap.db", hand_drop_record());
        FAIL("replaced an existing database");
    } catch (const DatabaseError& e) {
        CHECK_THAT(e.what(), Catch::Contains("heap.db"));
        CHECK(e.kind() == DatabaseError::Kind::bad_file);
    }
    CHECK(read_bytes(dir / "heap.db") == before);
    CHECK(dir.files() == std::vector<std::string>{"heap.db"});
}

TEST_CASE("a calibration database missing one of its tables is refused as damaged", "[db]") {
    ScratchDir dir;
    write_calibration(dir / "drop.db", hand_drop_record());
    sqlite3* raw = nullptr;
    REQUIRE(sqlite3_open((dir / "drop.db").c_str(), &raw) == SQLITE_OK);
    REQUIRE(sqlite3_exec(raw, "DROP TABLE heap_planes", nullptr, nullptr, nullptr) == SQLITE_OK);
    sqlite3_close(raw);
    CHECK_THROWS_WITH(ResultsDb::open_any(dir / "drop.db", false),
                      Catch::Contains("lacks its table 'heap_planes'"));
}
