#include "scenario/scenario_file.hpp"
#include "scenario_errors.hpp"

#include "risk/random_release.hpp"
#include "risk/sampling.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using rockfall::risk::Distribution;
using rockfall::risk::SweepSpec;
using rockfall::scenario::ScenarioError;
using rockfall::scenario::ScenarioFile;
using rockfall::shapes::RockKind;
using rockfall::test::line_of;
using rockfall::test::problem_for;
using Family = Distribution::Family;

namespace {

const fs::path samples = ROCKFALL_SAMPLES_DIR;
const fs::path bad = fs::path(ROCKFALL_SCENARIO_DATA_DIR);
constexpr double infinity = std::numeric_limits<double>::infinity();

ScenarioError load_error(const fs::path& file) {
    return rockfall::test::load_error(
        [](const fs::path& f) { rockfall::scenario::load_scenario(f); }, file);
}

// The error of scenario text that extends the seed slope.
ScenarioError text_error(const std::string& text) {
    return rockfall::test::parse_error(
        [](const std::string& t) {
            rockfall::scenario::parse_scenario_file("extends = \"seed_slope.toml\"\n" + t,
                                                    "inline.toml", samples);
        },
        text);
}

// The problem for `key` has this message and sits on the line containing `marker`.
void expect(const ScenarioError& error, const std::string& key, const std::string& message,
            const fs::path& file, const std::string& marker) {
    const rockfall::scenario::ScenarioProblem problem = problem_for(error, key);
    CHECK(problem.message == message);
    CHECK(problem.line == line_of(file, marker));
    CHECK(fs::path(problem.file).filename() == file.filename());
}

bool same(const Distribution& a, const Distribution& b) {
    return a.family == b.family && a.value == b.value && a.mean == b.mean && a.sd == b.sd &&
           a.min == b.min && a.max == b.max && a.mode == b.mode;
}

bool same(const SweepSpec& a, const SweepSpec& b) {
    bool zones = a.zones.size() == b.zones.size();
    for (std::size_t i = 0; zones && i < a.zones.size(); ++i) {
        zones = a.zones[i].name == b.zones[i].name && a.zones[i].weight == b.zones[i].weight &&
                same(a.zones[i].distance, b.zones[i].distance) &&
                same(a.zones[i].lateral, b.zones[i].lateral);
    }
    return zones && a.method == b.method && a.seed == b.seed && a.samples == b.samples &&
           a.kinds == b.kinds && a.kind_weights == b.kind_weights && same(a.size, b.size) &&
           same(a.density, b.density) && same(a.friction, b.friction) &&
           same(a.restitution, b.restitution) && same(a.rolling_resistance, b.rolling_resistance) &&
           a.lateral_margin == b.lateral_margin && same(a.speed, b.speed) && same(a.spin, b.spin) &&
           a.random_orientation == b.random_orientation;
}

Distribution uniform(double min, double max) {
    Distribution d;
    d.family = Family::uniform;
    d.min = min;
    d.max = max;
    return d;
}

}  // namespace

TEST_CASE("the seed sweep sample draws the population of the 200-rock runout check",
          "[scenario][sweep]") {
    const ScenarioFile file = rockfall::scenario::load_scenario(samples / "seed_sweep.toml");
    const SweepSpec& spec = file.sweep;
    REQUIRE(file.has_sweep);
    CHECK(spec.method == SweepSpec::Method::monte_carlo);
    CHECK(spec.samples == 2000);
    CHECK(spec.seed == 1);
    // risk::random_rock_scenario's defaults: the seed's three shapes equally often, sizes
    // uniform in [0.2, 0.4] m, lateral uniform where the rock fits with a 5 cm margin, random
    // orientation, everything else the base rock's.
    const rockfall::risk::RandomRockRanges ranges;
    CHECK(spec.kinds == ranges.kinds);
    CHECK(spec.kind_weights == std::vector<double>{1.0, 1.0, 1.0});
    CHECK(same(spec.size, uniform(ranges.min_size, ranges.max_size)));
    CHECK(spec.lateral_margin == ranges.lateral_margin);
    CHECK(spec.random_orientation);
    REQUIRE(spec.zones.size() == 1);
    CHECK(spec.zones[0].name == "crest");
    CHECK(same(spec.zones[0].distance, rockfall::risk::fixed(0.5)));
    CHECK(same(spec.zones[0].lateral, uniform(-2.5, 2.5)));
    CHECK(same(spec.density, rockfall::risk::fixed(2600.0)));
    CHECK(same(spec.friction, rockfall::risk::fixed(0.6)));
    CHECK(same(spec.speed, rockfall::risk::fixed(0.0)));
    for (std::int64_t i = 0; i < 30; ++i) {
        const auto inputs = rockfall::risk::draw_sample(spec, file.scenario, i);
        CHECK_NOTHROW(rockfall::scenario::validate_scenario(
            rockfall::risk::sample_scenario(file.scenario, inputs)));
    }
}

