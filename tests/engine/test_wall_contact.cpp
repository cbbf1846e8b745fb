// The compliant wall contact on its own (no Bullet): the force laws against a 1-DOF impact
// m x'' = -F(x, x') integrated here with small RK4 steps, the analytic impacts, the overlap
// geometry and the load cell's bookkeeping.

#include "wall_fixtures.hpp"

#include "engine/wall_contact.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <vector>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall::engine;
using rockfall::engine::test::effective_modulus_of;
using rockfall::engine::test::seed_wall;
using rockfall::shapes::OrientedBox;
using rockfall::shapes::RockGeometry;

namespace {

using Force = std::function<double(double overlap, double rate)>;

// A 0.2 m granite sphere on concrete (the seed's small rock).
constexpr double kRadius = 0.1;
const double kMass = 2600.0 * 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;

struct ImpactRun {
    double peak_force = 0.0;
    double peak_time = 0.0;
    double duration = 0.0;
    double restitution = 0.0;
    int steps = 0;
};

// Integrates m x'' = -force(x, x'), x(0) = 0, x'(0) = speed with RK4 steps of dt until the
// contact ends: the force vanishes while rebounding (clamped laws; the speed is final from
// then on) or, for a law that may pull, the overlap returns to 0 (speed interpolated there).
ImpactRun integrate_impact(const Force& force, double mass, double speed, double dt,
                           bool may_pull = false) {
    const auto acceleration = [&](double x, double v) { return -force(x, v) / mass; };
    double x = 0.0;
    double v = speed;
    double t = 0.0;
    ImpactRun run;
    run.peak_force = force(x, v);
    for (;;) {
        const auto [x_next, v_next] = test::rk4_step(acceleration, {x, v}, dt);
        ++run.steps;
        if (may_pull && x_next <= 0.0) {
            const double fraction = x / (x - x_next);
            run.duration = t + fraction * dt;
            run.restitution = -(v + fraction * (v_next - v));
            return run;
        }
        x = x_next;
        v = v_next;
        t += dt;
        const double f = force(x, v);
        if (f > run.peak_force) {
            run.peak_force = f;
            run.peak_time = t;
        }
        if (!may_pull && v < 0.0 && f <= 0.0) {
            run.duration = t;
            run.restitution = -v;
            return run;
        }
        if (run.steps > 10'000'000) {
            FAIL("the impact did not end within 10^7 steps");
        }
    }
}

WallContact linear_spec(double stiffness) {
    WallContact spec;
    spec.model = WallContact::Model::linear;
    spec.linear_stiffness = stiffness;
    return spec;
}

WallContact hertz_spec() {
    WallContact spec;
    spec.model = WallContact::Model::hertz;
    return spec;
}

// Wall and rock with the same restitution, so that their mean is e.
WallContactLaw make_law(const WallContact& spec, double restitution) {
    const Material material{0.5, restitution, 0.0};
    return WallContactLaw(spec, material, material, kMass, kRadius);
}

Force law_force(const WallContactLaw& law) {
    return [&law](double x, double v) { return law.normal_force(x, v); };
}

}  // namespace

TEST_CASE("effective modulus and damping ratio from restitution", "[wall_contact]") {
    CHECK_THAT(effective_modulus(30e9, 0.2, 30e9, 0.2), WithinRel(15.625e9, 1e-12));
    CHECK_THAT(effective_modulus(200e9, 0.3, 30e9, 0.2),
               WithinRel(1.0 / (0.91 / 200e9 + 0.96 / 30e9), 1e-12));
    CHECK_THAT(damping_ratio_from_restitution(1.0), WithinAbs(0.0, 1e-15));
    CHECK_THAT(damping_ratio_from_restitution(0.3), WithinRel(0.3578571305, 1e-9));
    CHECK_THAT(damping_ratio_from_restitution(0.5), WithinRel(0.2154537620, 1e-9));
    for (const double e : {0.05, 0.3, 0.5, 0.8, 0.99}) {
        const double b = damping_ratio_from_restitution(e);
        CHECK_THAT(std::exp(-b * std::numbers::pi / std::sqrt(1.0 - b * b)), WithinRel(e, 1e-12));
    }
}

