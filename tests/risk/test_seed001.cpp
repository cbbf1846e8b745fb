// Seed 001's published numbers and the comparison of simulated runs with them.

#include "risk/parallel.hpp"
#include "risk/seed001.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace seed001 = rockfall::risk::seed001;
using seed001::Cluster;
using seed001::Marked;
using seed001::Shape;

TEST_CASE("seed 001's Table 2 and speeds read back as printed", "[risk][seed001]") {
    // Spot checks against the paper's Table 2 and text (the 45 deg cells its text quotes).
    CHECK(seed001::published_force(Shape::cube, Cluster::c2, 45) == 340.8);
    CHECK(seed001::published_force(Shape::octahedron, Cluster::c2, 45) == 380.7);
    CHECK(seed001::published_force(Marked::green, Cluster::c2, 45) == 334.9);
    CHECK(seed001::published_force(Marked::blue, Cluster::c2, 45) == 373.7);
    CHECK(seed001::published_force(Marked::red, Cluster::c1, 30) == 200.3);
    CHECK(seed001::published_force(Marked::red, Cluster::c2, 60) == 838.3);
    CHECK(seed001::published_force(Shape::tetrahedron, Cluster::c1, 30) == 60.4);
    CHECK(seed001::published_force(Shape::sphere, Cluster::c2, 60) == 825.7);
    CHECK(seed001::published_speed_at_1_4m(Marked::red, Cluster::c1, 30) == 3.9);
    CHECK(seed001::published_speed_at_1_4m(Marked::yellow, Cluster::c2, 30) == 2.8);
    CHECK(seed001::published_speed_at_1_4m(Marked::blue, Cluster::c2, 45) == 4.5);
    CHECK(seed001::published_speed_at_1_4m(Marked::green, Cluster::c1, 60) == 5.6);
    CHECK_THROWS_AS(seed001::published_force(Shape::cube, Cluster::c1, 40), std::invalid_argument);
    CHECK(seed001::sphericity(Shape::tetrahedron) == 0.67);
    CHECK(seed001::sphericity(Marked::yellow) == 0.72);
}

TEST_CASE("Table 2 itself shows the paper's trends", "[risk][seed001]") {
    const std::vector<seed001::Trend> trends = seed001::trends(seed001::published_grid());
    // 6 sphericity orders, 2 angle effects, 12 cluster comparisons.
    REQUIRE(trends.size() == 20);
    for (const seed001::Trend& t : trends) {
        INFO(t.label);
        CHECK(t.published_holds);
        CHECK(t.holds);
    }
}

TEST_CASE("a trend fails when the simulated means break it", "[risk][seed001]") {
    seed001::ForceGrid grid = seed001::published_grid();
    std::swap(grid[0][0][1], grid[0][0][2]);  // C1, 30 deg: cube above octahedron
    grid[1][2][3] = std::nan("");             // C2, 60 deg, sphere: no value
    int failed = 0;
    for (const seed001::Trend& t : seed001::trends(grid)) {
        CHECK(t.published_holds);
        if (!t.holds) ++failed;
    }
    // The swap breaks C1 30 deg's order and puts C1's cube (now 145.4 N) above C2's (118.4 N);
    // C2 60 deg's order, C2's angle effect and "C2 above C1" for the sphere at 60 deg lose a
    // value.
    CHECK(failed == 5);
}

TEST_CASE("runs are pooled into Table 2's cells", "[risk][seed001]") {
    std::vector<seed001::RunRecord> runs;
    // Two seeds of the cube row, C2, 45 deg: four marked rocks each, one never at the wall.
    for (const std::uint64_t seed : {1u, 2u}) {
        seed001::RunRecord run;
        run.cluster = Cluster::c2;
        run.angle_deg = 45;
        run.shape = Shape::cube;
        run.seed = seed;
        run.rocks = {{"red", 300.0, 900.0, 4.0},
                     {"blue", 340.0, 900.0, 4.0},
                     {"green", 380.0, 900.0, 4.0},
                     {"yellow", std::nan(""), std::nan(""), 4.0}};
        runs.push_back(run);
    }
    // One physical run, C1, 30 deg: the red rock at the wall, the yellow one short of 1.4 m.
    seed001::RunRecord physical;
    physical.cluster = Cluster::c1;
    physical.angle_deg = 30;
    physical.seed = 1;
    physical.rocks = {{"red", 210.0, 800.0, 3.0}, {"yellow", 50.0, 100.0, std::nan("")}};
    runs.push_back(physical);

    const seed001::Reproduction r = seed001::compare(runs);
    CHECK(r.seeds == 2);
    REQUIRE(r.numerical_forces.size() == 24);
    REQUIRE(r.physical_forces.size() == 24);
    REQUIRE(r.speeds.size() == 24);
    // C2 is the second cluster, 45 deg the second angle, cube the second shape.
    const seed001::Comparison& cube = r.numerical_forces[(3 + 1) * 4 + 1];
    CHECK(cube.label == "peak force, cube, C2, 45 deg");
    CHECK(cube.published == 340.8);
    CHECK(cube.expected == 8);
    REQUIRE(cube.simulated.size() == 6);
    CHECK(cube.summary().mean == Approx(340.0));
    CHECK(cube.relative_error() == Approx((340.0 - 340.8) / 340.8));
    CHECK(cube.within());
    const seed001::Comparison& red = r.physical_forces[0 * 4 + 3];
    CHECK(red.label == "peak force, red, C1, 30 deg");
    CHECK(red.simulated == std::vector<double>{210.0});
    CHECK(red.within());  // 210 against 200.3: +4.8 %
    const seed001::Comparison& yellow = r.physical_forces[0];
    CHECK(yellow.simulated == std::vector<double>{50.0});
    CHECK(yellow.relative_error() == Approx((50.0 - 60.9) / 60.9));
    CHECK(yellow.within());  // -18 %, within 25 %
    CHECK(r.speeds[0].expected == 1);
    CHECK(r.speeds[0].simulated.empty());  // yellow did not travel 1.4 m
    CHECK_FALSE(r.speeds[0].within());
    CHECK(r.speeds[3].simulated == std::vector<double>{3.0});
    CHECK_FALSE(r.speeds[3].within());  // 3.0 against 3.9: -23 %, beyond 20 %
    // A cell no run reached has nothing.
    CHECK(r.numerical_forces[0].expected == 0);
    CHECK_FALSE(r.numerical_forces[0].within());
}

TEST_CASE("run_parallel runs every job once and rethrows a job's error", "[risk][parallel]") {
    std::vector<int> hits(100, 0);
    std::atomic<std::int64_t> last_done{0};
    rockfall::risk::run_parallel(
        100, 3, [&hits](std::int64_t i) { ++hits[static_cast<std::size_t>(i)]; }, 0, 100,
        [&last_done](std::int64_t done, std::int64_t) { last_done = done; });
    CHECK(std::count(hits.begin(), hits.end(), 1) == 100);
    // Progress is drawn while workers run; jobs this short may all end before the first draw.
    CHECK(last_done <= 100);
    CHECK_THROWS_AS(rockfall::risk::run_parallel(10, 2,
                                                 [](std::int64_t i) {
                                                     if (i == 4) throw std::runtime_error("x");
                                                 }),
                    std::runtime_error);
}
