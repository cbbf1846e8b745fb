#include "scenario/soil_file.hpp"
#include "scenario_errors.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using rockfall::scenario::ScenarioError;
using rockfall::scenario::ScenarioProblem;

using rockfall::test::line_of;
using rockfall::test::problem_for;

namespace {

const fs::path samples = fs::path(ROCKFALL_SAMPLES_DIR) / "soil";
const fs::path bad = fs::path(ROCKFALL_SOIL_DATA_DIR);

ScenarioError load_error(const fs::path& file) {
    return rockfall::test::load_error(
        [](const fs::path& f) { rockfall::scenario::load_soil_scenario(f); }, file);
}

// The error of parsing soil scenario `text` named `source` (fails the test if it parses).
ScenarioError parse_error(const std::string& text, const std::string& source) {
    try {
        rockfall::scenario::parse_soil_scenario(text, source);
    } catch (const ScenarioError& error) {
        return error;
    }
    FAIL("parsing " << source << " did not throw");
    throw std::logic_error("unreachable");
}

// Checks that `key` is reported at `line` of inline text, with each of `parts`.
void expect_at(const ScenarioError& error, const std::string& key, int line,
               std::initializer_list<std::string> parts) {
    const ScenarioProblem problem = problem_for(error, key);
    CHECK(problem.line == line);
    for (const std::string& part : parts) CHECK_THAT(problem.message, Contains(part));
}

// Checks that `key` is reported at the line of `file` that contains `needle`, with a message
// containing each of `parts`.
void expect_problem(const ScenarioError& error, const fs::path& file, const std::string& key,
                    const std::string& needle, std::initializer_list<std::string> parts) {
    const ScenarioProblem problem = problem_for(error, key);
    CHECK(fs::path(problem.file).filename() == file.filename());
    CHECK(problem.line == line_of(file, needle));
    for (const std::string& part : parts) CHECK_THAT(problem.message, Contains(part));
}

}  // namespace

TEST_CASE("soil samples load with the paper's parameters", "[scenario][soil]") {
    const auto seed = rockfall::scenario::load_soil_scenario(samples / "seed_3d.toml");
    CHECK(seed.scenario.numerics.dimension == 3);
    CHECK(seed.scenario.density == 1640.0);
    CHECK(seed.scenario.material.friction_angle_deg == 34.6);
    CHECK(seed.scenario.material.cohesion == 2100.0);
    CHECK(seed.scenario.material.match == rockfall::mpm::ConeMatch::plane_strain);
    CHECK(seed.scenario.boundaries.basal_friction_angle_deg == 30.0);
    CHECK(seed.scenario.slope.segments.size() == 3);
    CHECK_FALSE(seed.scenario.slope.bars.enabled);
    CHECK(seed.scenario.slope.wall.distance_from_toe == 0.5);
    CHECK_THAT(seed.name, Contains("3D"));

    const auto quick = rockfall::scenario::load_soil_scenario(samples / "quick_2d.toml");
    CHECK(quick.scenario.numerics.dimension == 2);
    CHECK(quick.scenario.slope.wall.distance_from_toe == 0.5);
    // Keys the quick sample leaves out keep the struct defaults.
    CHECK(quick.scenario.release.length == rockfall::mpm::SoilRelease{}.length);
    CHECK(quick.scenario.output.filter_window == rockfall::mpm::SoilOutput{}.filter_window);
}

TEST_CASE("soil file: unknown keys are reported with a suggestion", "[scenario][soil]") {
    const fs::path file = bad / "unknown_key.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 2);
    expect_problem(error, file, "material.frction_angle_deg", "frction_angle_deg",
                   {"unknown key", "did you mean 'friction_angle_deg'?"});
    expect_problem(error, file, "outputs", "[outputs]", {"unknown key", "did you mean 'output'?"});
}

