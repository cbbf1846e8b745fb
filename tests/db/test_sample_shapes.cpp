// The shape of each sample in the database: samples.shape, sphericity, and a generated rock's
// target and generator seed, written and read back, and results broken down by shape.

#include "db_test_support.hpp"

#include "db/queries.hpp"
#include "db/results_db.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace rockfall::db;
using rockfall::db::test::ScratchDir;
using rockfall::shapes::RockKind;

namespace {

// Sample `index` of kind custom with `shape` ("" for the base rock's own shape).
SampleRecord custom_record(std::int64_t index, double reach, const std::string& shape,
                           double sphericity) {
    SampleRecord record = test::hand_record(index, reach);
    record.inputs.kind = RockKind::custom;
    record.inputs.shape = shape;
    record.inputs.sphericity = sphericity;
    record.rocks.at(0).inputs = rockfall::risk::rock_inputs(record.inputs);
    return record;
}

}  // namespace

TEST_CASE("each sample's shape is stored and read back", "[db]") {
    ScratchDir dir;
    SampleRecord sphere = test::hand_record(0, 1.0);
    SampleRecord entry = custom_record(1, 2.0, "psi_0.72", 0.72);
    SampleRecord base = custom_record(2, 3.0, "", 0.81);
    SampleRecord generated = custom_record(3, 4.0, "generated", 0.8500321);
    generated.inputs.target_sphericity = 0.85;
    generated.inputs.shape_seed = 0xfedcba9876543210ULL;  // above 2^63
    { test::make_database(dir / "shapes.db", {sphere, entry, base, generated}); }
    const ResultsDb db = ResultsDb::open(dir / "shapes.db", false);

    const auto read = [&db](std::int64_t index) {
        std::optional<SampleRecord> record = db.sample(index);
        REQUIRE(record);
        return record->inputs;
    };
    const rockfall::risk::SampleInputs s0 = read(0);
    CHECK(s0.kind == RockKind::sphere);
    CHECK(s0.shape.empty());
    CHECK(s0.sphericity == 1.0);
    CHECK(std::isnan(s0.target_sphericity));
    const rockfall::risk::SampleInputs s1 = read(1);
    CHECK(s1.kind == RockKind::custom);
    CHECK(s1.shape == "psi_0.72");
    CHECK(s1.sphericity == 0.72);
    CHECK(read(2).shape.empty());
    const rockfall::risk::SampleInputs s3 = read(3);
    CHECK(s3.shape == "generated");
    CHECK(s3.sphericity == 0.8500321);
    CHECK(s3.target_sphericity == 0.85);
    CHECK(s3.shape_seed == 0xfedcba9876543210ULL);

    // The base rock's own shape is "custom" in the database, so that `--by shape` names it.
    const std::vector<Group> groups = read_groups(db, Quantity::reach, {GroupBy::shape, {}});
    std::vector<std::string> labels;
    for (const Group& group : groups) labels.push_back(group.id.label);
    CHECK(labels == std::vector<std::string>{"custom", "generated", "psi_0.72", "sphere"});
    CHECK(groups[1].values == std::vector<double>{4.0});
    CHECK(parse_group_by("shape") == GroupBy::shape);
}
