#include "risk/distribution.hpp"

#include "risk/number_text.hpp"
#include "risk/statistics.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rockfall::risk {
namespace {

using Family = Distribution::Family;

constexpr double infinity = std::numeric_limits<double>::infinity();

std::string number(double value) { return number_text(value); }

double normal_pdf(double z) {
    // phi(+-inf) = 0, and z phi(z) -> 0 there too, which the moment formulas rely on.
    if (std::isinf(z)) return 0.0;
    return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
}

// Phi(b) - Phi(a) for a <= b, from the upper tail when a is above the median: Phi(a) rounds to
// 1 there and the difference would keep no digits.
double normal_mass(double a, double b) {
    if (a > 0.0) return normal_cdf(-a) - normal_cdf(-b);
    return normal_cdf(b) - normal_cdf(a);
}

// The u-quantile of the standard normal conditioned on [a, b] (a < b, ends may be infinite).
double standard_normal_within(double a, double b, double u) {
    double z = 0.0;
    if (a > 0.0) {
        // Upper tail: invert the complementary CDF, S(z) = S(a) - u (S(a) - S(b)).
        const double upper_a = normal_cdf(-a);
        const double upper = upper_a - u * (upper_a - normal_cdf(-b));
        if (!(upper > 0.0)) return b;
        if (!(upper < 1.0)) return a;
        z = -normal_quantile(upper);
    } else {
        const double lower_a = normal_cdf(a);
        const double lower = lower_a + u * (normal_cdf(b) - lower_a);
        if (!(lower > 0.0)) return a;
        if (!(lower < 1.0)) return b;
        z = normal_quantile(lower);
    }
    // Rounding in Phi and its inverse may step a hair outside the truncation.
    return std::clamp(z, a, b);
}

// ln X ~ N(mu, sigma^2) for a lognormal X of the given mean and sd (method of moments).
struct LogParameters {
    double mu = 0.0;
    double sigma = 0.0;
};

LogParameters log_parameters(const Distribution& d) {
    const double ratio = d.sd / d.mean;
    const double variance = std::log1p(ratio * ratio);
    return {std::log(d.mean) - 0.5 * variance, std::sqrt(variance)};
}

// The truncation [min, max] as standardized bounds of the underlying normal (of ln X for a
// lognormal, where bounds at or below 0 mean no lower truncation).
Interval standard_bounds(const Distribution& d) {
    if (d.family == Family::normal) return {(d.min - d.mean) / d.sd, (d.max - d.mean) / d.sd};
    const LogParameters log = log_parameters(d);
    const double lower = d.min > 0.0 ? (std::log(d.min) - log.mu) / log.sigma : -infinity;
    const double upper = d.max > 0.0 ? (std::log(d.max) - log.mu) / log.sigma : -infinity;
    return {lower, upper};
}

std::string family_name(const Distribution& d) { return to_string(d.family); }

}  // namespace

std::string to_string(Distribution::Family family) {
    switch (family) {
        case Family::fixed:
            return "fixed";
        case Family::uniform:
            return "uniform";
        case Family::normal:
            return "normal";
        case Family::lognormal:
            return "lognormal";
        case Family::triangular:
            return "triangular";
    }
    assert(false && "unknown distribution family");
    return "unknown";
}

Distribution fixed(double value) {
    Distribution d;
    d.value = value;
    return d;
}

std::string describe(const Distribution& d) {
    switch (d.family) {
        case Family::fixed:
            return number(d.value);
        case Family::uniform:
            return "uniform [" + number(d.min) + ", " + number(d.max) + "]";
        case Family::triangular:
            return "triangular [" + number(d.min) + ", " + number(d.mode) + ", " + number(d.max) +
                   "]";
        case Family::normal:
        case Family::lognormal: {
            std::string text =
                family_name(d) + " (mean " + number(d.mean) + ", sd " + number(d.sd) + ")";
            if (d.min > -infinity || d.max < infinity) {
                text += " on [" + number(d.min) + ", " + number(d.max) + "]";
            }
            return text;
        }
    }
    assert(false && "unknown distribution family");
    return {};
}