TEST_CASE("the Latin hypercube sample overrides whole distributions of its base",
          "[scenario][sweep]") {
    const ScenarioFile file = rockfall::scenario::load_scenario(samples / "seed_sweep_lhs.toml");
    const SweepSpec& spec = file.sweep;
    CHECK(spec.method == SweepSpec::Method::latin_hypercube);
    CHECK(spec.samples == 1000);
    CHECK(spec.seed == 7);
    // Inherited from seed_sweep.toml.
    CHECK(spec.kinds.size() == 3);
    CHECK(spec.random_orientation);
    // An inline table replaces the base's (uniform) instead of merging into it.
    CHECK(spec.size.family == Family::lognormal);
    CHECK(spec.size.mean == 0.3);
    CHECK(spec.size.sd == 0.08);
    CHECK(spec.size.min == 0.15);
    CHECK(spec.size.max == 0.6);
    CHECK(spec.density.family == Family::normal);
    CHECK(spec.restitution.family == Family::triangular);
    CHECK(spec.restitution.mode == 0.3);
    REQUIRE(spec.zones.size() == 2);
    CHECK(spec.zones[0].name == "crest");
    CHECK(spec.zones[0].weight == 3.0);
    CHECK(spec.zones[1].name == "upper bench");
    CHECK(spec.zones[1].lateral.family == Family::normal);
    CHECK(spec.zones[1].lateral.min == -infinity);
}

TEST_CASE("the resolved text of a sweep reads back to the same spec", "[scenario][sweep]") {
    for (const char* name :
         {"seed_sweep.toml", "seed_sweep_lhs.toml", "seed_sweep_calibrated_wall.toml"}) {
        INFO(name);
        const ScenarioFile file = rockfall::scenario::load_scenario(samples / name);
        CHECK_THAT(file.text, Contains("[sweep]"));
        const ScenarioFile again =
            rockfall::scenario::parse_scenario_file(file.text, "stored.toml");
        CHECK(again.has_sweep);
        CHECK(same(again.sweep, file.sweep));
        CHECK(rockfall::scenario::format_scenario(again.scenario) ==
              rockfall::scenario::format_scenario(file.scenario));
    }
}

TEST_CASE("the calibrated-wall sweep differs from the seed sweep in the wall facing only",
          "[scenario][sweep]") {
    const ScenarioFile seed = rockfall::scenario::load_scenario(samples / "seed_sweep.toml");
    ScenarioFile calibrated =
        rockfall::scenario::load_scenario(samples / "seed_sweep_calibrated_wall.toml");
    CHECK(calibrated.scenario.wall_contact.wall_youngs_modulus == 2.95e9);
    CHECK(same(calibrated.sweep, seed.sweep));
    calibrated.scenario.wall_contact.wall_youngs_modulus =
        seed.scenario.wall_contact.wall_youngs_modulus;
    calibrated.scenario.name = seed.scenario.name;
    CHECK(rockfall::scenario::format_scenario(calibrated.scenario) ==
          rockfall::scenario::format_scenario(seed.scenario));
}

TEST_CASE("a scenario without [sweep] has the spec that varies nothing", "[scenario][sweep]") {
    const ScenarioFile file = rockfall::scenario::load_scenario(samples / "seed_slope.toml");
    CHECK_FALSE(file.has_sweep);
    CHECK(same(file.sweep, rockfall::risk::sweep_defaults(file.scenario)));
    CHECK(file.sweep.kinds == std::vector<RockKind>{RockKind::sphere});
    CHECK(same(file.sweep.size, rockfall::risk::fixed(0.2)));
    // A [sweep] with only some keys keeps the base rock's values for the others.
    const ScenarioFile partial = rockfall::scenario::parse_scenario_file(
        "extends = \"seed_slope.toml\"\n[sweep.rock]\ndensity = { uniform = [2500, 2700] }\n",
        "inline.toml", samples);
    CHECK(partial.has_sweep);
    CHECK(same(partial.sweep.density, uniform(2500.0, 2700.0)));
    CHECK(same(partial.sweep.size, rockfall::risk::fixed(0.2)));
    CHECK(same(partial.sweep.zones.at(0).distance, rockfall::risk::fixed(0.5)));
}