TEST_CASE("closed-form clamped spring-dashpot agrees with integration", "[wall_contact]") {
    // Unit mass and stiffness: forces in units of v0 sqrt(m k), times in 1 / omega0. Covers the
    // peak after first touch (beta < 1/2), the jump c v0 as the peak, and over-damping.
    for (const double beta : {0.02, 0.2, 0.45, 0.7, 1.0, 1.6, 5.0}) {
        CAPTURE(beta);
        const LinearImpact exact = linear_impact(beta);
        const ImpactRun run = integrate_impact(
            [beta](double x, double v) { return std::max(0.0, x + 2.0 * beta * v); }, 1.0, 1.0,
            1e-5);
        CHECK_THAT(run.peak_force, WithinRel(exact.peak_force, 1e-6));
        CHECK_THAT(run.peak_time, WithinAbs(exact.peak_time, 2e-5));
        CHECK_THAT(run.duration, WithinAbs(exact.duration, 2e-5));
        CHECK_THAT(run.restitution, WithinRel(exact.restitution, 1e-4));
    }
    // Undamped: F = sin t, contact of half a period.
    CHECK_THAT(linear_impact(0.0).peak_force, WithinRel(1.0, 1e-12));
    CHECK_THAT(linear_impact(0.0).duration, WithinRel(std::numbers::pi, 1e-12));
    CHECK_THAT(linear_impact(0.0).restitution, WithinRel(1.0, 1e-12));
}

TEST_CASE("linear law: peak force against the analytic spring-dashpot", "[wall_contact]") {
    const double k = 2e8;
    for (const double e : {0.3, 0.5, 0.8}) {
        const WallContactLaw law = make_law(linear_spec(k), e);
        const double speed = 8.0;
        const LinearImpact unit = linear_impact(clamped_damping_ratio(e));
        const double duration = unit.duration * std::sqrt(kMass / k);
        CHECK_THAT(law.contact_duration(speed), WithinRel(duration, 1e-12));
        const ImpactRun run = integrate_impact(law_force(law), kMass, speed, duration / 2000.0);
        CAPTURE(e, run.peak_force, unit.peak_force * speed * std::sqrt(kMass * k));
        CHECK_THAT(run.peak_force, WithinRel(unit.peak_force * speed * std::sqrt(kMass * k), 0.01));
        CHECK_THAT(run.duration, WithinRel(duration, 0.01));
    }
}

TEST_CASE("linear law: restitution equals the configured one", "[wall_contact]") {
    const double k = 2e8;
    const double speed = 5.0;
    for (const double e : {0.3, 0.5, 0.8}) {
        CAPTURE(e);
        // The textbook dashpot that may pull, with beta from e = exp(-beta pi / sqrt(1 -
        // beta^2)), rebounds with e when the overlap returns to 0.
        const double c_free = 2.0 * damping_ratio_from_restitution(e) * std::sqrt(kMass * k);
        const double period = std::numbers::pi * std::sqrt(kMass / k);
        const ImpactRun free =
            integrate_impact([k, c_free](double x, double v) { return k * x + c_free * v; }, kMass,
                             speed, period / 20000.0, true);
        CHECK_THAT(free.restitution / speed, WithinRel(e, 0.01));

        // The wall's law never pulls; its beta is calibrated on that clamped contact.
        const WallContactLaw law = make_law(linear_spec(k), e);
        const ImpactRun clamped =
            integrate_impact(law_force(law), kMass, speed, law.contact_duration(speed) / 20000.0);
        CHECK_THAT(clamped.restitution / speed, WithinRel(e, 0.01));

        // Effect of the clamp: the textbook beta without the pull rebounds faster.
        const double clamped_textbook =
            linear_impact(damping_ratio_from_restitution(e)).restitution;
        CAPTURE(clamped_textbook, clamped_damping_ratio(e), damping_ratio_from_restitution(e));
        CHECK(clamped_textbook > e * 1.01);
    }
    CHECK_THAT(linear_impact(damping_ratio_from_restitution(0.3)).restitution,
               WithinRel(0.3971, 1e-3));
}

