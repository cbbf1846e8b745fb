// Mass properties and sphericities of the verification report: the Platonic solids against
// their closed forms (tests/shapes/test_platonic_mass.cpp, test_measures.cpp) and generated
// rocks against their target sphericity (test_generators.cpp).

#include "report/text_format.hpp"
#include "validate_sections.hpp"

#include "shapes/generators.hpp"
#include "shapes/mass_properties.hpp"
#include "shapes/measures.hpp"
#include "shapes/platonic.hpp"
#include "shapes/rocks.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace rockfall::app {
namespace {

using report::fmt;
using report::VvCheck;
using shapes::PlatonicKind;

// Volume, area and moment about any axis through the centre for unit edge a: V = v a^3,
// A = s a^2, I = k V a^2 per unit density (Coxeter, Regular Polytopes, table I; the moments as
// tabulated by Satterly 1957); Wadell sphericity to three decimals (Wadell 1935).
struct Solid {
    PlatonicKind kind;
    double volume;
    double area;
    double moment;
    double sphericity;
};

}  // namespace

report::VvSection shapes_section(const VvOptions&) {
    const double r5 = std::sqrt(5.0);
    const double r3 = std::sqrt(3.0);
    const double phi = std::numbers::phi;
    const Solid solids[] = {
        {PlatonicKind::tetrahedron, 1.0 / (6.0 * std::numbers::sqrt2), r3, 1.0 / 20.0, 0.671},
        {PlatonicKind::cube, 1.0, 6.0, 1.0 / 6.0, 0.806},
        {PlatonicKind::octahedron, std::numbers::sqrt2 / 3.0, 2.0 * r3, 1.0 / 10.0, 0.846},
        {PlatonicKind::dodecahedron, (15.0 + 7.0 * r5) / 4.0, 3.0 * std::sqrt(25.0 + 10.0 * r5),
         (95.0 + 39.0 * r5) / 300.0, 0.910},
        {PlatonicKind::icosahedron, 5.0 * (3.0 + r5) / 12.0, 5.0 * r3, phi * phi / 10.0, 0.939},
    };
    const double a = 0.3;  // edge, m
    report::VvTable mass{"Platonic solids of 0.3 m edge: hull mass properties (per unit density)",
                         {}};
    report::VvTable sphericity{"Wadell sphericity pi^(1/3) (6 V)^(2/3) / A", {}};
    for (const Solid& s : solids) {
        const std::string name(shapes::to_string(s.kind));
        const shapes::ShapeMeasures m = shapes::shape_measures(shapes::platonic_solid(s.kind, a));
        const double volume = s.volume * a * a * a;
        const std::string closed = "closed form (Coxeter, table I)";
        mass.checks.push_back(report::make_check("mass." + name + ".volume", name + ": volume",
                                                 "m3", volume, closed, m.properties.volume, 1e-9,
                                                 true));
        mass.checks.push_back(report::make_check("mass." + name + ".area", name + ": surface area",
                                                 "m2", s.area * a * a, closed,
                                                 m.properties.surface_area, 1e-9, true));
        // The largest principal moment: all three are equal for a Platonic solid.
        mass.checks.push_back(
            report::make_check("mass." + name + ".moment", name + ": largest principal moment",
                               "m5", s.moment * volume * a * a, "closed form (Satterly 1957)",
                               m.properties.principal_moments[2], 1e-9, true));
        mass.checks.push_back(report::make_check(
            "mass." + name + ".centroid", name + ": centroid offset", "m", 0.0,
            "centred on the origin", m.properties.centroid.norm(), 1e-12, false));
        sphericity.checks.push_back(report::make_check("sphericity." + name, name, "", s.sphericity,
                                                       "Wadell 1935, three decimals",
                                                       m.wadell_sphericity, 0.001, false));
    }
    report::VvTable generated{
        "Generated rocks of a target sphericity (rock_with_sphericity, 0.25 m, seed 0)", {}};
    for (const double target : {0.6, 0.72, 0.8, 0.89}) {
        const auto rock = shapes::rock_with_sphericity(target, 0);
        const shapes::ShapeMeasures m =
            shapes::shape_measures(shapes::make_rock({"rock", rock.hull}, 0.25));
        generated.checks.push_back(
            report::make_check(fmt("sphericity.generated.%g", target), fmt("target %g", target), "",
                               target, "the requested target", m.wadell_sphericity, 0.02, false));
    }
    report::VvSection section = report::vv_section(
        "shapes", "Mass properties and sphericities",
        {"Hulls by Qhull and their exact polyhedral mass properties (shapes/mass_properties.hpp) "
         "against the closed forms; relative tolerance 1e-9 (round-off: the exact algorithm "
         "agrees to about 1e-14). Sphericities against Wadell's three-decimal values within "
         "0.001 (the rounding of the published values).",
         "Generated rocks meet their target within 0.02, the tolerance issue 5 set for the "
         "shape generator (the bisection itself stops within 1e-4)."});
    section.tables = {mass, sphericity, generated};
    return section;
}

}  // namespace rockfall::app
