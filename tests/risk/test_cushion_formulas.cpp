#include "risk/cushion_formulas.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall::risk;

namespace {

constexpr double kn = 1.0e3;  // N per kN

// A 1 t block falling 10 m: v = sqrt(2 g H) = sqrt(196.2) = 14.00714 m/s, so
// W H = m v^2 / 2 = 9.81 kN x 10 m = 98.1 kJ and (W H)^(3/5) = 98.1^0.6 = 15.66756.
const double velocity = std::sqrt(2.0 * 9.81 * 10.0);
constexpr double mass = 1000.0;
// Cushion M_E = 5 MPa = 5000 kN/m2: 5000^0.4 = 30.17088.
constexpr double modulus = 5.0e6;

LabiouseInputs labiouse_case() { return {mass, velocity, 0.5, modulus}; }
AstraInputs astra_case() { return {mass, velocity, 0.5, modulus, 1.0, 35.0}; }

}  // namespace

TEST_CASE("Labiouse formula gives the hand-computed value", "[risk][formulas]") {
    // F = 1.765 x 30.17088 x 0.5^0.2 (= 0.870551) x 15.66756 = 726.32 kN.
    CHECK_THAT(labiouse_impact_force(labiouse_case()), WithinAbs(726.32 * kn, 0.005 * kn));
}

TEST_CASE("ASTRA formula gives the hand-computed value", "[risk][formulas]") {
    // F = 2.8 x 1^-0.5 x 0.5^0.7 (= 0.615572) x 30.17088 x tan(35 deg)^0.2 (= 0.700208^0.2
    //   = 0.931205) x 15.66756 = 758.70 kN.
    CHECK_THAT(astra_impact_force(astra_case()), WithinAbs(758.70 * kn, 0.005 * kn));
}

TEST_CASE("cushion formulas follow their exponents", "[risk][formulas]") {
    const double labiouse = labiouse_impact_force(labiouse_case());
    const double astra = astra_impact_force(astra_case());

    LabiouseInputs l = labiouse_case();
    l.radius *= 32.0;  // R^(1/5)
    CHECK_THAT(labiouse_impact_force(l), WithinRel(2.0 * labiouse, 1e-12));
    l = labiouse_case();
    l.cushion_modulus *= 32.0;  // M_E^(2/5)
    CHECK_THAT(labiouse_impact_force(l), WithinRel(4.0 * labiouse, 1e-12));
    l = labiouse_case();
    l.velocity *= 2.0;  // energy x 4, (x 4)^(3/5)
    CHECK_THAT(labiouse_impact_force(l), WithinRel(std::pow(4.0, 0.6) * labiouse, 1e-12));

    AstraInputs a = astra_case();
    a.cushion_thickness = 4.0;  // e^(-1/2)
    CHECK_THAT(astra_impact_force(a), WithinRel(0.5 * astra, 1e-12));
    a = astra_case();
    a.mass *= 32.0;  // energy x 32, (x 32)^(3/5) = 8
    CHECK_THAT(astra_impact_force(a), WithinRel(8.0 * astra, 1e-12));
    a = astra_case();
    a.friction_angle_deg = 45.0;  // tan 45 = 1: the factor 0.931205 drops out
    CHECK_THAT(astra_impact_force(a), WithinRel(astra / 0.931205, 1e-6));

    // Same Hertz core: ASTRA / Labiouse = (2.8 / 1.765) e^(-1/2) r^(1/2) tan(phi)^(1/5).
    const double ratio =
        2.8 / 1.765 * std::sqrt(0.5) * std::pow(std::tan(35.0 * std::numbers::pi / 180.0), 0.2);
    CHECK_THAT(astra / labiouse, WithinRel(ratio, 1e-12));
}

TEST_CASE("equivalent radius inverts the sphere volume", "[risk][formulas]") {
    // A 0.2 m sphere at 2600 kg/m3: m = 4/3 pi 0.1^3 x 2600 = 10.8909 kg.
    const double m = 4.0 / 3.0 * std::numbers::pi * 1e-3 * 2600.0;
    CHECK_THAT(equivalent_radius(m, 2600.0), WithinRel(0.1, 1e-14));
    CHECK_THROWS_WITH(equivalent_radius(m, 0.0), Contains("density = 0 kg/m3"));
}

TEST_CASE("bad cushion inputs throw naming field, value and unit", "[risk][formulas]") {
    LabiouseInputs l = labiouse_case();
    l.mass = -1.0;
    CHECK_THROWS_WITH(labiouse_impact_force(l),
                      Contains("mass = -1 kg") && Contains("must be finite and > 0"));
    l = labiouse_case();
    l.velocity = 0.0;
    CHECK_THROWS_WITH(labiouse_impact_force(l), Contains("velocity = 0 m/s"));
    l = labiouse_case();
    l.cushion_modulus = -5.0;
    CHECK_THROWS_WITH(labiouse_impact_force(l), Contains("cushion modulus M_E = -5 Pa"));

    AstraInputs a = astra_case();
    a.cushion_thickness = 0.0;
    CHECK_THROWS_WITH(astra_impact_force(a), Contains("cushion thickness = 0 m"));
    a = astra_case();
    a.friction_angle_deg = 90.0;
    CHECK_THROWS_WITH(astra_impact_force(a),
                      Contains("friction angle = 90 deg") && Contains("must be in (0, 90)"));
    a = astra_case();
    a.radius = std::nan("");
    CHECK_THROWS_AS(astra_impact_force(a), std::invalid_argument);
}
