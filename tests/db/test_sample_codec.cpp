// Finished samples as bytes (db/sample_codec.hpp), as the MPI ranks of a sweep send them: a
// record read back equals the one sent in every stored field and bit for bit, and cut or
// damaged bytes are refused.

#include "db_test_support.hpp"
#include "scenario/scenario_file.hpp"

#include "db/sample_codec.hpp"
#include "risk/sweep_runner.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace rockfall;

namespace {

std::vector<db::SampleRecord> synthetic_records() {
    db::testing::SyntheticOptions options;
    options.stations = 3;
    options.trajectory_points = 7;
    std::vector<db::SampleRecord> records;
    for (std::int64_t i = 0; i < 40; ++i)
        records.push_back(db::testing::synthetic_record(options, i));
    records.push_back(db::test::hand_record(40, 2.5, {1.0e5, 3.0e5}));
    return records;
}

std::string encoded(const std::vector<db::SampleRecord>& records) {
    std::string bytes;
    for (const db::SampleRecord& record : records) db::encode_sample(record, bytes);
    return bytes;
}

void check_round_trip(const std::vector<db::SampleRecord>& records) {
    const std::string bytes = encoded(records);
    const std::vector<db::SampleRecord> decoded = db::decode_samples(bytes);
    REQUIRE(decoded.size() == records.size());
    for (std::size_t i = 0; i < records.size(); ++i) db::test::check_same(records[i], decoded[i]);
    // Every encoded field, NaN included, comes back with the same bits.
    CHECK(encoded(decoded) == bytes);
}

}  // namespace

TEST_CASE("synthetic samples with stations, wall hits and trajectories survive encoding",
          "[db][codec]") {
    const std::vector<db::SampleRecord> records = synthetic_records();
    std::size_t hits = 0;
    for (const db::SampleRecord& record : records) hits += record.rocks[0].outcome.wall_hits.size();
    REQUIRE(hits > 0);
    check_round_trip(records);
}

TEST_CASE("simulated cluster releases with trajectories survive encoding and store the same rows",
          "[db][codec][cluster]") {
    std::ifstream in(std::filesystem::path(ROCKFALL_TEST_DATA_DIR) / "cluster_sweep.toml");
    REQUIRE(in);
    std::stringstream text;
    text << in.rdbuf();
    const scenario::ScenarioFile file =
        scenario::parse_scenario_file(text.str(), "cluster_sweep.toml");
    std::vector<db::SampleRecord> records;
    for (std::int64_t i = 0; i < 2; ++i)
        records.push_back(risk::run_sample(file.sweep, file.scenario, i, 0.05));
    REQUIRE(records[0].rocks.size() == 5);
    REQUIRE_FALSE(records[0].rocks[0].trajectory.empty());
    check_round_trip(records);

    // The database rows written from the decoded records are those of the originals.
    db::test::ScratchDir dir;
    db::ResultsDb sent = db::test::make_database(dir / "sent.db", records, 1);
    db::ResultsDb received =
        db::test::make_database(dir / "received.db", db::decode_samples(encoded(records)), 1);
    for (std::int64_t i = 0; i < 2; ++i) {
        const auto a = sent.sample(i);
        const auto b = received.sample(i);
        REQUIRE(a);
        REQUIRE(b);
        db::test::check_same(*a, *b);
    }
}

TEST_CASE("cut or damaged sample bytes are refused", "[db][codec]") {
    const std::string bytes = encoded(synthetic_records());
    CHECK(db::decode_samples("").empty());
    CHECK_THROWS_WITH(db::decode_samples(std::string_view(bytes).substr(0, bytes.size() - 3)),
                      Catch::Contains("cut short"));
    std::string damaged = bytes;
    // The first record's shape length (after index, seed, zone and kind) made huge.
    const std::size_t at = sizeof(std::int64_t) + sizeof(std::uint64_t) + sizeof(std::size_t) +
                           sizeof(shapes::RockKind);
    damaged[at + 7] = '\x7f';
    CHECK_THROWS_WITH(db::decode_samples(damaged), Catch::Contains("exceeds the"));
}