TEST_CASE("Hertz-Tsuji law: restitution equals the configured one at any speed", "[wall_contact]") {
    for (const double e : {0.3, 0.5, 0.8}) {
        const WallContactLaw law = make_law(hertz_spec(), e);
        const TsujiImpact& unit = tsuji_impact_for_restitution(e);
        double restitution_at_1 = 0.0;
        for (const double speed : {1.0, 10.0}) {
            const ImpactRun run = integrate_impact(law_force(law), kMass, speed,
                                                   law.contact_duration(speed) / 20000.0);
            const double restitution = run.restitution / speed;
            CAPTURE(e, speed, unit.alpha, restitution);
            CHECK_THAT(restitution, WithinRel(e, 0.01));
            // The nondimensional solution the law is built on agrees with this integration.
            CHECK_THAT(restitution, WithinRel(unit.restitution, 1e-5));
            CHECK_THAT(run.duration, WithinRel(law.contact_duration(speed), 1e-3));
            if (speed == 1.0) {
                restitution_at_1 = restitution;
            } else {
                CHECK_THAT(restitution, WithinRel(restitution_at_1, 1e-4));
            }
        }
        // Effect of the clamp: the same alpha with a pulling force ends with a lower speed.
        const double alpha = unit.alpha;
        const double kn = 4.0 / 3.0 * effective_modulus_of(hertz_spec()) * std::sqrt(kRadius);
        const auto pulling = [alpha, kn](double x, double v) {
            const double root = x > 0.0 ? std::sqrt(std::sqrt(x)) : 0.0;
            return kn * x * root * root + alpha * std::sqrt(kMass * kn) * root * v;
        };
        const double speed = 5.0;
        const ImpactRun free =
            integrate_impact(pulling, kMass, speed, law.contact_duration(speed) / 20000.0, true);
        CAPTURE(e, alpha, free.restitution / speed);
        CHECK(free.restitution / speed < e);
    }
}

TEST_CASE("elastic Hertz law against Hertz's impact solution", "[wall_contact]") {
    const WallContact spec = hertz_spec();
    const WallContactLaw law = make_law(spec, 1.0);
    for (const double speed : {1.0, 8.0}) {
        const HertzImpact hertz = hertz_impact(effective_modulus_of(spec), kRadius, kMass, speed);
        // Energy balance at the deepest point: 2/5 k_n d_max^2.5 = m v^2 / 2.
        const double kn = 4.0 / 3.0 * effective_modulus_of(spec) * std::sqrt(kRadius);
        CHECK_THAT(0.4 * kn * std::pow(hertz.max_overlap, 2.5),
                   WithinRel(0.5 * kMass * speed * speed, 1e-12));
        const ImpactRun run =
            integrate_impact(law_force(law), kMass, speed, hertz.duration / 20000.0);
        CAPTURE(speed, run.peak_force, hertz.peak_force, run.duration, hertz.duration);
        CHECK_THAT(run.peak_force, WithinRel(hertz.peak_force, 0.01));
        CHECK_THAT(run.duration, WithinRel(hertz.duration, 0.01));
        CHECK_THAT(run.restitution / speed, WithinRel(1.0, 1e-4));
        CHECK_THAT(law.contact_duration(speed), WithinRel(hertz.duration, 0.01));
    }
}

TEST_CASE("Hertz-equivalent linear stiffness reproduces Hertz's peak force", "[wall_contact]") {
    const WallContact spec = linear_spec(0.0);
    for (const double e : {0.3, 0.8}) {
        WallContactLaw law = make_law(spec, e);
        for (const double speed : {2.0, 8.0}) {
            law.begin_contact(speed);
            const HertzImpact hertz =
                hertz_impact(effective_modulus_of(spec), kRadius, kMass, speed);
            const ImpactRun run = integrate_impact(law_force(law), kMass, speed,
                                                   law.contact_duration(speed) / 20000.0);
            CAPTURE(e, speed, law.stiffness(), run.peak_force, hertz.peak_force);
            CHECK_THAT(run.peak_force, WithinRel(hertz.peak_force, 0.01));
            CHECK_THAT(run.restitution / speed, WithinRel(e, 0.01));
        }
    }
}

