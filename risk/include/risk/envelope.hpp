#pragma once
/// Comparison of impact loads with a design-formula envelope: the ratio load / formula per
/// impact (formula evaluated for that rock's mass, shape and impact velocity), its
/// distribution, and the share of impacts above the envelope (ratio > 1) with its interval.

#include "risk/formulas.hpp"
#include "risk/impact_fit.hpp"
#include "risk/statistics.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rockfall::risk {

/// The distribution of the ratios and the share above the envelope.
struct EnvelopeStats {
    /// Impacts compared, and those with a ratio > 1 (above the envelope).
    std::size_t count = 0;
    std::size_t above = 0;
    /// above / count, and its Wilson score interval at `confidence`.
    double share = 0.0;
    Interval interval;
    double confidence = 0.95;
    /// Ratio statistics (dimensionless): extremes, mean and type 7 percentiles.
    double min = 0.0;
    double mean = 0.0;
    double median = 0.0;
    double p95 = 0.0;
    double p99 = 0.0;
    double max = 0.0;
};

/// Statistics of ratios (at least one, each finite and >= 0) at `confidence` in (0, 1).
/// Throws std::invalid_argument naming the first bad ratio.
EnvelopeStats envelope_stats(std::vector<double> ratios, double confidence = 0.95);

/// The formula every impact is compared with.
struct EnvelopeFormula {
    /// "seed": seed 000's preset for each rock's shape (formulas.hpp); "jra": the handbook
    /// formula, alpha = beta = 1, which needs `lambda`.
    std::string name = "seed";
    /// Given values replace the preset's for every shape: Lame constant of the wall (Pa),
    /// load scatter factor and shape factor.
    std::optional<double> lambda;
    std::optional<double> alpha;
    std::optional<double> beta;
};

/// The coefficients for a rock of `shape`; throws std::invalid_argument for jra without lambda
/// or a name other than seed and jra.
ImpactCoefficients envelope_coefficients(const EnvelopeFormula& formula, ImpactShape shape);

/// One impact compared: its index in the rows, the formula's load (N) for its mass, shape and
/// velocity, and the ratio peak load / formula.
struct ComparedImpact {
    std::size_t row = 0;
    double formula = 0.0;
    double ratio = 0.0;
};

/// Every row compared with the formula, in the rows' order.
std::vector<ComparedImpact> compare_with_formula(const std::vector<ImpactRow>& rows,
                                                 const EnvelopeFormula& formula);

/// The ratios of the rows of `shape` (all rows without one), in order.
std::vector<double> ratios_of(const std::vector<ComparedImpact>& compared,
                              const std::vector<ImpactRow>& rows, std::optional<ImpactShape> shape);

/// Indices into `compared` of the `count` largest ratios, largest first (ties: earlier first).
std::vector<std::size_t> worst_impacts(const std::vector<ComparedImpact>& compared,
                                       std::size_t count);

}  // namespace rockfall::risk
