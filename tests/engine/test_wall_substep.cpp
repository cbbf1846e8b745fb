// Per-rock sub-stepping of wall impacts (numerics.wall_stepping = "per_rock", the default)
// against the whole world at the fine step ("world"): the same hit, while the world stays at
// the coarse step.

#include "wall_scenario.hpp"

#include "engine/simulation.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall::engine;
using rockfall::engine::test::first_hit;

namespace {

constexpr double kSize = 0.2;
constexpr double kDensity = 2600.0;
constexpr double kSpeed = 8.0;

Scenario hit_scenario(WallStepping stepping) {
    Scenario scenario = test::wall_scenario(WallContact{}, 0.3, kSize, kSpeed, kDensity);
    scenario.numerics.wall_stepping = stepping;
    return scenario;
}

}  // namespace

TEST_CASE("a sub-stepped wall hit matches the whole world at the fine step",
          "[verification][wall][substep]") {
    for (const auto kind :
         {rockfall::shapes::RockKind::sphere, rockfall::shapes::RockKind::massive}) {
        Scenario per_rock = hit_scenario(WallStepping::per_rock);
        Scenario world = hit_scenario(WallStepping::world);
        per_rock.rocks[0].rock.kind = kind;
        world.rocks[0].rock.kind = kind;
        const Outcome a = simulate(per_rock, 1);
        const Outcome b = simulate(world, 1);
        const WallHit& hit = first_hit(a);
        const WallHit& reference = first_hit(b);
        CAPTURE(rockfall::shapes::to_string(kind), hit.peak_normal_force,
                reference.peak_normal_force, hit.normal_impulse, reference.normal_impulse,
                a.coarse_steps, a.fine_steps, b.coarse_steps, b.fine_steps);
        CHECK_THAT(hit.normal_impulse, WithinRel(reference.normal_impulse, 0.01));
        CHECK_THAT(hit.peak_normal_force, WithinRel(reference.peak_normal_force, 0.03));
        CHECK_THAT(hit.end_time - hit.start_time,
                   WithinRel(reference.end_time - reference.start_time, 0.05));
        CHECK_THAT(hit.velocity_after.x(), WithinRel(reference.velocity_after.x(), 0.01));
        CHECK(hit.history.size() >= 50);
        // The world never left the coarse step: every step of the run was a coarse one.
        CHECK_THAT(a.coarse_steps * per_rock.numerics.time_step, WithinAbs(a.simulated_time, 1e-9));
        CHECK(b.fine_steps > 50);
        // The pose correction puts the rock where the fine-stepped world has it: apart from
        // the drift of their (slightly different) rebound velocities since the hit, within 1 mm.
        const double drift =
            (a.rocks[0].final_state.velocity - b.rocks[0].final_state.velocity).norm() *
            (a.simulated_time - hit.end_time);
        CAPTURE(drift);
        CHECK((a.rocks[0].final_state.position - b.rocks[0].final_state.position).norm() <
              drift + 1e-3);
    }
}

TEST_CASE(
    "a sub-stepped wall hit's impulse is the rock's momentum change and does not depend "
    "on the coarse step",
    "[verification][wall][substep]") {
    Scenario scenario = hit_scenario(WallStepping::per_rock);
    const double mass = kDensity * std::numbers::pi / 6.0 * std::pow(kSize, 3);
    std::vector<double> peaks;
    for (const double dt : {1e-3, 2.5e-4}) {
        scenario.numerics.time_step = dt;
        const WallHit hit = first_hit(simulate(scenario, 1));
        const double lost = mass * (hit.velocity_before.x() - hit.velocity_after.x());
        CAPTURE(dt, hit.normal_impulse, lost, hit.peak_normal_force);
        CHECK_THAT(hit.normal_impulse, WithinRel(lost, 1e-9));
        CHECK_THAT(hit.normal_impulse, WithinRel(mass * 1.3 * kSpeed, 0.03));
        peaks.push_back(hit.peak_normal_force);
    }
    CHECK_THAT(peaks[0], WithinRel(peaks[1], 0.02));
}
