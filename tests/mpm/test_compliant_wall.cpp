// The spring-backed facing (SpringSupport): an elastic block pushed against it comes to rest
// with the spring carrying its weight and the facing displaced by weight / stiffness; a block
// striking it at v0 loads the spring like a mass-spring impact, peak force
// m v0 sqrt(k / (m + m_f)) after a contact of half a period pi sqrt((m + m_f) / k), and the
// impulse the spring passes on plus the facing's momentum equal the momentum the block lost.
#include "helpers.hpp"

#include "mpm/setup.hpp"
#include "mpm/solver.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace rockfall::mpm;
using namespace rockfall::mpm::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr double kCell = 0.05;
constexpr double kDensity = 1000.0;

// A 2D block of 0.6 m x 0.4 m (240 kg/m) in front of a frictionless facing whose face is the
// node plane x = 1 m; gravity `g` (scene frame).
Solver<2> block_and_facing(const SpringSupport& spring, const Vec3& g, double v0, double damping) {
    Particles<2> block;
    add_box_particles<2>(block, axis_box(Vec3(0.35, -0.5, 0.3), Vec3(0.95, 0.5, 0.7)), kCell / 2.0,
                         kDensity);
    for (auto& v : block.velocity) v[0] = v0;
    SolverSettings s;
    s.threads = 1;
    s.cell_size = kCell;
    s.domain_min = Vec3(0.0, 0.0, 0.0);
    s.domain_max = Vec3(1.6, 0.0, 1.0);
    s.gravity = g;
    s.damping = damping;
    std::vector<StaticBoundary> walls{solid(axis_box(Vec3(1.0, -1.0, -1.0), Vec3(1.5, 1.0, 2.0)),
                                            BoundaryKind::frictional, 0.0, spring.group)};
    return Solver<2>(s, LinearElastic{1.0e7, 0.3}, std::move(block), std::move(walls), {}, spring);
}

}  // namespace

TEST_CASE("Spring-backed facing: a block at rest against it displaces it by weight / stiffness",
          "[mpm][verification]") {
    SpringSupport spring;
    spring.mass = 24.0;  // 10 mm of concrete over 1 m of height, kg/m
    const double weight = 240.0 * 9.81;
    spring.stiffness = weight / 1e-3;  // 1 mm under the block's weight
    spring.damping = 2.0 * 0.7 * std::sqrt(spring.stiffness * (240.0 + spring.mass));
    Solver<2> solver = block_and_facing(spring, Vec3(9.81, 0.0, 0.0), 0.0, 20.0);
    REQUIRE_THAT(solver.particles().total_mass(), WithinRel(240.0, 1e-12));
    double force = 0.0;
    while (solver.time() < 2.0) {
        const StepReport& r = solver.step(solver.stable_time_step());
        force = r.spring_impulse / r.dt;
    }
    CHECK_THAT(force, WithinRel(weight, 0.01));
    CHECK_THAT(solver.spring_displacement(), WithinRel(weight / spring.stiffness, 0.01));
    CHECK_THAT(solver.spring_velocity(), WithinAbs(0.0, 1e-4));
}

TEST_CASE("Spring-backed facing: an impact loads it as a mass on a spring", "[mpm][verification]") {
    SpringSupport spring;
    spring.mass = 24.0;
    const double m = 240.0;
    const double v0 = 0.05;
    const double omega = 2.0 * std::numbers::pi / 0.6;  // contact of about 0.3 s
    spring.stiffness = omega * omega * (m + spring.mass);
    Solver<2> solver = block_and_facing(spring, Vec3::Zero(), v0, 0.0);
    const double p0 = solver.particles().momentum()[0];
    double passed = 0.0;
    double peak = 0.0;
    double peak_time = 0.0;
    double first_load = -1.0;
    double last_load = -1.0;
    while (solver.time() < 1.2) {
        const StepReport& r = solver.step(solver.stable_time_step());
        passed += r.spring_impulse;
        const double f = r.spring_impulse / r.dt;
        if (f > peak) {
            peak = f;
            peak_time = solver.time();
        }
        // The first loading: from the first step with load to the first without after it (the
        // facing, free again, then swings on its spring).
        if (f > 0.01 * m * v0 * omega && last_load < 0.0 && first_load < 0.0) {
            first_load = solver.time();
        } else if (f <= 0.0 && first_load >= 0.0 && last_load < 0.0) {
            last_load = solver.time();
        }
    }
    const double expected = m * v0 * std::sqrt(spring.stiffness / (m + spring.mass));
    WARN("peak " << peak << " N/m at " << peak_time << " s (mass-spring " << expected
                 << " N/m), loaded from " << first_load << " to " << last_load << " s");
    CHECK_THAT(peak, WithinRel(expected, 0.05));
    CHECK_THAT(last_load - first_load, WithinRel(std::numbers::pi / omega, 0.05));
    // The block rebounds; what it lost is on the support or in the moving facing.
    const double lost = p0 - solver.particles().momentum()[0];
    CHECK(lost > 1.5 * p0 * m / (m + spring.mass) * 0.9);
    CHECK_THAT(passed + spring.mass * solver.spring_velocity(), WithinRel(lost, 0.02));
}