TEST_CASE("restitution below the supported minimum is rejected", "[wall_contact]") {
    CHECK_THROWS_WITH(make_law(hertz_spec(), 0.0),
                      Catch::Contains("mean restitution of wall and rock"));
    CHECK_THROWS_AS(make_law(linear_spec(1e8), 0.005), std::invalid_argument);
}

namespace {

RockGeometry sphere_rock(double radius) {
    RockGeometry rock;
    rock.radius = radius;
    rock.nominal_size = 2.0 * radius;
    rock.bounding_radius = radius;
    return rock;
}

// A cube of side 2 h as a hull rock (only the vertices matter to the overlap).
RockGeometry cube_rock(double h) {
    RockGeometry rock;
    rock.kind = rockfall::shapes::RockKind::massive;
    rock.nominal_size = 2.0 * h;
    for (const double x : {-h, h}) {
        for (const double y : {-h, h}) {
            for (const double z : {-h, h}) {
                rock.hull.vertices.emplace_back(x, y, z);
            }
        }
    }
    rock.bounding_radius = std::sqrt(3.0) * h;
    return rock;
}

void check_vec(const Vec3& actual, const Vec3& expected, double tolerance) {
    CAPTURE(actual.transpose(), expected.transpose());
    CHECK((actual - expected).norm() <= tolerance);
}

}  // namespace

TEST_CASE("wall overlap of a sphere", "[wall_contact]") {
    const OrientedBox wall = seed_wall();
    const RockGeometry rock = sphere_rock(0.1);
    const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();

    CHECK_FALSE(wall_overlap(wall, rock, Vec3(9.64, 0.3, 0.5), identity));

    const std::optional<WallOverlap> face =
        wall_overlap(wall, rock, Vec3(9.66, 0.3, 0.5), identity);
    REQUIRE(face);
    CHECK_THAT(face->depth, WithinAbs(0.01, 1e-12));
    check_vec(face->normal, Vec3(-1.0, 0.0, 0.0), 1e-12);
    // The sphere's deepest point.
    check_vec(face->point, Vec3(9.76, 0.3, 0.5), 1e-12);

    // Over the wall's top edge: the normal points from the edge to the centre.
    const std::optional<WallOverlap> edge =
        wall_overlap(wall, rock, Vec3(9.7, 0.0, 1.55), identity);
    REQUIRE(edge);
    CHECK_THAT(edge->depth, WithinAbs(0.1 - 0.05 * std::sqrt(2.0), 1e-12));
    check_vec(edge->normal, Vec3(-1.0, 0.0, 1.0).normalized(), 1e-12);
}

