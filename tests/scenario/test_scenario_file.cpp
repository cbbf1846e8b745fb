#include "scenario/scenario_file.hpp"
#include "scenario_errors.hpp"

#include "shapes/lining.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using rockfall::scenario::ScenarioError;
using rockfall::scenario::ScenarioProblem;
using rockfall::shapes::RockKind;

using rockfall::test::line_of;
using rockfall::test::problem_for;

namespace {

ScenarioError load_error(const fs::path& file) {
    return rockfall::test::load_error(
        [](const fs::path& f) { rockfall::scenario::load_scenario(f); }, file);
}

const fs::path samples = ROCKFALL_SAMPLES_DIR;
const fs::path bad = fs::path(ROCKFALL_SCENARIO_DATA_DIR);

ScenarioError parse_error(const std::string& text) {
    return rockfall::test::parse_error(
        [](const std::string& t) { rockfall::scenario::parse_scenario(t, "inline.toml", samples); },
        text);
}

// Checks one reported line: key, value and rule text, file name and line.
void check_line(const ScenarioError& error, const std::string& key, const std::string& message,
                const fs::path& file, const std::string& marker) {
    const ScenarioProblem problem = problem_for(error, key);
    CHECK(problem.message == message);
    CHECK(problem.line == line_of(file, marker));
    CHECK(fs::path(problem.file).filename() == file.filename());
    const std::string expected = key + " = " + message + " (" + problem.file + ":" +
                                 std::to_string(line_of(file, marker)) + ")";
    CHECK_THAT(error.what(), Contains(expected));
}

}  // namespace

