// Axial vibration of an elastic bar, fixed at x = 0 and free at x = L, started in its first
// mode: u(x, t) = (v0 / omega) sin(pi x / 2L) sin(omega t), omega = pi c / (2L), c = sqrt(E/rho)
// (nu = 0, so plane strain and uniaxial stress coincide). A classic MPM check (Sulsky et al.
// 1994; Bardenhagen 2002). The set-up is mpm::verification::elastic_bar.
#include "mpm/verification.hpp"

#include <catch2/catch.hpp>

using Catch::Matchers::WithinRel;

TEST_CASE("Elastic bar: first axial mode period and amplitude", "[mpm][verification]") {
    const auto bar = rockfall::mpm::verification::elastic_bar(0.05);
    WARN("period " << bar.period << " s vs " << bar.expected_period << " s; tip amplitude "
                   << bar.tip_amplitude << " m vs " << bar.expected_tip_amplitude
                   << " m; mean-velocity amplitude in the third period "
                   << bar.late_velocity_amplitude << " vs " << bar.expected_velocity_amplitude);
    CHECK_THAT(bar.period, WithinRel(bar.expected_period, 0.03));
    CHECK_THAT(bar.tip_amplitude, WithinRel(bar.expected_tip_amplitude, 0.03));
    CHECK_THAT(bar.late_velocity_amplitude, WithinRel(bar.expected_velocity_amplitude, 0.05));
    CHECK(bar.time.size() == bar.mean_velocity.size());
}
