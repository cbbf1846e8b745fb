// The pressure-cell grid over the reaction wall (issue 14): a hit loads the cell where it
// touches, with the load cell's peak; sampling keeps every impulse; the cells sum to the wall's
// total force at every sample; saturation against the capacity.

#include "wall_scenario.hpp"

#include "engine/pressure_cells.hpp"
#include "engine/simulation.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>
#include <vector>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using namespace rockfall::engine;

namespace {

// A 0.2 m sphere at 8 m/s into the wall (centre 0.1 m above the run-out, on the centre line),
// and a grid over the whole face: 5 columns over the 5 m width (1 m each, the middle one
// centred), 4 rows over the wall's height.
Scenario hit() { return test::wall_scenario(WallContact{}, 0.3, 0.2, 8.0, 2600.0); }

PressureCells whole_face(const Scenario& scenario) {
    PressureCells cells;
    cells.columns = 5;
    cells.rows = 4;
    cells.width = scenario.slope.width;
    cells.height = scenario.slope.wall.height;
    return cells;
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

}  // namespace

TEST_CASE("a wall hit loads the cell it touches with the load cell's peak and impulse",
          "[engine][wall][pressure_cells]") {
    const Scenario scenario = hit();
    const Outcome outcome = simulate(scenario, 1);
    REQUIRE(outcome.rocks.front().wall_hits.size() == 1);
    const WallHit& h = outcome.rocks.front().wall_hits.front();
    const shapes::Slope slope(scenario.slope);
    const PressureCells cells = whole_face(scenario);
    const PressureMap map = pressure_map(cells, slope, outcome);

    // The contact point: y = 0 (middle column), 0.1 m up (row floor(0.1 / (height / 4))).
    const int row = static_cast<int>(0.1 / (cells.height / cells.rows));
    const int expected = row * cells.columns + 2;
    REQUIRE(map.cell_at(h.point) == expected);
    REQUIRE(map.rocks.size() == 1);
    CHECK(map.rocks.front().cells == std::vector<int>{expected});
    const PressureCellRecord& cell = map.cells[static_cast<std::size_t>(expected)];
    CHECK(cell.column == 2);
    CHECK(cell.row == row);
    CHECK(cell.peak_force == h.peak_normal_force);
    CHECK(cell.peak_time == h.peak_time);
    // Sampling keeps the impulse: sum of sampled forces times the interval.
    const double T = cells.sample_interval;
    CHECK_THAT(sum(cell.force) * T, WithinRel(h.normal_impulse, 1e-9));
    CHECK_THAT(sum(map.total) * T, WithinRel(h.normal_impulse, 1e-9));
    for (std::size_t i = 0; i < map.cells.size(); ++i) {
        if (static_cast<int>(i) != expected) REQUIRE(sum(map.cells[i].force) == 0.0);
    }
    // The impact (about 0.3 ms) is shorter than a sample: the sensor sees at most the impulse
    // over one interval and, split over two samples at worst, at least half of it.
    const double duration = h.end_time - h.start_time;
    INFO("contact " << duration << " s, impulse " << h.normal_impulse << " N s");
    REQUIRE(duration < T);
    CHECK(cell.sampled_peak_force <= h.normal_impulse / T * (1.0 + 1e-9));
    CHECK(cell.sampled_peak_force >= 0.5 * h.normal_impulse / T);
    CHECK(cell.sampled_peak_force < cell.peak_force);
    CHECK(map.rocks.front().sampled_peak_force == cell.sampled_peak_force);
    // 18 kN/m2 over a 1 m x 0.075 m cell is far below 345 kPa; a 1 kPa pad saturates.
    CHECK(!cell.saturated);
    PressureCells weak = cells;
    weak.capacity = 1e3;
    const PressureMap saturated = pressure_map(weak, slope, outcome);
    CHECK(saturated.cells[static_cast<std::size_t>(expected)].saturated);
    CHECK(!saturated.cells[static_cast<std::size_t>(expected + 1)].saturated);
}

TEST_CASE("the cells sum to the wall's total force at every sample, resting contacts included",
          "[engine][wall][pressure_cells]") {
    // Three spheres side by side hit the wall and stay against it (no rebound restitution), a
    // fourth off the grid's columns when the grid covers only the middle 3 m of the face.
    Scenario scenario = hit();
    scenario.materials.wall.restitution = 0.0;
    scenario.numerics.max_time = 1.0;
    const RockRelease base = scenario.rocks.front();
    scenario.rocks.clear();
    for (const double y : {-2.0, -1.0, 0.0, 1.0}) {
        RockRelease rock = base;
        rock.release.lateral = y;
        rock.release.velocity = Vec3(3.0 + y, 0.0, 0.0);
        scenario.rocks.push_back(rock);
    }
    const Outcome outcome = simulate(scenario, 1);
    const shapes::Slope slope(scenario.slope);
    PressureCells cells = whole_face(scenario);
    cells.columns = 3;
    cells.width = 3.0;
    const PressureMap map = pressure_map(cells, slope, outcome);
    double impulse = 0.0;
    for (const RockOutcome& rock : outcome.rocks) {
        for (const WallHit& h : rock.wall_hits) impulse += h.normal_impulse;
    }
    REQUIRE(impulse > 0.0);
    CHECK_THAT(sum(map.total) * cells.sample_interval, WithinRel(impulse, 1e-9));
    REQUIRE(map.samples > 100);
    for (std::size_t k = 0; k < map.samples; ++k) {
        double on_cells = 0.0;
        for (const PressureCellRecord& cell : map.cells) on_cells += cell.force[k];
        REQUIRE_THAT(on_cells + map.outside[k], WithinAbs(map.total[k], 1e-9 * map.total[k]));
    }
    // The rock at y = -2 is left of the grid (|y| > 1.5 m): its load is outside.
    CHECK(sum(map.outside) > 0.0);
    REQUIRE(map.rocks.size() == 3);
    CHECK(map.rocks[0].rock == 1);
    for (const RockCellLoad& load : map.rocks) {
        const int column = static_cast<int>(load.rock) - 1;  // y = -1, 0, 1: columns 0, 1, 2
        for (const int index : load.cells) CHECK(index % cells.columns == column);
    }
    // Resting against the wall, they still press on it at the end of the run.
    CHECK(map.total[map.samples - 2] > 0.0);
}

TEST_CASE("forces starting on sample boundaries are sampled once, whole",
          "[engine][wall][pressure_cells]") {
    // Steps of T/3 and T/7 from t = 0: their starts fall on the boundaries k T up to
    // round-off, which once sent the sampling into an endless loop.
    const Scenario scenario = hit();
    const shapes::Slope slope(scenario.slope);
    const PressureCells cells = whole_face(scenario);
    const double T = cells.sample_interval;
    Outcome outcome;
    RockOutcome& rock = outcome.rocks.emplace_back();
    WallHit& h = rock.wall_hits.emplace_back();
    const Vec3 point(slope.wall_x(), 0.0, 0.1);
    double t = 0.0;
    double impulse = 0.0;
    for (int i = 0; i < 3000; ++i) {
        const double dt = i % 2 == 0 ? T / 3.0 : T / 7.0;
        h.history.push_back(ForceSample{t, 10.0 + i % 5, 0.0, dt, point});
        impulse += (10.0 + i % 5) * dt;
        t += dt;
    }
    const PressureMap map = pressure_map(cells, slope, outcome);
    CHECK_THAT(sum(map.total) * T, WithinRel(impulse, 1e-12));
    // A constant-ish force: every full sample reads between the smallest and largest force.
    for (std::size_t k = 0; k + 1 < map.samples && map.sample_time(k + 1) <= t; ++k) {
        REQUIRE(map.total[k] >= 10.0 - 1e-9);
        REQUIRE(map.total[k] <= 14.0 + 1e-9);
    }
}