TEST_CASE("the seed slope sample loads with scenario A's values", "[scenario][scenario]") {
    const rockfall::scenario::ScenarioFile file =
        rockfall::scenario::load_scenario(samples / "seed_slope.toml");
    const rockfall::engine::Scenario& s = file.scenario;
    CHECK(s.name == "seed slope (scenario A): sphere 0.20 m, bars on");
    CHECK(s.slope.width == 5.0);
    REQUIRE(s.slope.segments.size() == 3);
    CHECK(s.slope.segments[0].length == 5.0);
    CHECK(s.slope.segments[0].angle_deg == 43.0);
    CHECK(s.slope.segments[1].length == 5.7);
    CHECK(s.slope.segments[1].angle_deg == 29.0);
    CHECK(s.slope.segments[2].length == 7.5);
    CHECK(s.slope.segments[2].angle_deg == 0.0);
    CHECK(s.slope.bars.enabled);
    CHECK(s.slope.bars.leg == 0.05);
    CHECK(s.slope.bars.thickness == 0.005);
    CHECK(s.slope.bars.spacing == 1.0);
    CHECK(s.slope.bars.segments == std::vector<int>{0, 1});
    CHECK(s.slope.wall.enabled);
    CHECK(s.slope.wall.distance_from_toe == 5.0);
    CHECK(s.wall_contact.model == rockfall::engine::WallContact::Model::hertz);
    CHECK(s.wall_contact.rock_youngs_modulus == 30e9);
    REQUIRE(s.rocks.size() == 1);
    CHECK(s.rocks[0].rock.kind == RockKind::sphere);
    CHECK(s.rocks[0].rock.size == 0.20);
    CHECK(s.rocks[0].rock.density == 2600.0);
    CHECK(s.rocks[0].release.distance == 0.5);
    CHECK(s.stations == std::vector<double>{0.0, 4.0});
    CHECK(s.numerics.time_step == 1e-3);
    CHECK(s.numerics.restitution_threshold == 0.05);
    CHECK(s.gravity == 9.81);
    // Without extends the text is the file as written, comments included.
    std::ifstream in(samples / "seed_slope.toml");
    const std::string written((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
    CHECK(file.text == written);
}

TEST_CASE("every shipped rockfall sample loads", "[scenario][scenario]") {
    // samples/soil holds soil-flow scenarios, a different format with a loader of its own;
    // samples/rocks holds shape catalogues.
    int count = 0;
    for (const auto& entry : fs::recursive_directory_iterator(samples)) {
        if (entry.path().extension() != ".toml") continue;
        if (entry.path().parent_path().filename() == "soil") continue;
        if (entry.path().parent_path().filename() == "rocks") continue;
        INFO(entry.path());
        CHECK_NOTHROW(rockfall::scenario::load_scenario(entry.path()));
        ++count;
    }
    CHECK(count >= 13);
}

TEST_CASE("the seed variants differ from the seed only in shape, size and bars",
          "[scenario][scenario]") {
    const rockfall::engine::Scenario seed =
        rockfall::scenario::load_scenario(samples / "seed_slope.toml").scenario;
    const std::pair<const char*, RockKind> kinds[] = {
        {"sphere", RockKind::sphere}, {"massive", RockKind::massive}, {"planar", RockKind::planar}};
    int count = 0;
    for (const auto& [kind_name, kind] : kinds) {
        for (const int size_cm : {20, 40}) {
            for (const bool bars : {true, false}) {
                const std::string stem = std::string(kind_name) + "_" + std::to_string(size_cm) +
                                         "cm_bars_" + (bars ? "on" : "off");
                INFO(stem);
                const rockfall::scenario::ScenarioFile variant =
                    rockfall::scenario::load_scenario(samples / "seed_slope" / (stem + ".toml"));
                rockfall::engine::Scenario expected = seed;
                expected.name = variant.scenario.name;
                expected.rocks[0].rock.kind = kind;
                expected.rocks[0].rock.size = size_cm / 100.0;
                expected.slope.bars.enabled = bars;
                CHECK(rockfall::scenario::format_scenario(variant.scenario) ==
                      rockfall::scenario::format_scenario(expected));
                // With extends the text is the resolved scenario, which reads back the same.
                CHECK(rockfall::scenario::format_scenario(
                          rockfall::scenario::parse_scenario(variant.text, stem)) ==
                      rockfall::scenario::format_scenario(variant.scenario));
                ++count;
            }
        }
    }
    CHECK(count == 12);
}

TEST_CASE("extends merges tables key by key and replaces arrays", "[scenario][scenario]") {
    const rockfall::engine::Scenario s = rockfall::scenario::parse_scenario(R"(
extends = "seed_slope.toml"
name = "shorter slope"
[slope]
width = 4.0
[[slope.segments]]
length = 3.0
angle_deg = 30.0
[[slope.segments]]
length = 6.0
angle_deg = 0.0
[slope.wall]
height = 2.0
)",
                                                                            "inline.toml", samples);
    CHECK(s.name == "shorter slope");
    CHECK(s.slope.width == 4.0);
    CHECK(s.slope.thickness == 0.5);  // kept from the base's [slope]
    REQUIRE(s.slope.segments.size() == 2);
    CHECK(s.slope.segments[0].length == 3.0);
    CHECK(s.slope.segments[1].length == 6.0);
    CHECK(s.slope.wall.height == 2.0);
    CHECK(s.slope.wall.distance_from_toe == 5.0);  // kept from the base's [slope.wall]
    CHECK(s.rocks[0].rock.size == 0.20);
}

TEST_CASE("an empty file gives the struct defaults", "[scenario][scenario]") {
    const rockfall::engine::Scenario s = rockfall::scenario::parse_scenario("", "empty.toml");
    CHECK(rockfall::scenario::format_scenario(s) ==
          rockfall::scenario::format_scenario(rockfall::engine::Scenario{}));
}

TEST_CASE("format_scenario reads back to an identical scenario", "[scenario][scenario]") {
    rockfall::engine::Scenario s;
    s.name = "quote \" backslash \\ tab\t";
    s.gravity = 9.80665;
    s.slope.segments = {{4.1, 37.3}, {0.1 + 0.2, 12.0}, {8.0, 0.0}};
    s.slope.bars.segments = {1};
    s.wall_contact.model = rockfall::engine::WallContact::Model::linear;
    s.wall_contact.linear_stiffness = 1.234567890123e8;
    s.rocks[0].rock.kind = RockKind::planar;
    s.rocks[0].release.velocity = {1.0 / 3.0, -2.0, 1e-7};
    s.rocks[0].release.random_orientation = true;
    s.rocks.push_back(s.rocks[0]);
    s.rocks[1].release.lateral = -1.5;
    s.numerics.time_step = 1e-5;
    s.numerics.restitution_threshold = 0.125;
    s.numerics.contact_slop = 0.5;
    s.numerics.bar_refinement = 4;
    const rockfall::engine::Scenario back = rockfall::scenario::parse_scenario(
        rockfall::scenario::format_scenario(s), "formatted.toml");
    CHECK(back.name == s.name);
    CHECK(back.gravity == s.gravity);
    CHECK(back.slope.segments[1].length == 0.1 + 0.2);
    CHECK(back.wall_contact.model == s.wall_contact.model);
    CHECK(back.wall_contact.linear_stiffness == s.wall_contact.linear_stiffness);
    REQUIRE(back.rocks.size() == 2);
    CHECK(back.rocks[0].rock.kind == RockKind::planar);
    CHECK(back.rocks[0].release.velocity == s.rocks[0].release.velocity);
    CHECK(back.rocks[0].release.random_orientation);
    CHECK(back.rocks[1].release.lateral == -1.5);
    CHECK(back.numerics.time_step == 1e-5);
    CHECK(back.numerics.restitution_threshold == 0.125);
    CHECK(back.numerics.contact_slop == 0.5);
    CHECK(back.numerics.bar_refinement == 4);
    CHECK(rockfall::scenario::format_scenario(back) == rockfall::scenario::format_scenario(s));
}

TEST_CASE("a TOML syntax error names file, line, column and toml++'s description",
          "[scenario][scenario][errors]") {
    const fs::path file = bad / "syntax_error.toml";
    const ScenarioError error = load_error(file);
    REQUIRE(error.problems().size() == 1);
    const ScenarioProblem& problem = error.problems()[0];
    CHECK(problem.line == line_of(file, "width = 5.0 m"));
    CHECK(problem.column > 0);
    CHECK_THAT(problem.message, Contains("TOML syntax error: "));
    CHECK(problem.message.size() > std::string("TOML syntax error: ").size());
    const std::regex location("syntax_error\\.toml:" + std::to_string(problem.line) +
                              ":[0-9]+\\)$");
    CHECK(std::regex_search(std::string(error.what()), location));
}

TEST_CASE("unknown keys are reported with a suggestion", "[scenario][scenario][errors]") {
    const fs::path file = bad / "unknown_key.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 2);
    const ScenarioProblem misspelt = problem_for(error, "rocks[0].densty");
    CHECK(misspelt.line == line_of(file, "densty"));
    CHECK_THAT(misspelt.message, Contains("2600.0: unknown key (did you mean 'density'?)"));
    CHECK_THAT(misspelt.message, Contains("allowed here: name, kind, size, density"));
    const ScenarioProblem table = problem_for(error, "weather");
    CHECK(table.line == line_of(file, "[weather]"));
    CHECK_THAT(table.message, Contains("unknown key"));
}

TEST_CASE("wrong types name the expected type, unit and range", "[scenario][scenario][errors]") {
    const fs::path file = bad / "wrong_type.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 3);
    check_line(error, "rocks[0].density", "\"heavy\": must be a number (kg/m3) in [500, 10000]",
               file, "density");
    check_line(error, "numerics.solver_iterations", "10.5: must be an integer in [1, 100]", file,
               "solver_iterations");
    check_line(error, "slope.side_walls.enabled", "\"yes\": must be true or false", file,
               "enabled");
}

TEST_CASE("an out-of-range value gives key, value, unit, range, file and line",
          "[scenario][scenario][errors]") {
    const fs::path file = bad / "out_of_range.toml";
    const ScenarioError error = load_error(file);
    REQUIRE(error.problems().size() == 1);
    const std::string expected = "rocks[0].density = -2500 kg/m3: must be in [500, 10000] (" +
                                 file.string() + ":" +
                                 std::to_string(line_of(file, "density = -2500")) + ")";
    CHECK(std::string(error.what()) == expected);
}

TEST_CASE("an unknown name lists the allowed ones", "[scenario][scenario][errors]") {
    const fs::path file = bad / "bad_enum.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 2);
    check_line(error, "wall_contact.model", "\"spring\": must be one of \"hertz\", \"linear\"",
               file, "spring");
    check_line(error, "rocks[0].kind",
               "\"cube\": must be one of \"sphere\", \"massive\", \"planar\"", file, "cube");
}

TEST_CASE("values that do not fit together are reported with the range they allow",
          "[scenario][scenario][errors]") {
    const fs::path file = bad / "bad_cross_field.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 5);
    check_line(error, "stations[2]",
               "9 m: must be in [0, 7.5] (a station past the end of the run-out is never crossed)",
               file, "stations");
    check_line(error, "slope.bars.segments[2]",
               "3: must be a segment index in [0, 3) (0 is the top segment)", file,
               "segments = [0, 1, 3]");
    check_line(error, "slope.wall.distance_from_toe",
               "7.2 m: must be in (0, 7] so that the wall (0.5 m thick) stands on the last segment "
               "(7.5 m long horizontally)",
               file, "distance_from_toe");
    check_line(error, "rocks[0].release.distance",
               "12 m: must be in [0, 10.7) so that the rock starts on the inclined part, above "
               "the toe",
               file, "distance = 12.0");
    const ScenarioProblem lateral = problem_for(error, "rocks[0].release.lateral");
    CHECK(lateral.line == line_of(file, "lateral"));
    CHECK_THAT(lateral.message, Contains("2.45 m: must be in [-2.4"));
    CHECK_THAT(lateral.message, Contains("bounding radius 0.1"));
}

TEST_CASE("a cross-field rule on a key left out points at its table",
          "[scenario][scenario][errors]") {
    const ScenarioError error = parse_error(R"(
[materials.wall]
restitution = 0.0

[[rocks]]
[rocks.material]
restitution = 0.0
)");
    REQUIRE(error.problems().size() == 1);
    CHECK(error.problems()[0].key == "rocks[0].material.restitution");
    CHECK(error.problems()[0].line == 7);
    CHECK_THAT(error.what(), Contains("mean restitution > 0"));
}

TEST_CASE("every problem in a file is reported at once, in line order",
          "[scenario][scenario][errors]") {
    const fs::path file = bad / "many_problems.toml";
    const ScenarioError error = load_error(file);
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"gravity", "gravity = -9.81"},
        {"slope.width", "width = 0.0"},
        {"slope.segments[0].angle_deg", "angle_deg = 95.0"},
        {"materials.wall.restitution", "restitution = 1.5"},
        {"materials.wall.frictoin", "frictoin"},
        {"rocks[0].density", "density = -2500"},
        {"numerics.time_step", "time_step = 0.5"},
        {"numerics.contact_slop", "contact_slop = -1.0"},
        {"numerics.bar_refinement", "bar_refinement = 0"},
    };
    REQUIRE(error.problems().size() == expected.size());
    const std::string what = error.what();
    CHECK(std::count(what.begin(), what.end(), '\n') == static_cast<long>(expected.size()) - 1);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        INFO(expected[i].first);
        CHECK(error.problems()[i].key == expected[i].first);
        CHECK(error.problems()[i].line == line_of(file, expected[i].second));
    }
    check_line(error, "slope.segments[0].angle_deg", "95 deg: must be in [0, 80]", file,
               "angle_deg = 95.0");
    check_line(error, "numerics.time_step", "0.5 s: must be in [1e-5, 0.01]", file,
               "time_step = 0.5");
    check_line(error, "gravity", "-9.81 m/s2: must be > 0", file, "gravity = -9.81");
    check_line(error, "numerics.contact_slop", "-1 g dt^2: must be in [0, 100]", file,
               "contact_slop = -1.0");
    check_line(error, "numerics.bar_refinement", "0: must be in [1, 64]", file,
               "bar_refinement = 0");
}

