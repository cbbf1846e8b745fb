// Ratio of impact loads to a design-formula envelope (see envelope.hpp).

#include "risk/envelope.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

namespace rockfall::risk {

EnvelopeStats envelope_stats(std::vector<double> ratios, double confidence) {
    if (ratios.empty()) throw std::invalid_argument("envelope: no ratios to compare");
    for (std::size_t i = 0; i < ratios.size(); ++i) {
        if (!(std::isfinite(ratios[i]) && ratios[i] >= 0.0)) {
            std::ostringstream message;
            message << "envelope: ratio[" << i << "] = " << ratios[i]
                    << ": must be finite and >= 0";
            throw std::invalid_argument(message.str());
        }
    }
    std::sort(ratios.begin(), ratios.end());
    EnvelopeStats s;
    s.count = ratios.size();
    s.above = static_cast<std::size_t>(ratios.end() -
                                       std::upper_bound(ratios.begin(), ratios.end(), 1.0));
    s.share = static_cast<double>(s.above) / static_cast<double>(s.count);
    s.confidence = confidence;
    s.interval = wilson_interval(static_cast<std::int64_t>(s.above),
                                 static_cast<std::int64_t>(s.count), confidence);
    s.min = ratios.front();
    s.max = ratios.back();
    s.mean = mean(ratios);
    s.median = quantile(ratios, 0.5);
    s.p95 = quantile(ratios, 0.95);
    s.p99 = quantile(ratios, 0.99);
    return s;
}

}  // namespace rockfall::risk
