#include "risk/formulas.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall::risk;

namespace {

// The worked example: m = 0.0105 t, v = 8 m/s, lambda = 5.0e5 kN/m2, g = 9.81.
constexpr double mass = 10.5;     // kg
constexpr double velocity = 8.0;  // m/s
constexpr double kn = 1.0e3;      // N per kN
// The issue quotes its values to 0.01 kN.
constexpr double quoted = 0.005 * kn;

ImpactCoefficients with_factors(double alpha, double beta) { return {seed_lambda, alpha, beta}; }

}  // namespace

TEST_CASE("handbook formula gives the issue's worked values", "[risk][formulas]") {
    CHECK_THAT(jra_impact_force(mass, velocity, jra_coefficients(5.0e8)),
               WithinAbs(179.25 * kn, quoted));
    CHECK_THAT(jra_impact_force(mass, velocity, with_factors(1.3, 1.0)),
               WithinAbs(233.02 * kn, quoted));
    CHECK_THAT(jra_impact_force(mass, velocity, with_factors(1.6, 0.5)),
               WithinAbs(143.40 * kn, quoted));
    CHECK_THAT(jra_impact_force(mass, velocity, with_factors(1.7, 0.4)),
               WithinAbs(121.89 * kn, quoted));
}

TEST_CASE("handbook formula follows its exponents", "[risk][formulas]") {
    const ImpactCoefficients c = jra_coefficients(seed_lambda);
    const double p = jra_impact_force(mass, velocity, c);
    // P ~ m^(2/3), v^(6/5) (H^(3/5) with H ~ v^2), lambda^(2/5).
    CHECK_THAT(jra_impact_force(8.0 * mass, velocity, c), WithinRel(4.0 * p, 1e-12));
    CHECK_THAT(jra_impact_force(mass, 2.0 * velocity, c), WithinRel(std::pow(2.0, 1.2) * p, 1e-12));
    CHECK_THAT(jra_impact_force(mass, velocity, jra_coefficients(32.0 * seed_lambda)),
               WithinRel(4.0 * p, 1e-12));
}

TEST_CASE("seed presets carry the paper's coefficients", "[risk][formulas]") {
    const ImpactCoefficients sphere = seed_coefficients(ImpactShape::sphere);
    const ImpactCoefficients massive = seed_coefficients(ImpactShape::massive);
    const ImpactCoefficients planar = seed_coefficients(ImpactShape::planar);
    CHECK(sphere.lambda == 5.0e8);
    CHECK(massive.lambda == 5.0e8);
    CHECK(planar.lambda == 5.0e8);
    CHECK(sphere.alpha == 1.3);
    CHECK(sphere.beta == 1.0);
    CHECK(massive.alpha == 1.6);
    CHECK(massive.beta == 0.5);
    CHECK(planar.alpha == 1.7);
    CHECK(planar.beta == 0.4);
    CHECK(kawase_lambda == 1.2e8);
    CHECK_THAT(jra_impact_force(mass, velocity, sphere), WithinAbs(233.02 * kn, quoted));
    CHECK_THAT(jra_impact_force(mass, velocity, massive), WithinAbs(143.40 * kn, quoted));
    CHECK_THAT(jra_impact_force(mass, velocity, planar), WithinAbs(121.89 * kn, quoted));
}

TEST_CASE("shape names round-trip", "[risk][formulas]") {
    for (const ImpactShape shape : all_impact_shapes) {
        CHECK(parse_impact_shape(to_string(shape)) == shape);
        CHECK(find_impact_shape(to_string(shape)) == shape);
    }
    CHECK(std::size(all_impact_shapes) == 3);
    CHECK_FALSE(find_impact_shape("custom").has_value());
    CHECK_THROWS_WITH(parse_impact_shape("cube"),
                      Contains("cube") && Contains("sphere, massive or planar"));
}

TEST_CASE("fall height form equals velocity form", "[risk][formulas]") {
    const double height = jra_equivalent_height(velocity);
    CHECK_THAT(height, WithinRel(64.0 / 19.62, 1e-14));
    CHECK_THAT(jra_impact_velocity(height), WithinRel(velocity, 1e-14));
    CHECK_THROWS_WITH(jra_impact_velocity(0.0), Contains("height = 0 m"));
    for (const ImpactShape shape :
         {ImpactShape::sphere, ImpactShape::massive, ImpactShape::planar}) {
        const ImpactCoefficients c = seed_coefficients(shape);
        CHECK_THAT(jra_impact_force_from_height(mass, height, c),
                   WithinRel(jra_impact_force(mass, velocity, c), 1e-14));
    }
}

TEST_CASE("bad formula inputs throw naming field, value, unit and range", "[risk][formulas]") {
    const ImpactCoefficients c = seed_coefficients(ImpactShape::sphere);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(jra_impact_force(-10.0, velocity, c),
                      Contains("mass = -10 kg") && Contains("must be finite and > 0"));
    CHECK_THROWS_WITH(jra_impact_force(0.0, velocity, c), Contains("mass = 0 kg"));
    CHECK_THROWS_WITH(jra_impact_force(mass, 0.0, c),
                      Contains("velocity = 0 m/s") && Contains("must be finite and > 0"));
    CHECK_THROWS_WITH(jra_impact_force(mass, -3.0, c), Contains("velocity = -3 m/s"));
    CHECK_THROWS_WITH(jra_impact_force(mass, nan, c), Contains("velocity = nan m/s"));
    CHECK_THROWS_WITH(jra_impact_force(mass, inf, c), Contains("velocity = inf m/s"));
    CHECK_THROWS_WITH(jra_impact_force_from_height(mass, -1.0, c),
                      Contains("height = -1 m") && Contains("must be finite and > 0"));
    CHECK_THROWS_WITH(jra_impact_force(mass, velocity, {-5.0e8, 1.0, 1.0}),
                      Contains("lambda = -5e+08 Pa") && Contains("must be finite and > 0"));
    CHECK_THROWS_WITH(jra_coefficients(0.0), Contains("lambda = 0 Pa"));
    CHECK_THROWS_WITH(jra_impact_force(mass, velocity, with_factors(0.0, 1.0)),
                      Contains("alpha = 0") && Contains("must be finite and > 0"));
    CHECK_THROWS_WITH(jra_impact_force(mass, velocity, with_factors(1.0, -0.5)),
                      Contains("beta = -0.5") && Contains("must be finite and > 0"));
    CHECK_THROWS_AS(jra_impact_force(nan, velocity, c), std::invalid_argument);
}