TEST_CASE("a missing file is one clear problem", "[scenario][scenario][errors]") {
    const fs::path file = bad / "does_not_exist.toml";
    const ScenarioError error = load_error(file);
    REQUIRE(error.problems().size() == 1);
    CHECK(std::string(error.what()) ==
          "cannot read the scenario file: no such file (" + file.string() + ")");
    CHECK_THAT(load_error(bad).what(), Contains("is a directory"));
}

TEST_CASE("extends problems name the file that caused them", "[scenario][scenario][errors]") {
    SECTION("missing base") {
        const fs::path file = bad / "extends_missing_base.toml";
        const ScenarioError error = load_error(file);
        REQUIRE(error.problems().size() == 1);
        CHECK(error.problems()[0].line == line_of(file, "extends"));
        CHECK_THAT(error.what(), Contains("no_such_base.toml"));
        CHECK_THAT(error.what(), Contains("no such file"));
    }
    SECTION("cycle") {
        const ScenarioError error = load_error(bad / "cycle_a.toml");
        REQUIRE(error.problems().size() == 1);
        CHECK_THAT(error.what(),
                   Contains("extends forms a cycle: cycle_a.toml -> cycle_b.toml -> cycle_a.toml"));
    }
    SECTION("bad value in the base") {
        const ScenarioError error = load_error(bad / "extends_bad_base.toml");
        check_line(error, "numerics.rest_speed", "-1 m/s: must be > 0", bad / "bad_base.toml",
                   "rest_speed");
    }
    SECTION("extends of the wrong type") {
        const ScenarioError error = parse_error("extends = 3\n");
        CHECK_THAT(error.what(), Contains("extends = 3: must be the path of a base scenario file"));
    }
}

