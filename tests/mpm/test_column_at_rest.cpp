// An elastic soil column at rest in a box with frictionless walls (plane strain). The base
// carries the weight; the lateral walls carry the at-rest thrust K0 gamma H^2 / 2 with
// K0 = nu / (1 - nu) (uniaxial strain). The column starts stress-free and settles under
// gravity with damping; forces are averaged over the last 0.2 s.
//
// The grid is placed explicitly: domain_min is a grid node, so node planes lie on the base and
// both walls when the column's width is a whole number of cells (the set-up an engineer
// chooses); then every Poisson ratio matches within 5 % at any cell size. With the walls
// between node planes they act up to a cell behind their surface (the default
// SolverSettings::boundary_reach = 0) and the thrust falls to 45 % of K0 gamma H^2 / 2 at
// h = 0.13 m; boundary_reach = 0.5 (the nearest node layer, within h/2) gives 89 % without
// volumetric averaging and 86 % with it (the default since 2026-12-04).
// The set-up is mpm::verification::column_at_rest.
#include "mpm/verification.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rockfall::mpm;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

using verification::column_at_rest;
using verification::ColumnForces;

TEST_CASE("Soil column at rest: base force and K0 thrust for every Poisson ratio",
          "[mpm][verification]") {
    const double nu = GENERATE(0.0, 0.1, 0.2, 0.3, 0.4, 0.45);
    const double cell = GENERATE(0.1, 0.13, 0.15);
    // Walls and base on node planes: a width of whole cells, the grid anchored at the corner.
    const double width = std::round(1.0 / cell) * cell;
    const ColumnForces f = column_at_rest(nu, cell, width, 4.0 * cell);
    WARN("nu " << nu << ", h " << cell << " m: base " << f.base << " N/m vs weight " << f.weight
               << "; lateral " << f.left << " and " << f.right
               << " N/m vs K0 gamma H^2/2 = " << f.thrust);
    CHECK_THAT(f.base, WithinRel(f.weight, 0.01));
    if (nu == 0.0) {
        CHECK_THAT(f.left, WithinAbs(0.0, 0.01 * f.weight));
        CHECK_THAT(f.right, WithinAbs(0.0, 0.01 * f.weight));
    } else {
        CHECK_THAT(f.left, WithinRel(f.thrust, 0.05));
        CHECK_THAT(f.right, WithinRel(f.thrust, 0.05));
    }
}

TEST_CASE("Soil column at rest: walls between node planes act at the nearest node layer",
          "[mpm][verification]") {
    // h = 0.13 m from x = -0.5: the left wall's nearest node is 0.02 m inside the soil, the
    // right wall's 0.06 m behind it, the base's 0.02 m above it.
    const ColumnForces nearest = column_at_rest(0.3, 0.13, 1.0, 0.5, 0.5);
    const ColumnForces behind = column_at_rest(0.3, 0.13, 1.0, 0.5);
    // Each particle's own volumetric rate (the solver before 2026-12-04).
    const ColumnForces own_rate = column_at_rest(0.3, 0.13, 1.0, 0.5, 0.5, false);
    WARN("misaligned walls, nu 0.3: lateral " << nearest.left << " N/m (nearest node layer), "
                                              << own_rate.left << " N/m (same, own rates), "
                                              << behind.left << " N/m (nodes inside only) vs "
                                              << nearest.thrust);
    CHECK_THAT(nearest.base, WithinRel(nearest.weight, 0.01));
    CHECK_THAT(own_rate.left, WithinRel(own_rate.thrust, 0.12));
    // Averaged over dual cells, the rate next to a wall acting up to h/2 off its surface mixes
    // the wall's cell with the soil's: 3 points lower (14.0 % below K0 gamma H^2 / 2).
    CHECK_THAT(nearest.left, WithinRel(nearest.thrust, 0.15));
    CHECK(behind.left < 0.6 * behind.thrust);
}
