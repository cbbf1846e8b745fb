// Faults of the rigid-body contacts found while checking seed 000 (issue 16) and the sweeps'
// step dependence, each against an analytic answer: rolling resistance through an impact, a
// sphere's spin through a frictionless landing, and the tail of small bounces of a dropped
// sphere; and frictionless spheres in a cluster, whose spin nothing may change.

#include "flume_cluster.hpp"
#include "plane_scenario.hpp"

#include "engine/simulation.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using engine::RockState;
using engine::Vec3;
using engine::test::kGravity;
using engine::test::plane_scenario;
using engine::test::trajectory;

TEST_CASE("rolling resistance acts through an impact: the spin drops by mu_r r J / I",
          "[verification][contact]") {
    const double dt = GENERATE(1e-3, 5e-4);
    const double e = GENERATE(0.3, 0.8);
    const double rolling = 0.05;
    // No friction: the landing changes the spin only through the rolling-resistance torque.
    engine::Scenario scenario =
        plane_scenario(0.0, shapes::RockKind::sphere, {0.0, e, rolling}, dt);
    const double spin = 50.0;  // rad/s about the horizontal y axis
    scenario.rocks.front().release.height = 1.0;
    scenario.rocks.front().release.spin = Vec3(0.0, spin, 0.0);
    scenario.numerics.max_time = 0.6;
    const std::vector<RockState> states = trajectory(scenario, 1e-6);
    std::size_t k = 1;
    while (k < states.size() &&
           !(states[k - 1].velocity.z() < 0.0 && states[k].velocity.z() > 0.0)) {
        ++k;
    }
    REQUIRE(k < states.size());
    const RockState& before = states[k - 1];
    const RockState& after = states[k];
    const double r = 0.1;
    // The normal impulse per unit mass of the landing step (gravity's share dt g added back),
    // and the documented law's angular impulse mu_r r J about the spin axis: with I = 2/5 m r^2
    // the spin falls by mu_r J / (0.4 m r).
    const double impulse_per_mass = after.velocity.z() - before.velocity.z() + kGravity * dt;
    const double expected = rolling * impulse_per_mass / (0.4 * r);
    const double measured = before.angular_velocity.y() - after.angular_velocity.y();
    INFO("dt = " << dt << " s, e = " << e << ": spin " << before.angular_velocity.y() << " -> "
                 << after.angular_velocity.y() << " rad/s, expected drop " << expected);
    CHECK_THAT(measured, WithinRel(expected, 0.02));
    // Spin about the contact normal and about x stays zero.
    CHECK_THAT(after.angular_velocity.x(), WithinAbs(0.0, 1e-9));
    CHECK_THAT(after.angular_velocity.z(), WithinAbs(0.0, 1e-9));
}

TEST_CASE("rolling resistance slows a block spinning on its face by mu_r r m g / I",
          "[verification][contact]") {
    // The rows of a face's points about one axis are one constraint, bounded by mu_r r times
    // the face's whole normal impulse (one row per axis per patch, merged with the patch's
    // twist about the normal): without friction only that moment slows the spin.
    const double dt = GENERATE(1e-3, 5e-4);
    const double rolling = 0.05;
    engine::Scenario scenario =
        plane_scenario(0.0, shapes::RockKind::massive, {0.0, 0.0, rolling}, dt);
    const double spin = 10.0;  // rad/s about the vertical, the block's short axis
    scenario.rocks.front().release.spin = Vec3(0.0, 0.0, spin);
    scenario.numerics.max_time = 0.7;
    const std::vector<RockState> states = trajectory(scenario, 0.01);
    const shapes::RockGeometry rock = scenario.rocks.front().rock.geometry();
    const double r = 0.5 * rock.nominal_size;
    const double expected = rolling * r * kGravity * rock.properties.volume /
                            rock.properties.principal_moments.z();  // rad/s^2
    const RockState& from = engine::test::state_at(states, 0.1);
    const RockState& to = engine::test::state_at(states, 0.6);
    const double measured =
        (from.angular_velocity.z() - to.angular_velocity.z()) / (to.time - from.time);
    INFO("dt = " << dt << " s: spin " << from.angular_velocity.z() << " -> "
                 << to.angular_velocity.z() << " rad/s, deceleration " << measured
                 << " rad/s2, expected " << expected);
    REQUIRE(to.angular_velocity.z() > 0.0);
    CHECK_THAT(measured, WithinRel(expected, 0.01));
}