TEST_CASE("scenarios built in code are held to the same rules", "[scenario][scenario][errors]") {
    CHECK_NOTHROW(rockfall::scenario::validate_scenario(rockfall::engine::Scenario{}));
    rockfall::engine::Scenario s;
    s.rocks.clear();
    s.slope.segments.clear();
    try {
        rockfall::scenario::validate_scenario(s);
        FAIL("no error");
    } catch (const ScenarioError& error) {
        CHECK(std::string(error.what()) ==
              "slope.segments = []: must have at least one segment\n"
              "rocks = []: must have at least one rock (or a [cluster])");
    }
}

TEST_CASE("the restitution threshold is a numerics key with its range",
          "[scenario][scenario][errors]") {
    const rockfall::engine::Scenario read = rockfall::scenario::parse_scenario(
        "[numerics]\nrestitution_threshold = 0.2\n", "threshold.toml");
    CHECK(read.numerics.restitution_threshold == 0.2);
    try {
        rockfall::scenario::parse_scenario("[numerics]\nrestitution_threshold = 0\n",
                                           "threshold.toml");
        FAIL("no error");
    } catch (const ScenarioError& error) {
        CHECK_THAT(error.what(),
                   Catch::Matchers::Contains("numerics.restitution_threshold = 0 m/s: must be in "
                                             "[0.001, 1]"));
    }
}

