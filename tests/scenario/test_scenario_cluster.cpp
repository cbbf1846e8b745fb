// [cluster] with marked rocks, rock names and numerics.wall_stepping in scenario files: read,
// checked and written back.

#include "scenario/scenario_file.hpp"
#include "scenario_errors.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using rockfall::scenario::ScenarioError;
using rockfall::test::problem_for;

namespace {

const fs::path samples = ROCKFALL_SAMPLES_DIR;

rockfall::engine::Scenario parse(const std::string& text) {
    // As if written in the samples folder, so that rocks/catalogue.toml is the sample catalogue.
    return rockfall::scenario::parse_scenario(text, (samples / "inline.toml").string(), samples);
}

ScenarioError parse_error(const std::string& text) {
    return rockfall::test::parse_error([](const std::string& t) { parse(t); }, text);
}

// Seed 001's flume with a 10-rock cluster; the tests append keys of [cluster] and tables.
const std::string flume = R"(
stations = [0.0]
[slope]
width = 0.6
[[slope.segments]]
length = 1.82
angle_deg = 45.0
[[slope.segments]]
length = 1.82
angle_deg = 0.0
[slope.bars]
enabled = false
segments = []
[slope.wall]
distance_from_toe = 0.5
[cluster.material]
friction = 0.4
[cluster]
count = 10
density = 2620.0
)";

}  // namespace

TEST_CASE("marked cluster rocks take the cluster's defaults and read back from format_scenario",
          "[scenario][cluster]") {
    const rockfall::engine::Scenario s = parse(flume + R"(
[[cluster.marked]]
name = "red"
catalogue = "rocks/catalogue.toml"
entry = "psi_0.89"
size = 0.06
along = 0.3
across = -0.2

[[cluster.marked]]
name = "plain"
orientation_deg = [0.0, 10.0, 90.0]

[numerics]
wall_stepping = "world"
sheet_contact = "mesh"
)");
    REQUIRE(s.cluster);
    REQUIRE(s.cluster->marked.size() == 2);
    const rockfall::engine::MarkedRock& red = s.cluster->marked[0];
    CHECK(red.name == "red");
    CHECK(red.rock.kind == rockfall::shapes::RockKind::custom);
    CHECK(red.rock.shape->name == "psi_0.89");
    CHECK(red.rock.size == 0.06);
    CHECK(red.rock.density == 2620.0);  // the cluster's
    CHECK(red.rock.material.friction == 0.4);
    CHECK(red.along == 0.3);
    CHECK(red.across == -0.2);
    CHECK(!red.orientation_deg);
    const rockfall::engine::MarkedRock& plain = s.cluster->marked[1];
    CHECK(plain.rock.kind == rockfall::shapes::RockKind::massive);  // the cluster's family
    CHECK(plain.rock.size == s.cluster->grading.d50);
    CHECK(plain.orientation_deg == rockfall::engine::Vec3(0.0, 10.0, 90.0));
    CHECK(s.numerics.wall_stepping == rockfall::engine::WallStepping::world);
    CHECK(s.numerics.sheet_contact == rockfall::engine::SheetContact::mesh);

    const rockfall::engine::Scenario back = parse(rockfall::scenario::format_scenario(s));
    REQUIRE(back.cluster->marked.size() == 2);
    CHECK(back.cluster->marked[0].name == "red");
    // The hull comes back as its vertices (re-hulled: the same rock, in another order).
    CHECK(back.cluster->marked[0].rock.shape->hull.vertices.size() ==
          red.rock.shape->hull.vertices.size());
    CHECK_THAT(back.cluster->marked[0].rock.geometry().bounding_radius,
               Catch::Matchers::WithinRel(red.rock.geometry().bounding_radius, 1e-12));
    CHECK(back.cluster->marked[0].rock.size == 0.06);
    CHECK(back.cluster->marked[0].across == -0.2);
    CHECK(back.cluster->marked[1].orientation_deg == plain.orientation_deg);
    CHECK(back.cluster->marked[1].rock.material.friction == 0.4);
    CHECK(back.numerics.wall_stepping == rockfall::engine::WallStepping::world);
    CHECK(back.numerics.sheet_contact == rockfall::engine::SheetContact::mesh);
}

TEST_CASE("named rocks read back, and the default wall stepping is per rock",
          "[scenario][cluster]") {
    const rockfall::engine::Scenario s = parse("[[rocks]]\nname = \"boulder\"\nsize = 0.3\n");
    CHECK(s.rocks.at(0).name == "boulder");
    CHECK(s.numerics.wall_stepping == rockfall::engine::WallStepping::per_rock);
    CHECK(s.numerics.sheet_contact == rockfall::engine::SheetContact::structured);
    const rockfall::engine::Scenario back = parse(rockfall::scenario::format_scenario(s));
    CHECK(back.rocks.at(0).name == "boulder");
}

