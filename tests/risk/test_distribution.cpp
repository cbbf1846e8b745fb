#include "risk_test_support.hpp"

#include "risk/distribution.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using Family = risk::Distribution::Family;

namespace {

using test::infinity;
using test::normal;
using test::uniform;

risk::Distribution lognormal(double mean, double sd, double min = -infinity,
                             double max = infinity) {
    risk::Distribution d = normal(mean, sd, min, max);
    d.family = Family::lognormal;
    return d;
}

risk::Distribution triangular(double min, double mode, double max) {
    risk::Distribution d = uniform(min, max);
    d.family = Family::triangular;
    d.mode = mode;
    return d;
}

// Uniform in (0, 1) with 52 random bits, independent of the library's own generator code.
double open_uniform(std::mt19937_64& generator) {
    return (static_cast<double>(generator() >> 12) + 0.5) / 4503599627370496.0;
}

struct Moments {
    double mean = 0.0;
    double variance = 0.0;
    // Standard errors of the sample mean and of the sample variance:
    // sqrt(var / n) and sqrt((m4 - var^2) / n).
    double mean_error = 0.0;
    double variance_error = 0.0;
    double min = infinity;
    double max = -infinity;
};

Moments sample_moments(const risk::Distribution& d, int draws, std::uint64_t seed) {
    std::mt19937_64 generator(seed);
    std::vector<double> x(static_cast<std::size_t>(draws));
    double sum = 0.0;
    Moments m;
    for (double& value : x) {
        value = risk::inverse_cdf(d, open_uniform(generator));
        sum += value;
        m.min = std::min(m.min, value);
        m.max = std::max(m.max, value);
    }
    m.mean = sum / draws;
    double second = 0.0;
    double fourth = 0.0;
    for (const double value : x) {
        const double deviation = value - m.mean;
        second += deviation * deviation;
        fourth += deviation * deviation * deviation * deviation;
    }
    m.variance = second / (draws - 1);
    m.mean_error = std::sqrt(m.variance / draws);
    m.variance_error = std::sqrt((fourth / draws - m.variance * m.variance) / draws);
    return m;
}

}  // namespace

TEST_CASE("sample moments of every family match the analytic mean and variance",
          "[risk][distribution]") {
    // 200 000 draws each: the sample mean and variance must lie within 5 standard errors of the
    // analytic values (a false alarm once in 1.7 million per check).
    const std::vector<risk::Distribution> cases = {
        uniform(0.2, 0.4),
        normal(2600.0, 100.0),
        normal(2600.0, 100.0, 2400.0, 2800.0),
        normal(0.0, 1.0, 0.5, infinity),    // one-sided, upper part
        normal(0.0, 1.0, -infinity, -1.0),  // one-sided, lower tail
        normal(0.0, 1.0, 3.0, 4.0),         // both bounds in the upper tail
        lognormal(0.3, 0.1),
        lognormal(0.3, 0.1, 0.2, 0.5),
        lognormal(1.0, 2.0, -infinity, 3.0),  // heavy tail cut off
        triangular(0.2, 0.25, 0.4),
        triangular(0.0, 0.0, 1.0),  // mode at an end
        triangular(0.0, 1.0, 1.0),
    };
    constexpr int draws = 200000;
    std::uint64_t seed = 1;
    for (const risk::Distribution& d : cases) {
        const Moments m = sample_moments(d, draws, seed++);
        const double mean = risk::distribution_mean(d);
        const double variance = risk::distribution_variance(d);
        INFO(risk::describe(d) << ": sample mean " << m.mean << " vs " << mean << ", variance "
                               << m.variance << " vs " << variance);
        CHECK(std::abs(m.mean - mean) < 5.0 * m.mean_error);
        CHECK(std::abs(m.variance - variance) < 5.0 * m.variance_error);
        const risk::Interval support = risk::support(d);
        CHECK(m.min >= support.lower);
        CHECK(m.max <= support.upper);
    }
}

