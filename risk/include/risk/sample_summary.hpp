#pragma once
/// The distribution of a sample of one output (a coefficient of restitution, an angle of
/// repose) over repeated virtual experiments: mean, spread, percentiles and a Student t
/// interval of the mean.

#include "risk/statistics.hpp"

#include <cstdint>
#include <vector>

namespace rockfall::risk {

/// A sample's distribution: mean, spread, percentiles and a confidence interval of the mean.
struct SampleSummary {
    /// Sample size.
    std::int64_t count = 0;
    /// Mean and sample standard deviation (0 for one value), in the sample's unit.
    double mean = 0.0;
    double standard_deviation = 0.0;
    /// 5th, 50th and 95th percentiles (type 7, risk::quantile).
    double p5 = 0.0;
    double p50 = 0.0;
    double p95 = 0.0;
    /// Student t interval of the mean, mean -/+ t(1 - (1 - c) / 2, n - 1) s / sqrt(n); the
    /// mean itself for one value.
    Interval mean_interval;
};

/// The distribution of a sample (not empty) with a `confidence` in (0, 1) interval of its mean.
SampleSummary sample_summary(const std::vector<double>& sample, double confidence = 0.95);

}  // namespace rockfall::risk
