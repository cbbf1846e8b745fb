#include "risk/statistics.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <vector>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall::risk;

// Reference values below were computed with mpmath 1.3 at 30-40 significant digits
// (erfinv, betainc, exact binomial sums).

TEST_CASE("normal quantile matches high-precision values", "[risk][statistics]") {
    CHECK(normal_quantile(0.5) == 0.0);
    CHECK_THAT(normal_quantile(0.975), WithinRel(1.9599639845400538556, 1e-14));
    CHECK_THAT(normal_quantile(0.995), WithinRel(2.5758293035489004539, 1e-14));
    CHECK_THAT(normal_quantile(0.3), WithinRel(-0.52440051270804081597, 1e-14));
    CHECK_THAT(normal_quantile(1e-10), WithinRel(-6.3613409024040561991, 1e-13));
    CHECK_THAT(normal_quantile(0.999999), WithinRel(4.7534243088170877657, 1e-10));
    CHECK_THAT(normal_quantile(0.025), WithinRel(-normal_quantile(0.975), 1e-14));
    CHECK_THROWS_AS(normal_quantile(0.0), std::invalid_argument);
    CHECK_THROWS_AS(normal_quantile(1.0), std::invalid_argument);
}

TEST_CASE("regularized incomplete beta matches closed forms and references", "[risk][statistics]") {
    // Closed forms: I_x(1, b) = 1 - (1 - x)^b, I_x(a, 1) = x^a, I_1/2(a, a) = 1/2.
    CHECK_THAT(regularized_incomplete_beta(0.3, 1.0, 4.0),
               WithinRel(1.0 - std::pow(0.7, 4), 1e-14));
    CHECK_THAT(regularized_incomplete_beta(0.8, 3.5, 1.0), WithinRel(std::pow(0.8, 3.5), 1e-14));
    // Tolerances grow with a + b: the log-gamma prefactor costs about (a + b) * 1e-15.
    CHECK_THAT(regularized_incomplete_beta(0.5, 200.0, 200.0), WithinRel(0.5, 1e-12));
    CHECK_THAT(regularized_incomplete_beta(0.3, 2.5, 4.5),
               WithinRel(0.40653901668245924935, 1e-13));
    CHECK_THAT(regularized_incomplete_beta(0.9, 50.0, 3.0),
               WithinRel(0.096633285137252208871, 1e-13));
    CHECK_THAT(regularized_incomplete_beta(0.01, 0.5, 10.0),
               WithinRel(0.34207182484321553304, 1e-13));
    CHECK_THAT(regularized_incomplete_beta(0.7, 0.1, 0.2),
               WithinRel(0.71632698299586115243, 1e-13));
    CHECK_THAT(regularized_incomplete_beta(0.45, 300.0, 360.0),
               WithinRel(0.40819231856508133826, 1e-11));
    CHECK_THAT(regularized_incomplete_beta(0.2, 1000.0, 4000.0),
               WithinRel(0.50282103954586265764, 1e-10));
    CHECK(regularized_incomplete_beta(0.0, 2.0, 3.0) == 0.0);
    CHECK(regularized_incomplete_beta(1.0, 2.0, 3.0) == 1.0);
    CHECK_THROWS_AS(regularized_incomplete_beta(1.5, 2.0, 3.0), std::invalid_argument);
}

TEST_CASE("binomial cdf matches exact sums", "[risk][statistics]") {
    CHECK_THAT(binomial_cdf(3, 10, 0.3), WithinRel(0.64961071840000002962, 1e-13));
    CHECK_THAT(binomial_cdf(480, 1000, 0.5), WithinRel(0.10872414660207047141, 1e-10));
    CHECK(binomial_cdf(-1, 10, 0.3) == 0.0);
    CHECK(binomial_cdf(10, 10, 0.3) == 1.0);
    CHECK(binomial_cdf(4, 10, 0.0) == 1.0);
    CHECK(binomial_cdf(4, 10, 1.0) == 0.0);
}

TEST_CASE("Wilson interval of 50 in 1000", "[risk][statistics]") {
    const Interval i = wilson_interval(50, 1000);
    CHECK_THAT(i.lower, WithinAbs(0.0381302623927, 1e-12));
    CHECK_THAT(i.upper, WithinAbs(0.0653138202443, 1e-12));
    // At the edges the interval stays inside [0, 1] and still has width.
    const Interval none = wilson_interval(0, 20);
    CHECK(none.lower == 0.0);
    CHECK(none.upper > 0.1);
    CHECK(wilson_interval(20, 20).upper == 1.0);
    // A higher confidence gives a wider interval.
    const Interval wide = wilson_interval(50, 1000, 0.99);
    CHECK(wide.lower < i.lower);
    CHECK(wide.upper > i.upper);
    CHECK_THROWS_AS(wilson_interval(5, 0), std::invalid_argument);
    CHECK_THROWS_AS(wilson_interval(11, 10), std::invalid_argument);
    CHECK_THROWS_AS(wilson_interval(5, 10, 1.0), std::invalid_argument);
}

TEST_CASE("Clopper-Pearson interval matches exact references", "[risk][statistics]") {
    struct Case {
        int successes, trials;
        double lower, upper;
    };
    const Case cases[] = {
        {50, 1000, 0.0373353976046618, 0.0653904879154936},
        {3, 10, 0.0667395111777345, 0.652452850059997},
        {1, 200, 0.000126581027867018, 0.0275418984572056},
        {0, 10, 0.0, 0.308497107818761},  // 1 - 0.025^(1/10)
        {10, 10, 0.691502892181239, 1.0},
    };
    for (const Case& c : cases) {
        INFO(c.successes << " of " << c.trials);
        const Interval i = clopper_pearson_interval(c.successes, c.trials);
        CHECK_THAT(i.lower, WithinAbs(c.lower, 1e-12));
        CHECK_THAT(i.upper, WithinAbs(c.upper, 1e-12));
    }
    // Conservative: wider than the Wilson interval for the same data.
    const Interval exact = clopper_pearson_interval(50, 1000);
    const Interval wilson = wilson_interval(50, 1000);
    CHECK(exact.lower < wilson.lower);
    CHECK(exact.upper > wilson.upper);
}

