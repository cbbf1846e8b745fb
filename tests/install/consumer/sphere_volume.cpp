// The volume of a sphere through the installed rockfall::shapes: the exact value it carries and
// the volume of its tessellated hull, both against 4/3 pi r^3.

#include "shapes/mass_properties.hpp"
#include "shapes/rocks.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

int main() {
    namespace shapes = rockfall::shapes;
    const double radius = 0.75;
    const double expected = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
    const shapes::RockGeometry rock = shapes::make_rock(shapes::RockKind::sphere, 2.0 * radius);
    const double exact = rock.properties.volume;
    const double hull = shapes::mass_properties(rock.hull).volume;
    std::printf("sphere of radius %.2f m: volume %.6f m3, hull %.6f m3, 4/3 pi r^3 = %.6f m3\n",
                radius, exact, hull, expected);
    // The hull is inscribed in the sphere: a little smaller, within 2 %.
    const bool ok =
        std::abs(exact - expected) <= 1e-12 * expected && hull < expected && hull > 0.98 * expected;
    if (!ok) std::printf("sphere_volume: FAILED\n");
    return ok ? 0 : 1;
}
