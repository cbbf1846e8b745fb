// The FLIP part of the particle velocity update (SolverSettings::flip): exact where APIC is
// exact, and keeping what APIC smooths away; the density floor (momentum and thread-count
// independence with FLIP are in test_solver.cpp).
#include "helpers.hpp"

#include "mpm/setup.hpp"
#include "mpm/solver.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>
#include <utility>
#include <vector>

using namespace rockfall::mpm;
using namespace rockfall::mpm::test;

namespace {

// A 2 m square 2D domain of 0.1 m cells, one thread, no gravity.
SolverSettings quiet_2d() {
    SolverSettings s;
    s.threads = 1;
    s.cell_size = 0.1;
    s.domain_max = Vec3(2.0, 0.0, 2.0);
    s.gravity = Vec3::Zero();
    return s;
}

// One step of an affine velocity field in a square under a uniform initial stress: the stress
// loads the square's edge nodes, so a FLIP update that kept any of that force in the "old" grid
// velocity would differ from APIC, which is exact here.
Particles<2> affine_step(double flip) {
    Mat<2> gradient;
    gradient << 0.3, -0.7, 0.5, 0.2;
    Particles<2> p;
    add_box_particles<2>(p, axis_box(Vec3(0.6, -0.5, 0.6), Vec3(1.4, 0.5, 1.4)), 0.05, 1000.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.velocity[i] = Vec<2>(1.0, -2.0) + gradient * p.position[i];
        p.affine[i] = gradient;
        p.stress[i] = Mat3::Identity() * -2.0e3;
        p.stress[i](0, 2) = p.stress[i](2, 0) = 500.0;
    }
    SolverSettings s = quiet_2d();
    s.gravity = Vec3(0.0, 0.0, -9.81);
    s.flip = flip;
    Solver<2> solver(s, LinearElastic{}, std::move(p), {});
    solver.step(1e-4);
    return solver.particles();
}

}  // namespace

TEST_CASE("FLIP: where APIC is exact (affine field) the blend changes nothing", "[mpm][solver]") {
    const Particles<2> apic = affine_step(0.0);
    const Particles<2> flip = affine_step(0.99);
    REQUIRE(apic.size() == flip.size());
    double worst = 0.0;
    double largest_change = 0.0;
    for (std::size_t i = 0; i < apic.size(); ++i) {
        worst = std::max(worst, (apic.velocity[i] - flip.velocity[i]).norm());
        largest_change = std::max(largest_change, apic.velocity[i].norm());
    }
    CHECK(worst < 1e-12 * largest_change);
}

TEST_CASE("FLIP: a non-affine flow keeps more of its kinetic energy than APIC", "[mpm][solver]") {
    // A shear velocity field 4 cells long in a square too soft (E = 1 Pa) to store energy over
    // 0.05 s: its kinetic energy should stay; APIC smooths its non-affine part at every transfer.
    auto energy_kept = [](double flip) {
        Particles<2> p;
        add_box_particles<2>(p, axis_box(Vec3(0.4, -0.5, 0.4), Vec3(1.6, 0.5, 1.6)), 0.025, 1000.0);
        for (std::size_t i = 0; i < p.size(); ++i) {
            p.velocity[i] =
                Vec<2>(0.1 * std::sin(2.0 * 3.141592653589793 * p.position[i][1] / 0.4), 0.0);
        }
        const auto kinetic = [](const Particles<2>& q) {
            double e = 0.0;
            for (std::size_t i = 0; i < q.size(); ++i)
                e += 0.5 * q.mass[i] * q.velocity[i].squaredNorm();
            return e;
        };
        const double e0 = kinetic(p);
        SolverSettings s = quiet_2d();
        s.flip = flip;
        Solver<2> solver(s, LinearElastic{1.0, 0.3}, std::move(p), {});
        for (int i = 0; i < 50; ++i) {
            solver.step(1e-3);
        }
        return kinetic(solver.particles()) / e0;
    };
    const double apic = energy_kept(0.0);
    const double flip = energy_kept(1.0);
    WARN("kinetic energy kept over 50 steps: APIC " << apic << ", FLIP " << flip);
    CHECK(apic < 0.9);
    CHECK(flip > 0.97);
}

TEST_CASE("Density floor: a spreading body's particles stop dilating at the floor",
          "[mpm][solver]") {
    // A soft square (E = 1 Pa) spreading at 2 /s in x: det(I + dt C) = 1 + 2 dt each step, so
    // its density halves in about 0.35 s.
    auto lowest_density = [](double ratio) {
        Particles<2> p;
        add_box_particles<2>(p, axis_box(Vec3(0.8, -0.5, 0.8), Vec3(1.2, 0.5, 1.2)), 0.025, 1000.0);
        for (std::size_t i = 0; i < p.size(); ++i) {
            p.velocity[i] = Vec<2>(2.0 * (p.position[i][0] - 1.0), 0.0);
            p.affine[i] << 2.0, 0.0, 0.0, 0.0;
        }
        SolverSettings s = quiet_2d();
        s.min_density_ratio = ratio;
        Solver<2> solver(s, LinearElastic{1.0, 0.0}, std::move(p), {});
        for (int i = 0; i < 50; ++i) {
            solver.step(1e-2);
        }
        double lowest = 1e300;
        for (std::size_t i = 0; i < solver.particles().size(); ++i) {
            lowest = std::min(lowest, solver.particles().mass[i] / solver.particles().volume[i]);
        }
        return lowest;
    };
    CHECK(lowest_density(0.0) < 500.0);
    CHECK_THAT(lowest_density(0.8), Catch::Matchers::WithinRel(800.0, 1e-12));
}

TEST_CASE("FLIP fraction and density floor out of range are rejected with the field named",
          "[mpm][solver]") {
    SolverSettings s;
    s.flip = 1.5;
    Particles<2> p;
    add_box_particles<2>(p, axis_box(Vec3(0.2, -0.5, 0.2), Vec3(0.4, 0.5, 0.4)), 0.05, 1000.0);
    CHECK_THROWS_WITH((Solver<2>(s, LinearElastic{}, p, {})), Catch::Matchers::Contains("flip"));
    s.flip = 0.0;
    s.min_density_ratio = 1.0;
    CHECK_THROWS_WITH((Solver<2>(s, LinearElastic{}, p, {})),
                      Catch::Matchers::Contains("min_density_ratio"));
}