TEST_CASE("type 7 quantile interpolates between order statistics", "[risk][statistics]") {
    const std::vector<double> x = {1.0, 2.0, 4.0, 8.0, 16.0};
    CHECK(quantile(x, 0.0) == 1.0);
    CHECK(quantile(x, 1.0) == 16.0);
    CHECK(quantile(x, 0.5) == 4.0);
    CHECK_THAT(quantile(x, 0.1), WithinRel(1.4, 1e-15));   // h = 0.4
    CHECK_THAT(quantile(x, 0.9), WithinRel(12.8, 1e-15));  // h = 3.6: 8 + 0.6 * 8
    CHECK(quantile({7.0}, 0.3) == 7.0);
    CHECK(median({3.0, 1.0, 2.0, 10.0}) == 2.5);
    CHECK_THROWS_AS(quantile({}, 0.5), std::invalid_argument);
    CHECK_THROWS_AS(quantile(x, 1.5), std::invalid_argument);
}

TEST_CASE("median confidence interval uses the binomial order statistics", "[risk][statistics]") {
    // Sample 1..n: the bounds are the ranks themselves. Ranks from exact binomial sums.
    const auto ranks = [](int n) {
        std::vector<double> sample(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) sample[static_cast<std::size_t>(i)] = n - i;  // unsorted
        return median_confidence_interval(sample);
    };
    const std::vector<std::tuple<int, int, int>> expected = {
        {6, 1, 6}, {7, 1, 7}, {20, 6, 15}, {100, 40, 61}, {200, 86, 115}, {1000, 469, 532}};
    for (const auto& [n, lower, upper] : expected) {
        INFO("n = " << n);
        const Interval i = ranks(n);
        CHECK(i.lower == lower);
        CHECK(i.upper == upper);
    }
    CHECK_THROWS_AS(ranks(5), std::invalid_argument);
    CHECK_THROWS_AS(median_confidence_interval({}), std::invalid_argument);
}

TEST_CASE("quantile confidence ranks match exact binomial sums", "[risk][statistics]") {
    // Ranks from exact rational binomial sums (Python fractions).
    const std::vector<std::tuple<std::int64_t, double, double, std::int64_t, std::int64_t>>
        expected = {{100, 0.9, 0.95, 84, 96},     {100, 0.1, 0.95, 5, 17},
                    {1000, 0.95, 0.95, 936, 964}, {1000, 0.99, 0.95, 983, 997},
                    {20, 0.25, 0.95, 2, 10},      {1000, 0.9, 0.99, 875, 925},
                    {1000, 0.5, 0.95, 469, 532}};
    for (const auto& [n, p, confidence, lower, upper] : expected) {
        INFO("n = " << n << ", p = " << p << ", confidence = " << confidence);
        const QuantileRanks r = quantile_confidence_ranks(n, p, confidence);
        CHECK(r.lower == lower);
        CHECK(r.upper == upper);
    }
    // 0.95^n > 0.025 up to n = 71: no order statistic bounds the 95th percentile from above.
    CHECK(quantile_confidence_ranks(71, 0.95).upper == 72);
    CHECK(quantile_confidence_ranks(72, 0.95).upper == 72);
    CHECK(quantile_confidence_ranks(59, 0.95).lower == 52);
    CHECK(quantile_confidence_ranks(0, 0.5).lower == 0);
    CHECK_THROWS_AS(quantile_confidence_ranks(10, 0.0), std::invalid_argument);
    CHECK_THROWS_AS(quantile_confidence_ranks(10, 1.0), std::invalid_argument);
}

TEST_CASE("quantile confidence interval is the bounding order statistics", "[risk][statistics]") {
    std::vector<double> sample(100);
    for (std::size_t i = 0; i < sample.size(); ++i) sample[i] = 0.5 * static_cast<double>(100 - i);
    const Interval i90 = quantile_confidence_interval(sample, 0.9);
    CHECK(i90.lower == 42.0);  // x(84) = 84 / 2
    CHECK(i90.upper == 48.0);  // x(96)
    CHECK_THROWS_AS(quantile_confidence_interval(std::vector<double>(71, 1.0), 0.95),
                    std::invalid_argument);
}

TEST_CASE("quantile confidence ranks stay fast for a million values", "[risk][statistics]") {
    // The query command bounds percentiles of a million outcomes with these ranks; the normal
    // approximation n p +- z sqrt(n p (1 - p)) places them within a rank or two.
    const std::int64_t n = 1000000;
    const QuantileRanks r = quantile_confidence_ranks(n, 0.99);
    const double half = 1.959964 * std::sqrt(n * 0.99 * 0.01);
    CHECK(std::abs(static_cast<double>(r.lower) - (0.99 * n - half)) < 2.0);
    CHECK(std::abs(static_cast<double>(r.upper) - (0.99 * n + half + 1.0)) < 2.0);
}

TEST_CASE("mean and standard deviation", "[risk][statistics]") {
    const std::vector<double> x = {2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0};
    CHECK(mean(x) == 5.0);
    CHECK_THAT(standard_deviation(x), WithinRel(std::sqrt(32.0 / 7.0), 1e-15));
    CHECK_THROWS_AS(standard_deviation({1.0}), std::invalid_argument);
}
