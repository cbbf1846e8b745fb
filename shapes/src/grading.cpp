#include "shapes/grading.hpp"

#include "lining_frame.hpp"

#include "shapes/random.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rockfall::shapes {
namespace {

// Bisection stops when the bracket in ln d (or in mu, sigma) is narrower than this.
constexpr double kTolerance = 1e-14;

// Widest sigma of ln d tried in the fit, as a multiple of ln(d_max / d_min): there the
// truncated log-normal is within a few per mille of its wide limit (a tilted log-uniform).
constexpr double kWideSigma = 50.0;

// Fraction of the mass a normal (mean, sigma) of ln d truncated to [a, b] puts below x. The
// tail form that does not cancel is used: upper tails Q(z) = erfc(z / sqrt 2) / 2 when the
// interval lies above the mean. Where both tails underflow the distribution sits on one end.
double truncated_cdf(double x, double mean, double sigma, double a, double b) {
    const double za = (a - mean) / sigma;
    const double zb = (b - mean) / sigma;
    const double zx = (std::clamp(x, a, b) - mean) / sigma;
    double below = 0.0;
    double total = 0.0;
    if (za > 0.0) {
        const auto q = [](double z) { return 0.5 * std::erfc(z / std::numbers::sqrt2); };
        below = q(za) - q(zx);
        total = q(za) - q(zb);
    } else {
        const auto phi = [](double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); };
        below = phi(zx) - phi(za);
        total = phi(zb) - phi(za);
    }
    if (!(total > 0.0)) {
        return mean < a ? 1.0 : 0.0;
    }
    return std::clamp(below / total, 0.0, 1.0);
}

