// Samples of a cluster scenario (issue 13): whole releases drawn by the engine from the
// sample's seed, which comes from the same stream as a one-rock sample's.

#include "risk/sampling.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rockfall;

namespace {

engine::Scenario cluster_scenario() {
    engine::Scenario scenario;
    scenario.rocks.clear();
    scenario.cluster = engine::Cluster{};
    scenario.cluster->rock.density = 2620.0;
    return scenario;
}

}  // namespace

TEST_CASE("a cluster sample draws only its engine seed", "[risk][sampling][cluster]") {
    const engine::Scenario cluster = cluster_scenario();
    const engine::Scenario rock;  // the default scenario: one sphere
    risk::SweepSpec spec = risk::sweep_defaults(cluster);
    spec.seed = 42;
    risk::SweepSpec rock_spec = risk::sweep_defaults(rock);
    rock_spec.seed = 42;
    for (const std::int64_t index : {0, 1, 17}) {
        const risk::SampleInputs s = risk::draw_sample(spec, cluster, index);
        CHECK(s.index == index);
        CHECK(s.seed == risk::draw_sample(rock_spec, rock, index).seed);
        CHECK(s.kind == cluster.cluster->rock.kind);
        CHECK(s.density == 2620.0);
        CHECK(std::isnan(s.size));
        CHECK(std::isnan(s.release_distance));
        // The scenario a cluster sample runs is the cluster scenario itself.
        const engine::Scenario run = risk::sample_scenario(cluster, s);
        CHECK(run.rocks.empty());
        REQUIRE(run.cluster);
        CHECK(run.cluster->grading.count == cluster.cluster->grading.count);
    }
    CHECK(risk::draw_sample(spec, cluster, 0).seed != risk::draw_sample(spec, cluster, 1).seed);
}

TEST_CASE("a cluster sweep spec is checked for its sample count only",
          "[risk][sampling][cluster]") {
    const engine::Scenario cluster = cluster_scenario();
    risk::SweepSpec spec = risk::sweep_defaults(cluster);
    CHECK(risk::find_problems(spec, cluster).empty());
    spec.samples = 0;
    const std::vector<risk::SweepProblem> problems = risk::find_problems(spec, cluster);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].key == "sweep.samples");
}

TEST_CASE("each rock of a cluster release has its inputs", "[risk][sampling][cluster]") {
    engine::Scenario scenario = cluster_scenario();
    scenario.rocks = {engine::RockRelease{}};  // a marked rock beside the cluster
    scenario.rocks[0].rock.size = 0.05;
    scenario.rocks[0].rock.density = 2000.0;
    std::vector<engine::RockOutcome> outcomes(3);
    outcomes[0].size = 0.05;
    outcomes[1].size = 0.04;
    outcomes[2].size = 0.07;
    const risk::SampleInputs inputs =
        risk::draw_sample(risk::sweep_defaults(scenario), scenario, 0);
    const std::vector<risk::RockInputs> rocks = risk::rock_inputs(scenario, inputs, outcomes);
    REQUIRE(rocks.size() == 3);
    CHECK_FALSE(rocks[0].cluster);
    CHECK(rocks[0].kind == scenario.rocks[0].rock.kind);
    CHECK(rocks[0].mass == Approx(2000.0 * M_PI / 6.0 * 0.05 * 0.05 * 0.05));
    CHECK(rocks[1].cluster);
    CHECK(rocks[1].kind == scenario.cluster->rock.kind);
    CHECK(rocks[2].size == 0.07);
    CHECK(rocks[2].mass == Approx(2620.0 * M_PI / 6.0 * 0.07 * 0.07 * 0.07));
}
