#include "risk/sample_summary.hpp"

#include "validation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace rockfall::risk {

SampleSummary sample_summary(const std::vector<double>& sample, double confidence) {
    detail::require(!sample.empty(), "distribution of an empty sample");
    detail::require(confidence > 0.0 && confidence < 1.0,
                    "confidence = " + std::to_string(confidence) + ": must be in (0, 1)");
    SampleSummary d;
    d.count = static_cast<std::int64_t>(sample.size());
    d.mean = mean(sample);
    std::vector<double> sorted = sample;
    std::sort(sorted.begin(), sorted.end());
    d.p5 = quantile(sorted, 0.05);
    d.p50 = quantile(sorted, 0.50);
    d.p95 = quantile(sorted, 0.95);
    d.mean_interval = {d.mean, d.mean};
    if (d.count >= 2) {
        d.standard_deviation = standard_deviation(sample);
        const double half =
            student_t_quantile(1.0 - 0.5 * (1.0 - confidence), static_cast<double>(d.count - 1)) *
            d.standard_deviation / std::sqrt(static_cast<double>(d.count));
        d.mean_interval = {d.mean - half, d.mean + half};
    }
    return d;
}

}  // namespace rockfall::risk
