// Rough linings in the engine (issue 13): a sphere layer and a perforated sheet slow rocks down
// against the same slope without them.

#include "plane_scenario.hpp"

#include "engine/simulation.hpp"
#include "shapes/lining.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

using Catch::Matchers::WithinRel;
using namespace rockfall;
using namespace rockfall::engine;
using namespace rockfall::engine::test;

namespace {

// Seed 001's flume width with side walls, one 2.5 m segment at `angle_deg`, and a rock
// released 0.3 m below the crown.
Scenario flume(double angle_deg, shapes::RockKind kind, double size, const Material& material) {
    Scenario scenario = plane_scenario(angle_deg, kind, material, 1e-3);
    scenario.slope.segments = {{2.5, angle_deg}};
    scenario.slope.width = 0.6;
    scenario.slope.side_walls.enabled = true;
    scenario.slope.side_walls.height = 0.3;
    scenario.materials.side_walls = material;
    scenario.rocks.front().rock.size = size;
    scenario.rocks.front().release.distance = 0.3;
    scenario.numerics.max_time = 5.0;
    return scenario;
}

// The rock's speed when its centre has travelled `distance` m down the slope from its start,
// m/s (linear between samples), or -1 if it never got there.
double speed_after(const Scenario& scenario, double distance) {
    const std::vector<RockState> states = trajectory(scenario, 1e-3);
    const Vec3 start = states.front().position;
    for (std::size_t i = 1; i < states.size(); ++i) {
        const double a = (states[i - 1].position - start).norm();
        const double b = (states[i].position - start).norm();
        if (a < distance && b >= distance) {
            const double w = (distance - a) / (b - a);
            return (1.0 - w) * states[i - 1].velocity.norm() + w * states[i].velocity.norm();
        }
    }
    return -1.0;
}

// The rock's mean speed over its first `distance` m of travel, or until it stopped if it
// stopped sooner (travel / time), m/s.
double mean_speed(const Scenario& scenario, double distance) {
    const std::vector<RockState> states = trajectory(scenario, 1e-3);
    const Vec3 start = states.front().position;
    for (const RockState& s : states) {
        const double travel = (s.position - start).norm();
        if (travel >= distance) return travel / s.time;
    }
    return (states.back().position - start).norm() / states.back().time;
}

}  // namespace

TEST_CASE("a sphere rolling over the sphere layer loses energy row by row",
          "[engine][lining][verification]") {
    // A 53 mm sphere (C2's d50) rolls 1.5 m down 10 deg. On the smooth plane it rolls without
    // slip: v^2 = (10/7) g s sin(a). Over close-packed 16 mm spheres (seed 001's DEM lining) it
    // drops into every row's hollows and hits the next row.
    const Material rough{0.4, 0.3, 0.0};
    const double travel = 1.5;
    Scenario smooth = flume(10.0, shapes::RockKind::sphere, 0.053, rough);
    const double v_smooth = speed_after(smooth, travel);
    CHECK_THAT(
        v_smooth,
        WithinRel(std::sqrt(10.0 / 7.0 * kGravity * travel * std::sin(radians(10.0))), 0.01));

    Scenario layered = smooth;
    auto lining = std::make_shared<shapes::Lining>();
    lining->spheres = shapes::SphereLayer{};
    layered.slope.lining = lining;
    // Released on top of the layer: the centre 2 radii of lining higher.
    layered.rocks.front().release.height = 2.0 * lining->spheres->radius;
    const double v_layer = speed_after(layered, travel);
    REQUIRE(v_layer > 0.0);
    const double rows = travel / (std::sqrt(3.0) / 2.0 * lining->spheres->spacing);
    const double mass = 2600.0 * std::numbers::pi / 6.0 * std::pow(0.053, 3);
    // Kinetic energy of rolling, (7/10) m v^2.
    const double loss = 0.7 * mass * (v_smooth * v_smooth - v_layer * v_layer);
    std::cout << "sphere layer: " << v_layer << " m/s against " << v_smooth << " m/s smooth; "
              << loss / rows << " J lost per row (" << rows << " rows)\n";
    CHECK(v_layer < 0.9 * v_smooth);
}

TEST_CASE("a pebble sliding over the perforated sheet catches in its holes",
          "[engine][lining][verification]") {
    // A 53 mm block slides down 30 deg (friction 0.4 < tan 30 deg) on the sheet and on the
    // same slope without it; in the holes its edges catch on the 1.5 mm rims.
    const Material rough{0.4, 0.3, 0.0};
    const double travel = 1.5;
    Scenario smooth = flume(30.0, shapes::RockKind::massive, 0.053, rough);
    smooth.rocks.front().release.height = 0.002;
    const double v_smooth = mean_speed(smooth, travel);

    Scenario sheet = smooth;
    auto lining = std::make_shared<shapes::Lining>();
    lining->sheet = shapes::PerforatedSheet{};
    sheet.slope.lining = lining;
    sheet.rocks.front().release.height = 0.002 + lining->sheet->thickness;
    const double v_sheet = mean_speed(sheet, travel);
    Scenario mesh = sheet;
    mesh.numerics.sheet_contact = SheetContact::mesh;
    const double v_mesh = mean_speed(mesh, travel);
    std::cout << "perforated sheet: mean speed " << v_sheet << " m/s (mesh contact " << v_mesh
              << ") against " << v_smooth << " m/s smooth over the first " << travel << " m\n";
    CHECK(v_sheet < 0.9 * v_smooth);
}