TEST_CASE("a lining is read, checked and written back", "[scenario][scenario][lining]") {
    const std::string text =
        "stations = [0.5]\n[[slope.segments]]\nlength = 1.82\nangle_deg = 45.0\n"
        "[[slope.segments]]\nlength = 1.82\nangle_deg = 0.0\n"
        "[slope]\nwidth = 0.6\n[slope.bars]\nenabled = false\nsegments = []\n"
        "[slope.wall]\ndistance_from_toe = 1.0\n"
        "[slope.lining.spheres]\nradius = 0.008\nspacing = 0.016\nsegments = [0]\n"
        "[slope.lining.sheet]\nsegments = [1]\n"
        "[[rocks]]\nsize = 0.05\n";
    const rockfall::engine::Scenario read = rockfall::scenario::parse_scenario(text, "lined.toml");
    REQUIRE(read.slope.lining);
    REQUIRE(read.slope.lining->spheres);
    CHECK(read.slope.lining->spheres->radius == 0.008);
    CHECK(read.slope.lining->spheres->segments == std::vector<int>{0});
    REQUIRE(read.slope.lining->sheet);
    CHECK(read.slope.lining->sheet->thickness == 0.0015);
    CHECK(read.slope.lining->sheet->segments == std::vector<int>{1});
    CHECK_FALSE(read.slope.lining->bumps);
    const std::string formatted = rockfall::scenario::format_scenario(read);
    const rockfall::engine::Scenario back =
        rockfall::scenario::parse_scenario(formatted, "formatted.toml");
    CHECK(rockfall::scenario::format_scenario(back) == formatted);

    // The geometry's own rule: spheres closer than touching.
    std::string bad = text;
    bad.replace(bad.find("spacing = 0.016"), 15, "spacing = 0.010");
    try {
        rockfall::scenario::parse_scenario(bad, "lined.toml");
        FAIL("no error");
    } catch (const ScenarioError& error) {
        CHECK_THAT(error.what(), Catch::Matchers::Contains("slope.lining.spheres"));
        CHECK_THAT(error.what(), Catch::Matchers::Contains("spacing"));
    }
}

