// Axial vibration of an elastic bar, fixed at x = 0 and free at x = L, started in its first
// mode: u(x, t) = (v0 / omega) sin(pi x / 2L) sin(omega t), omega = pi c / (2L), c = sqrt(E/rho)
// (nu = 0, so plane strain and uniaxial stress coincide). A classic MPM check (Sulsky et al.
// 1994; Bardenhagen 2002).
#include "helpers.hpp"

#include "mpm/setup.hpp"
#include "mpm/solver.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace rockfall::mpm;
using namespace rockfall::mpm::test;
using Catch::Matchers::WithinRel;

TEST_CASE("Elastic bar: first axial mode period and amplitude", "[mpm][verification]") {
    const double length = 1.0;
    const double h = 0.05;
    const double youngs = 1.0e7;
    const double density = 1000.0;
    const double v0 = 0.1;
    const double c = std::sqrt(youngs / density);
    const double omega = std::numbers::pi * c / (2.0 * length);
    const double period = 2.0 * std::numbers::pi / omega;

    Particles<2> bar;
    add_box_particles<2>(bar, axis_box(Vec3(0.0, -0.5, 0.5), Vec3(length, 0.5, 0.6)), h / 2.0,
                         density);
    std::vector<double> x0;
    for (std::size_t p = 0; p < bar.size(); ++p) {
        const double x = bar.position[p][0];
        const double k = std::numbers::pi / (2.0 * length);
        bar.velocity[p] = Vec<2>(v0 * std::sin(k * x), 0.0);
        bar.affine[p](0, 0) = v0 * k * std::cos(k * x);
    }
    const double mass = bar.total_mass();

    SolverSettings s;

    s.threads = 1;
    s.cell_size = h;
    s.domain_min = Vec3(-0.3, 0.0, 0.2);
    s.domain_max = Vec3(1.3, 0.0, 0.9);
    s.gravity = Vec3::Zero();
    std::vector<StaticBoundary> clamp{
        solid(axis_box(Vec3(-1.0, -1.0, -1.0), Vec3(0.0, 1.0, 2.0)), BoundaryKind::fixed, 0.0, 0)};
    Solver<2> solver(s, LinearElastic{youngs, 0.0}, std::move(bar), std::move(clamp));

    // Tip: particles in the last lattice column, tracked by their initial x.
    auto tip_displacement = [&](const Particles<2>& p) {
        double sum = 0.0;
        double weight = 0.0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            const double x = p.position[i][0];
            if (x > length - h / 2.0 - 0.01) {
                sum += x - (length - h / 4.0);
                weight += 1.0;
            }
        }
        return sum / weight;
    };

    const double dt = solver.stable_time_step();
    std::vector<double> crossings;
    double previous_v = v0 * 2.0 / std::numbers::pi;
    double max_tip = 0.0;
    double max_v_late = 0.0;
    while (solver.time() < 3.0 * period) {
        solver.step(dt);
        const double v = solver.particles().momentum()[0] / mass;
        if ((previous_v > 0.0) != (v > 0.0)) {
            crossings.push_back(solver.time() - dt * v / (v - previous_v));
        }
        previous_v = v;
        if (solver.time() < period) {
            max_tip = std::max(max_tip, std::abs(tip_displacement(solver.particles())));
        }
        if (solver.time() > 2.0 * period) {
            max_v_late = std::max(max_v_late, std::abs(v));
        }
    }
    REQUIRE(crossings.size() >= 5);
    // Zero crossings of the mean velocity are half a period apart.
    const double measured_period = 2.0 * (crossings[4] - crossings[0]) / 4.0;
    const double expected_tip =
        v0 / omega * std::sin(std::numbers::pi * (length - h / 4.0) / (2.0 * length));
    WARN("period " << measured_period << " s vs " << period << " s; tip amplitude " << max_tip
                   << " m vs " << expected_tip << " m; mean-velocity amplitude in the third period "
                   << max_v_late << " vs " << v0 * 2.0 / std::numbers::pi);
    CHECK_THAT(measured_period, WithinRel(period, 0.03));
    CHECK_THAT(max_tip, WithinRel(expected_tip, 0.03));
    CHECK_THAT(max_v_late, WithinRel(v0 * 2.0 / std::numbers::pi, 0.05));
}
