#include "db_test_support.hpp"

#include <sqlite3.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace rockfall::db::test {
namespace {

namespace fs = std::filesystem;

void check_vec(const engine::Vec3& expected, const engine::Vec3& actual) {
    for (int i = 0; i < 3; ++i) CHECK(same_value(expected[i], actual[i]));
}

}  // namespace

ScratchDir::ScratchDir() {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() /
            ("rockfall_db_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
}

ScratchDir::~ScratchDir() {
    std::error_code ignored;
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ignored);
    for (const auto& entry : fs::directory_iterator(path_, ignored)) {
        fs::permissions(entry.path(), fs::perms::owner_all, fs::perm_options::add, ignored);
    }
    fs::remove_all(path_, ignored);
}

std::vector<std::string> ScratchDir::files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path_)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void write_bytes(const fs::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
}

void run_sql(const fs::path& path, const std::string& sql) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open(path.c_str(), &db) == SQLITE_OK);
    CHECK(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK);
    sqlite3_close(db);
}

SampleRecord hand_record(std::int64_t index, double reach, const std::vector<double>& peak_forces) {
    SampleRecord record;
    record.inputs.index = index;
    record.inputs.seed = 1000u + static_cast<std::uint64_t>(index);
    record.inputs.kind = shapes::RockKind::sphere;
    record.inputs.size = 0.3;
    record.inputs.mass = 36.8;
    record.rocks.push_back({risk::rock_inputs(record.inputs), {}, {}});
    record.rocks.front().outcome.stop = engine::StopReason::at_rest;
    record.rocks.front().outcome.stop_time = 5.0;
    record.rocks.front().outcome.reach = reach;
    record.rocks.front().outcome.max_speed = 8.0;
    record.rocks.front().outcome.max_bounce_height = 0.25;
    record.rocks.front().outcome.velocity_change = std::nan("");
    for (std::size_t i = 0; i < peak_forces.size(); ++i) {
        engine::WallHit& hit = record.rocks.front().outcome.wall_hits.emplace_back();
        hit.start_time = 2.0 + static_cast<double>(i);
        hit.end_time = hit.start_time + 0.01;
        hit.peak_normal_force = peak_forces[i];
        hit.energy_before = peak_forces[i] / 100.0;
        hit.normal_impulse = peak_forces[i] / 1000.0;
        hit.velocity_before = {peak_forces[i] / 10000.0, 0.0, 0.0};
    }
    return record;
}

void check_same(const SampleRecord& expected, const SampleRecord& actual) {
    const risk::SampleInputs& a = expected.inputs;
    const risk::SampleInputs& b = actual.inputs;
    CHECK(a.index == b.index);
    CHECK(a.seed == b.seed);
    CHECK(a.zone == b.zone);
    CHECK(a.kind == b.kind);
    CHECK(same_value(a.size, b.size));
    CHECK(same_value(a.density, b.density));
    CHECK(same_value(a.mass, b.mass));
    CHECK(same_value(a.material.friction, b.material.friction));
    CHECK(same_value(a.material.restitution, b.material.restitution));
    CHECK(same_value(a.material.rolling_resistance, b.material.rolling_resistance));
    CHECK(same_value(a.release_distance, b.release_distance));
    CHECK(same_value(a.release_lateral, b.release_lateral));
    CHECK(same_value(a.speed, b.speed));
    CHECK(same_value(a.spin, b.spin));
    check_vec(a.orientation_deg, b.orientation_deg);

    REQUIRE(expected.rocks.size() == actual.rocks.size());
    for (std::size_t rock = 0; rock < expected.rocks.size(); ++rock) {
        INFO("rock " << rock);
        check_same_rock(expected.rocks[rock], actual.rocks[rock]);
    }
}