TEST_CASE("analytic moments agree with closed forms", "[risk][distribution]") {
    // Half-normal: mean sigma sqrt(2 / pi), variance sigma^2 (1 - 2 / pi).
    const risk::Distribution half = normal(0.0, 2.0, 0.0, infinity);
    CHECK_THAT(risk::distribution_mean(half),
               WithinRel(2.0 * std::sqrt(2.0 / std::numbers::pi), 1e-12));
    CHECK_THAT(risk::distribution_variance(half),
               WithinRel(4.0 * (1.0 - 2.0 / std::numbers::pi), 1e-12));
    // An untruncated lognormal keeps the mean and sd it was given.
    const risk::Distribution log = lognormal(0.3, 0.1);
    CHECK_THAT(risk::distribution_mean(log), WithinRel(0.3, 1e-12));
    CHECK_THAT(risk::distribution_variance(log), WithinRel(0.01, 1e-12));
    // Symmetric truncation leaves the normal's mean in place.
    CHECK_THAT(risk::distribution_mean(normal(2600.0, 100.0, 2400.0, 2800.0)),
               WithinAbs(2600.0, 1e-9));
    CHECK(risk::distribution_mean(risk::fixed(3.5)) == 3.5);
    CHECK(risk::distribution_variance(risk::fixed(3.5)) == 0.0);
    CHECK_THAT(risk::distribution_variance(triangular(0.0, 0.0, 1.0)),
               WithinRel(1.0 / 18.0, 1e-12));
}

TEST_CASE("draws stay inside truncations, even far in a tail", "[risk][distribution]") {
    // S(8) = 6.2e-16: Phi(8) rounds to 1 - 6.7e-16, so inverting the CDF there would give
    // nothing but 8; the complementary CDF keeps the conditional distribution.
    const risk::Distribution upper = normal(0.0, 1.0, 8.0, 9.0);
    const risk::Distribution lower = normal(0.0, 1.0, -9.0, -8.0);
    for (const double u : {1e-12, 0.1, 0.5, 0.9, 1.0 - 1e-12}) {
        const double x = risk::inverse_cdf(upper, u);
        CHECK(x >= 8.0);
        CHECK(x <= 9.0);
        // Mirror symmetry of the two truncations.
        CHECK_THAT(risk::inverse_cdf(lower, 1.0 - u), WithinAbs(-x, 1e-9));
        CHECK_THAT(risk::cdf(upper, x), WithinAbs(u, 1e-9));
    }
    // The conditional median of Z given 8 <= Z <= 9: S(m) = (S(8) + S(9)) / 2.
    const double median = risk::inverse_cdf(upper, 0.5);
    CHECK_THAT(risk::normal_cdf(-median),
               WithinRel(0.5 * (risk::normal_cdf(-8.0) + risk::normal_cdf(-9.0)), 1e-9));
    // Mean of Z beyond 8 is about 8 + 1/8 (Mills ratio); the cut at 9 barely moves it.
    CHECK_THAT(risk::distribution_mean(upper), WithinAbs(8.1211, 1e-3));
    const Moments m = sample_moments(upper, 50000, 99);
    CHECK(std::abs(m.mean - risk::distribution_mean(upper)) < 5.0 * m.mean_error);
    CHECK(m.min >= 8.0);
    CHECK(m.max <= 9.0);

    // A truncated lognormal far in its upper tail.
    const risk::Distribution heavy = lognormal(1.0, 0.1, 2.0, 3.0);
    for (const double u : {1e-9, 0.5, 1.0 - 1e-9}) {
        const double x = risk::inverse_cdf(heavy, u);
        CHECK(x >= 2.0);
        CHECK(x <= 3.0);
    }
    CHECK(risk::inverse_cdf(heavy, 0.5) > 2.0);
}

TEST_CASE("inverse CDFs are monotone and invert the CDF", "[risk][distribution]") {
    const std::vector<risk::Distribution> cases = {
        uniform(-1.0, 2.0),          normal(1.0, 0.5),
        normal(0.0, 1.0, -0.5, 2.0), normal(0.0, 1.0, 5.0, infinity),
        lognormal(0.3, 0.1),         lognormal(0.3, 0.2, 0.1, 0.6),
        triangular(0.2, 0.25, 0.4),  triangular(-1.0, 1.0, 1.0),
    };
    for (const risk::Distribution& d : cases) {
        INFO(risk::describe(d));
        double previous = -infinity;
        for (int i = 1; i < 20000; ++i) {
            const double u = i / 20000.0;
            const double x = risk::inverse_cdf(d, u);
            REQUIRE(x >= previous);
            previous = x;
            REQUIRE_THAT(risk::cdf(d, x), WithinAbs(u, 1e-9));
        }
        // The extreme uniforms the samplers produce give finite values inside the support.
        for (const double u : {0x1.0p-53, 1.0 - 0x1.0p-53}) {
            const double x = risk::inverse_cdf(d, u);
            CHECK(std::isfinite(x));
            CHECK(x >= risk::support(d).lower);
            CHECK(x <= risk::support(d).upper);
        }
    }
}