TEST_CASE("a frictionless sphere landing while it moves along the surface keeps its spin",
          "[verification][contact]") {
    // Bullet's sphere-box manifold kept the points of earlier steps (found on the way down,
    // then refreshed from where they were on the sphere), v dt apart behind its true contact
    // point: the landing's normal impulse, spread over them, acted off the line through the
    // centre and spun the sphere. A sphere touches a plane at one point, so without friction
    // or rolling resistance no impulse has a moment about its centre. The case is a sphere of
    // the seed sweep past the toe (29 degrees, then flat), which gained 3.25 rad/s at 1 ms.
    const double dt = GENERATE(1e-3, 5e-4);
    engine::Scenario scenario = plane_scenario(0.0, shapes::RockKind::sphere, {0.0, 0.3, 0.0}, dt);
    scenario.slope.segments = {{5.7, 29.0}, {7.5, 0.0}};
    engine::RockRelease& rock = scenario.rocks.front();
    rock.rock.size = 0.288;
    rock.release.distance = 5.451;
    rock.release.height = 0.285;
    rock.release.velocity = Vec3(5.344, 0.0, -5.411);
    const double spin = 37.04;  // rad/s: about the sphere's speed over its radius
    rock.release.spin = Vec3(0.0, spin, 0.0);
    scenario.numerics.max_time = 0.3;
    const std::vector<RockState> states = trajectory(scenario, 1e-6);
    bool landed = false;
    double largest = 0.0;  // largest change of the spin, rad/s
    for (const RockState& state : states) {
        landed = landed || state.velocity.z() > 0.0;
        largest = std::max(largest, std::abs(state.angular_velocity.y() - spin));
    }
    INFO("dt = " << dt << " s: spin changed by up to " << largest << " rad/s");
    REQUIRE(landed);
    CHECK(largest < 1e-9);
}

namespace {

// Mechanical energy of a sphere of diameter `size` (m, density 2600 kg/m3), J: kinetic plus
// m g z.
double sphere_energy(const RockState& state, double size) {
    const double mass = 2600.0 * std::numbers::pi / 6.0 * size * size * size;
    const double inertia = 0.4 * mass * 0.25 * size * size;
    return 0.5 * mass * state.velocity.squaredNorm() +
           0.5 * inertia * state.angular_velocity.squaredNorm() +
           mass * kGravity * state.position.z();
}

}  // namespace

TEST_CASE("refining the step near the angle bars gives a bar crossing the fine step's energy",
          "[verification][contact]") {
    // The seed slope's 0.365 m sphere lands 12 cm above the fourth bar and strikes its edge 6 ms
    // later. A 1 ms step takes both impacts in one step (the edge's then approached at the fall
    // speed as well) and lost 0.25 of the sphere's energy at that bar against 0.13 at 0.5 ms and
    // finer (docs/sweeps.md, "Step size").
    const auto run = [](double dt, int refinement) {
        engine::Scenario scenario =
            plane_scenario(0.0, shapes::RockKind::sphere, {0.6, 0.3, 0.02}, dt);
        scenario.slope.segments = {{5.0, 43.0}, {5.7, 29.0}, {7.5, 0.0}};
        scenario.slope.bars.enabled = true;
        scenario.materials.bars = {0.4, 0.3, 0.02};
        scenario.rocks.front().rock.size = 0.365;
        scenario.rocks.front().release.distance = 0.5;
        scenario.numerics.max_time = 1.6;
        scenario.numerics.bar_refinement = refinement;
        const std::vector<RockState> states = trajectory(scenario, 1e-6);
        // Before the fourth bar (1.35 s: in flight towards it) and after it (1.55 s: in flight).
        return std::pair{sphere_energy(engine::scenes::state_at(states, 1.35), 0.365),
                         sphere_energy(engine::scenes::state_at(states, 1.55), 0.365)};
    };
    const auto [fine_before, fine_after] = run(2.5e-4, 1);
    const auto [coarse_before, coarse_after] = run(1e-3, 1);
    const auto [refined_before, refined_after] = run(1e-3, 4);
    const double fine = fine_after / fine_before;
    const double coarse = coarse_after / coarse_before;
    const double refined = refined_after / refined_before;
    INFO("energy kept across the bar: 0.25 ms "
         << fine << ", 1 ms " << coarse << ", 1 ms refined 4 times near the bars " << refined);
    // The case shows the fault (the coarse step loses far more) and the refinement removes it.
    CHECK(coarse < fine - 0.05);
    CHECK_THAT(refined, WithinAbs(fine, 0.005));
}

namespace {

// The scenario's default restitution threshold, m/s (numerics.restitution_threshold).
const double kRestitutionThreshold = engine::Numerics{}.restitution_threshold;

// Time at which a sphere dropped from h comes to rest under the engine's contact model: it
// lands at v0 = sqrt(2 g h) and rebounds at e v while the impact speed v is at least the
// restitution threshold, each flight lasting 2 e v / g.
double modelled_rest_time(double h, double e, double threshold) {
    double v = std::sqrt(2.0 * kGravity * h);
    double t = v / kGravity;
    while (v >= threshold) {
        t += 2.0 * e * v / kGravity;
        v *= e;
    }
    return t;
}

}  // namespace