TEST_CASE("soil file: out-of-range values name value, unit and range", "[scenario][soil]") {
    const fs::path file = bad / "out_of_range.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 3);
    expect_problem(error, file, "density", "density", {"-1640 kg/m3", "must be > 0"});
    expect_problem(error, file, "material.poisson_ratio", "poisson_ratio",
                   {"0.6", "must be in [0, 0.5)"});
    expect_problem(error, file, "numerics.particles_per_cell", "particles_per_cell",
                   {"12", "must be in [1, 8]"});
    // One line per problem, in file order.
    CHECK_THAT(std::string(error.what()),
               Contains("density = -1640 kg/m3: must be > 0 (" + file.string() + ":4)\n"));
}

TEST_CASE("soil file: wrong types and unknown choices", "[scenario][soil]") {
    const fs::path file = bad / "wrong_type.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 3);
    expect_problem(error, file, "material.cohesion", "cohesion",
                   {"\"2.1 kPa\"", "must be a number (Pa) >= 0"});
    expect_problem(
        error, file, "material.match", "match",
        {"\"outer\"", "must be one of \"plane_strain\", \"compression\", \"extension\""});
    expect_problem(error, file, "numerics.dimension", "dimension",
                   {"2.5", "must be an integer in [2, 3]"});
}

TEST_CASE("soil file: rules between keys", "[scenario][soil]") {
    const fs::path file = bad / "cross_field.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 3);
    expect_problem(error, file, "material.dilatancy_angle_deg", "dilatancy_angle_deg",
                   {"35 deg", "friction_angle_deg = 30 deg"});
    expect_problem(error, file, "output.sample_interval", "sample_interval",
                   {"1 s", "duration = 0.5 s"});
    expect_problem(error, file, "slope.wall.distance_from_toe", "distance_from_toe",
                   {"9 m", "stands on the last segment"});
}

TEST_CASE("soil file: syntax errors and missing files", "[scenario][soil]") {
    const ScenarioError syntax = load_error(bad / "syntax_error.toml");
    REQUIRE(syntax.problems().size() == 1);
    CHECK(syntax.problems()[0].line == 2);
    CHECK(syntax.problems()[0].column > 0);
    CHECK_THAT(syntax.problems()[0].message, Contains("TOML syntax error"));

    const ScenarioError missing = load_error(bad / "does_not_exist.toml");
    REQUIRE(missing.problems().size() == 1);
    CHECK_THAT(missing.problems()[0].message, Contains("no such file"));
}

TEST_CASE("soil file: a soil without friction needs cohesion", "[scenario][soil]") {
    const std::string text = "[material]\nfriction_angle_deg = 0\ncohesion = 0\n";
    try {
        rockfall::scenario::parse_soil_scenario(text, "inline.toml");
        FAIL("parsing did not throw");
    } catch (const ScenarioError& error) {
        const ScenarioProblem problem = problem_for(error, "material.cohesion");
        CHECK(problem.line == 3);
        CHECK_THAT(problem.message, Contains("must be > 0 when friction_angle_deg = 0"));
    }
}

TEST_CASE("soil file: with extends, the text is the merged scenario and stands alone",
          "[scenario][soil]") {
    const std::string child = "extends = \"quick_2d.toml\"\n[output]\nduration = 1.5\n";
    const rockfall::scenario::SoilFile file =
        rockfall::scenario::parse_soil_scenario(child, "child.toml", samples);
    CHECK(file.scenario.output.duration == 1.5);
    CHECK(file.scenario.numerics.dimension == 2);
    CHECK(file.text.find("extends") == std::string::npos);
    // Read back from its own text, without the base file, it is the same scenario.
    const rockfall::scenario::SoilFile again =
        rockfall::scenario::parse_soil_scenario(file.text, "stored.toml", fs::path("/nonexistent"));
    CHECK(again.name == file.name);
    CHECK(again.scenario.output.duration == 1.5);
    CHECK(again.scenario.numerics.dimension == 2);
    CHECK(again.scenario.slope.wall.distance_from_toe ==
          file.scenario.slope.wall.distance_from_toe);
}

