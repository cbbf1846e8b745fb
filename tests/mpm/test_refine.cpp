// Richardson extrapolation on sequences with a known limit and order, and the refinement
// study's input checks.
#include "helpers.hpp"

#include "mpm/refine.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

using namespace rockfall::mpm;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("Richardson extrapolation recovers the limit and order of f = f0 + C h^p",
          "[mpm][refine]") {
    const double p = GENERATE(1.0, 1.5, 2.0);
    const double ratio = GENERATE(2.0, 1.5);
    auto f = [&](double h) { return 7.0 - 3.0 * std::pow(h, p); };
    const double h = 0.2;
    const RichardsonEstimate e = richardson(f(h), f(h / ratio), f(h / (ratio * ratio)), ratio);
    REQUIRE(e.monotone);
    CHECK_THAT(e.order, WithinRel(p, 1e-9));
    CHECK_THAT(e.extrapolated, WithinRel(7.0, 1e-9));
    const double f3 = f(h / (ratio * ratio));
    CHECK_THAT(e.finest_change, WithinRel(std::abs(f3 - f(h / ratio)) / f3, 1e-12));
    // GCI = 1.25 |f3 - f2| / (|f3| (r^p - 1)) = 1.25 |f3 - f0| / |f3|.
    CHECK_THAT(e.gci_fine, WithinRel(1.25 * std::abs(f3 - 7.0) / f3, 1e-9));
}

TEST_CASE("Richardson extrapolation refuses oscillating or diverging sequences", "[mpm][refine]") {
    const RichardsonEstimate oscillating = richardson(1.0, 2.0, 1.5, 2.0);
    CHECK_FALSE(oscillating.monotone);
    CHECK(std::isnan(oscillating.extrapolated));
    CHECK(std::isnan(oscillating.order));
    const RichardsonEstimate diverging = richardson(1.0, 1.1, 1.3, 2.0);
    CHECK_FALSE(diverging.monotone);
    CHECK_THAT(diverging.finest_change, WithinRel(0.2 / 1.3, 1e-12));
    const RichardsonEstimate exact = richardson(1.0, 2.0, 2.0, 2.0);
    CHECK(exact.monotone);
    CHECK(exact.extrapolated == 2.0);
    CHECK_THROWS_AS(richardson(1.0, 2.0, 3.0, 1.0), std::invalid_argument);
}

TEST_CASE("Refinement study checks its cell sizes and window", "[mpm][refine]") {
    SoilScenario s;
    s.numerics.dimension = 2;
    RefinementSettings settings;
    settings.cell_sizes = {0.2, 0.2, 0.1};
    CHECK_THROWS_WITH(run_refinement(s, settings),
                      Catch::Contains("refine.cell_sizes[1] = 0.2 m: must be > 0 and smaller"));
    settings.cell_sizes = {0.2};
    CHECK_THROWS_WITH(run_refinement(s, settings), Catch::Contains("at least 2"));
    settings.cell_sizes = {0.4, 0.2};
    settings.steady_window = 20.0;
    CHECK_THROWS_WITH(run_refinement(s, settings), Catch::Contains("refine.steady_window = 20 s"));
}

TEST_CASE("Refinement level: steady load is the mean over the last window", "[mpm][refine]") {
    SoilOutcome o;
    o.particles = 10;
    o.peak_wall_force = 5.0;
    o.peak_wall_force_time = 0.2;
    o.peak_wall_force_filtered = 4.5;
    for (int k = 1; k <= 10; ++k) {
        o.sample_time.push_back(0.1 * k);
        o.wall_force.push_back(k <= 6 ? 5.0 : 2.0);
    }
    const RefinementLevel level = refinement_level(o, 0.1, 0.4);
    CHECK_THAT(level.steady_wall_force, WithinRel(2.0, 1e-12));
    CHECK(level.peak_wall_force == 5.0);
    CHECK(level.peak_time == 0.2);
    CHECK(level.peak_wall_force_filtered == 4.5);
}