TEST_CASE("a dropped sphere comes to rest when the bouncing model says",
          "[verification][contact]") {
    const double e = GENERATE(0.3, 0.5, 0.8);
    const double h = 1.0;
    engine::Scenario scenario = plane_scenario(0.0, shapes::RockKind::sphere, {0.5, e, 0.0}, 1e-3);
    scenario.rocks.front().release.height = h;
    scenario.numerics.max_time = 6.0;
    const std::vector<RockState> states = trajectory(scenario, 1e-6);
    // The last landing: the end of the last step that stopped a downward motion faster than
    // the 1.5 g dt of a resting sphere that lost contact for one step.
    const double resting = 1.5 * kGravity * scenario.numerics.time_step;
    double landing = 0.0;
    for (std::size_t k = 1; k < states.size(); ++k) {
        if (states[k - 1].velocity.z() < -resting && states[k].velocity.z() >= -1e-6) {
            landing = states[k].time;
        }
    }
    const double expected = modelled_rest_time(h, e, kRestitutionThreshold);
    const double analytic = std::sqrt(2.0 * h / kGravity) * (1.0 + e) / (1.0 - e);
    INFO("e = " << e << ": comes to rest at " << landing << " s, model " << expected
                << " s, untruncated " << analytic << " s");
    // Before the first-touch restitution the sphere came to rest 0.79 %, 0.93 % and 2.77 % late
    // (e = 0.3, 0.5, 0.8). What remains is about one step of detection lag per bounce (the
    // point is found below the surface and leaves from there): 4.6 ms over four bounces at
    // e = 0.3, which is why that case is held to 0.6 % instead of 0.5 %.
    CHECK_THAT(landing, WithinRel(expected, e < 0.4 ? 0.006 : 0.005));
}

namespace {

// The turn of the rock about the slope normal since the first state, deg: the angle between
// the body x axis projected on the slope plane then and now.
double heading_change(const RockState& first, const RockState& now, const Vec3& normal) {
    const auto projected = [&](const RockState& s) {
        const Vec3 axis = s.orientation * Vec3::UnitX();
        return Vec3(axis - axis.dot(normal) * normal).normalized();
    };
    const Vec3 a = projected(first);
    const Vec3 b = projected(now);
    return std::atan2(a.cross(b).dot(normal), a.dot(b)) * 180.0 / std::numbers::pi;
}

}  // namespace

TEST_CASE("a block sliding straight down an incline keeps its heading", "[verification][contact]") {
    // By symmetry a block released square to the fall line, on its face, cannot turn about the
    // slope normal: the friction of a symmetric contact patch has no moment about it.
    const double dt = GENERATE(1e-3, 5e-4);
    const double mu = GENERATE(0.3, 0.45);
    const double angle = 30.0;
    engine::Scenario scenario =
        plane_scenario(angle, shapes::RockKind::massive, {mu, 0.0, 0.0}, dt);
    scenario.numerics.max_time = 2.4;
    const std::vector<RockState> states = trajectory(scenario, 0.01);
    REQUIRE(states.size() > 100);
    const double a = engine::test::radians(angle);
    const Vec3 normal(std::sin(a), 0.0, std::cos(a));
    double worst = 0.0;
    for (const RockState& s : states) {
        worst = std::max(worst, std::abs(heading_change(states.front(), s, normal)));
    }
    INFO("dt = " << dt << " s, mu = " << mu << ": largest heading change " << worst << " deg");
    // Per-point friction turned it 15 to 65 degrees (29 at mu = 0.3, 1 ms); the patch friction
    // on the face's four widest corners keeps it within 0.003 degrees.
    CHECK(worst < 0.01);
}