TEST_CASE("soil file: grid placement keys", "[scenario][soil]") {
    const rockfall::scenario::SoilFile file = rockfall::scenario::parse_soil_scenario(
        "[numerics]\nalign_grid = false\nboundary_reach = 0.5\n", "grid.toml");
    CHECK_FALSE(file.scenario.numerics.align_grid);
    CHECK(file.scenario.numerics.boundary_reach == 0.5);
    const rockfall::scenario::SoilFile defaults =
        rockfall::scenario::parse_soil_scenario("", "defaults.toml");
    CHECK(defaults.scenario.numerics.align_grid);
    CHECK(defaults.scenario.numerics.boundary_reach == 0.0);
    const ScenarioError error =
        parse_error("[numerics]\ncell_size = 0.1\nalign_grid = \"no\"\nboundary_reach = 0.7\n",
                    "bad_grid.toml");
    CHECK(error.problems().size() == 2);
    expect_at(error, "numerics.align_grid", 3, {"\"no\"", "must be true or false"});
    expect_at(error, "numerics.boundary_reach", 4, {"0.7", "must be in [0, 0.5]"});
    CHECK_THAT(std::string(error.what()), Contains("bad_grid.toml:4"));
}

TEST_CASE("soil file: numerics.flip and min_density_ratio", "[scenario][soil]") {
    CHECK(rockfall::scenario::parse_soil_scenario("", "defaults.toml").scenario.numerics.flip ==
          0.0);
    CHECK(rockfall::scenario::parse_soil_scenario("[numerics]\nflip = 0.99\n", "flip.toml")
              .scenario.numerics.flip == 0.99);
    const ScenarioError error =
        parse_error("[numerics]\nflip = 1.2\nmin_density_ratio = 1\n", "bad_flip.toml");
    REQUIRE(error.problems().size() == 2);
    expect_at(error, "numerics.flip", 2, {"1.2", "must be in [0, 1]"});
    expect_at(error, "numerics.min_density_ratio", 3, {"1", "must be in [0, 1)"});
    CHECK(rockfall::scenario::parse_soil_scenario("[numerics]\nmin_density_ratio = 0.5\n", "f.toml")
              .scenario.numerics.min_density_ratio == 0.5);
}

TEST_CASE("soil file: spring-backed wall keys", "[scenario][soil]") {
    const rockfall::scenario::SoilFile file = rockfall::scenario::parse_soil_scenario(
        "[boundaries]\nwall_support = \"spring\"\nwall_facing_mass = 30\nwall_stiffness = 2e6\n"
        "wall_damping_ratio = 0.7\n",
        "spring.toml");
    const rockfall::mpm::SoilBoundaries& b = file.scenario.boundaries;
    CHECK(b.wall_support == rockfall::mpm::WallSupport::spring);
    CHECK(b.wall_facing_mass == 30.0);
    CHECK(b.wall_stiffness == 2e6);
    CHECK(b.wall_damping_ratio == 0.7);
    CHECK(rockfall::scenario::parse_soil_scenario("", "rigid.toml")
              .scenario.boundaries.wall_support == rockfall::mpm::WallSupport::rigid);
    const ScenarioError error = parse_error(
        "[boundaries]\nwall_support = \"elastic\"\nwall_stiffness = 0\nwall_damping_ratio = 11\n",
        "bad_spring.toml");
    CHECK(error.problems().size() == 3);
    expect_at(error, "boundaries.wall_support", 2, {"must be one of \"rigid\", \"spring\""});
    expect_at(error, "boundaries.wall_stiffness", 3, {"0 Pa/m", "must be > 0"});
    expect_at(error, "boundaries.wall_damping_ratio", 4, {"must be in [0, 10]"});
    const ScenarioError no_wall = parse_error(
        "[slope.wall]\nenabled = false\n[boundaries]\nwall_support = \"spring\"\n", "no_wall.toml");
    expect_at(no_wall, "boundaries.wall_support", 4, {"must be \"rigid\" without a wall"});
}
