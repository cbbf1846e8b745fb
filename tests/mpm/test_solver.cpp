#include "helpers.hpp"

#include "mpm/setup.hpp"
#include "mpm/solver.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace rockfall::mpm;
using namespace rockfall::mpm::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

SolverSettings settings_2d(double h) {
    SolverSettings s;
    s.threads = 1;
    s.cell_size = h;
    s.domain_min = Vec3(0.0, 0.0, 0.0);
    s.domain_max = Vec3(2.0, 0.0, 2.0);
    s.gravity = Vec3::Zero();
    return s;
}

Particles<2> square_2d(double spacing) {
    Particles<2> p;
    add_box_particles<2>(p, axis_box(Vec3(0.6, -0.5, 0.6), Vec3(1.4, 0.5, 1.4)), spacing, 1000.0);
    return p;
}

}  // namespace

TEST_CASE("APIC transfers reproduce an affine velocity field exactly", "[mpm][solver]") {
    Mat<2> gradient;
    gradient << 0.3, -0.7, 0.5, 0.2;
    const Vec<2> v0(1.0, -2.0);
    Particles<2> p = square_2d(0.05);
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.velocity[i] = v0 + gradient * p.position[i];
        p.affine[i] = gradient;
    }
    const Particles<2> before = p;
    Solver<2> solver(settings_2d(0.1), LinearElastic{}, std::move(p), {});
    solver.step(1e-4);
    // The solver reorders particles; match them by their advected position.
    const Particles<2>& after = solver.particles();
    REQUIRE(after.size() == before.size());
    double worst_velocity = 0.0;
    double worst_gradient = 0.0;
    for (std::size_t i = 0; i < after.size(); ++i) {
        const Vec<2> x_old = after.position[i] - 1e-4 * after.velocity[i];
        worst_velocity =
            std::max(worst_velocity, (after.velocity[i] - (v0 + gradient * x_old)).norm());
        worst_gradient = std::max(worst_gradient, (after.affine[i] - gradient).norm());
    }
    CHECK(worst_velocity < 1e-12);
    CHECK(worst_gradient < 1e-11);
}

TEST_CASE("Free fall: every particle gains g t, momentum balances gravity", "[mpm][solver]") {
    SolverSettings s = settings_2d(0.1);
    s.gravity = Vec3(0.0, 0.0, -9.81);
    Particles<2> p = square_2d(0.05);
    const double mass = p.total_mass();
    Solver<2> solver(s, LinearElastic{}, std::move(p), {});
    for (int i = 0; i < 20; ++i) {
        solver.step(1e-3);
    }
    for (std::size_t i = 0; i < solver.particles().size(); ++i) {
        CHECK_THAT(solver.particles().velocity[i][1], WithinRel(-9.81 * 0.02, 1e-12));
        CHECK_THAT(solver.particles().velocity[i][0], WithinAbs(0.0, 1e-14));
    }
    CHECK_THAT(solver.particles().momentum()[1], WithinRel(-mass * 9.81 * 0.02, 1e-12));
}

TEST_CASE("Linear momentum is conserved by internal forces (APIC and FLIP)", "[mpm][solver]") {
    const double flip = GENERATE(0.0, 0.99);
    CAPTURE(flip);
    Particles<3> p;
    add_box_particles<3>(p, axis_box(Vec3(0.5, 0.5, 0.5), Vec3(1.1, 0.9, 1.3)), 0.05, 2000.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3& x = p.position[i];
        p.velocity[i] = Vec3(std::sin(7.0 * x.y()), std::cos(5.0 * x.z()), std::sin(3.0 * x.x()));
    }
    const Vec3 momentum = p.momentum();
    SolverSettings s;
    s.threads = 1;
    s.cell_size = 0.1;
    s.domain_max = Vec3(2.0, 2.0, 2.0);
    s.gravity = Vec3::Zero();
    s.flip = flip;
    Solver<3> solver(s, DruckerPrager{}, std::move(p), {});
    for (int i = 0; i < 30; ++i) {
        solver.step(solver.stable_time_step());
    }
    CHECK((solver.particles().momentum() - momentum).norm() < 1e-10 * momentum.norm());
}

