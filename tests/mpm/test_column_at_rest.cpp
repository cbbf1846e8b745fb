// An elastic soil column at rest in a box with frictionless walls (plane strain). The base
// carries the weight; the lateral walls carry the at-rest thrust K0 gamma H^2 / 2 with
// K0 = nu / (1 - nu) (uniaxial strain). The column starts stress-free and settles under
// gravity with damping; forces are averaged over the last 0.2 s.
#include "helpers.hpp"

#include "mpm/setup.hpp"
#include "mpm/solver.hpp"

#include <catch2/catch.hpp>

#include <vector>

using namespace rockfall::mpm;
using namespace rockfall::mpm::test;
using Catch::Matchers::WithinRel;

TEST_CASE("Soil column at rest: base force and at-rest lateral thrust", "[mpm][verification]") {
    const double width = 1.0;
    const double height = 2.0;
    const double density = 2000.0;
    const double g = 9.81;
    const double nu = 0.3;

    Particles<2> column;
    add_box_particles<2>(column, axis_box(Vec3(0.0, -0.5, 0.0), Vec3(width, 0.5, height)), 0.05,
                         density);
    SolverSettings s;
    s.threads = 1;
    s.cell_size = 0.1;
    s.domain_min = Vec3(-0.5, 0.0, -0.5);
    s.domain_max = Vec3(width + 0.5, 0.0, height + 0.5);
    s.damping = 60.0;
    std::vector<StaticBoundary> box{solid(axis_box(Vec3(-1.0, -1.0, -1.0), Vec3(2.0, 1.0, 0.0)),
                                          BoundaryKind::frictional, 0.0, 0),
                                    solid(axis_box(Vec3(-1.0, -1.0, -1.0), Vec3(0.0, 1.0, 3.0)),
                                          BoundaryKind::frictional, 0.0, 1),
                                    solid(axis_box(Vec3(width, -1.0, -1.0), Vec3(2.0, 1.0, 3.0)),
                                          BoundaryKind::frictional, 0.0, 2)};
    Solver<2> solver(s, LinearElastic{1.0e7, nu}, std::move(column), std::move(box));

    const double duration = 1.0;
    const double window = 0.2;
    std::array<Vec3, kBoundaryGroups> impulse = zero_impulses();
    double averaged_time = 0.0;
    while (solver.time() < duration) {
        const StepReport& r = solver.step(solver.stable_time_step());
        if (solver.time() > duration - window) {
            for (int i = 0; i < kBoundaryGroups; ++i) {
                impulse[i] += r.impulse[i];
            }
            averaged_time += r.dt;
        }
    }
    const double weight = density * g * width * height;
    const double k0 = nu / (1.0 - nu);
    const double thrust = k0 * density * g * height * height / 2.0;
    const double base = -impulse[0].z() / averaged_time;
    const double left = -impulse[1].x() / averaged_time;
    const double right = impulse[2].x() / averaged_time;
    WARN("base " << base << " N/m vs weight " << weight << "; lateral " << left << " and " << right
                 << " N/m vs K0 gamma H^2/2 = " << thrust);
    CHECK_THAT(base, WithinRel(weight, 0.01));
    CHECK_THAT(left, WithinRel(thrust, 0.05));
    CHECK_THAT(right, WithinRel(thrust, 0.05));
}
