// Ratio of impact loads to a design-formula envelope (see envelope.hpp).

#include "risk/envelope.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
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

ImpactCoefficients envelope_coefficients(const EnvelopeFormula& formula, ImpactShape shape) {
    ImpactCoefficients c;
    if (formula.name == "jra") {
        if (!formula.lambda) {
            throw std::invalid_argument("envelope: the jra formula needs lambda (Pa)");
        }
        c = jra_coefficients(*formula.lambda);
    } else if (formula.name == "seed") {
        c = seed_coefficients(shape);
    } else {
        throw std::invalid_argument("envelope: formula \"" + formula.name +
                                    "\": must be seed or jra");
    }
    if (formula.lambda) c.lambda = *formula.lambda;
    if (formula.alpha) c.alpha = *formula.alpha;
    if (formula.beta) c.beta = *formula.beta;
    return c;
}

std::vector<ComparedImpact> compare_with_formula(const std::vector<ImpactRow>& rows,
                                                 const EnvelopeFormula& formula) {
    std::vector<ComparedImpact> out;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const ImpactRow& row = rows[i];
        const double load =
            jra_impact_force(row.mass, row.velocity, envelope_coefficients(formula, row.shape));
        out.push_back({i, load, row.peak_force / load});
    }
    return out;
}

std::vector<double> ratios_of(const std::vector<ComparedImpact>& compared,
                              const std::vector<ImpactRow>& rows,
                              std::optional<ImpactShape> shape) {
    std::vector<double> ratios;
    for (const ComparedImpact& c : compared) {
        if (!shape || rows[c.row].shape == *shape) ratios.push_back(c.ratio);
    }
    return ratios;
}

std::vector<std::size_t> worst_impacts(const std::vector<ComparedImpact>& compared,
                                       std::size_t count) {
    std::vector<std::size_t> order(compared.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const std::size_t n = std::min(order.size(), count);
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(),
                      [&](std::size_t a, std::size_t b) {
                          return compared[a].ratio > compared[b].ratio ||
                                 (compared[a].ratio == compared[b].ratio && a < b);
                      });
    order.resize(n);
    return order;
}

}  // namespace rockfall::risk
