#include "risk/parameter_search.hpp"

#include "validation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace rockfall::risk {
namespace {

// Where the band [lower, upper] of the mean, over points sorted by parameter, contains the
// target: the first crossing of the upper bound to the last crossing of the lower bound.
Interval consistent_range(const std::vector<SearchPoint>& points, double target) {
    const auto cross = [&](std::size_t i, double (*bound)(const SearchPoint&)) {
        const SearchPoint& a = points[i];
        const SearchPoint& b = points[i + 1];
        const double fa = bound(a) - target;
        const double fb = bound(b) - target;
        const double t = fa == fb ? 0.0 : fa / (fa - fb);
        return a.parameter + t * (b.parameter - a.parameter);
    };
    const auto upper = [](const SearchPoint& p) { return p.value.mean_interval.upper; };
    const auto lower = [](const SearchPoint& p) { return p.value.mean_interval.lower; };
    Interval range{points.front().parameter, points.back().parameter};
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (upper(points[i]) >= target) {
            range.lower = i == 0 ? points[0].parameter : cross(i - 1, upper);
            break;
        }
    }
    for (std::size_t j = points.size(); j-- > 0;) {
        if (lower(points[j]) <= target) {
            range.upper = j + 1 == points.size() ? points[j].parameter : cross(j, lower);
            break;
        }
    }
    return range;
}

bool by_parameter(const SearchPoint& x, const SearchPoint& y) { return x.parameter < y.parameter; }

}  // namespace

std::vector<SearchPoint> all_points(const ParameterSearch& search) {
    std::vector<SearchPoint> all = search.curve;
    all.insert(all.end(), search.refinements.begin(), search.refinements.end());
    std::stable_sort(all.begin(), all.end(), by_parameter);
    return all;
}

std::string curve_text(const std::vector<SearchPoint>& curve) {
    std::ostringstream text;
    text.precision(4);
    for (std::size_t i = 0; i < curve.size(); ++i) {
        text << (i > 0 ? ", " : "") << curve[i].parameter << ": " << curve[i].value.mean;
    }
    return text.str();
}

ParameterSearch search_parameter(const std::vector<double>& curve, double target,
                                 const SearchOptions& options, const SearchEvaluator& evaluate,
                                 const UnreachableTarget& unreachable) {
    detail::require(curve.size() >= 2,
                    "curve points = " + std::to_string(curve.size()) + ": must be >= 2");
    detail::require(std::is_sorted(curve.begin(), curve.end()),
                    "curve parameters must be ascending");
    detail::require_positive("tolerance", options.tolerance, "");
    ParameterSearch search;
    const std::vector<SampleSummary> values = evaluate(curve);
    for (std::size_t i = 0; i < curve.size(); ++i) search.curve.push_back({curve[i], values[i]});

    // The first bracket where the mean crosses the target.
    std::size_t b = 1;
    while (b < search.curve.size() &&
           (search.curve[b - 1].value.mean - target) * (search.curve[b].value.mean - target) > 0.0)
        ++b;
    if (b == search.curve.size()) {
        double lo = search.curve.front().value.mean, hi = lo;
        for (const SearchPoint& p : search.curve) {
            lo = std::min(lo, p.value.mean);
            hi = std::max(hi, p.value.mean);
        }
        unreachable(lo, hi, search.curve);
        detail::require(false, "target out of the curve's range");
    }
    // Illinois regula falsi on the bracket [lo, hi]: the residual of an end that survives
    // twice in a row is halved, so the bracket closes from both sides.
    SearchPoint lo = search.curve[b - 1];
    SearchPoint hi = search.curve[b];
    double f_lo = lo.value.mean - target;
    double f_hi = hi.value.mean - target;
    SearchPoint best = std::abs(f_lo) < std::abs(f_hi) ? lo : hi;
    int kept = 0;  // -1: lo survived the last step, +1: hi did
    for (int it = 0; it < options.max_iterations && best.value.mean != target &&
                     hi.parameter - lo.parameter > options.tolerance;
         ++it) {
        const double x = hi.parameter - f_hi * (hi.parameter - lo.parameter) / (f_hi - f_lo);
        const SearchPoint p{x, evaluate({x}).front()};
        search.refinements.push_back(p);
        const double f = p.value.mean - target;
        if (std::abs(f) < std::abs(best.value.mean - target)) best = p;
        if (f == 0.0) break;
        if ((f < 0.0) == (f_lo < 0.0)) {
            lo = p;
            f_lo = f;
            if (kept == 1) f_hi *= 0.5;
            kept = 1;
        } else {
            hi = p;
            f_hi = f;
            if (kept == -1) f_lo *= 0.5;
            kept = -1;
        }
    }
    search.best = best;
    std::sort(search.refinements.begin(), search.refinements.end(), by_parameter);
    search.consistent = consistent_range(all_points(search), target);
    return search;
}

}  // namespace rockfall::risk