TEST_CASE("frictionless spheres in a cluster keep zero spin against spheres, blocks and boxes",
          "[verification][contact][cluster]") {
    // Every contact normal on a sphere passes through its centre, so without friction and
    // rolling resistance nothing can spin it: any spin is a contact that pushes off the centre
    // line or a tangential row (patch friction, twist, rolling resistance) that acts with a
    // zero coefficient. Checked against the other spheres (Bullet's sphere-sphere manifold),
    // against blocks (its convex-convex manifold), against the box's, slope's and side walls'
    // boxes, and through wall impacts, at the 1 ms step. These spheres start without spin, so a
    // stale manifold point (the sphere-box fault above, which needs a spinning sphere) keeps its
    // normal through the centre and cannot show here: this case guards the other paths.
    const bool among_blocks = GENERATE(false, true);
    engine::Scenario scenario = engine::test::flume_cluster(20);
    const engine::Material frictionless{0.0, 0.3, 0.0};
    scenario.materials = {frictionless, frictionless, frictionless, frictionless};
    engine::Cluster& cluster = *scenario.cluster;
    cluster.rock.material = frictionless;
    cluster.rock.kind = among_blocks ? shapes::RockKind::massive : shapes::RockKind::sphere;
    for (const double across : {-0.15, 0.0, 0.15}) {
        engine::MarkedRock sphere;
        sphere.rock.kind = shapes::RockKind::sphere;
        sphere.rock.size = 0.06;
        sphere.rock.density = 2620.0;
        sphere.rock.material = frictionless;
        sphere.along = 0.3;
        sphere.across = across;
        cluster.marked.push_back(sphere);
    }
    scenario.numerics.max_time = 2.0;
    const int first_sphere = among_blocks ? 20 : 0;
    double largest = 0.0;  // rad/s
    int samples = 0;
    engine::RunOptions options;
    options.trajectory = [&](int index, const RockState& state) {
        if (index < first_sphere) return;
        largest = std::max(largest, state.angular_velocity.norm());
        ++samples;
    };
    const engine::Outcome outcome = engine::simulate(scenario, 1, options);
    double fastest = 0.0;
    for (const auto& rock : outcome.rocks) fastest = std::max(fastest, rock.max_speed);
    INFO((among_blocks ? "3 spheres among 20 blocks" : "23 spheres")
         << ": largest spin " << largest << " rad/s over " << samples << " samples; fastest rock "
         << fastest << " m/s");
    REQUIRE(samples > 100);
    CHECK(fastest > 2.0);  // the cluster did run down the flume
    CHECK(largest < 1e-9);
}

TEST_CASE("the step is refined only while a rock approaches an angle bar at 1 m/s or more",
          "[verification][contact]") {
    // A rock slides without friction along a horizontal plane into the bar 0.5 m ahead (bars
    // every metre). Refined steps come only within two coarse steps of the bar while the rock
    // nears it at 1 m/s or more: none for a slow approach, a handful for a fast sphere that
    // bounces back; and none for a block until two coarse steps before it touches (its gap is
    // its own, not its bounding sphere's, which reaches the bar about 10 ms earlier at 3 m/s).
    const auto scenario_of = [](shapes::RockKind kind, double speed) {
        engine::Scenario scenario = plane_scenario(0.0, kind, {0.0, 0.3, 0.0}, 1e-3);
        scenario.slope.bars.enabled = true;
        scenario.slope.bars.segments = {0};
        engine::RockRelease& rock = scenario.rocks.front();
        rock.rock.size = 0.16;
        rock.release.distance = 5.5;
        rock.release.velocity = Vec3(speed, 0.0, 0.0);
        scenario.numerics.max_time = 0.6;
        scenario.numerics.bar_refinement = 4;
        return scenario;
    };
    for (const shapes::RockKind kind : {shapes::RockKind::sphere, shapes::RockKind::massive}) {
        INFO((kind == shapes::RockKind::sphere ? "sphere" : "block"));
        const engine::Outcome slow = engine::simulate(scenario_of(kind, 0.9), 1);
        CHECK(slow.rocks.front().final_state.velocity.x() < 0.0);  // it reached the bar
        CHECK(slow.fine_steps == 0);
    }
    const engine::Outcome sphere = engine::simulate(scenario_of(shapes::RockKind::sphere, 3.0), 1);
    INFO("sphere at 3 m/s: " << sphere.fine_steps << " refined steps");
    CHECK(sphere.rocks.front().final_state.velocity.x() < 0.0);
    CHECK(sphere.fine_steps > 0);
    CHECK(sphere.fine_steps <= 4 * 6);
    // The block's first touch: where the bar first slows it.
    engine::Scenario block = scenario_of(shapes::RockKind::massive, 3.0);
    const std::vector<RockState> states = trajectory(block, 1e-4);
    const auto touch = std::find_if(states.begin(), states.end(),
                                    [](const RockState& s) { return s.velocity.x() < 2.99; });
    REQUIRE(touch != states.end());
    block.numerics.max_time = touch->time - 0.005;
    const engine::Outcome before = engine::simulate(block, 1);
    INFO("block: touches at " << touch->time << " s, " << before.fine_steps
                              << " refined steps until 5 ms before");
    CHECK(before.fine_steps == 0);
    block.numerics.max_time = touch->time + 0.001;
    CHECK(engine::simulate(block, 1).fine_steps > 0);
}
