#include "risk/statistics.hpp"

#include "validation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace rockfall::risk {
namespace {

constexpr double pi = 3.14159265358979323846;

using detail::require;

void require_confidence(double confidence) {
    require(confidence > 0.0 && confidence < 1.0,
            "confidence = " + std::to_string(confidence) + ": must be in (0, 1)");
}

void require_counts(std::int64_t successes, std::int64_t trials) {
    require(trials > 0, "trials = " + std::to_string(trials) + ": must be > 0");
    require(successes >= 0 && successes <= trials, "successes = " + std::to_string(successes) +
                                                       ": must be in [0, " +
                                                       std::to_string(trials) + "]");
}

// The continued fraction of DLMF 8.17.22, 1 + d1 / (1 + d2 / (1 + ...)), by the modified
// Lentz method (Press et al., Numerical Recipes, 3rd ed., sec. 5.2); converges quickly for
// x < (a + 1) / (a + b + 2).
double beta_continued_fraction(double x, double a, double b) {
    constexpr double tiny = 1e-300;
    constexpr double tolerance = 1e-15;
    constexpr int max_terms = 100000;
    double f = 1.0;
    double c = 1.0;
    double d = 0.0;
    for (int j = 1; j <= max_terms; ++j) {
        const int m = j / 2;
        const double dm = m;
        const double term =
            j % 2 == 0 ? dm * (b - dm) * x / ((a + 2.0 * dm - 1.0) * (a + 2.0 * dm))
                       : -(a + dm) * (a + b + dm) * x / ((a + 2.0 * dm) * (a + 2.0 * dm + 1.0));
        d = 1.0 + term * d;
        if (std::abs(d) < tiny) d = tiny;
        c = 1.0 + term / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = c * d;
        f *= delta;
        if (std::abs(delta - 1.0) < tolerance) return f;
    }
    assert(false && "incomplete beta continued fraction did not converge");
    return f;
}

// The smallest p in [0, 1] with increasing(p) >= target, to 1e-14 by bisection.
template <class F>
double bisect(F increasing, double target) {
    double lo = 0.0;
    double hi = 1.0;
    while (hi - lo > 1e-14) {
        const double mid = 0.5 * (lo + hi);
        (increasing(mid) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

double normal_quantile(double p) {
    require(p > 0.0 && p < 1.0, "p = " + std::to_string(p) + ": must be in (0, 1)");
    // Acklam's coefficients (P. J. Acklam, "An algorithm for computing the inverse normal
    // cumulative distribution function", 2003): a central rational function in (p - 1/2)^2
    // and tail rational functions in sqrt(-2 ln p).
    static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                                   -2.759285104469687e+02, 1.383577518672690e+02,
                                   -3.066479806614716e+01, 2.506628277459239e+00};
    static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                                   -1.556989798598866e+02, 6.680131188771972e+01,
                                   -1.328068155288572e+01};
    static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                                   -2.400758277161838e+00, -2.549732539343734e+00,
                                   4.374664141464968e+00,  2.938163982698783e+00};
    static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01,
                                   2.445134137142996e+00, 3.754408661907416e+00};
    constexpr double p_low = 0.02425;