TEST_CASE("Results do not depend on the thread count (APIC and FLIP)", "[mpm][solver]") {
    const double flip = GENERATE(0.0, 0.95);
    CAPTURE(flip);
    auto run = [flip](int threads) {
        SolverSettings s;
        s.flip = flip;
        s.cell_size = 0.1;
        s.domain_min = Vec3(-0.5, -0.5, -0.5);
        s.domain_max = Vec3(2.0, 1.5, 2.0);
        s.threads = threads;
        s.reorder_interval = 7;
        Particles<3> p;
        add_box_particles<3>(p, axis_box(Vec3(0.0, 0.0, 0.4), Vec3(0.8, 1.0, 1.2)), 0.05, 1640.0);
        std::vector<StaticBoundary> statics{
            solid(inclined_box(20.0, Vec3(0.5, 0.5, 0.0), Vec3(3.0, 3.0, 0.2)),
                  BoundaryKind::frictional, 0.5, 0),
            solid(axis_box(Vec3(1.5, -1.0, -1.0), Vec3(2.5, 3.0, 3.0)), BoundaryKind::fixed, 0.0,
                  1)};
        Solver<3> solver(s, DruckerPrager{}, std::move(p), std::move(statics));
        Vec3 impulse = Vec3::Zero();
        for (int i = 0; i < 60; ++i) {
            impulse += solver.step(solver.stable_time_step()).impulse[0];
        }
        return std::pair{solver.particles(), impulse};
    };
    const auto [one, impulse_one] = run(1);
    const auto [two, impulse_two] = run(2);
    REQUIRE(one.size() == two.size());
    bool identical = impulse_one == impulse_two;
    for (std::size_t i = 0; i < one.size(); ++i) {
        identical = identical && one.position[i] == two.position[i] &&
                    one.velocity[i] == two.velocity[i] && one.stress[i] == two.stress[i];
    }
    CHECK(identical);
    CHECK(impulse_one.norm() > 0.0);
}

TEST_CASE("Stable time step follows the CFL condition", "[mpm][solver]") {
    SolverSettings s = settings_2d(0.1);
    s.cfl = 0.5;
    LinearElastic material{1.0e6, 0.0};
    Solver<2> solver(s, material, square_2d(0.05), {});
    const double c = std::sqrt(1.0e6 / 1000.0);
    CHECK_THAT(solver.stable_time_step(), WithinRel(0.5 * 0.1 / c, 1e-12));
}

TEST_CASE("Invalid settings and particles are rejected with the field named", "[mpm][solver]") {
    SolverSettings s = settings_2d(0.1);
    s.cfl = 1.5;
    CHECK_THROWS_WITH((Solver<2>(s, LinearElastic{}, square_2d(0.05), {})),
                      Catch::Contains("solver.cfl") && Catch::Contains("1.5"));
    Particles<2> outside;
    outside.add(Vec<2>(5.0, 1.0), 1e-3, 1000.0);
    CHECK_THROWS_AS((Solver<2>(settings_2d(0.1), LinearElastic{}, outside, {})),
                    std::invalid_argument);
}

TEST_CASE("A hinged boundary ramps its angle linearly", "[mpm][boundary]") {
    HingedBoundary bed;
    bed.start_angle_deg = 0.0;
    bed.end_angle_deg = 60.0;
    bed.start_time = 1.0;
    bed.duration = 2.0;
    bed.hinge = Vec3(1.0, 0.0, 2.0);
    bed.boxes = {axis_box(Vec3(-1.0, -0.5, 1.8), Vec3(1.0, 0.5, 2.0))};
    CHECK(bed.angle_deg(0.5) == 0.0);
    CHECK_THAT(bed.angle_deg(2.0), WithinRel(30.0, 1e-12));
    CHECK(bed.angle_deg(5.0) == 60.0);
    CHECK_THAT(bed.angular_velocity(2.0), WithinRel(std::numbers::pi / 6.0, 1e-12));
    CHECK(bed.angular_velocity(3.5) == 0.0);
    // At 90 degrees the far (-x) end of the bed points straight up from the hinge.
    bed.end_angle_deg = 90.0;
    const auto placed = bed.boxes_at(10.0);
    const Vec3 far_corner = placed[0].center + placed[0].rotation * Vec3(-1.0, 0.0, 0.1);
    CHECK_THAT(far_corner.x(), WithinAbs(1.0, 1e-12));
    CHECK_THAT(far_corner.z(), WithinAbs(4.0, 1e-12));
}

