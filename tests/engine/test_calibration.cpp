// Contact calibration on the seed slope (issue 2): the runout statistics of 200 random rocks
// must not move by more than their own 95 % confidence intervals when the time step is halved.

#include "engine/simulation.hpp"
#include "risk/random_release.hpp"
#include "risk/statistics.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

using namespace rockfall;

namespace {

constexpr int kRocks = 200;

struct Runout {
    std::vector<double> reaches;  // m
    std::int64_t wall_reached = 0;
};

// The seed slope (scenario defaults: bars on, wall 5 m from the toe) with kRocks random
// rocks from risk::random_rock_scenario, one run each, seeds 1..kRocks.
Runout runout(double time_step) {
    engine::Scenario base;
    base.numerics.time_step = time_step;
    Runout result;
    for (std::uint64_t seed = 1; seed <= kRocks; ++seed) {
        const engine::Outcome outcome =
            engine::simulate(risk::random_rock_scenario(base, seed), seed);
        const engine::RockOutcome& rock = outcome.rocks.front();
        result.reaches.push_back(rock.reach);
        result.wall_reached += rock.wall_hits.empty() ? 0 : 1;
    }
    return result;
}

}  // namespace

TEST_CASE("runout statistics of 200 random rocks hold when the step is halved",
          "[verification][calibration]") {
    const Runout coarse = runout(1e-3);
    const Runout fine = runout(5e-4);

    const double median_coarse = risk::median(coarse.reaches);
    const double median_fine = risk::median(fine.reaches);
    const risk::Interval median_ci_coarse = risk::median_confidence_interval(coarse.reaches);
    const risk::Interval median_ci_fine = risk::median_confidence_interval(fine.reaches);
    INFO("median reach " << median_coarse << " m [" << median_ci_coarse.lower << ", "
                         << median_ci_coarse.upper << "] at 1 ms, " << median_fine << " m ["
                         << median_ci_fine.lower << ", " << median_ci_fine.upper << "] at 0.5 ms");
    CHECK(median_fine >= median_ci_coarse.lower);
    CHECK(median_fine <= median_ci_coarse.upper);
    CHECK(median_coarse >= median_ci_fine.lower);
    CHECK(median_coarse <= median_ci_fine.upper);

    const double share_coarse = static_cast<double>(coarse.wall_reached) / kRocks;
    const double share_fine = static_cast<double>(fine.wall_reached) / kRocks;
    const risk::Interval share_ci_coarse = risk::wilson_interval(coarse.wall_reached, kRocks);
    const risk::Interval share_ci_fine = risk::wilson_interval(fine.wall_reached, kRocks);
    INFO("share reaching the wall " << share_coarse << " [" << share_ci_coarse.lower << ", "
                                    << share_ci_coarse.upper << "] at 1 ms, " << share_fine << " ["
                                    << share_ci_fine.lower << ", " << share_ci_fine.upper
                                    << "] at 0.5 ms");
    CHECK(share_fine >= share_ci_coarse.lower);
    CHECK(share_fine <= share_ci_coarse.upper);
    CHECK(share_coarse >= share_ci_fine.lower);
    CHECK(share_coarse <= share_ci_fine.upper);
    // Both samples have rocks that reach the wall and rocks that stop short of it.
    CHECK(coarse.wall_reached > 0);
    CHECK(coarse.wall_reached < kRocks);
}
