// The rounded-polyhedron wall law through the whole engine: a massive rock slides without
// friction into the reaction wall at 8 m/s, face first and edge first (turned 45 degrees
// about the vertical), and a sphere with hull_model = "rounded" keeps its Hertz law.

#include "wall_scenario.hpp"

#include "engine/simulation.hpp"
#include "engine/wall_contact.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace rockfall::engine;
using Catch::Matchers::WithinRel;

namespace {

using test::first_hit;

// A 0.2 m massive rock (the mass of the sphere of its nominal size) at 8 m/s.
constexpr double kSpeed = 8.0;
constexpr double kSize = 0.2;
constexpr double kDensity = 2600.0;
const double kMass = kDensity * std::numbers::pi / 6.0 * kSize * kSize * kSize;

WallContact rounded(int steps_per_contact = 100) {
    WallContact contact;
    contact.hull_model = WallContact::HullModel::rounded;
    contact.steps_per_contact = steps_per_contact;
    return contact;
}

// A massive rock at restitution e, turned by yaw_deg about the vertical.
Scenario massive_hit(const WallContact& contact, double e, double yaw_deg) {
    Scenario scenario = test::wall_scenario(contact, e, kSize, kSpeed, kDensity);
    scenario.rocks[0].rock.kind = rockfall::shapes::RockKind::massive;
    scenario.rocks[0].release.orientation_deg = Vec3(0.0, 0.0, yaw_deg);
    return scenario;
}

}  // namespace

TEST_CASE("rounded wall law: impulse equals the rock's momentum change", "[verification][wall]") {
    const Vec3 n(-1.0, 0.0, 0.0);
    for (const double yaw : {0.0, 45.0, 20.0}) {
        const Outcome outcome = simulate(massive_hit(rounded(), 0.3, yaw), 1);
        const WallHit& hit = first_hit(outcome);
        const double momentum_change = kMass * (hit.velocity_after - hit.velocity_before).dot(n);
        CAPTURE(yaw, outcome.rocks[0].wall_hits.size(), hit.normal_speed, hit.normal_impulse,
                momentum_change, hit.peak_normal_force, hit.history.size());
        CHECK_THAT(hit.normal_impulse, WithinRel(momentum_change, 0.02));
        CHECK(hit.history.size() >= 20);
        if (yaw == 0.0) {
            // Face first and without spin: the normal impulse is m (1 + e) v_n.
            CHECK_THAT(hit.normal_impulse, WithinRel(kMass * 1.3 * hit.normal_speed, 0.05));
        }
    }
}

TEST_CASE("rounded wall law: the peak converges when the contact step is halved",
          "[verification][wall]") {
    for (const double yaw : {0.0, 45.0, 20.0}) {
        const WallHit coarse = first_hit(simulate(massive_hit(rounded(40), 0.3, yaw), 1));
        const WallHit fine = first_hit(simulate(massive_hit(rounded(80), 0.3, yaw), 1));
        CAPTURE(yaw, coarse.peak_normal_force, fine.peak_normal_force, coarse.history.size(),
                fine.history.size());
        CHECK_THAT(coarse.peak_normal_force, WithinRel(fine.peak_normal_force, 0.05));
        CHECK_THAT(coarse.normal_impulse, WithinRel(fine.normal_impulse, 0.01));
    }
}

TEST_CASE("rounded wall law: a sphere still matches Hertz", "[verification][wall]") {
    // Nearly elastic, where Hertz's elastic solution is the reference (Tsuji's damping lowers
    // the peak by 3 % at e = 0.95); the sphere's law is the one of hull_model = "sphere".
    const double e = 0.95;
    const WallHit hit =
        first_hit(simulate(test::wall_scenario(rounded(), e, kSize, kSpeed, kDensity), 1));
    const WallHit sphere =
        first_hit(simulate(test::wall_scenario(WallContact{}, e, kSize, kSpeed, kDensity), 1));
    const WallContact contact;
    const double e_star =
        effective_modulus(contact.rock_youngs_modulus, contact.rock_poisson_ratio,
                          contact.wall_youngs_modulus, contact.wall_poisson_ratio);
    const HertzImpact hertz = hertz_impact(e_star, 0.5 * kSize, kMass, hit.normal_speed);
    CAPTURE(hit.peak_normal_force, sphere.peak_normal_force, hertz.peak_force);
    CHECK_THAT(hit.peak_normal_force, WithinRel(hertz.peak_force, 0.10));
    CHECK(hit.peak_normal_force == sphere.peak_normal_force);
}
