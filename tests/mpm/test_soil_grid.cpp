// Grid placement of the soil scenario (SoilNumerics::align_grid, boundary_reach): node planes
// on the wall's face and the run-out surface when aligned, the placement of before otherwise.
#include "helpers.hpp"
#include "soil_model.hpp"

#include "mpm/soil.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace rockfall::mpm;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

SoilScenario quick_2d(double cell, bool align) {
    SoilScenario s = test::quick_2d(cell);
    s.numerics.align_grid = align;
    return s;
}

// Distance of x from the nearest node plane origin + k h, in cells.
double off_lattice(double x, double origin, double h) {
    const double cells = (x - origin) / h;
    return std::abs(cells - std::round(cells));
}

}  // namespace

TEST_CASE("Soil grid: aligned node planes lie on the wall face and the run-out surface",
          "[mpm][soil]") {
    for (const double h : {0.2, 0.15, 0.13, 0.1, 0.07}) {
        CAPTURE(h);
        const auto aligned = detail::build_soil_model<2>(quick_2d(h, true));
        const auto old = detail::build_soil_model<2>(quick_2d(h, false));
        const Vec3 lo = aligned.solver->settings().domain_min;
        const Vec3 lo_old = old.solver->settings().domain_min;
        const double wall_x = aligned.slope.wall_x();
        const double run_out_z = aligned.slope.surface_height(aligned.slope.toe_x());
        CHECK(off_lattice(wall_x, lo.x(), h) < 1e-9);
        CHECK(off_lattice(run_out_z, lo.z(), h) < 1e-9);
        // Aligning moves the first node back by at most a cell from where it was.
        CHECK(lo.x() <= lo_old.x());
        CHECK(lo.x() >= lo_old.x() - h * (1.0 + 1e-9));
        CHECK(lo.z() <= lo_old.z());
        CHECK(lo.z() >= lo_old.z() - h * (1.0 + 1e-9));
    }
    // At these cell sizes the old corner puts the wall's face between node planes.
    for (const double h : {0.2, 0.1}) {
        const auto old = detail::build_soil_model<2>(quick_2d(h, false));
        CHECK(off_lattice(old.slope.wall_x(), old.solver->settings().domain_min.x(), h) > 0.01);
    }
}

TEST_CASE("Soil grid: align_grid false reproduces the flow of the old placement",
          "[mpm][soil][regression]") {
    // docs/soil.md, grid placement: rockfall soil samples/soil/quick_2d.toml with align_grid =
    // false at 0.2 and 0.1 m cells, since the hinge's wedge was closed (before that, at 51bb616:
    // 5.71 kN/m at 3.28 s, 0.54 m and 9.52 kN/m at 3.33 s, 0.48 m).
    struct Before {
        double cell, peak, peak_time, runout;
    };
    for (const Before& b : {Before{0.2, 5.787e3, 3.26, 0.54}, Before{0.1, 9.009e3, 3.03, 0.50}}) {
        CAPTURE(b.cell);
        SoilScenario s = quick_2d(b.cell, false);
        // The solver of those numbers: each particle's own volumetric rate.
        s.numerics.volumetric_averaging = false;
        const SoilOutcome o = run_soil(s);
        REQUIRE(o.status == SoilStatus::completed);
        // Those peaks were read on the 0.01 s sample grid (the largest sample, at its end).
        const auto largest = std::max_element(o.wall_force.begin(), o.wall_force.end());
        const auto k = static_cast<std::size_t>(largest - o.wall_force.begin());
        CHECK_THAT(*largest, WithinRel(b.peak, 0.005));
        CHECK_THAT(o.sample_time[k], WithinAbs(b.peak_time, 0.005));
        CHECK_THAT(o.deposit.runout_past_toe, WithinAbs(b.runout, 0.005));
    }
}

TEST_CASE("Soil grid: boundary_reach is validated and reaches the solver", "[mpm][soil]") {
    SoilScenario s = quick_2d(0.2, false);
    s.numerics.boundary_reach = 0.5;
    CHECK(detail::build_soil_model<2>(s).solver->settings().boundary_reach == 0.5);
    s.numerics.boundary_reach = 0.6;
    CHECK_THROWS_WITH(validate(s), Catch::Matchers::Contains(
                                       "numerics.boundary_reach = 0.6: must be in [0, 0.5]"));
}

TEST_CASE("Soil numerics: flip and min_density_ratio are validated and reach the solver",
          "[mpm][soil]") {
    SoilScenario s = quick_2d(0.2, true);
    CHECK(detail::build_soil_model<2>(s).solver->settings().flip == 0.0);
    s.numerics.flip = 0.99;
    CHECK(detail::build_soil_model<2>(s).solver->settings().flip == 0.99);
    s.numerics.min_density_ratio = 0.5;
    CHECK(detail::build_soil_model<2>(s).solver->settings().min_density_ratio == 0.5);
    s.numerics.flip = -0.1;
    CHECK_THROWS_WITH(validate(s),
                      Catch::Matchers::Contains("numerics.flip = -0.1: must be in [0, 1]"));
    s.numerics.flip = 0.0;
    s.numerics.min_density_ratio = 1.0;
    CHECK_THROWS_WITH(validate(s), Catch::Matchers::Contains(
                                       "numerics.min_density_ratio = 1: must be in [0, 1)"));
}

TEST_CASE("Soil spring-backed wall: stiff as the rigid wall; at rest displaced by load / k",
          "[mpm][soil]") {
    const SoilOutcome rigid = run_soil(quick_2d(0.2, true));
    SoilScenario s = quick_2d(0.2, true);
    s.boundaries.wall_support = WallSupport::spring;
    s.boundaries.wall_stiffness = 1e9;
    const SoilOutcome stiff = run_soil(s);
    CHECK_THAT(stiff.peak_wall_force, WithinRel(rigid.peak_wall_force, 0.005));
    CHECK_THAT(stiff.wall_impulse, WithinRel(rigid.wall_impulse, 0.005));
    CHECK(rigid.max_wall_displacement == 0.0);

    s.boundaries.wall_stiffness = 1e6;
    s.boundaries.wall_damping_ratio = 1.0;
    const SoilOutcome soft = run_soil(s);
    REQUIRE(soft.status == SoilStatus::completed);
    // The deposit rests against the wall: the spring holds the last load.
    const double k = s.boundaries.wall_stiffness * s.slope.wall.height;  // N/m per m
    CHECK_THAT(soft.final_wall_displacement, WithinRel(soft.wall_force.back() / k, 0.02));
    CHECK(soft.max_wall_displacement >= soft.final_wall_displacement);
    CHECK(soft.max_wall_displacement < 0.05 * s.numerics.cell_size);
}