void check_same_rock(const risk::RockResult& expected, const risk::RockResult& actual) {
    const risk::RockInputs& p = expected.inputs;
    const risk::RockInputs& q = actual.inputs;
    CHECK(p.cluster == q.cluster);
    CHECK(p.kind == q.kind);
    CHECK(p.shape == q.shape);
    CHECK(same_value(p.size, q.size));
    CHECK(same_value(p.density, q.density));
    CHECK(same_value(p.mass, q.mass));
    CHECK(same_value(p.material.friction, q.material.friction));
    CHECK(same_value(p.material.restitution, q.material.restitution));
    CHECK(same_value(p.material.rolling_resistance, q.material.rolling_resistance));
    const engine::RockOutcome& x = expected.outcome;
    const engine::RockOutcome& y = actual.outcome;
    CHECK(x.stop == y.stop);
    CHECK(same_value(x.stop_time, y.stop_time));
    CHECK(same_value(x.reach, y.reach));
    check_vec(x.final_state.position, y.final_state.position);
    check_vec(x.final_state.velocity, y.final_state.velocity);
    CHECK(same_value(x.max_speed, y.max_speed));
    CHECK(same_value(x.max_kinetic_energy, y.max_kinetic_energy));
    CHECK(same_value(x.max_bounce_height, y.max_bounce_height));
    CHECK(same_value(x.velocity_change, y.velocity_change));
    REQUIRE(x.stations.size() == y.stations.size());
    for (std::size_t i = 0; i < x.stations.size(); ++i) {
        const engine::StationCrossing& s = x.stations[i];
        const engine::StationCrossing& t = y.stations[i];
        CHECK(same_value(s.distance_from_toe, t.distance_from_toe));
        CHECK(s.reached == t.reached);
        if (!s.reached) continue;
        CHECK(same_value(s.time, t.time));
        CHECK(same_value(s.speed, t.speed));
        CHECK(same_value(s.parallel_speed, t.parallel_speed));
        CHECK(same_value(s.angular_speed, t.angular_speed));
        CHECK(same_value(s.bounce_height, t.bounce_height));
        CHECK(same_value(s.rolling_coefficient, t.rolling_coefficient));
        CHECK(same_value(s.translational_energy, t.translational_energy));
        CHECK(same_value(s.rotational_energy, t.rotational_energy));
    }
    REQUIRE(x.wall_hits.size() == y.wall_hits.size());
    for (std::size_t i = 0; i < x.wall_hits.size(); ++i) {
        const engine::WallHit& h = x.wall_hits[i];
        const engine::WallHit& k = y.wall_hits[i];
        CHECK(same_value(h.start_time, k.start_time));
        CHECK(same_value(h.end_time, k.end_time));
        check_vec(h.point, k.point);
        CHECK(same_value(h.normal_impulse, k.normal_impulse));
        check_vec(h.tangential_impulse, k.tangential_impulse);
        check_vec(h.velocity_before, k.velocity_before);
        check_vec(h.velocity_after, k.velocity_after);
        check_vec(h.angular_velocity_before, k.angular_velocity_before);
        check_vec(h.angular_velocity_after, k.angular_velocity_after);
        CHECK(same_value(h.energy_before, k.energy_before));
        CHECK(same_value(h.energy_after, k.energy_after));
        CHECK(same_value(h.normal_speed, k.normal_speed));
        CHECK(same_value(h.peak_normal_force, k.peak_normal_force));
        CHECK(same_value(h.peak_time, k.peak_time));
    }
    REQUIRE(expected.trajectory.size() == actual.trajectory.size());
    for (std::size_t i = 0; i < expected.trajectory.size(); ++i) {
        const engine::RockState& s = expected.trajectory[i];
        const engine::RockState& t = actual.trajectory[i];
        CHECK(same_value(s.time, t.time));
        check_vec(s.position, t.position);
        check_vec(s.velocity, t.velocity);
        check_vec(s.angular_velocity, t.angular_velocity);
        CHECK(s.orientation.coeffs() == t.orientation.coeffs());
        CHECK(same_value(s.translational_energy, t.translational_energy));
        CHECK(same_value(s.rotational_energy, t.rotational_energy));
    }
}

ResultsDb make_database(const fs::path& path, const std::vector<SampleRecord>& records,
                        std::size_t zones) {
    testing::SyntheticOptions options;
    options.zones = zones;
    ResultsDb db = ResultsDb::create(path, testing::synthetic_run(options, 1000));
    if (!records.empty()) db.write_batch(records);
    return db;
}

}  // namespace rockfall::db::test