TEST_CASE("a cluster or lining on a slope whose wall does not fit is reported, not built",
          "[scenario][scenario][lining][errors]") {
    // Found by fuzz_scenario: the cluster's box check built the whole slope, whose wall past
    // the end of the run-out failed the Slope's assertion.
    const std::string text =
        "[[slope.segments]]\nlength = 1.82\nangle_deg = 45.0\n"
        "[[slope.segments]]\nlength = 1.82\nangle_deg = 0.0\n"
        "[slope]\nwidth = 0.6\n[slope.wall]\ndistance_from_toe = 5.0\n"
        "[slope.lining.spheres]\n[cluster]\ncount = 10\n";
    try {
        rockfall::scenario::parse_scenario(text, "cluster.toml");
        FAIL("no error");
    } catch (const ScenarioError& error) {
        CHECK_THAT(error.what(), Contains("slope.wall.distance_from_toe"));
    }
}

TEST_CASE("angle bars and rock size must fit the slope", "[scenario][scenario][errors]") {
    const ScenarioError error = parse_error(R"(
[slope]
width = 0.3

[slope.bars]
leg = 0.05
thickness = 0.06
spacing = 0.04
segments = [1, 1]

[[rocks]]
size = 0.4
)");
    CHECK(error.problems().size() == 4);
    CHECK_THAT(problem_for(error, "slope.bars.thickness").message,
               Contains("0.06 m: must be < the leg (0.05 m)"));
    CHECK_THAT(problem_for(error, "slope.bars.spacing").message,
               Contains("0.04 m: must be > the leg (0.05 m)"));
    CHECK(problem_for(error, "slope.bars.segments[1]").message == "1: is listed twice");
    CHECK_THAT(problem_for(error, "rocks[0].size").message,
               Contains("0.4 m: a sphere this size (bounding radius 0.2 m) is wider than the "
                        "slope (0.3 m)"));
}