std::vector<std::string> find_problems(const Distribution& d) {
    std::vector<std::string> problems;
    const auto require = [&](bool condition, std::string rule) {
        if (!condition) problems.push_back(std::move(rule));
    };
    const auto finite = [&](const char* name, double value) {
        require(std::isfinite(value),
                std::string(name) + " = " + number(value) + ": must be finite");
    };
    switch (d.family) {
        case Family::fixed:
            finite("value", d.value);
            break;
        case Family::uniform:
        case Family::triangular:
            finite("min", d.min);
            finite("max", d.max);
            require(d.min < d.max, "min = " + number(d.min) + ", max = " + number(d.max) +
                                       ": must have min < max (a single value is written as "
                                       "a plain number)");
            if (d.family == Family::triangular) {
                require(d.mode >= d.min && d.mode <= d.max,
                        "mode = " + number(d.mode) + ": must be in [min, max] = [" + number(d.min) +
                            ", " + number(d.max) + "]");
            }
            break;
        case Family::normal:
        case Family::lognormal: {
            const bool lognormal = d.family == Family::lognormal;
            if (lognormal) {
                require(d.mean > 0.0 && std::isfinite(d.mean),
                        "mean = " + number(d.mean) + ": must be > 0 and finite");
            } else {
                finite("mean", d.mean);
            }
            require(d.sd > 0.0 && std::isfinite(d.sd),
                    "sd = " + number(d.sd) + ": must be > 0 and finite");
            // Infinite bounds mean no truncation on that side.
            require(d.min < d.max, "min = " + number(d.min) + ", max = " + number(d.max) +
                                       ": must have min < max");
            if (lognormal) {
                require(!(d.max <= 0.0),
                        "max = " + number(d.max) + ": must be > 0 (a lognormal is positive)");
            }
            if (problems.empty()) {
                const Interval z = standard_bounds(d);
                require(normal_mass(z.lower, z.upper) > 0.0,
                        "[min, max] = [" + number(d.min) + ", " + number(d.max) +
                            "]: holds no probability (its ends are " + number(z.lower) + " and " +
                            number(z.upper) + " standard deviations" +
                            (lognormal ? " of ln X" : "") + " from the mean)");
            }
            break;
        }
    }
    return problems;
}

void validate(const Distribution& distribution, const std::string& name) {
    const std::vector<std::string> problems = find_problems(distribution);
    if (problems.empty()) return;
    std::string message = name + " = " + describe(distribution) + ": ";
    for (std::size_t i = 0; i < problems.size(); ++i) message += (i == 0 ? "" : "; ") + problems[i];
    throw std::invalid_argument(message);
}

Interval support(const Distribution& d) {
    switch (d.family) {
        case Family::fixed:
            return {d.value, d.value};
        case Family::lognormal:
            return {std::max(d.min, 0.0), d.max};
        case Family::uniform:
        case Family::triangular:
        case Family::normal:
            return {d.min, d.max};
    }
    assert(false && "unknown distribution family");
    return {};
}

double cdf(const Distribution& d, double x) {
    switch (d.family) {
        case Family::fixed:
            return x >= d.value ? 1.0 : 0.0;
        case Family::uniform:
            return std::clamp((x - d.min) / (d.max - d.min), 0.0, 1.0);
        case Family::triangular: {
            // Piecewise quadratic (Kotz and van Dorp, Beyond Beta, 2004, ch. 1).
            if (x <= d.min) return 0.0;
            if (x >= d.max) return 1.0;
            const double width = d.max - d.min;
            if (x <= d.mode) return (x - d.min) * (x - d.min) / (width * (d.mode - d.min));
            return 1.0 - (d.max - x) * (d.max - x) / (width * (d.max - d.mode));
        }
        case Family::normal:
        case Family::lognormal: {
            if (x < support(d).lower) return 0.0;
            if (x >= d.max) return 1.0;
            const Interval bounds = standard_bounds(d);
            double z = (x - d.mean) / d.sd;
            if (d.family == Family::lognormal) {
                const LogParameters log = log_parameters(d);
                z = (std::log(x) - log.mu) / log.sigma;
            }
            return std::clamp(normal_mass(bounds.lower, std::max(z, bounds.lower)) /
                                  normal_mass(bounds.lower, bounds.upper),
                              0.0, 1.0);
        }
    }
    assert(false && "unknown distribution family");
    return 0.0;
}

