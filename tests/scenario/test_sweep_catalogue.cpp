// The shape keys of [sweep.rock]: catalogue entries and inline hulls as shape names,
// generated rocks of a target sphericity, the stored text that stands alone, and their errors.

#include "scenario/scenario_file.hpp"
#include "scenario_errors.hpp"

#include "risk/sampling.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using rockfall::scenario::ScenarioError;
using rockfall::scenario::ScenarioFile;
using rockfall::shapes::RockKind;
using rockfall::test::problem_for;

namespace {

const fs::path samples = ROCKFALL_SAMPLES_DIR;

// Scenario text that extends seed_sweep.toml, as if written in the samples folder (so that
// rocks/catalogue.toml is the sample catalogue).
ScenarioFile parse(const std::string& text) {
    return rockfall::scenario::parse_scenario_file("extends = \"seed_sweep.toml\"\n" + text,
                                                   (samples / "inline.toml").string(), samples);
}

ScenarioError parse_error(const std::string& text) {
    return rockfall::test::parse_error(parse, text);
}

std::vector<std::string> entry_names(const rockfall::risk::SweepSpec& spec) {
    std::vector<std::string> names;
    for (const auto& entry : spec.entries) names.push_back(entry->name);
    return names;
}

// The hull's vertices in a fixed order, to compare hulls whose vertex order may differ.
std::vector<std::array<double, 3>> sorted_vertices(const rockfall::shapes::ConvexPolyhedron& hull) {
    std::vector<std::array<double, 3>> points;
    for (const auto& v : hull.vertices) points.push_back({v.x(), v.y(), v.z()});
    std::sort(points.begin(), points.end());
    return points;
}

const std::string catalogue_choice =
    "[sweep.rock]\ncatalogue = \"rocks/catalogue.toml\"\n"
    "kind = { choice = [\"sphere\", \"cube\", \"flat\"], weights = [1, 2, 3] }\n";

}  // namespace

TEST_CASE("the catalogue sweep sample draws families, entries and generated rocks",
          "[scenario][sweep]") {
    const ScenarioFile file =
        rockfall::scenario::load_scenario(samples / "seed_sweep_catalogue.toml");
    const rockfall::risk::SweepSpec& spec = file.sweep;
    CHECK(spec.kinds == std::vector<RockKind>{RockKind::sphere});
    CHECK(entry_names(spec) ==
          std::vector<std::string>{"cube", "octahedron", "psi_0.72", "psi_0.85"});
    CHECK(spec.entry_weights == std::vector<double>{1.0, 1.0, 1.0, 1.0});
    CHECK(spec.generated_weight == 3.0);
    REQUIRE(spec.sphericity);
    CHECK(spec.sphericity->min == 0.7);
    CHECK(spec.sphericity->max == 0.9);
    // The stored text stands alone: the entries' hulls, not the catalogue's path.
    CHECK_THAT(file.text, Contains("[[sweep.rock.shapes]]\nname = \"psi_0.72\""));
    CHECK(file.text.find("catalogue =") == std::string::npos);
}

TEST_CASE("the resolved text reads back to the same shapes, the same way every time",
          "[scenario][sweep]") {
    const ScenarioFile file = parse(catalogue_choice);
    REQUIRE(entry_names(file.sweep) == std::vector<std::string>{"cube", "flat"});
    CHECK(file.sweep.kinds == std::vector<RockKind>{RockKind::sphere});
    CHECK(file.sweep.kind_weights == std::vector<double>{1.0});
    CHECK(file.sweep.entry_weights == std::vector<double>{2.0, 3.0});
    const ScenarioFile stored = rockfall::scenario::parse_scenario_file(file.text, "stored");
    const ScenarioFile again = rockfall::scenario::parse_scenario_file(file.text, "stored");
    REQUIRE(entry_names(stored.sweep) == entry_names(file.sweep));
    CHECK(stored.sweep.entry_weights == file.sweep.entry_weights);
    for (std::size_t i = 0; i < file.sweep.entries.size(); ++i) {
        // The same points (written in full precision); Qhull may list them in another order,
        // which is why sweeps run on the text read back, as replays do.
        CHECK(sorted_vertices(stored.sweep.entries[i]->hull) ==
              sorted_vertices(file.sweep.entries[i]->hull));
        CHECK(stored.sweep.entries[i]->hull.vertices == again.sweep.entries[i]->hull.vertices);
    }
    // Every sample of the read-back spec is a valid scenario with the entry's shape.
    for (std::int64_t i = 0; i < 30; ++i) {
        const auto inputs = rockfall::risk::draw_sample(stored.sweep, stored.scenario, i);
        const auto scenario = rockfall::risk::sample_scenario(stored.scenario, inputs);
        REQUIRE_NOTHROW(rockfall::scenario::validate_scenario(scenario));
        if (inputs.kind == RockKind::custom) {
            CHECK(scenario.rocks.front().rock.shape->name == inputs.shape);
        }
    }
}