TEST_CASE("a distribution conditioned on an interval stays in it", "[risk][distribution]") {
    // Uniform across 5 m conditioned on the 4 m band where a rock fits: uniform on the band.
    const risk::Distribution across = uniform(-2.5, 2.5);
    CHECK_THAT(risk::inverse_cdf_within(across, -2.0, 2.0, 0.25), WithinAbs(-1.0, 1e-12));
    CHECK_THAT(risk::inverse_cdf_within(across, -2.0, 2.0, 0.75), WithinAbs(1.0, 1e-12));
    // Normal and triangular: the conditional quantile.
    const risk::Distribution n = normal(0.0, 1.0);
    CHECK_THAT(risk::inverse_cdf_within(n, 0.0, infinity, 0.5),
               WithinAbs(risk::inverse_cdf(n, 0.75), 1e-12));
    const risk::Distribution t = triangular(0.0, 0.5, 1.0);
    const double x = risk::inverse_cdf_within(t, 0.0, 0.5, 0.5);
    CHECK_THAT(risk::cdf(t, x), WithinAbs(0.25, 1e-12));
    // No probability inside: the median clamped to the interval.
    CHECK(risk::inverse_cdf_within(risk::fixed(3.0), -2.0, 2.0, 0.3) == 2.0);
    CHECK(risk::inverse_cdf_within(uniform(2.2, 2.5), -2.0, 2.0, 0.3) == 2.0);
    CHECK(risk::inverse_cdf_within(normal(-100.0, 0.01), -2.0, 2.0, 0.3) == -2.0);
}

TEST_CASE("choose follows the cumulative weights", "[risk][distribution]") {
    const std::vector<double> weights = {1.0, 0.0, 3.0};
    CHECK(risk::choose(weights, 0.0) == 0);
    CHECK(risk::choose(weights, 0.2499) == 0);
    CHECK(risk::choose(weights, 0.25) == 2);
    CHECK(risk::choose(weights, 0.9999999999) == 2);
    // Never an index of weight 0, even at the top end.
    CHECK(risk::choose({2.0, 1.0, 0.0}, 1.0 - 0x1.0p-53) == 1);
    CHECK(risk::choose({1.0, 1.0, 1.0}, 0.5) == 1);
}

TEST_CASE("impossible distributions are rejected naming the key and parameter",
          "[risk][distribution]") {
    const auto message = [](const risk::Distribution& d) {
        try {
            risk::validate(d, "sweep.rock.size");
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        FAIL("no error for " << risk::describe(d));
        return std::string();
    };
    CHECK_THAT(message(uniform(0.4, 0.2)),
               Contains("sweep.rock.size = uniform [0.4, 0.2]") && Contains("must have min < max"));
    CHECK_THAT(message(normal(2600.0, -1.0)), Contains("sd = -1: must be > 0"));
    CHECK_THAT(message(normal(0.0, 1.0, 2.0, 1.0)), Contains("must have min < max"));
    CHECK_THAT(message(normal(0.0, 1.0, 50.0, 60.0)), Contains("holds no probability"));
    CHECK_THAT(message(lognormal(-0.3, 0.1)), Contains("mean = -0.3: must be > 0"));
    CHECK_THAT(message(lognormal(0.3, 0.1, -infinity, -1.0)), Contains("max = -1: must be > 0"));
    CHECK_THAT(message(triangular(0.2, 0.5, 0.4)), Contains("mode = 0.5: must be in [min, max]"));
    CHECK_THAT(message(risk::fixed(std::nan(""))), Contains("value = nan: must be finite"));
    CHECK_THAT(message(uniform(0.0, infinity)), Contains("max = inf: must be finite"));
    CHECK_NOTHROW(risk::validate(normal(0.0, 1.0, 8.0, 9.0), "x"));
    CHECK_NOTHROW(risk::validate(triangular(0.0, 0.0, 1.0), "x"));
}