TEST_CASE("wall overlap of a cube", "[wall_contact]") {
    const OrientedBox wall = seed_wall();
    const RockGeometry rock = cube_rock(0.1);
    const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();

    CHECK_FALSE(wall_overlap(wall, rock, Vec3(9.64, 0.0, 0.5), identity));

    // Face on: four vertices 10 mm deep, one contact at the face's centre.
    const std::optional<WallOverlap> face =
        wall_overlap(wall, rock, Vec3(9.66, 0.0, 0.5), identity);
    REQUIRE(face);
    CHECK_THAT(face->depth, WithinAbs(0.01, 1e-12));
    check_vec(face->normal, Vec3(-1.0, 0.0, 0.0), 1e-12);
    check_vec(face->point, Vec3(9.76, 0.0, 0.5), 1e-12);

    // Edge first, turned 45 degrees about z: the two vertices of the leading edge.
    const Eigen::Quaterniond yaw(Eigen::AngleAxisd(std::numbers::pi / 4.0, Vec3::UnitZ()));
    const double reach = 0.1 * std::sqrt(2.0);
    const std::optional<WallOverlap> edge =
        wall_overlap(wall, rock, Vec3(9.75 - reach + 0.004, 0.2, 0.5), yaw);
    REQUIRE(edge);
    CHECK_THAT(edge->depth, WithinAbs(0.004, 1e-12));
    check_vec(edge->point, Vec3(9.754, 0.2, 0.5), 1e-12);

    // Tilted about y: two vertex pairs at different depths, the point weighted by depth.
    const double tilt = 0.1;
    const Eigen::Quaterniond pitch(Eigen::AngleAxisd(tilt, Vec3::UnitY()));
    const double shallow = 0.002;
    const double deep = shallow + 0.2 * std::sin(tilt);
    const double x = 9.75 + shallow - 0.1 * (std::cos(tilt) - std::sin(tilt));
    const std::optional<WallOverlap> tilted = wall_overlap(wall, rock, Vec3(x, 0.0, 0.5), pitch);
    REQUIRE(tilted);
    CHECK_THAT(tilted->depth, WithinAbs(deep, 1e-12));
    check_vec(tilted->normal, Vec3(-1.0, 0.0, 0.0), 1e-12);
    // Pair positions (x, z) from rotating the body corners (0.1, +-0.1) by the pitch.
    const Eigen::Matrix3d r = pitch.toRotationMatrix();
    const Vec3 deep_pair = Vec3(x, 0.0, 0.5) + r * Vec3(0.1, 0.0, 0.1);
    const Vec3 shallow_pair = Vec3(x, 0.0, 0.5) + r * Vec3(0.1, 0.0, -0.1);
    check_vec(tilted->point, (deep * deep_pair + shallow * shallow_pair) / (deep + shallow), 1e-12);
}

TEST_CASE("wall friction opposes slip, saturates at Coulomb and never pulls", "[wall_contact]") {
    WallContactLaw law = make_law(hertz_spec(), 0.5);
    REQUIRE_THAT(law.friction(), WithinRel(0.5, 1e-12));
    const double speed = 8.0;
    law.begin_contact(speed);
    const WallOverlap overlap{1e-3, Vec3(-1.0, 0.0, 0.0), Vec3(9.75, 0.0, 0.5), {}};

    // Fast slip along +y while pressing into the wall: full Coulomb friction along -y.
    const WallForce sliding = law.force(overlap, Vec3(2.0, 3.0, 0.0));
    CHECK_THAT(sliding.normal, WithinRel(law.normal_force(1e-3, 2.0), 1e-12));
    CHECK_THAT(sliding.tangential, WithinRel(0.5 * sliding.normal, 1e-12));
    check_vec(sliding.force, Vec3(-sliding.normal, -sliding.tangential, 0.0),
              1e-12 * sliding.normal);
    check_vec(sliding.normal_direction, Vec3(-1.0, 0.0, 0.0), 0.0);

    // Creeping slip: no more than stops the slip of m / 7 within one fine step.
    const double fine_step = law.contact_duration(speed) / hertz_spec().steps_per_contact;
    const WallForce creeping = law.force(overlap, Vec3(2.0, 0.0, 1e-4));
    CHECK_THAT(creeping.tangential,
               WithinRel(kMass / WallContactLaw::kTangentialMassRatio * 1e-4 / fine_step, 1e-9));
    CHECK(creeping.tangential < 0.5 * creeping.normal);
    CHECK(creeping.force.z() < 0.0);

    // Receding fast: the damping would pull, the clamp gives no force at all.
    const WallForce receding = law.force(overlap, Vec3(-20.0, 1.0, 0.0));
    CHECK(receding.normal == 0.0);
    CHECK(receding.force.norm() == 0.0);
}

namespace {

RockState state_at(double time, const Vec3& velocity, double energy) {
    RockState state;
    state.time = time;
    state.velocity = velocity;
    state.angular_velocity = Vec3(0.0, time, 0.0);
    state.translational_energy = energy;
    state.rotational_energy = 0.5 * energy;
    return state;
}

WallForce wall_force(double normal, double tangential_z, const Vec3& point) {
    WallForce force;
    force.normal_direction = Vec3(-1.0, 0.0, 0.0);
    force.normal = normal;
    force.tangential = std::abs(tangential_z);
    force.force = Vec3(-normal, 0.0, tangential_z);
    force.point = point;
    return force;
}

}  // namespace

