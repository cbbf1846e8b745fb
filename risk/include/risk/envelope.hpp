#pragma once
/// Comparison of impact loads with a design-formula envelope: the ratio load / formula per
/// impact (formula evaluated for that rock's mass, shape and impact velocity), its
/// distribution, and the share of impacts above the envelope (ratio > 1) with its interval.

#include "risk/statistics.hpp"

#include <cstddef>
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

}  // namespace rockfall::risk