// The ln d at which truncated_cdf reaches p, by bisection on [a, b].
double truncated_quantile(double p, double mean, double sigma, double a, double b) {
    double lo = a;
    double hi = b;
    while (hi - lo > kTolerance * std::max(1.0, std::abs(lo))) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) {
            break;
        }
        (truncated_cdf(mid, mean, sigma, a, b) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// The mean mu of ln d, for a given sigma, that puts the truncated median at ln d50: the
// truncated cdf at ln d50 falls from 1 to 0 as mu runs from far below a to far above b.
double fitted_mean(double x50, double sigma, double a, double b) {
    const double reach = 2.0 * (b - a) + 10.0 * sigma;
    double lo = a - reach;
    double hi = b + reach;
    while (hi - lo > kTolerance * std::max(1.0, std::abs(lo))) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) {
            break;
        }
        (truncated_cdf(x50, mid, sigma, a, b) > 0.5 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// d60 / d10 of the truncated mass distribution fitted to d50 at this sigma.
double fitted_cu(double x50, double sigma, double a, double b) {
    const double mean = fitted_mean(x50, sigma, a, b);
    return std::exp(truncated_quantile(0.6, mean, sigma, a, b) -
                    truncated_quantile(0.1, mean, sigma, a, b));
}

std::string number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

void check_amount(const Grading& grading) {
    const bool by_count = grading.count != 0;
    const bool by_volume = grading.total_volume != 0.0;
    if (by_count == by_volume) {
        throw std::invalid_argument("grading.count = " + std::to_string(grading.count) +
                                    " and grading.total_volume = " + number(grading.total_volume) +
                                    " m3: give exactly one of them (the other 0)");
    }
    if (by_count && (grading.count < 1 || grading.count > max_cluster_rocks)) {
        throw std::invalid_argument("grading.count = " + std::to_string(grading.count) +
                                    ": must be in [1, " + std::to_string(max_cluster_rocks) + "]");
    }
    if (by_volume && !(grading.total_volume > 0.0 && std::isfinite(grading.total_volume))) {
        throw std::invalid_argument("grading.total_volume = " + number(grading.total_volume) +
                                    " m3: must be finite and > 0");
    }
}

double rock_volume(double d) { return std::numbers::pi / 6.0 * d * d * d; }

// The mean volume of one rock drawn from the model, m3: the mean over 2000 equal-probability
// slices of the number distribution, each at its middle quantile.
double mean_rock_volume(const GradingModel& model) {
    constexpr int kSlices = 2000;
    const double a = std::log(model.d_min);
    const double b = std::log(model.d_max);
    const double mean = model.mu - 3.0 * model.sigma * model.sigma;
    double sum = 0.0;
    for (int i = 0; i < kSlices; ++i) {
        const double p = (i + 0.5) / kSlices;
        sum += rock_volume(std::exp(truncated_quantile(p, mean, model.sigma, a, b)));
    }
    return sum / kSlices;
}

}  // namespace

Grading seed001_c1() {
    Grading grading;
    grading.count = 53;
    grading.d50 = 0.051;
    grading.cu = 1.52;
    grading.d_min = 0.030;
    grading.d_max = 0.095;
    return grading;
}

Grading seed001_c2() { return Grading{}; }

GradingModel grading_model(const Grading& grading) {
    check_amount(grading);
    detail::check_range("grading.d_min", grading.d_min, "m", 1e-3, 100.0);
    detail::check_range("grading.d_max", grading.d_max, "m", grading.d_min, 100.0);
    if (grading.d_max <= grading.d_min) {
        throw std::invalid_argument("grading.d_max = " + number(grading.d_max) +
                                    " m: must be larger than d_min = " + number(grading.d_min) +
                                    " m");
    }
    if (!(grading.d50 > grading.d_min && grading.d50 < grading.d_max)) {
        throw std::invalid_argument("grading.d50 = " + number(grading.d50) +
                                    " m: must be in (d_min, d_max) = (" + number(grading.d_min) +
                                    ", " + number(grading.d_max) + ") m");
    }
    const double a = std::log(grading.d_min);
    const double b = std::log(grading.d_max);
    const double x50 = std::log(grading.d50);
    const double widest = fitted_cu(x50, kWideSigma * (b - a), a, b);
    if (!(grading.cu > 1.0 && grading.cu < widest)) {
        throw std::invalid_argument(
            "grading.cu = " + number(grading.cu) + ": must be in (1, " + number(widest) +
            "), the widest d60/d10 of a log-normal truncated to [d_min, d_max] = [" +
            number(grading.d_min) + ", " + number(grading.d_max) +
            "] m about d50 = " + number(grading.d50) + " m");
    }
    // Cu grows with sigma (the truncated curve spreads out): bisection in ln sigma.
    double lo = std::log(1e-6 * (b - a));
    double hi = std::log(kWideSigma * (b - a));
    for (int i = 0; i < 200 && hi - lo > kTolerance; ++i) {
        const double mid = 0.5 * (lo + hi);
        (fitted_cu(x50, std::exp(mid), a, b) < grading.cu ? lo : hi) = mid;
    }
    GradingModel model;
    model.sigma = std::exp(0.5 * (lo + hi));
    model.mu = fitted_mean(x50, model.sigma, a, b);
    model.d_min = grading.d_min;
    model.d_max = grading.d_max;
    if (grading.total_volume > 0.0) {
        const double expected = grading.total_volume / mean_rock_volume(model);
        if (expected > max_cluster_rocks) {
            throw std::invalid_argument("grading.total_volume = " + number(grading.total_volume) +
                                        " m3: about " + number(std::round(expected)) +
                                        " rocks of this grading, more than " +
                                        std::to_string(max_cluster_rocks));
        }
    }
    return model;
}

double mass_passing(const GradingModel& model, double d) {
    if (d <= model.d_min) {
        return 0.0;
    }
    if (d >= model.d_max) {
        return 1.0;
    }
    return truncated_cdf(std::log(d), model.mu, model.sigma, std::log(model.d_min),
                         std::log(model.d_max));
}

std::vector<double> cluster_sizes(const Grading& grading, std::mt19937_64& generator) {
    const GradingModel model = grading_model(grading);
    const double a = std::log(model.d_min);
    const double b = std::log(model.d_max);
    const double mean = model.mu - 3.0 * model.sigma * model.sigma;
    const auto draw = [&] {
        const double x = truncated_quantile(uniform01(generator), mean, model.sigma, a, b);
        return std::clamp(std::exp(x), model.d_min, model.d_max);
    };
    std::vector<double> sizes;
    if (grading.count > 0) {
        sizes.reserve(static_cast<std::size_t>(grading.count));
        for (int i = 0; i < grading.count; ++i) {
            sizes.push_back(draw());
        }
        return sizes;
    }
    double sum = 0.0;
    while (sum < grading.total_volume && static_cast<int>(sizes.size()) < max_cluster_rocks) {
        const double d = draw();
        const double before = sum;
        sum += rock_volume(d);
        if (sum >= grading.total_volume && !sizes.empty() &&
            sum - grading.total_volume >= grading.total_volume - before) {
            break;
        }
        sizes.push_back(d);
    }
    return sizes;
}

GradingStats grading_of(const std::vector<double>& sizes) {
    if (sizes.empty()) {
        throw std::invalid_argument("grading_of: no rock sizes");
    }
    std::vector<double> sorted = sizes;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        if (!(std::isfinite(sorted[i]) && sorted[i] > 0.0)) {
            throw std::invalid_argument("grading_of: size[" + std::to_string(i) +
                                        "] = " + number(sorted[i]) + " m: must be finite and > 0");
        }
    }
    std::sort(sorted.begin(), sorted.end());
    GradingStats stats;
    stats.count = static_cast<int>(sorted.size());
    std::vector<double> plotted(sorted.size());
    double total = 0.0;
    for (const double d : sorted) {
        total += d * d * d;
    }
    double cumulative = 0.0;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        const double mass = sorted[i] * sorted[i] * sorted[i] / total;
        plotted[i] = cumulative + 0.5 * mass;
        cumulative += mass;
    }
    stats.total_volume = std::numbers::pi / 6.0 * total;
    const auto size_passing = [&](double p) {
        if (p <= plotted.front()) {
            return sorted.front();
        }
        if (p >= plotted.back()) {
            return sorted.back();
        }
        const auto upper = static_cast<std::size_t>(
            std::upper_bound(plotted.begin(), plotted.end(), p) - plotted.begin());
        const std::size_t lower = upper - 1;
        const double t = (p - plotted[lower]) / (plotted[upper] - plotted[lower]);
        return std::exp(std::log(sorted[lower]) +
                        t * (std::log(sorted[upper]) - std::log(sorted[lower])));
    };
    stats.d10 = size_passing(0.10);
    stats.d30 = size_passing(0.30);
    stats.d50 = size_passing(0.50);
    stats.d60 = size_passing(0.60);
    stats.cu = stats.d60 / stats.d10;
    stats.cc = stats.d30 * stats.d30 / (stats.d10 * stats.d60);
    return stats;
}

}  // namespace rockfall::shapes
