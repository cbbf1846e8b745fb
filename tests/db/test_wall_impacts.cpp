// Every wall hit read back with its sample's identity, in sample and hit order.

#include "db_test_support.hpp"

#include "db/wall_impacts.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rockfall::db;
using rockfall::db::test::hand_record;
using rockfall::db::test::make_database;
using rockfall::db::test::ScratchDir;

TEST_CASE("wall impacts come back one per hit with their sample", "[db][impacts]") {
    ScratchDir dir;
    // Sample 0: two hits; sample 1: none; sample 2: one hit, a massive rock of 80 kg.
    std::vector<SampleRecord> records = {hand_record(0, 5.0, {1.0e4, 2.0e4}), hand_record(1, 3.0),
                                         hand_record(2, 5.0, {5.0e4})};
    records[0].rocks.at(0).outcome.wall_hits[1].normal_speed = 1.5;
    records[2].inputs.kind = rockfall::shapes::RockKind::massive;
    records[2].inputs.mass = 80.0;
    records[2].rocks.at(0).inputs = rockfall::risk::rock_inputs(records[2].inputs);
    const ResultsDb db = make_database(dir / "impacts.db", records);

    const std::vector<WallImpact> impacts = read_wall_impacts(db);
    REQUIRE(impacts.size() == 3);
    CHECK(impacts[0].sample == 0);
    CHECK(impacts[0].hit == 1);
    CHECK(impacts[1].hit == 2);
    CHECK(impacts[2].sample == 2);
    CHECK(impacts[2].hit == 1);
    // hand_record: seed 1000 + index, sphere of 0.3 m and 36.8 kg, speed = peak / 10000.
    CHECK(impacts[0].seed == 1000u);
    CHECK(impacts[2].seed == 1002u);
    CHECK(impacts[0].kind == "sphere");
    CHECK(impacts[2].kind == "massive");
    CHECK(impacts[0].size == 0.3);
    CHECK(impacts[0].mass == 36.8);
    CHECK(impacts[2].mass == 80.0);
    CHECK(impacts[1].peak_force == 2.0e4);
    CHECK(impacts[2].impact_speed == 5.0);
    CHECK(impacts[1].normal_speed == 1.5);
    CHECK(impacts[1].energy_before == 200.0);
}

TEST_CASE("a database without wall hits has no impacts", "[db][impacts]") {
    ScratchDir dir;
    const ResultsDb db = make_database(dir / "none.db", {hand_record(0, 1.0)});
    CHECK(read_wall_impacts(db).empty());
}