TEST_CASE("bad marked rocks are reported at their keys", "[scenario][cluster][errors]") {
    const ScenarioError error = parse_error(flume + R"(
[[rocks]]
name = "twin"

[[cluster.marked]]
along = 0.3

[[cluster.marked]]
name = "twin"
kind = "sphere"
size = 0.06
along = 0.39

[[cluster.marked]]
name = "big"
kind = "cube"

[numerics]
wall_stepping = "sometimes"
)");
    CHECK_THAT(problem_for(error, "cluster.marked[0].name").message,
               Contains("a marked rock needs a name"));
    CHECK_THAT(problem_for(error, "cluster.marked[1].name").message,
               Contains("\"twin\": is already the name of rocks[0]"));
    // 0.39 m from the back face of a 0.40 m box: a 60 mm sphere's centre may go to 0.37 m.
    CHECK_THAT(problem_for(error, "cluster.marked[1].along").message,
               Contains("spot along the box = 0.39 m: must be in [0.03, 0.37]"));
    CHECK_THAT(problem_for(error, "cluster.marked[2].kind").message, Contains("\"cube\""));
    CHECK_THAT(problem_for(error, "numerics.wall_stepping").message,
               Contains("\"per_rock\", \"world\""));
}

TEST_CASE("a cluster's rocks may be a catalogue hull or a target sphericity",
          "[scenario][cluster]") {
    const rockfall::engine::Scenario hull = parse(flume + R"(
catalogue = "rocks/catalogue.toml"
entry = "octahedron"
)");
    REQUIRE(hull.cluster);
    CHECK(hull.cluster->rock.kind == rockfall::shapes::RockKind::custom);
    CHECK(hull.cluster->rock.shape->name == "octahedron");
    const rockfall::engine::Scenario back = parse(rockfall::scenario::format_scenario(hull));
    CHECK(back.cluster->rock.shape->hull.vertices.size() ==
          hull.cluster->rock.shape->hull.vertices.size());

    const rockfall::engine::Scenario round = parse(flume + "sphericity = 0.8\n");
    CHECK(round.cluster->sphericity == 0.8);
    CHECK(parse(rockfall::scenario::format_scenario(round)).cluster->sphericity == 0.8);

    const ScenarioError low = parse_error(flume + "sphericity = 0.3\nlong_axis = 0.1\n");
    CHECK_THAT(problem_for(low, "cluster.sphericity").message,
               Contains("must be 0 (off) or in [0.5, 0.95]"));
    CHECK_THAT(problem_for(low, "cluster.long_axis").message, Contains("not for a cluster"));
    const ScenarioError both = parse_error(
        flume + "sphericity = 0.8\ncatalogue = \"rocks/catalogue.toml\"\nentry = \"cube\"\n");
    CHECK_THAT(problem_for(both, "cluster.sphericity").message, Contains("not both"));
}

TEST_CASE("cluster.box.packing reads, writes back and lays marked rocks flat",
          "[scenario][cluster]") {
    const rockfall::engine::Scenario s =
        parse(flume + "sphericity = 0.72\n[cluster.box]\npacking = \"flat\"\n");
    CHECK(s.cluster->box.packing == rockfall::shapes::Packing::flat);
    CHECK(parse(rockfall::scenario::format_scenario(s)).cluster->box.packing ==
          rockfall::shapes::Packing::flat);
    const ScenarioError error = parse_error(flume + R"(
[cluster.box]
packing = "flat"
[[cluster.marked]]
name = "m"
orientation_deg = [0.0, 0.0, 45.0]
)");
    CHECK_THAT(problem_for(error, "cluster.marked[0].orientation_deg").message,
               Contains("not with cluster.box.packing = \"flat\""));
    const ScenarioError bad = parse_error(flume + "[cluster.box]\npacking = \"loose\"\n");
    CHECK_THAT(problem_for(bad, "cluster.box.packing").message, Contains("\"spheres\", \"flat\""));
}

TEST_CASE("[wall_cells] reads its grid, writes it back and checks it fits the wall",
          "[scenario][wall_cells]") {
    const rockfall::engine::Scenario s = parse(flume + R"(
[wall_cells]
columns = 8
sample_interval = 0.0005
)");
    REQUIRE(s.wall_cells);
    CHECK(s.wall_cells->columns == 8);
    CHECK(s.wall_cells->rows == 16);  // defaults: seed 001's pad
    CHECK(s.wall_cells->width == 0.6);
    CHECK(s.wall_cells->capacity == 345e3);
    CHECK(s.wall_cells->sample_interval == 0.0005);
    const rockfall::engine::Scenario back = parse(rockfall::scenario::format_scenario(s));
    REQUIRE(back.wall_cells);
    CHECK(back.wall_cells->columns == 8);
    CHECK(back.wall_cells->sample_interval == 0.0005);
    CHECK(!parse(flume).wall_cells);

    const ScenarioError error = parse_error(flume + R"(
[wall_cells]
rows = 0
width = 0.7
capacity = -1.0
)");
    CHECK_THAT(problem_for(error, "wall_cells.rows").message, Contains("[1, 256]"));
    CHECK_THAT(problem_for(error, "wall_cells.capacity").message, Contains("Pa"));
    const ScenarioError wide = parse_error(flume + "[wall_cells]\nwidth = 0.7\nheight = 1.6\n");
    CHECK_THAT(problem_for(wide, "wall_cells.width").message,
               Contains("0.7 m: must be in (0, 0.6] (the slope's width)"));
    CHECK_THAT(problem_for(wide, "wall_cells.height").message,
               Contains("1.6 m: must be in (0, 1.5] (the wall's height)"));
}
