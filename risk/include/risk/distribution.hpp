#pragma once
/// Probability distributions of the uncertain inputs of a sweep, evaluated by their inverse
/// cumulative distribution function so that plain Monte Carlo and Latin hypercube sampling
/// share one code path: a draw is inverse_cdf(distribution, u) with u in (0, 1).

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
    /// normal, lognormal: mean and standard deviation of X itself (sd > 0; lognormal mean > 0).
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

/// Throws std::invalid_argument naming `name` (a key path such as "sweep.rock.size"), the
/// offending parameter, its value and the allowed range, when the parameters are impossible.
void validate(const Distribution& distribution, const std::string& name);

/// The value whose cumulative probability is u, for u in (0, 1) (0 and 1 give the support's
/// ends when finite). Truncated families invert the truncated CDF: F^-1(F(min) + u (F(max) -
/// F(min))). Deterministic and platform-independent given the same libm.
double inverse_cdf(const Distribution& distribution, double u);

/// Analytic mean of the (truncated) distribution, in its unit; for tests and reports.
double distribution_mean(const Distribution& distribution);

/// Analytic variance of the (truncated) distribution, in its unit squared.
double distribution_variance(const Distribution& distribution);

/// Standard normal cumulative distribution function Phi(x) = erfc(-x / sqrt 2) / 2.
double normal_cdf(double x);

/// Index chosen from non-negative weights (at least one positive) for u in [0, 1): the first
/// i whose cumulative weight share exceeds u.
std::size_t choose(const std::vector<double>& weights, double u);

}  // namespace rockfall::risk
