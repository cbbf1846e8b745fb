#pragma once
/// Summary statistics and confidence intervals for Monte Carlo sweeps: proportions (share of
/// rocks reaching the wall), quantiles and the median of a sample (reach, peak force).

#include <cstdint>
#include <vector>

namespace rockfall::risk {

/// A closed interval [lower, upper].
struct Interval {
    /// Lower bound, in the unit of the estimate.
    double lower = 0.0;
    /// Upper bound (>= lower).
    double upper = 0.0;
};

/// Standard normal quantile z with P(Z <= z) = p, for p in (0, 1): Acklam's rational
/// approximation (relative error 1.15e-9) refined by one Halley step on erfc, which brings it
/// to about 1e-15. Throws std::invalid_argument outside (0, 1).
double normal_quantile(double p);

/// Two-sided Student t quantile: t with P(T <= t) = p for T of `dof` degrees of freedom
/// (> 0), p in (0, 1), by bisection on the t distribution's CDF through the regularized
/// incomplete beta function to 1e-12 relative.
double student_t_quantile(double p, double dof);

/// Regularized incomplete beta function I_x(a, b) for x in [0, 1], a > 0, b > 0, from its
/// continued fraction (DLMF 8.17.22) evaluated by the modified Lentz method. Relative error
/// about 1e-15 (a + b): the log-gamma prefactor loses digits as a + b grows (measured 1e-13 at
/// a + b = 400, 3e-11 at 40000). Throws std::invalid_argument outside that domain.
double regularized_incomplete_beta(double x, double a, double b);

/// P(X <= k) for X ~ Binomial(n, p), p in [0, 1]; 1 for k >= n, 0 for k < 0.
double binomial_cdf(std::int64_t k, std::int64_t n, double p);

/// Wilson score interval for a proportion (Wilson 1927; Brown, Cai and DasGupta 2001):
/// successes in [0, trials], trials > 0, confidence in (0, 1). Good coverage near 0 and 1,
/// where the normal (Wald) interval fails. Throws std::invalid_argument on bad input.
Interval wilson_interval(std::int64_t successes, std::int64_t trials, double confidence = 0.95);

/// Clopper-Pearson ("exact") interval for a proportion (Clopper and Pearson 1934): the
/// binomial tails at each bound equal (1 - confidence) / 2, found by bisection on the
/// regularized incomplete beta function to 1e-12. Conservative: coverage >= confidence.
/// Same arguments as wilson_interval.
Interval clopper_pearson_interval(std::int64_t successes, std::int64_t trials,
                                  double confidence = 0.95);

/// Quantile p in [0, 1] of a sample sorted in ascending order (not empty), by linear
/// interpolation between order statistics: Hyndman and Fan (1996) type 7, the default of R and
/// NumPy: h = (n - 1) p, Q = x[floor h] + (h - floor h) (x[floor h + 1] - x[floor h]).
double quantile(const std::vector<double>& sorted, double p);

/// Median of a sample in any order (type 7 quantile at 0.5); the sample must not be empty.
double median(std::vector<double> sample);

/// 1-based ranks of the order statistics x(lower) <= x(upper) that bound quantile p.
struct QuantileRanks {
    /// Rank of the lower bound, in [1, n]; 0 when no order statistic bounds the quantile from
    /// below at the confidence (the sample is too small for that tail).
    std::int64_t lower = 0;
    /// Rank of the upper bound, in [1, n]; n + 1 when none bounds it from above.
    std::int64_t upper = 0;
};

/// Ranks of the distribution-free confidence interval [x(r), x(s)] for the quantile p in
/// (0, 1) of a sample of n values (Conover, Practical Nonparametric Statistics, 3rd ed., 1999,
/// sec. 3.2): with B ~ Binomial(n, p) the number of values below the quantile, r is the
/// largest rank with P(B <= r - 1) <= (1 - confidence) / 2 and s the smallest with
/// P(B >= s) <= (1 - confidence) / 2; coverage >= confidence for any continuous distribution.
/// n >= 0; throws std::invalid_argument for p or confidence outside (0, 1).
QuantileRanks quantile_confidence_ranks(std::int64_t n, double p, double confidence = 0.95);

/// The interval of quantile_confidence_ranks as values of a sample in any order. Throws
/// std::invalid_argument when the sample is too small for either bound (at 95 %: n < 6 for
/// the median, n < 72 for the 95th percentile).
Interval quantile_confidence_interval(std::vector<double> sample, double p,
                                      double confidence = 0.95);

/// Distribution-free confidence interval for the median: quantile_confidence_interval at
/// p = 1/2, where the bounds are symmetric, [x(r), x(n+1-r)]. Throws std::invalid_argument
/// when the sample is too small for the confidence (n < 6 at 95 %).
Interval median_confidence_interval(std::vector<double> sample, double confidence = 0.95);

/// Arithmetic mean of a sample (not empty).
double mean(const std::vector<double>& sample);

/// Sample standard deviation with Bessel's correction (n - 1); the sample needs 2 values.
double standard_deviation(const std::vector<double>& sample);

/// An ordinary least-squares line y = intercept + slope x, with the sums it came from.
struct LineFit {
    /// Intercept, in the unit of y, and slope, in the unit of y per unit of x.
    double intercept = 0.0;
    double slope = 0.0;
    /// Centred sums of squares and products: Sxx = sum (x - mean x)^2 (> 0), Sxy, Syy.
    double sxx = 0.0;
    double sxy = 0.0;
    double syy = 0.0;
    /// Pearson's correlation coefficient Sxy / sqrt(Sxx Syy), in [-1, 1]; 0 when Syy = 0.
    double correlation() const;
};

/// Least squares of y on x with centred sums (two passes, no cancellation in Sxx). x and y of
/// equal size with at least 2 distinct x; throws std::invalid_argument otherwise.
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace rockfall::risk