TEST_CASE("load cell: one event from first force to the first step without", "[wall_contact]") {
    LoadCell cell;
    const double dt = 1e-3;
    // States at t = 0.000 ... 0.005: approaching at 4 m/s, rebounding at 1 m/s.
    std::vector<RockState> s;
    for (int i = 0; i <= 5; ++i) {
        const double v = i <= 1 ? 4.0 : (i == 2 ? 2.0 : -1.0);
        s.push_back(state_at(i * dt, Vec3(v, 0.0, -0.5), 10.0 * (6 - i)));
    }
    cell.record(dt, std::nullopt, s[0], s[1]);
    CHECK_FALSE(cell.in_contact());
    cell.record(dt, wall_force(100.0, -10.0, Vec3(9.75, 0.0, 0.4)), s[1], s[2]);
    CHECK(cell.in_contact());
    cell.record(dt, wall_force(300.0, -30.0, Vec3(9.75, 0.0, 0.6)), s[2], s[3]);
    cell.record(dt, wall_force(200.0, 0.0, Vec3(9.75, 0.2, 0.6)), s[3], s[4]);
    CHECK(cell.hits().empty());
    // The overlap lingers with zero force after separation: that closes the event.
    cell.record(dt, wall_force(0.0, 0.0, Vec3(9.75, 0.0, 0.6)), s[4], s[5]);
    CHECK_FALSE(cell.in_contact());
    REQUIRE(cell.hits().size() == 1);

    const WallHit& hit = cell.hits()[0];
    CHECK_THAT(hit.start_time, WithinAbs(0.001, 1e-15));
    CHECK_THAT(hit.end_time, WithinAbs(0.004, 1e-15));
    CHECK_THAT(hit.normal_impulse, WithinRel(0.6, 1e-12));
    // On the wall: opposite to the friction on the rock.
    check_vec(hit.tangential_impulse, Vec3(0.0, 0.0, 0.04), 1e-15);
    CHECK(hit.peak_normal_force == 300.0);
    CHECK_THAT(hit.peak_time, WithinAbs(0.002, 1e-15));
    check_vec(hit.point, Vec3(9.75, 200.0 * 0.2 / 600.0, (100.0 * 0.4 + 500.0 * 0.6) / 600.0),
              1e-12);
    REQUIRE(hit.history.size() == 3);
    CHECK(hit.history[1].normal == 300.0);
    CHECK(hit.history[1].tangential == 30.0);
    CHECK_THAT(hit.history[2].time, WithinAbs(0.003, 1e-15));
    check_vec(hit.velocity_before, Vec3(4.0, 0.0, -0.5), 0.0);
    check_vec(hit.velocity_after, Vec3(-1.0, 0.0, -0.5), 0.0);
    check_vec(hit.angular_velocity_before, Vec3(0.0, 0.001, 0.0), 0.0);
    check_vec(hit.angular_velocity_after, Vec3(0.0, 0.004, 0.0), 0.0);
    CHECK(hit.energy_before == 75.0);
    CHECK(hit.energy_after == 30.0);
    CHECK(hit.normal_speed == 4.0);

    // A second touch is a second event; finish() closes it at the end of the run.
    cell.record(dt, wall_force(50.0, 0.0, Vec3(9.75, 0.0, 0.5)), s[4], s[5]);
    CHECK(cell.in_contact());
    cell.finish(s[5]);
    CHECK_FALSE(cell.in_contact());
    REQUIRE(cell.hits().size() == 2);
    CHECK_THAT(cell.hits()[1].normal_impulse, WithinRel(0.05, 1e-12));
    CHECK_THAT(cell.hits()[1].end_time, WithinAbs(0.005, 1e-15));
    cell.finish(s[5]);
    CHECK(cell.hits().size() == 2);
}
