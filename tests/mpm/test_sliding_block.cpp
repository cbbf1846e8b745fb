// An elastic block sliding down an inclined frictional boundary: a = g (sin(theta) -
// tan(phi_b) cos(theta)) while sliding, rest when tan(phi_b) >= tan(theta). The incline is an
// oriented box not aligned with the grid, as the slope segments are.
// The set-up is mpm::verification::sliding_block.
#include "mpm/verification.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

auto slide(double angle_deg, double friction_angle_deg, double duration, double damping = 0.0) {
    return rockfall::mpm::verification::sliding_block(angle_deg, friction_angle_deg, duration,
                                                      damping);
}

}  // namespace

TEST_CASE("Block on a 43 degree incline with a 30 degree basal friction angle",
          "[mpm][verification]") {
    const double theta = 43.0 * std::numbers::pi / 180.0;
    const double expected =
        9.81 * (std::sin(theta) - std::tan(std::numbers::pi / 6.0) * std::cos(theta));
    const auto result = slide(43.0, 30.0, 0.6);
    WARN("43 deg, phi_b 30 deg: a = " << result.fitted_acceleration << " m/s2 vs " << expected);
    CHECK_THAT(result.fitted_acceleration, WithinRel(expected, 0.03));
}

TEST_CASE("Block on a frictionless 29 degree incline", "[mpm][verification]") {
    const double expected = 9.81 * std::sin(29.0 * std::numbers::pi / 180.0);
    const auto result = slide(29.0, 0.0, 0.5);
    WARN("29 deg, frictionless: a = " << result.fitted_acceleration << " m/s2 vs " << expected);
    CHECK_THAT(result.fitted_acceleration, WithinRel(expected, 0.03));
}

// Started from zero stress, an undamped elastic block vibrates and the vibration ratchets it
// down a slope whose friction has a small margin (tan 30 / tan 25 = 1.24): about 13 mm in
// 0.5 s here. Damping the release transient (20 1/s) shows the static limit itself holds.
TEST_CASE("Block stays on a 25 degree incline with a 30 degree basal friction angle",
          "[mpm][verification]") {
    const auto result = slide(25.0, 30.0, 0.5, 20.0);
    WARN("25 deg, phi_b 30 deg: displacement " << result.displacement << " m");
    CHECK_THAT(result.displacement, WithinAbs(0.0, 2e-3));
}
