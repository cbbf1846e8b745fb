// A cluster released from a box (issue 13): drawn from its grading by the seed, packed and
// settled behind a gate, released at t = 0, and run until every rock is at rest.

#include "engine/simulation.hpp"
#include "shapes/release_box.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <vector>

using namespace rockfall;
using namespace rockfall::engine;

namespace {

// Seed 001's flume at 45 deg with the wall 0.5 m past the toe and a cluster of `count` rocks
// of C2's grading in a 0.4 m box at the top.
Scenario flume_cluster(int count) {
    Scenario scenario;
    scenario.slope.segments = {{1.82, 45.0}, {1.82, 0.0}};
    scenario.slope.width = 0.6;
    scenario.slope.thickness = 0.1;
    scenario.slope.bars.enabled = false;
    scenario.slope.bars.segments.clear();
    scenario.slope.side_walls.height = 0.3;
    scenario.slope.side_walls.thickness = 0.01;
    scenario.slope.wall.distance_from_toe = 0.5;
    scenario.slope.wall.height = 0.3;
    scenario.slope.wall.thickness = 0.2;
    const Material rock_material{0.4, 0.3, 0.02};
    scenario.materials.slope = rock_material;
    scenario.stations = {0.0};
    scenario.rocks.clear();
    Cluster cluster;
    cluster.grading = shapes::seed001_c2();
    cluster.grading.count = count;
    cluster.rock.kind = shapes::RockKind::massive;
    cluster.rock.density = 2620.0;
    cluster.rock.material = rock_material;
    scenario.cluster = cluster;
    scenario.numerics.max_time = 10.0;
    return scenario;
}

}  // namespace

TEST_CASE("a cluster released from its box runs down the flume and comes to rest",
          "[engine][cluster][verification]") {
    const Scenario scenario = flume_cluster(20);
    std::map<int, RockState> start;
    RunOptions options;
    options.trajectory = [&](int index, const RockState& s) {
        if (s.time == 0.0) start[index] = s;
    };
    const Outcome outcome = simulate(scenario, 7, options);
    REQUIRE(outcome.rocks.size() == 20);
    // At the gate's opening every rock is inside the box and nearly still (settled).
    const shapes::Slope slope(scenario.slope);
    const shapes::OrientedBox box = shapes::release_box_region(slope, scenario.cluster->box);
    REQUIRE(start.size() == 20);
    for (const auto& [index, s] : start) {
        INFO("rock " << index);
        const Vec3 local = box.rotation.transpose() * (s.position - box.center);
        CHECK(std::abs(local.x()) <= box.half_extents.x() + 1e-3);
        CHECK(std::abs(local.y()) <= box.half_extents.y() + 1e-3);
        CHECK(s.velocity.norm() < 0.5);
    }
    int at_rest = 0;
    int hit_wall = 0;
    for (const RockOutcome& rock : outcome.rocks) {
        CHECK(rock.stop != StopReason::numerical_failure);
        at_rest += rock.stop == StopReason::at_rest ? 1 : 0;
        hit_wall += rock.wall_hits.empty() ? 0 : 1;
        CHECK(rock.reach > 0.0);  // every rock left the box and passed the toe
        CHECK(rock.final_state.position.x() < slope.wall_x());
    }
    CHECK(at_rest == 20);
    // The front hits the wall; the rocks behind come to rest against it and each other
    // (6 of the 20 touch the wall with seed 7).
    CHECK(hit_wall >= 1);

    // Reproducible from the seed; another seed draws another cluster.
    const Outcome again = simulate(scenario, 7);
    CHECK(again.state_hash == outcome.state_hash);
    const Outcome other = simulate(scenario, 8);
    CHECK(other.state_hash != outcome.state_hash);
}
