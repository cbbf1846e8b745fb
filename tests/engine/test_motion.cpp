// The rigid-body engine against analytic motion, each at the default step (1 ms) and at half
// of it: free fall, a block sliding on an incline, a sphere rolling without slip, and the
// drop-bounce that calibrates restitution (issue 2, "Contact calibration").

#include "plane_scenario.hpp"

#include "engine/simulation.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using engine::RockState;

namespace {

using engine::test::downslope;
using engine::test::kGravity;
using engine::test::plane_scenario;
using engine::test::radians;
using engine::test::trajectory;

using engine::scenes::mean_acceleration;
using engine::scenes::state_at;

}  // namespace

TEST_CASE("free fall follows z0 - g t^2 / 2 at two step sizes", "[verification]") {
    const double dt = GENERATE(1e-3, 5e-4);
    engine::Scenario scenario = plane_scenario(0.0, shapes::RockKind::sphere, {}, dt);
    scenario.rocks.front().release.height = 10.0;
    scenario.numerics.max_time = 1.0;  // 4.9 m of fall: it never lands
    const std::vector<RockState> states = trajectory(scenario, 0.1);
    REQUIRE(states.size() >= 10);
    const double z0 = states.front().position.z();
    for (const RockState& s : states) {
        const double t = s.time;
        // Symplectic Euler: velocity exact; position z0 - g t (t + dt) / 2, an O(dt) lag.
        CHECK_THAT(s.velocity.z(), WithinAbs(-kGravity * t, 1e-9));
        CHECK_THAT(s.position.z(), WithinAbs(z0 - 0.5 * kGravity * t * (t + dt), 1e-9));
        CHECK_THAT(s.position.z(),
                   WithinAbs(z0 - 0.5 * kGravity * t * t, 0.5 * kGravity * t * dt + 1e-12));
        CHECK_THAT(s.position.x(), WithinAbs(states.front().position.x(), 1e-12));
    }
}

TEST_CASE("a block slides down an incline with a = g (sin t - mu cos t)", "[verification]") {
    const double dt = GENERATE(1e-3, 5e-4);
    const double mu = GENERATE(0.3, 0.45);
    const double angle = 30.0;
    // Restitution 0: the block lands flat and stays on its face.
    const engine::Scenario scenario =
        plane_scenario(angle, shapes::RockKind::massive, {mu, 0.0, 0.0}, dt);
    const std::vector<RockState> states = trajectory(scenario, 0.01);
    const double expected = kGravity * (std::sin(radians(angle)) - mu * std::cos(radians(angle)));
    INFO("dt = " << dt << " s, mu = " << mu);
    CHECK_THAT(mean_acceleration(states, downslope(angle), 0.5, 2.0), WithinRel(expected, 0.02));
    // Sliding, not tumbling: the spin stays far below that of rolling at this speed.
    const RockState& end = state_at(states, 2.0);
    CHECK(end.angular_velocity.norm() * 0.1 < 0.05 * end.velocity.norm());
}

TEST_CASE("a sphere rolls without slip with a = 5/7 g sin t", "[verification]") {
    const double dt = GENERATE(1e-3, 5e-4);
    const double angle = 30.0;
    const double radius = 0.1;
    const engine::Scenario scenario =
        plane_scenario(angle, shapes::RockKind::sphere, {1.0, 0.0, 0.0}, dt);
    const std::vector<RockState> states = trajectory(scenario, 0.01);
    const double expected = 5.0 / 7.0 * kGravity * std::sin(radians(angle));
    INFO("dt = " << dt << " s");
    CHECK_THAT(mean_acceleration(states, downslope(angle), 0.5, 2.0), WithinRel(expected, 0.02));
    const RockState& end = state_at(states, 2.0);
    CHECK_THAT(end.angular_velocity.norm() * radius, WithinRel(end.velocity.norm(), 0.01));
}

TEST_CASE("rolling resistance slows a rolling sphere to a = 5/7 g (sin t - mu_r cos t)",
          "[verification]") {
    const double dt = GENERATE(1e-3, 5e-4);
    const double angle = 30.0;
    const double rolling = 0.05;
    const engine::Scenario scenario =
        plane_scenario(angle, shapes::RockKind::sphere, {1.0, 0.0, rolling}, dt);
    const std::vector<RockState> states = trajectory(scenario, 0.01);
    // Torque balance with a resisting moment mu_r r N: (7/5) m a = m g (sin t - mu_r cos t).
    const double expected =
        5.0 / 7.0 * kGravity * (std::sin(radians(angle)) - rolling * std::cos(radians(angle)));
    INFO("dt = " << dt << " s");
    CHECK_THAT(mean_acceleration(states, downslope(angle), 0.5, 2.0), WithinRel(expected, 0.02));
}