double inverse_cdf(const Distribution& d, double u) {
    assert(u >= 0.0 && u <= 1.0);
    switch (d.family) {
        case Family::fixed:
            return d.value;
        case Family::uniform:
            return std::clamp(d.min + u * (d.max - d.min), d.min, d.max);
        case Family::triangular: {
            const double width = d.max - d.min;
            const double at_mode = (d.mode - d.min) / width;
            const double x = u < at_mode ? d.min + std::sqrt(u * width * (d.mode - d.min))
                                         : d.max - std::sqrt((1.0 - u) * width * (d.max - d.mode));
            return std::clamp(x, d.min, d.max);
        }
        case Family::normal: {
            const Interval z = standard_bounds(d);
            return std::clamp(d.mean + d.sd * standard_normal_within(z.lower, z.upper, u), d.min,
                              d.max);
        }
        case Family::lognormal: {
            const Interval z = standard_bounds(d);
            const LogParameters log = log_parameters(d);
            return std::clamp(
                std::exp(log.mu + log.sigma * standard_normal_within(z.lower, z.upper, u)),
                support(d).lower, d.max);
        }
    }
    assert(false && "unknown distribution family");
    return 0.0;
}

double inverse_cdf_within(const Distribution& d, double lo, double hi, double u) {
    assert(lo <= hi);
    Distribution conditioned = d;
    switch (d.family) {
        case Family::fixed:
            break;
        case Family::uniform:
        case Family::normal:
        case Family::lognormal:
            // These families are closed under truncation: intersect the bounds.
            conditioned.min = std::max(d.min, lo);
            conditioned.max = std::min(d.max, hi);
            if (find_problems(conditioned).empty()) return inverse_cdf(conditioned, u);
            break;
        case Family::triangular: {
            const double below = cdf(d, lo);
            const double mass = cdf(d, hi) - below;
            if (mass > 0.0) return std::clamp(inverse_cdf(d, below + u * mass), lo, hi);
            break;
        }
    }
    return std::clamp(inverse_cdf(d, 0.5), lo, hi);
}

double distribution_mean(const Distribution& d) {
    switch (d.family) {
        case Family::fixed:
            return d.value;
        case Family::uniform:
            return 0.5 * (d.min + d.max);
        case Family::triangular:
            return (d.min + d.mode + d.max) / 3.0;
        case Family::normal: {
            const Interval z = standard_bounds(d);
            return d.mean + d.sd * (normal_pdf(z.lower) - normal_pdf(z.upper)) /
                                normal_mass(z.lower, z.upper);
        }
        case Family::lognormal: {
            const Interval z = standard_bounds(d);
            const LogParameters log = log_parameters(d);
            return std::exp(log.mu + 0.5 * log.sigma * log.sigma) *
                   normal_mass(z.lower - log.sigma, z.upper - log.sigma) /
                   normal_mass(z.lower, z.upper);
        }
    }
    assert(false && "unknown distribution family");
    return 0.0;
}

double distribution_variance(const Distribution& d) {
    switch (d.family) {
        case Family::fixed:
            return 0.0;
        case Family::uniform:
            return (d.max - d.min) * (d.max - d.min) / 12.0;
        case Family::triangular:
            return (d.min * d.min + d.mode * d.mode + d.max * d.max - d.min * d.mode -
                    d.min * d.max - d.mode * d.max) /
                   18.0;
        case Family::normal: {
            const Interval z = standard_bounds(d);
            const double mass = normal_mass(z.lower, z.upper);
            // z phi(z) is 0 at infinite bounds (normal_pdf returns 0 there, not inf * 0).
            const auto z_pdf = [](double b) { return std::isinf(b) ? 0.0 : b * normal_pdf(b); };
            const double shift = (normal_pdf(z.lower) - normal_pdf(z.upper)) / mass;
            return d.sd * d.sd * (1.0 + (z_pdf(z.lower) - z_pdf(z.upper)) / mass - shift * shift);
        }
        case Family::lognormal: {
            const Interval z = standard_bounds(d);
            const LogParameters log = log_parameters(d);
            const double mass = normal_mass(z.lower, z.upper);
            const double s = log.sigma;
            const double mean =
                std::exp(log.mu + 0.5 * s * s) * normal_mass(z.lower - s, z.upper - s) / mass;
            const double square = std::exp(2.0 * log.mu + 2.0 * s * s) *
                                  normal_mass(z.lower - 2.0 * s, z.upper - 2.0 * s) / mass;
            return square - mean * mean;
        }
    }
    assert(false && "unknown distribution family");
    return 0.0;
}

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

std::size_t choose(const std::vector<double>& weights, double u) {
    assert(!weights.empty());
    double total = 0.0;
    for (const double w : weights) total += w;
    assert(total > 0.0);
    const double target = u * total;
    double cumulative = 0.0;
    std::size_t last_positive = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        if (weights[i] <= 0.0) continue;
        cumulative += weights[i];
        last_positive = i;
        if (target < cumulative) return i;
    }
    // u close to 1 can reach the total after rounding: the last index that can be chosen.
    return last_positive;
}

}  // namespace rockfall::risk