namespace {

// One step of the square from v = (x^2 / 2, 0), whose volumetric rate x varies inside every
// cell; per particle its old position (found from the advected one) and its volume ratio.
std::vector<std::pair<Vec<2>, double>> volume_ratios(bool averaging) {
    SolverSettings s = settings_2d(0.1);
    s.volumetric_averaging = averaging;
    // 4 per cell edge: no particle on a dual cell's edge (x = 0.05 + 0.1 k).
    Particles<2> p = square_2d(0.025);
    const double v0 = p.volume[0];
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double x = p.position[i][0];
        p.velocity[i] = Vec<2>(0.5 * x * x, 0.0);
        p.affine[i] << x, 0.0, 0.0, 0.0;
    }
    Solver<2> solver(s, LinearElastic{}, std::move(p), {});
    const double dt = 1e-4;
    solver.step(dt);
    std::vector<std::pair<Vec<2>, double>> out;
    const Particles<2>& after = solver.particles();
    for (std::size_t i = 0; i < after.size(); ++i) {
        out.emplace_back(after.position[i] - dt * after.velocity[i], after.volume[i] / v0);
    }
    return out;
}

// The dual cell of a position on the 0.1 m grid from the origin: its stencil's base node.
std::pair<int, int> dual_cell_of(const Vec<2>& x) {
    return {static_cast<int>(std::floor(x[0] / 0.1 - 0.5)),
            static_cast<int>(std::floor(x[1] / 0.1 - 0.5))};
}

}  // namespace

TEST_CASE("Volumetric averaging: an affine field is unchanged", "[mpm][solver]") {
    Mat<2> gradient;
    gradient << 0.3, -0.7, 0.5, 0.2;
    std::vector<Particles<2>> results;
    for (const bool averaging : {false, true}) {
        SolverSettings s = settings_2d(0.1);
        s.volumetric_averaging = averaging;
        Particles<2> p = square_2d(0.05);
        for (std::size_t i = 0; i < p.size(); ++i) {
            p.velocity[i] = gradient * p.position[i];
            p.affine[i] = gradient;
        }
        Solver<2> solver(s, LinearElastic{1.0e6, 0.3}, std::move(p), {});
        solver.step(1e-4);
        results.push_back(solver.particles());
    }
    // Same order (the same binning): every particle's rate is already its cell's mean.
    REQUIRE(results[0].size() == results[1].size());
    double worst = 0.0;
    for (std::size_t i = 0; i < results[0].size(); ++i) {
        worst = std::max(worst, (results[0].stress[i] - results[1].stress[i]).norm() /
                                    results[0].stress[i].norm());
        CHECK_THAT(results[1].volume[i], WithinRel(results[0].volume[i], 1e-14));
    }
    CHECK(worst < 1e-12);
}

TEST_CASE("Volumetric averaging: one volume ratio per dual cell, its volume-weighted mean",
          "[mpm][solver]") {
    const auto own = volume_ratios(false);
    const auto averaged = volume_ratios(true);
    // Group by dual cell: with averaging every particle of a cell changes volume alike, and the
    // cell's volume change is the same as with each particle's own rate (the mean is
    // volume-weighted, all volumes being equal here).
    std::map<std::pair<int, int>, std::vector<double>> cells_own;
    std::map<std::pair<int, int>, std::vector<double>> cells_averaged;
    for (const auto& [x, ratio] : own) cells_own[dual_cell_of(x)].push_back(ratio);
    for (const auto& [x, ratio] : averaged) cells_averaged[dual_cell_of(x)].push_back(ratio);
    REQUIRE(cells_own.size() == cells_averaged.size());
    double spread_own = 0.0;
    for (const auto& [cell, ratios] : cells_averaged) {
        CAPTURE(cell.first, cell.second);
        const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
        // F-bar: every particle's volume ratio is the cell's mean, to round-off.
        CHECK(*hi - *lo < 1e-13);
        const std::vector<double>& mine = cells_own.at(cell);
        const auto [lo_own, hi_own] = std::minmax_element(mine.begin(), mine.end());
        spread_own = std::max(spread_own, *hi_own - *lo_own);
        double sum_own = 0.0;
        double sum = 0.0;
        for (const double r : mine) sum_own += r;
        for (const double r : ratios) sum += r;
        CHECK_THAT(sum, WithinRel(sum_own, 1e-9));
    }
    // Without averaging the volume ratios differ across a cell by dx dt: 0.75e-5 here.
    CHECK(spread_own > 3e-6);
}