TEST_CASE("every kind of bad distribution is reported with its key and line", "[scenario][sweep]") {
    const fs::path file = bad / "sweep_bad_distributions.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 10);
    expect(error, "sweep.rock.size",
           "\"big\": must be a number (m) or a distribution: { uniform = [min, max] }, { normal "
           "= { mean = ..., sd = ... }, min = ..., max = ... }, { lognormal = { mean = ..., sd = "
           "... }, min = ..., max = ... } or { triangular = [min, mode, max] }",
           file, "size = \"big\"");
    expect(error, "sweep.rock.density.normal",
           "{...}: must give sd (the standard deviation of the value itself, before any "
           "truncation)",
           file, "density =");
    CHECK_THAT(problem_for(error, "sweep.rock.material.friction.uniform").message,
               Contains("must be [min, max], two numbers"));
    expect(error, "sweep.rock.material.restitution",
           "triangular [0.2, 0.5, 0.4]: mode = 0.5: must be in [min, max] = [0.2, 0.4]", file,
           "restitution =");
    CHECK_THAT(problem_for(error, "sweep.rock.material.rolling_resistance.max").message,
               Contains("truncates a normal or lognormal only; a uniform distribution gives its "
                        "bounds in its array"));
    expect(error, "sweep.release.speed",
           "normal (mean 1, sd 0.5) m/s: every value must be >= 0 (a speed along the downslope "
           "tangent); truncate it with min = 0",
           file, "speed =");
    CHECK_THAT(problem_for(error, "sweep.release.spin").message, Contains("names no distribution"));
    CHECK_THAT(problem_for(error, "sweep.release.spin.gamma").message, Contains("unknown key"));
    expect(error, "sweep.release.zones[0].distance",
           "lognormal (mean 0.5, sd -0.1) m: sd = -0.1: must be > 0 and finite", file,
           "distance =");
    expect(error, "sweep.release.zones[0].lateral",
           "{...}: names 2 distributions (uniform, normal): give one", file, "lateral =");
}

TEST_CASE("unknown keys in [sweep] are reported with the key meant", "[scenario][sweep]") {
    const fs::path file = bad / "sweep_unknown_keys.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 6);
    CHECK_THAT(problem_for(error, "sweep.sample").message,
               Contains("unknown key (did you mean 'samples'?)"));
    CHECK_THAT(problem_for(error, "sweep.rock.kind.choise").message,
               Contains("did you mean 'choice'?"));
    CHECK_THAT(problem_for(error, "sweep.rock.kind").message,
               Contains("must list the shapes to draw"));
    CHECK_THAT(problem_for(error, "sweep.rock.sizes").message, Contains("did you mean 'size'?"));
    CHECK(problem_for(error, "sweep.release.spin.normal.max").line == line_of(file, "spin ="));
    CHECK_THAT(problem_for(error, "sweep.release.zones[0].lateral.mode").message,
               Contains("unknown key; allowed here: uniform, normal, lognormal, triangular, min, "
                        "max"));
}