namespace {

engine::scenes::Bounce first_bounce(double angle_deg, shapes::RockKind kind, double restitution,
                                    double dt, double height) {
    engine::scenes::Bounce bounce;
    REQUIRE_NOTHROW(bounce =
                        engine::scenes::first_bounce(angle_deg, kind, restitution, dt, height));
    return bounce;
}

}  // namespace

TEST_CASE("a sphere dropped on the flat rebounds to e^2 h", "[verification]") {
    const double dt = GENERATE(1e-3, 5e-4);
    const double e = GENERATE(0.3, 0.5, 0.8);
    const double h = 1.0;
    const engine::scenes::Bounce bounce = first_bounce(0.0, shapes::RockKind::sphere, e, dt, h);
    INFO("dt = " << dt << " s, e = " << e);
    CHECK_THAT(bounce.rebound_height, WithinRel(e * e * h, 0.05));
    CHECK_THAT(std::sqrt(bounce.rebound_height / h), WithinRel(e, 0.025));
    CHECK_THAT(bounce.velocity_ratio, WithinRel(e, 0.025));
}

TEST_CASE("a sphere dropped on an incline rebounds to e^2 h along the normal", "[verification]") {
    const double dt = GENERATE(1e-3, 5e-4);
    const double e = GENERATE(0.3, 0.8);
    const double angle = GENERATE(29.0, 43.0);
    const double h = 1.0;
    // Falling vertically onto the incline it meets it at sqrt(2 g h / cos t); the normal
    // component then rises against g cos t to e^2 h.
    const engine::scenes::Bounce bounce = first_bounce(angle, shapes::RockKind::sphere, e, dt, h);
    INFO("dt = " << dt << " s, e = " << e << ", angle = " << angle << " deg");
    CHECK_THAT(bounce.rebound_height, WithinRel(e * e * h, 0.05));
    CHECK_THAT(bounce.velocity_ratio, WithinRel(e, 0.025));
}

TEST_CASE("a block landing flat on a face rebounds to e^2 h", "[verification]") {
    const double dt = GENERATE(1e-3, 5e-4);
    const double e = GENERATE(0.3, 0.8);
    const double h = 1.0;
    const engine::scenes::Bounce bounce = first_bounce(0.0, shapes::RockKind::massive, e, dt, h);
    INFO("dt = " << dt << " s, e = " << e);
    CHECK_THAT(bounce.rebound_height, WithinRel(e * e * h, 0.05));
    CHECK_THAT(bounce.velocity_ratio, WithinRel(e, 0.025));
}

TEST_CASE("a slab spinning down onto the flat meets it with its end, not through it",
          "[verification]") {
    // The narrowphase skips a pair that is apart until its bodies can have closed the gap
    // (engine/src/hull_contacts.hpp): here the gap closes by the spin (the end sweeps down at
    // about 3 m/s) while the centre has hardly fallen, so a bound that missed the rotation would
    // let the end through the surface. Each step the end can sink by at most its speed times dt
    // before the contact acts; 1 mm more is slack.
    const double dt = 1e-3;
    const double spin = 20.0;  // rad/s about the y axis
    engine::Material material;
    material.friction = 0.5;
    material.restitution = 0.3;
    engine::Scenario scenario = plane_scenario(0.0, shapes::RockKind::planar, material, dt);
    scenario.rocks[0].release.height = 0.04;
    scenario.rocks[0].release.spin = engine::Vec3(0.0, spin, 0.0);
    scenario.numerics.max_time = 0.3;
    const std::vector<RockState> states = trajectory(scenario, dt);
    const shapes::RockGeometry geometry = scenario.rocks[0].rock.geometry();
    double lowest = 1e9;  // the lowest vertex over the run, m (the surface is at z = 0)
    double touched = -1;  // when a vertex first came within 1 mm of the surface, s
    for (const RockState& s : states) {
        const Eigen::Matrix3d rotation = s.orientation.toRotationMatrix();
        double bottom = 1e9;
        for (const engine::Vec3& v : geometry.hull.vertices) {
            bottom = std::min(bottom, (s.position + rotation * v).z());
        }
        lowest = std::min(lowest, bottom);
        if (touched < 0 && bottom < 1e-3) touched = s.time;
    }
    REQUIRE(touched > 0);
    const double end_speed = spin * geometry.bounding_radius;
    INFO("touched at " << touched << " s, lowest vertex " << lowest << " m");
    // Far sooner than a free fall of 0.04 m (0.09 s): the spin brought the end down.
    CHECK(touched < 0.05);
    CHECK(lowest > -(end_speed * dt + 1e-3));
}