    const auto tail = [&](double q) {
        return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
               ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
    };
    double x = 0.0;
    if (p < p_low) {
        x = tail(std::sqrt(-2.0 * std::log(p)));
    } else if (p > 1.0 - p_low) {
        x = -tail(std::sqrt(-2.0 * std::log1p(-p)));
    } else {
        const double q = p - 0.5;
        const double r = q * q;
        x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
            (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
    }
    // One Halley step on Phi(x) - p, with Phi from erfc (accurate in both tails).
    const double error = 0.5 * std::erfc(-x / std::sqrt(2.0)) - p;
    const double u = error * std::sqrt(2.0 * pi) * std::exp(0.5 * x * x);
    return x - u / (1.0 + 0.5 * x * u);
}

double regularized_incomplete_beta(double x, double a, double b) {
    require(x >= 0.0 && x <= 1.0, "x = " + std::to_string(x) + ": must be in [0, 1]");
    require(a > 0.0 && b > 0.0, "a and b must be > 0");
    if (x == 0.0 || x == 1.0) return x;
    // The fraction converges fast below the mean-like point; above it use the symmetry
    // I_x(a, b) = 1 - I_{1-x}(b, a) (DLMF 8.17.4).
    if (x > (a + 1.0) / (a + b + 2.0)) return 1.0 - regularized_incomplete_beta(1.0 - x, b, a);
    const double log_prefactor =
        a * std::log(x) + b * std::log1p(-x) - std::lgamma(a) - std::lgamma(b) + std::lgamma(a + b);
    return std::exp(log_prefactor) / (a * beta_continued_fraction(x, a, b));
}

double binomial_cdf(std::int64_t k, std::int64_t n, double p) {
    require(n >= 0, "n = " + std::to_string(n) + ": must be >= 0");
    require(p >= 0.0 && p <= 1.0, "p = " + std::to_string(p) + ": must be in [0, 1]");
    if (k < 0) return 0.0;
    if (k >= n) return 1.0;
    // P(X <= k) = 1 - P(X >= k + 1) = I_{1-p}(n - k, k + 1) (DLMF 8.17.5 and 8.17.4).
    return regularized_incomplete_beta(1.0 - p, static_cast<double>(n - k),
                                       static_cast<double>(k + 1));
}

Interval wilson_interval(std::int64_t successes, std::int64_t trials, double confidence) {
    require_counts(successes, trials);
    require_confidence(confidence);
    const double n = static_cast<double>(trials);
    const double p = static_cast<double>(successes) / n;
    const double z = normal_quantile(0.5 + 0.5 * confidence);
    const double z2 = z * z;
    const double centre = (p + 0.5 * z2 / n) / (1.0 + z2 / n);
    const double half = z / (1.0 + z2 / n) * std::sqrt(p * (1.0 - p) / n + 0.25 * z2 / (n * n));
    // The bounds are exactly 0 at no successes and 1 at all successes; say so rather than
    // leave rounding residue there.
    return {successes == 0 ? 0.0 : centre - half, successes == trials ? 1.0 : centre + half};
}

Interval clopper_pearson_interval(std::int64_t successes, std::int64_t trials, double confidence) {
    require_counts(successes, trials);
    require_confidence(confidence);
    const double alpha = 1.0 - confidence;
    const double x = static_cast<double>(successes);
    const double n = static_cast<double>(trials);
    Interval interval{0.0, 1.0};
    // Lower bound: P(X >= x | p) = I_p(x, n - x + 1) = alpha / 2; upper bound:
    // P(X <= x | p) = alpha / 2, i.e. I_p(x + 1, n - x) = 1 - alpha / 2. Both increase with p.
    if (successes > 0) {
        interval.lower = bisect(
            [&](double p) { return regularized_incomplete_beta(p, x, n - x + 1.0); }, 0.5 * alpha);
    }
    if (successes < trials) {
        interval.upper =
            bisect([&](double p) { return regularized_incomplete_beta(p, x + 1.0, n - x); },
                   1.0 - 0.5 * alpha);
    }
    return interval;
}

double quantile(const std::vector<double>& sorted, double p) {
    require(!sorted.empty(), "quantile of an empty sample");
    require(p >= 0.0 && p <= 1.0, "p = " + std::to_string(p) + ": must be in [0, 1]");
    assert(std::is_sorted(sorted.begin(), sorted.end()));
    const double h = static_cast<double>(sorted.size() - 1) * p;
    const auto below = static_cast<std::size_t>(std::floor(h));
    if (below + 1 >= sorted.size()) return sorted.back();
    return sorted[below] + (h - static_cast<double>(below)) * (sorted[below + 1] - sorted[below]);
}

double median(std::vector<double> sample) {
    std::sort(sample.begin(), sample.end());
    return quantile(sample, 0.5);
}

QuantileRanks quantile_confidence_ranks(std::int64_t n, double p, double confidence) {
    require_confidence(confidence);
    require(n >= 0, "n = " + std::to_string(n) + ": must be >= 0");
    require(p > 0.0 && p < 1.0, "p = " + std::to_string(p) + ": must be in (0, 1)");
    const double tail = 0.5 * (1.0 - confidence);
    const double dn = static_cast<double>(n);
    const auto lower_ok = [&](std::int64_t r) { return binomial_cdf(r - 1, n, p) <= tail; };
    // P(B >= s) = I_p(s, n - s + 1) (DLMF 8.17.5) taken directly, not as 1 - P(B <= s - 1):
    // at p = 1/2 it is then bitwise the lower tail at rank n + 1 - s, so the median's interval
    // stays exactly symmetric.
    const auto upper_ok = [&](std::int64_t s) {
        const double ds = static_cast<double>(s);
        return regularized_incomplete_beta(p, ds, dn - ds + 1.0) <= tail;
    };
    QuantileRanks ranks{0, n + 1};
    // lower_ok falls from true to false as r grows (it fails at r = n + 1, where the cdf is 1);
    // upper_ok rises from false (s = 0) to true. Bisect each between a known good and bad rank.
    if (n > 0 && lower_ok(1)) {
        std::int64_t good = 1;
        std::int64_t bad = n + 1;
        while (bad - good > 1) {
            const std::int64_t mid = good + (bad - good) / 2;
            (lower_ok(mid) ? good : bad) = mid;
        }
        ranks.lower = good;
    }
    if (n > 0 && upper_ok(n)) {
        std::int64_t bad = 0;
        std::int64_t good = n;
        while (good - bad > 1) {
            const std::int64_t mid = bad + (good - bad) / 2;
            (upper_ok(mid) ? good : bad) = mid;
        }
        ranks.upper = good;
    }
    return ranks;
}

Interval quantile_confidence_interval(std::vector<double> sample, double p, double confidence) {
    const auto n = static_cast<std::int64_t>(sample.size());
    const QuantileRanks ranks = quantile_confidence_ranks(n, p, confidence);
    require(ranks.lower >= 1 && ranks.upper <= n,
            "a sample of " + std::to_string(n) + " is too small for a " +
                std::to_string(confidence) + " confidence interval of the " + std::to_string(p) +
                " quantile (even [min, max] covers less)");
    std::sort(sample.begin(), sample.end());
    return {sample[static_cast<std::size_t>(ranks.lower - 1)],
            sample[static_cast<std::size_t>(ranks.upper - 1)]};
}

Interval median_confidence_interval(std::vector<double> sample, double confidence) {
    return quantile_confidence_interval(std::move(sample), 0.5, confidence);
}

double mean(const std::vector<double>& sample) {
    require(!sample.empty(), "mean of an empty sample");
    return std::accumulate(sample.begin(), sample.end(), 0.0) / static_cast<double>(sample.size());
}

double standard_deviation(const std::vector<double>& sample) {
    require(sample.size() >= 2, "standard deviation needs at least 2 values");
    const double m = mean(sample);
    double sum = 0.0;
    for (const double value : sample) sum += (value - m) * (value - m);
    return std::sqrt(sum / static_cast<double>(sample.size() - 1));
}

double LineFit::correlation() const { return syy > 0.0 ? sxy / std::sqrt(sxx * syy) : 0.0; }

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
    require(x.size() == y.size(), "line fit: " + std::to_string(x.size()) + " x values but " +
                                      std::to_string(y.size()) + " y values");
    require(x.size() >= 2, "line fit needs at least 2 points");
    const double x_mean = mean(x);
    const double y_mean = mean(y);
    LineFit fit;
    for (std::size_t i = 0; i < x.size(); ++i) {
        fit.sxx += (x[i] - x_mean) * (x[i] - x_mean);
        fit.sxy += (x[i] - x_mean) * (y[i] - y_mean);
        fit.syy += (y[i] - y_mean) * (y[i] - y_mean);
    }
    require(fit.sxx > 0.0, "line fit needs at least 2 distinct x values");
    fit.slope = fit.sxy / fit.sxx;
    fit.intercept = y_mean - fit.slope * x_mean;
    return fit;
}

double student_t_quantile(double p, double dof) {
    detail::require(p > 0.0 && p < 1.0, "p = " + std::to_string(p) + ": must be in (0, 1)");
    detail::require_positive("dof", dof, "");
    if (p < 0.5) return -student_t_quantile(1.0 - p, dof);
    // P(T <= t) = 1 - I_{dof / (dof + t^2)}(dof / 2, 1 / 2) / 2 for t >= 0.
    const auto cdf = [dof](double t) {
        return 1.0 - 0.5 * regularized_incomplete_beta(dof / (dof + t * t), 0.5 * dof, 0.5);
    };
    double lo = 0.0;
    double hi = 1.0;
    while (cdf(hi) < p) hi *= 2.0;
    while (hi - lo > 1e-12 * hi) {
        const double mid = 0.5 * (lo + hi);
        (cdf(mid) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace rockfall::risk
