#pragma once
/// Probability distributions of the uncertain inputs of a sweep, evaluated by their inverse
/// cumulative distribution function so that plain Monte Carlo and Latin hypercube sampling
/// share one code path: a draw is inverse_cdf(distribution, u) with u in (0, 1).

#include "risk/statistics.hpp"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace rockfall::risk {

/// One real-valued input's distribution, in the input's own unit.
struct Distribution {
    /// The family.
    enum class Family {
        fixed,       ///< always `value`
        uniform,     ///< uniform on [min, max]
        normal,      ///< normal (mean, sd), truncated to [min, max] when either is finite
        lognormal,   ///< ln X normal, X with the given mean and sd, truncated to [min, max]
        triangular,  ///< triangular on [min, max] with its peak at `mode`
    };
    Family family = Family::fixed;
    /// fixed: the value.
    double value = 0.0;
    /// normal, lognormal: mean and standard deviation of X itself before truncation (sd > 0;
    /// lognormal mean > 0). The lognormal's ln X is normal with sigma^2 = ln(1 + sd^2 / mean^2)
    /// and mu = ln(mean) - sigma^2 / 2.
    double mean = 0.0;
    double sd = 0.0;
    /// uniform, triangular: the support (min < max); normal, lognormal: optional truncation
    /// bounds (infinite when absent), with positive probability in between.
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    /// triangular: the mode, in [min, max].
    double mode = 0.0;
};

/// Lower-case name of a family ("fixed", "uniform", "normal", "lognormal", "triangular").
std::string to_string(Distribution::Family family);

/// A fixed distribution at `value`.
Distribution fixed(double value);

/// The distribution as people write it, for messages: "0.3", "uniform [0.2, 0.4]",
/// "normal (mean 2600, sd 100) on [2400, 2800]", "lognormal (mean 0.3, sd 0.1)",
/// "triangular [0.2, 0.25, 0.4]".
std::string describe(const Distribution& distribution);

/// What is impossible in the parameters, one rule per entry naming the parameter, its value
/// and the allowed range ("sd = -1: must be > 0 and finite"); empty when the distribution is
/// valid. Valid means: finite parameters (truncation bounds may be infinite), min < max,
/// sd > 0, lognormal mean > 0 and max > 0, mode in [min, max], and a truncation holding a
/// probability that does not underflow.
std::vector<std::string> find_problems(const Distribution& distribution);

/// Throws std::invalid_argument naming `name` (a key path such as "sweep.rock.size"), the
/// offending parameter, its value and the allowed range, when the parameters are impossible.
void validate(const Distribution& distribution, const std::string& name);

/// The smallest closed interval holding every draw, in the input's unit: [value, value] for
/// fixed, [min, max] for uniform, triangular and normal (infinite ends when not truncated),
/// [max(min, 0), max] for lognormal.
Interval support(const Distribution& distribution);

/// Cumulative distribution function P(X <= x) of the (truncated) distribution. Normal and
/// lognormal tails above the median are computed from the complementary function, so that
/// truncations far in the upper tail keep their relative precision.
double cdf(const Distribution& distribution, double x);

/// The value whose cumulative probability is u, for u in (0, 1) (0 and 1 give the support's
/// ends when finite). Truncated families invert the truncated CDF: F^-1(F(min) + u (F(max) -
/// F(min))), written with the complementary CDF when min lies above the median. Monotone in
/// u and inside the support. Deterministic and platform-independent given the same libm.
double inverse_cdf(const Distribution& distribution, double u);

/// inverse_cdf of the distribution conditioned on [lo, hi] (lo <= hi): the u-quantile of X
/// given lo <= X <= hi. When that event has no probability (a fixed value, or a support
/// outside [lo, hi]) the median clamped to [lo, hi]. Used to keep a lateral release position
/// where the rock fits: rocks that would not fit are redrawn, not piled at the edge.
double inverse_cdf_within(const Distribution& distribution, double lo, double hi, double u);

/// Analytic mean of the (truncated) distribution, in its unit; for tests and reports.
/// Truncated normal: mu + sigma (phi(a) - phi(b)) / Z; truncated lognormal: the partial
/// moments exp(k mu + k^2 sigma^2 / 2) (Phi(b - k sigma) - Phi(a - k sigma)) / Z (Johnson,
/// Kotz and Balakrishnan, Continuous Univariate Distributions, vol. 1, 2nd ed., 1994, ch. 13
/// and 14), with a, b the standardized bounds and Z = Phi(b) - Phi(a).
double distribution_mean(const Distribution& distribution);

/// Analytic variance of the (truncated) distribution, in its unit squared. The truncated
/// normal's sigma^2 (1 + (a phi(a) - b phi(b)) / Z - ((phi(a) - phi(b)) / Z)^2) loses about
/// log10(a^2) digits when both bounds lie a standard deviations out in one tail.
double distribution_variance(const Distribution& distribution);

/// Standard normal cumulative distribution function Phi(x) = erfc(-x / sqrt 2) / 2.
double normal_cdf(double x);

/// Index chosen from non-negative weights (at least one positive) for u in [0, 1): the first
/// i whose cumulative weight share exceeds u.
std::size_t choose(const std::vector<double>& weights, double u);

}  // namespace rockfall::risk