TEST_CASE("sweep values are judged by the scenario's own ranges and rules", "[scenario][sweep]") {
    const fs::path file = bad / "sweep_ranges.toml";
    const ScenarioError error = load_error(file);
    CHECK(error.problems().size() == 12);
    expect(error, "sweep.method",
           "\"quasi_random\": must be one of \"monte_carlo\", "
           "\"latin_hypercube\"",
           file, "method =");
    expect(error, "sweep.samples", "0: must be an integer in [1, 9223372036854775807]", file,
           "samples =");
    expect(error, "sweep.seed", "-3: must be an integer in [0, 9223372036854775807]", file,
           "seed =");
    expect(error, "sweep.lateral_margin", "-0.1 m: must be >= 0", file, "lateral_margin =");
    CHECK_THAT(
        problem_for(error, "sweep.rock.kind.choice[2]").message,
        Contains("\"cube\": must be one of \"sphere\", \"massive\", \"planar\", \"custom\""));
    // Range of rocks.size, [0.01, 10] m, applied to the support's lower end.
    expect(error, "sweep.rock.size",
           "uniform [0.005, 0.4] m: its lower end 0.005 m: must be in [0.01, 10]", file, "size =");
    // An untruncated normal reaches every value.
    CHECK_THAT(problem_for(error, "sweep.rock.density").message,
               Contains("its lower end -inf kg/m3: must be finite and in [500, 10000] (truncate "
                        "the distribution with min and max)"));
    // A cross-field rule of the scenario: the wall contact needs a mean restitution > 0.
    expect(error, "sweep.rock.material.restitution",
           "uniform [0, 0.5]: its lower end 0: must be > 0 when materials.wall.restitution is 0 "
           "(the wall contact's damping needs a mean restitution > 0)",
           file, "restitution = {");
    expect(error, "sweep.release.zones[0].weight", "0: must be > 0", file, "weight = 0");
    expect(error, "sweep.release.zones[0].distance",
           "uniform [10, 12] m: its upper end 12 m: must be in [0, 10.7) so that the rock starts "
           "on the inclined part, above the toe",
           file, "distance =");
    CHECK_THAT(problem_for(error, "sweep.release.zones[1].name").message,
               Contains("zone 0 has this name too"));
}

TEST_CASE("rocks that do not fit across the slope with their margins are reported",
          "[scenario][sweep]") {
    const fs::path file = bad / "sweep_too_wide.toml";
    const ScenarioError error = load_error(file);
    // A 3 m planar slab has a bounding radius of 2.4 m: it fits in the 5 m slope, but not with
    // 1 m margins; a 3 m sphere (radius 1.5 m) just does.
    REQUIRE(error.problems().size() == 1);
    expect(error, "sweep.rock.size", error.problems().front().message, file, "size =");
    CHECK_THAT(error.problems().front().message,
               Contains("a planar of 3 m") && Contains("lateral margin of 1 m") &&
                   Contains("does not fit across the slope (5 m wide)"));
}

TEST_CASE("shape choices need names and matching weights", "[scenario][sweep]") {
    const ScenarioError mismatch = text_error(
        "[sweep.rock]\nkind = { choice = [\"sphere\", \"planar\"], weights = [1, 1, 1] }\n");
    CHECK(problem_for(mismatch, "sweep.rock.kind").message ==
          "2 shapes and 3 weights: must give one weight per shape");
    CHECK(problem_for(mismatch, "sweep.rock.kind").line == 3);
    const ScenarioError custom = text_error("[sweep.rock]\nkind = \"custom\"\n");
    CHECK_THAT(problem_for(custom, "sweep.rock.kind").message,
               Contains("the base rock's custom shape") && Contains("rocks[0] has none"));
    const ScenarioError not_table = text_error("sweep = 3\n");
    CHECK(problem_for(not_table, "sweep").message == "3: must be a table ([sweep])");
}

TEST_CASE("a sweep over a bad base reports both at once", "[scenario][sweep]") {
    const ScenarioError error = text_error("gravity = -1\n[sweep]\nsample = 10\n");
    CHECK_THAT(problem_for(error, "gravity").message, Contains("must be > 0"));
    CHECK_THAT(problem_for(error, "sweep.sample").message, Contains("unknown key"));
}

TEST_CASE("validate_sweep holds specs built in code to the file's rules", "[scenario][sweep]") {
    const rockfall::engine::Scenario base;
    SweepSpec spec = rockfall::risk::sweep_defaults(base);
    CHECK_NOTHROW(rockfall::scenario::validate_sweep(spec, base));
    spec.size = uniform(0.2, 20.0);
    spec.samples = 0;
    try {
        rockfall::scenario::validate_sweep(spec, base);
        FAIL("validate_sweep accepted a 20 m rock");
    } catch (const ScenarioError& error) {
        CHECK(problem_for(error, "sweep.rock.size").message ==
              "uniform [0.2, 20] m: its upper end 20 m: must be in [0.01, 10]");
        CHECK(problem_for(error, "sweep.samples").message == "0: must be >= 1");
        CHECK(error.problems().size() == 2);
    }
    // The base itself must be valid.
    rockfall::engine::Scenario broken = base;
    broken.gravity = 0.0;
    CHECK_THROWS_AS(
        rockfall::scenario::validate_sweep(rockfall::risk::sweep_defaults(base), broken),
        ScenarioError);
}