TEST_CASE("generated rocks combine with other shapes or replace the kind draw",
          "[scenario][sweep]") {
    SECTION("with \"generated\" in kind's choice") {
        const ScenarioFile file = parse(catalogue_choice.substr(0, catalogue_choice.find("kind")) +
                                        "kind = { choice = [\"cube\", \"generated\"] }\n"
                                        "sphericity = { uniform = [0.8, 0.9] }\n");
        CHECK(file.sweep.kinds.empty());
        CHECK(entry_names(file.sweep) == std::vector<std::string>{"cube"});
        CHECK(file.sweep.generated_weight == 1.0);
        // Written out and read back: the same choice and targets.
        const ScenarioFile stored = rockfall::scenario::parse_scenario_file(file.text, "stored");
        CHECK(stored.sweep.generated_weight == 1.0);
        REQUIRE(stored.sweep.sphericity);
        CHECK(stored.sweep.sphericity->max == 0.9);
    }
    SECTION("sphericity alone, over the kind inherited from seed_sweep.toml") {
        const ScenarioFile file = parse("[sweep.rock]\nsphericity = { uniform = [0.8, 0.9] }\n");
        CHECK(file.sweep.kinds.empty());
        CHECK(file.sweep.entries.empty());
        CHECK(file.sweep.generated_weight == 1.0);
        const auto inputs = rockfall::risk::draw_sample(file.sweep, file.scenario, 3);
        CHECK(inputs.shape == "generated");
        CHECK(std::abs(inputs.sphericity - inputs.target_sphericity) < 1e-4);
    }
}

TEST_CASE("bad shape keys are reported with the key, the value and what is available",
          "[scenario][sweep]") {
    const ScenarioError unknown = parse_error(
        "[sweep.rock]\ncatalogue = \"rocks/catalogue.toml\"\n"
        "kind = { choice = [\"sphere\", \"boulder\"] }\n");
    const auto problem = problem_for(unknown, "sweep.rock.kind.choice[1]");
    CHECK_THAT(problem.message, Contains("\"boulder\": must be one of \"sphere\""));
    CHECK_THAT(problem.message, Contains("\"tetrahedron\", \"cube\", \"octahedron\""));
    CHECK(problem.line == 4);

    const ScenarioError no_catalogue =
        parse_error("[sweep.rock]\ncatalogue = \"rocks/none.toml\"\nkind = \"sphere\"\n");
    CHECK_THAT(problem_for(no_catalogue, "sweep.rock.catalogue").message,
               Contains("no such file or folder"));

    const ScenarioError entry_without_catalogue =
        parse_error("[sweep.rock]\nkind = { choice = [\"sphere\", \"cube\"] }\n");
    CHECK_THAT(problem_for(entry_without_catalogue, "sweep.rock.kind.choice[1]").message,
               Contains("give sweep.rock.catalogue"));

    const ScenarioError undrawn =
        parse_error("[sweep.rock]\ncatalogue = \"rocks/catalogue.toml\"\n");
    CHECK_THAT(problem_for(undrawn, "sweep.rock.catalogue").message,
               Contains("none of its entries is drawn"));

    const ScenarioError out_of_range =
        parse_error("[sweep.rock]\nsphericity = { uniform = [0.5, 0.99] }\n");
    CHECK(problem_for(out_of_range, "sweep.rock.sphericity").message ==
          "uniform [0.5, 0.99]: every target must lie in [0.3, 0.95] (Wadell sphericity; "
          "generated rocks reach it for every seed, without slivers)");

    const ScenarioError side_by_side =
        parse_error("[sweep.rock]\nkind = \"sphere\"\nsphericity = { uniform = [0.7, 0.8] }\n");
    CHECK_THAT(problem_for(side_by_side, "sweep.rock.sphericity").message,
               Contains("add \"generated\" to kind's choice"));

    const ScenarioError no_targets = parse_error("[sweep.rock]\nkind = \"generated\"\n");
    CHECK_THAT(problem_for(no_targets, "sweep.rock.kind").message,
               Contains("needs sweep.rock.sphericity"));

    const ScenarioError inline_names = parse_error(
        "[sweep.rock]\nkind = { choice = [\"sphere\", \"tet\"] }\n"
        "[[sweep.rock.shapes]]\nname = \"massive\"\nvertices = [[0, 0, 0], [1, 0, 0], "
        "[0, 1, 0], [0, 0, 1]]\n"
        "[[sweep.rock.shapes]]\nname = \"tet\"\nvertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], "
        "[0, 0, 1]]\n"
        "[[sweep.rock.shapes]]\nname = \"spare\"\nvertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], "
        "[0, 0, 1]]\n");
    CHECK_THAT(problem_for(inline_names, "sweep.rock.shapes[0].name").message,
               Contains("names a family or kind"));
    CHECK_THAT(problem_for(inline_names, "sweep.rock.shapes[2].name").message,
               Contains("\"spare\": is never drawn"));
}
