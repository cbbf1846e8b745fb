// Collision detection on several threads (engine/src/pair_dispatcher.hpp) changes nothing but
// the speed: a heap test, whose pile makes and drops hundreds of contact manifolds a step (rock
// pairs, rocks against the funnel's boxes through Bullet's compound algorithm, rocks on the
// floor or on the perforated sheet), and a cluster down seed 001's lined flume (the sphere
// layer's compound tiles, the sheet, the wall) end bit for bit as on one thread.

#include "flume_cluster.hpp"
#include "small_heap.hpp"

#include "engine/heap_test.hpp"
#include "engine/simulation.hpp"
#include "shapes/lining.hpp"

#include <catch2/catch.hpp>

#include <cstddef>
#include <memory>

using namespace rockfall;

namespace {

// 100 rocks of the small heap, half a second each for the fill and the settling.
engine::HeapScenario dispatcher_heap(bool sheet) {
    engine::HeapScenario heap = engine::test::small_heap(100);
    heap.max_fill_time = 0.5;
    heap.max_settle_time = 0.5;
    if (sheet) {
        shapes::PerforatedSheet perforated;
        perforated.hole_diameter = 0.02;
        perforated.hole_spacing = 0.03;
        heap.sheet = perforated;
    }
    return heap;
}

void require_identical(const engine::HeapOutcome& a, const engine::HeapOutcome& b) {
    REQUIRE(a.final_states.size() == b.final_states.size());
    CHECK(a.steps == b.steps);
    CHECK(a.fill_height == b.fill_height);
    std::size_t different = 0;
    for (std::size_t i = 0; i < a.final_states.size(); ++i) {
        const engine::RockState& s = a.final_states[i];
        const engine::RockState& t = b.final_states[i];
        const bool same = s.position == t.position && s.velocity == t.velocity &&
                          s.angular_velocity == t.angular_velocity &&
                          s.orientation.coeffs() == t.orientation.coeffs();
        different += same ? 0 : 1;
    }
    CHECK(different == 0);
}

}  // namespace

TEST_CASE("collision detection on several threads gives the one-thread heap bit for bit",
          "[verification]") {
    for (const bool sheet : {false, true}) {
        CAPTURE(sheet);
        engine::HeapScenario heap = dispatcher_heap(sheet);
        const engine::HeapOutcome one = engine::simulate_heap(heap, 7);
        REQUIRE(one.steps > 500);
        for (const int threads : {2, 3}) {
            CAPTURE(threads);
            heap.collision_threads = threads;
            require_identical(one, engine::simulate_heap(heap, 7));
        }
    }
}

TEST_CASE("a cluster down the lined flume is the same on one thread and on two", "[verification]") {
    // Seed 001's flume at 45 deg, the sphere layer on the incline and the sheet on the run-out,
    // 40 blocky rocks of C2's grading; 1.2 s of flow reaches the wall.
    engine::Scenario scenario = engine::test::flume_cluster(40);
    shapes::Lining lining;
    lining.spheres = shapes::SphereLayer{};
    lining.sheet = shapes::PerforatedSheet{};
    lining.sheet->segments = {1};
    scenario.slope.lining = std::make_shared<const shapes::Lining>(lining);
    scenario.numerics.max_time = 1.2;
    const engine::Outcome one = engine::simulate(scenario, 3);
    engine::RunOptions two_threads;
    two_threads.collision_threads = 2;
    const engine::Outcome two = engine::simulate(scenario, 3, two_threads);
    REQUIRE(one.rocks.size() == 40);
    CHECK(one.state_hash == two.state_hash);
    CHECK(one.coarse_steps == two.coarse_steps);
    CHECK(one.fine_steps == two.fine_steps);
}
