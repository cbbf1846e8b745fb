// Exact mass properties of the five Platonic solids against their closed forms.

#include "shapes/mass_properties.hpp"
#include "shapes/platonic.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

namespace {

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using rockfall::shapes::PlatonicKind;

// Volume, area and moment of inertia about any axis through the centre per unit density, for
// edge a: V = v a^3, A = s a^2, I = k V a^2 (closed forms as tabulated by Coxeter, "Regular
// Polytopes", and, for the moments, Satterly 1957 / the standard tables: tetrahedron 1/20,
// cube 1/6, octahedron 1/10, dodecahedron (95 + 39 sqrt 5)/300, icosahedron phi^2/10).
struct ClosedForm {
    PlatonicKind kind;
    double volume;
    double area;
    double moment;
};

}  // namespace

TEST_CASE("Platonic solids have their exact volume, area, centroid and inertia",
          "[shapes][verification]") {
    const double r5 = std::sqrt(5.0);
    const double r3 = std::sqrt(3.0);
    const double phi = std::numbers::phi;
    const ClosedForm solids[] = {
        {PlatonicKind::tetrahedron, 1.0 / (6.0 * std::numbers::sqrt2), r3, 1.0 / 20.0},
        {PlatonicKind::cube, 1.0, 6.0, 1.0 / 6.0},
        {PlatonicKind::octahedron, std::numbers::sqrt2 / 3.0, 2.0 * r3, 1.0 / 10.0},
        {PlatonicKind::dodecahedron, (15.0 + 7.0 * r5) / 4.0, 3.0 * std::sqrt(25.0 + 10.0 * r5),
         (95.0 + 39.0 * r5) / 300.0},
        {PlatonicKind::icosahedron, 5.0 * (3.0 + r5) / 12.0, 5.0 * r3, phi * phi / 10.0},
    };
    for (const double a : {1.0, 0.137}) {
        for (const ClosedForm& solid : solids) {
            INFO(rockfall::shapes::to_string(solid.kind) << ", edge " << a);
            const auto p =
                rockfall::shapes::mass_properties(rockfall::shapes::platonic_solid(solid.kind, a));
            const double volume = solid.volume * a * a * a;
            CHECK_THAT(p.volume, WithinRel(volume, 1e-12));
            CHECK_THAT(p.surface_area, WithinRel(solid.area * a * a, 1e-12));
            const double moment = solid.moment * volume * a * a;
            for (int i = 0; i < 3; ++i) {
                CHECK_THAT(p.centroid[i], WithinAbs(0.0, 1e-14 * a));
                CHECK_THAT(p.principal_moments[i], WithinRel(moment, 1e-12));
                for (int j = 0; j < 3; ++j) {
                    CHECK_THAT(p.inertia(i, j), WithinAbs(i == j ? moment : 0.0, 1e-12 * moment));
                }
            }
        }
    }
}