TEST_CASE("Refinement study: no extrapolation when a fine level did not complete",
          "[mpm][refine]") {
    RefinementStudy study;
    for (const double h : {0.4, 0.2, 0.1, 0.05}) {
        RefinementLevel l;
        l.cell_size = h;
        l.peak_wall_force = 10.0 - 8.0 * h;  // first order, limit 10
        l.peak_time = 3.0;
        l.peak_wall_force_filtered = 8.0 - 16.0 * h * h;  // second order, limit 8
        l.steady_wall_force = 5.0 - 4.0 * h;
        l.runout_past_toe = 0.5 - h;
        study.levels.push_back(l);
    }
    extrapolate_study(study);
    REQUIRE(study.extrapolated);
    CHECK_THAT(study.ratio, WithinRel(2.0, 1e-12));
    CHECK_THAT(study.peak_wall_force.extrapolated, WithinRel(10.0, 1e-9));
    CHECK_THAT(study.peak_wall_force.order, WithinRel(1.0, 1e-9));
    CHECK_THAT(study.peak_wall_force_filtered.extrapolated, WithinRel(8.0, 1e-9));
    CHECK_THAT(study.peak_wall_force_filtered.order, WithinRel(2.0, 1e-9));
    // A non-finite finest level (its values NaN) leaves the study without extrapolation.
    study.levels.back().status = SoilStatus::non_finite;
    study.levels.back().peak_wall_force = std::nan("");
    extrapolate_study(study);
    CHECK_FALSE(study.extrapolated);
    // The coarsest level is not among the three used.
    study.levels.back().status = SoilStatus::completed;
    study.levels.back().peak_wall_force = 10.0 - 8.0 * 0.05;
    study.levels.front().status = SoilStatus::left_domain;
    extrapolate_study(study);
    CHECK(study.extrapolated);
}

TEST_CASE("Refinement level of several runs: means, ranges, first failure", "[mpm][refine]") {
    std::vector<RefinementLevel> runs(3);
    const double peaks[] = {9.0, 12.0, 10.5};
    for (int k = 0; k < 3; ++k) {
        runs[k].cell_size = 0.1;
        runs[k].particles = 400;
        runs[k].steps = 100 + k;
        runs[k].peak_wall_force = peaks[k];
        runs[k].peak_time = 3.0;
        runs[k].peak_wall_force_filtered = 7.0 + k;
        runs[k].steady_wall_force = 5.0;
        runs[k].runout_past_toe = 0.5 - 0.01 * k;
    }
    runs[2].status = SoilStatus::left_domain;
    const RefinementLevel level = mean_of_runs(runs);
    CHECK(level.runs == 3);
    CHECK(level.particles == 400);
    CHECK(level.steps == 101);
    CHECK(level.status == SoilStatus::left_domain);
    CHECK_THAT(level.peak_wall_force, WithinRel(10.5, 1e-12));
    CHECK(level.peak_wall_force_range.min == 9.0);
    CHECK(level.peak_wall_force_range.max == 12.0);
    CHECK_THAT(level.peak_wall_force_filtered, WithinRel(8.0, 1e-12));
    CHECK(level.steady_wall_force_range.min == level.steady_wall_force_range.max);
    CHECK_THAT(level.runout_past_toe, WithinRel(0.49, 1e-12));
    CHECK_THAT(level.runout_past_toe_range.min, WithinRel(0.48, 1e-12));
    CHECK_THROWS_AS(mean_of_runs({}), std::invalid_argument);
}

TEST_CASE("Refinement study with repeats: each level the mean of runs with the step changed",
          "[mpm][refine]") {
    SoilScenario s = test::quick_2d(0.4);
    RefinementSettings settings;
    settings.cell_sizes = {0.4, 0.2};
    settings.steady_window = 0.5;
    settings.repeats = 2;
    const RefinementStudy study = run_refinement(s, settings);
    REQUIRE(study.levels.size() == 2);
    for (const RefinementLevel& level : study.levels) {
        std::vector<RefinementLevel> runs;
        for (int k = 0; k < 2; ++k) {
            SoilScenario run = s;
            run.numerics.cell_size = level.cell_size;
            run.numerics.cfl *= 1.0 - k * kRepeatTimeStepChange;
            runs.push_back(refinement_level(run_soil(run), level.cell_size, 0.5));
        }
        CHECK(level.runs == 2);
        CHECK(level.runout_past_toe == 0.5 * (runs[0].runout_past_toe + runs[1].runout_past_toe));
        CHECK(level.runout_past_toe_range.min ==
              std::min(runs[0].runout_past_toe, runs[1].runout_past_toe));
        CHECK(level.steps == std::lround(0.5 * static_cast<double>(runs[0].steps + runs[1].steps)));
        CHECK(level.peak_wall_force == 0.5 * (runs[0].peak_wall_force + runs[1].peak_wall_force));
        CHECK(level.peak_wall_force_range.max ==
              std::max(runs[0].peak_wall_force, runs[1].peak_wall_force));
    }
    // The second run took another time step: at 0.2 m the flow reaches the wall, and its peak
    // differs (by about 0.1 %).
    CHECK(study.levels[1].peak_wall_force_range.max > study.levels[1].peak_wall_force_range.min);
    settings.repeats = 0;
    CHECK_THROWS_WITH(run_refinement(s, settings),
                      Catch::Contains("refine.repeats = 0: must be in [1, 20]"));
    settings.repeats = kMaxRepeats + 1;
    CHECK_THROWS_WITH(run_refinement(s, settings), Catch::Contains("refine.repeats = 21"));
}
