// The rounded-polyhedron wall law's keys: wall_contact.hull_model and
// wall_contact.corner_roundness read, written back, and rejected with key, value and range.

#include "scenario/scenario_file.hpp"
#include "scenario_errors.hpp"

#include <catch2/catch.hpp>

#include <string>

using Catch::Matchers::Contains;
using rockfall::engine::WallContact;
using rockfall::scenario::ScenarioError;

namespace {

// Parses `table` as the [wall_contact] table of an otherwise default scenario.
void parse_wall_contact(const std::string& table) {
    rockfall::scenario::parse_scenario("[wall_contact]\n" + table, "wall.toml");
}

ScenarioError wall_contact_error(const std::string& table) {
    return rockfall::test::parse_error(parse_wall_contact, table);
}

}  // namespace

TEST_CASE("wall_contact.hull_model and corner_roundness are read and written back",
          "[scenario][wall_contact]") {
    const rockfall::engine::Scenario defaults =
        rockfall::scenario::parse_scenario("", "empty.toml");
    CHECK(defaults.wall_contact.hull_model == WallContact::HullModel::sphere);
    CHECK(defaults.wall_contact.corner_roundness == 0.38);

    const rockfall::engine::Scenario s = rockfall::scenario::parse_scenario(
        "[wall_contact]\nhull_model = \"rounded\"\ncorner_roundness = 0.25\n", "wall.toml");
    CHECK(s.wall_contact.hull_model == WallContact::HullModel::rounded);
    CHECK(s.wall_contact.corner_roundness == 0.25);
    const rockfall::engine::Scenario back =
        rockfall::scenario::parse_scenario(rockfall::scenario::format_scenario(s), "back.toml");
    CHECK(back.wall_contact.hull_model == WallContact::HullModel::rounded);
    CHECK(back.wall_contact.corner_roundness == 0.25);
}

TEST_CASE("bad wall_contact.hull_model and corner_roundness name key, value and range",
          "[scenario][wall_contact][errors]") {
    for (const std::string value : {"0", "-0.1", "1.5"}) {
        const ScenarioError error = wall_contact_error("corner_roundness = " + value + "\n");
        REQUIRE(error.problems().size() == 1);
        CHECK(std::string(error.what()) ==
              "wall_contact.corner_roundness = " + value + ": must be in (0, 1] (wall.toml:2)");
    }
    CHECK(rockfall::scenario::parse_scenario("[wall_contact]\ncorner_roundness = 1.0\n", "w.toml")
              .wall_contact.corner_roundness == 1.0);

    const ScenarioError name = wall_contact_error("hull_model = \"cube\"\n");
    CHECK_THAT(name.what(), Contains("wall_contact.hull_model = \"cube\": must be one of "
                                     "\"sphere\", \"rounded\""));

    const ScenarioError linear =
        wall_contact_error("model = \"linear\"\nhull_model = \"rounded\"\n");
    REQUIRE(linear.problems().size() == 1);
    CHECK(linear.problems()[0].key == "wall_contact.hull_model");
    CHECK_THAT(linear.what(), Contains("needs wall_contact.model = \"hertz\""));
}
