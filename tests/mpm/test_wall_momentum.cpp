// Momentum balance at a fixed wall: a soil block slides on a frictionless floor into the wall.
// The wall load is the momentum the wall's nodes lose, so its time integral must equal the
// horizontal momentum the soil lost (the floor takes none).
#include "helpers.hpp"

#include "mpm/setup.hpp"
#include "mpm/solver.hpp"

#include <catch2/catch.hpp>

#include <vector>

using namespace rockfall::mpm;
using namespace rockfall::mpm::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

template <int Dim>
void check_wall_balance(double h) {
    Particles<Dim> soil;
    add_box_particles<Dim>(soil, axis_box(Vec3(0.5, -0.3, 0.0), Vec3(1.5, 0.3, 0.4)), h / 2.0,
                           1640.0);
    for (auto& v : soil.velocity) {
        v[0] = 3.0;
    }
    SolverSettings s;
    s.threads = 1;
    s.cell_size = h;
    s.domain_min = Vec3(0.0, -0.8, -0.4);
    s.domain_max = Vec3(3.6, 0.8, 1.6);
    std::vector<StaticBoundary> boundaries{
        solid(axis_box(Vec3(-1.0, -2.0, -1.0), Vec3(5.0, 2.0, 0.0)), BoundaryKind::frictional, 0.0,
              0),
        solid(axis_box(Vec3(3.0, -2.0, -1.0), Vec3(4.0, 2.0, 2.0)), BoundaryKind::fixed, 0.0, 1)};
    Solver<Dim> solver(s, DruckerPrager{}, std::move(soil), std::move(boundaries));
    const double p0 = solver.particles().momentum()[0];
    double wall_impulse = 0.0;
    double floor_impulse = 0.0;
    while (solver.time() < 1.5) {
        const StepReport& r = solver.step(solver.stable_time_step());
        wall_impulse += r.impulse[1].x();
        floor_impulse += r.impulse[0].x();
        REQUIRE(r.clamped_particles == 0);
    }
    const double lost = p0 - solver.particles().momentum()[0];
    WARN(Dim << "D: horizontal momentum lost " << lost << ", wall impulse " << wall_impulse
             << ", floor impulse " << floor_impulse << " (N s" << (Dim == 2 ? "/m)" : ")"));
    CHECK(lost > 0.5 * p0);
    CHECK_THAT(wall_impulse, WithinRel(lost, 0.02));
    CHECK_THAT(floor_impulse, WithinAbs(0.0, 1e-12 * p0));
}

}  // namespace

TEST_CASE("Wall impulse equals the horizontal momentum the soil lost (2D)", "[mpm][verification]") {
    check_wall_balance<2>(0.05);
}

TEST_CASE("Wall impulse equals the horizontal momentum the soil lost (3D)", "[mpm][verification]") {
    check_wall_balance<3>(0.1);
}
