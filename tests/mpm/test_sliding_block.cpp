// An elastic block sliding down an inclined frictional boundary: a = g (sin(theta) -
// tan(phi_b) cos(theta)) while sliding, rest when tan(phi_b) >= tan(theta). The incline is an
// oriented box not aligned with the grid, as the slope segments are.
#include "helpers.hpp"

#include "mpm/setup.hpp"
#include "mpm/solver.hpp"

#include <Eigen/Cholesky>
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace rockfall::mpm;
using namespace rockfall::mpm::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

struct Slide {
    double fitted_acceleration;
    double displacement;
};

// Slides a 0.4 m x 0.2 m block, released with zero stress, for `duration` seconds; returns the
// acceleration along the incline from a least-squares fit s = s0 + v0 t + a t^2 / 2 of its centre
// of mass.
Slide slide(double angle_deg, double friction_angle_deg, double duration, double damping = 0.0) {
    const double a = angle_deg * std::numbers::pi / 180.0;
    const Vec3 down(std::cos(a), 0.0, -std::sin(a));
    const Vec3 normal(std::sin(a), 0.0, std::cos(a));
    const Vec3 top(0.6, 0.0, 2.2);
    const double h = 0.05;

    Particles<2> block;
    add_box_particles<2>(block, inclined_box(angle_deg, top + 0.1 * normal, Vec3(0.2, 0.5, 0.1)),
                         h / 2.0, 2000.0);
    SolverSettings s;
    s.threads = 1;
    s.cell_size = h;
    s.domain_min = Vec3(-0.5, 0.0, -0.5);
    s.domain_max = Vec3(3.5, 0.0, 3.0);
    s.damping = damping;
    const double mu = std::tan(friction_angle_deg * std::numbers::pi / 180.0);
    std::vector<StaticBoundary> incline{
        solid(inclined_box(angle_deg, top - 0.5 * normal, Vec3(4.0, 1.0, 0.5)),
              BoundaryKind::frictional, mu, 0)};
    Solver<2> solver(s, LinearElastic{5.0e6, 0.3}, std::move(block), std::move(incline));

    const Vec3 start = to_scene<2>(solver.particles().centre_of_mass());
    // Normal equations of the quadratic fit in t.
    Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
    Vec3 rhs = Vec3::Zero();
    while (solver.time() < duration) {
        solver.step(solver.stable_time_step());
        const double t = solver.time();
        const double along = (to_scene<2>(solver.particles().centre_of_mass()) - start).dot(down);
        const Vec3 basis(1.0, t, 0.5 * t * t);
        normal_matrix += basis * basis.transpose();
        rhs += basis * along;
    }
    const Vec3 fit = normal_matrix.ldlt().solve(rhs);
    const double along = (to_scene<2>(solver.particles().centre_of_mass()) - start).dot(down);
    return {fit[2], along};
}

}  // namespace

TEST_CASE("Block on a 43 degree incline with a 30 degree basal friction angle",
          "[mpm][verification]") {
    const double theta = 43.0 * std::numbers::pi / 180.0;
    const double expected =
        9.81 * (std::sin(theta) - std::tan(std::numbers::pi / 6.0) * std::cos(theta));
    const Slide result = slide(43.0, 30.0, 0.6);
    WARN("43 deg, phi_b 30 deg: a = " << result.fitted_acceleration << " m/s2 vs " << expected);
    CHECK_THAT(result.fitted_acceleration, WithinRel(expected, 0.03));
}

TEST_CASE("Block on a frictionless 29 degree incline", "[mpm][verification]") {
    const double expected = 9.81 * std::sin(29.0 * std::numbers::pi / 180.0);
    const Slide result = slide(29.0, 0.0, 0.5);
    WARN("29 deg, frictionless: a = " << result.fitted_acceleration << " m/s2 vs " << expected);
    CHECK_THAT(result.fitted_acceleration, WithinRel(expected, 0.03));
}

// Started from zero stress, an undamped elastic block vibrates and the vibration ratchets it
// down a slope whose friction has a small margin (tan 30 / tan 25 = 1.24): about 13 mm in
// 0.5 s here. Damping the release transient (20 1/s) shows the static limit itself holds.
TEST_CASE("Block stays on a 25 degree incline with a 30 degree basal friction angle",
          "[mpm][verification]") {
    const Slide result = slide(25.0, 30.0, 0.5, 20.0);
    WARN("25 deg, phi_b 30 deg: displacement " << result.displacement << " m");
    CHECK_THAT(result.displacement, WithinAbs(0.0, 2e-3));
}
