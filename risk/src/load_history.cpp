// Comparison of wall-load histories (see load_history.hpp).

#include "risk/load_history.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rockfall::risk {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Linear interpolation of `h` at time t inside its range.
double load_at(const LoadHistory& h, double t) {
    const auto upper = std::upper_bound(h.time.begin(), h.time.end(), t);
    if (upper == h.time.begin()) return h.load.front();
    if (upper == h.time.end()) return h.load.back();
    const auto i = static_cast<std::size_t>(upper - h.time.begin());
    const double w = (t - h.time[i - 1]) / (h.time[i] - h.time[i - 1]);
    return (1.0 - w) * h.load[i - 1] + w * h.load[i];
}

double ratio(double simulated, double measured) {
    return measured > 0.0 ? simulated / measured : nan;
}

// Trapezoidal integrals of both loads over the measured times [first, last].
struct Integrals {
    double simulated = 0.0;
    double measured = 0.0;
    double duration = 0.0;
};
Integrals integrate(const std::vector<double>& t, const std::vector<double>& simulated,
                    const std::vector<double>& measured, std::size_t first, std::size_t last) {
    Integrals sum;
    for (std::size_t i = first; i < last; ++i) {
        const double dt = t[i + 1] - t[i];
        sum.simulated += 0.5 * dt * (simulated[i] + simulated[i + 1]);
        sum.measured += 0.5 * dt * (measured[i] + measured[i + 1]);
        sum.duration += dt;
    }
    return sum;
}

}  // namespace

int check_comparable(bool simulated_per_metre, double from, double to,
                     const LoadHistory& measured) {
    if (simulated_per_metre != measured.per_metre) {
        throw std::invalid_argument(
            measured.source + ": " +
            (simulated_per_metre
                 ? "a 2D (plane-strain) run gives loads per metre of width: the measured file "
                   "needs a load_kN_per_m or load_N_per_m column"
                 : "a 3D run gives the total load on the wall: the measured file needs a "
                   "load_kN or load_N column"));
    }
    const auto shared = std::count_if(measured.time.begin(), measured.time.end(),
                                      [&](double t) { return t >= from && t <= to; });
    if (shared < 2) {
        std::ostringstream message;
        message << measured.source << ": the measured history (t = " << measured.time.front()
                << " to " << measured.time.back() << " s) shares fewer than two times with the "
                << "simulated one (t = " << from << " to " << to << " s)";
        throw std::invalid_argument(message.str());
    }
    return static_cast<int>(shared);
}

HistoryComparison compare_histories(const LoadHistory& simulated, const LoadHistory& measured) {
    HistoryComparison c;
    c.points = check_comparable(simulated.per_metre, simulated.time.front(), simulated.time.back(),
                                measured);
    c.from = std::max(simulated.time.front(), measured.time.front());
    c.to = std::min(simulated.time.back(), measured.time.back());
    // Both histories, linear between their points, on the union of their times in the overlap:
    // a sparse record (a digitised figure) counts as well as a dense one.
    std::vector<double> t{c.from, c.to};
    for (const LoadHistory* h : {&simulated, &measured}) {
        for (const double time : h->time) {
            if (time > c.from && time < c.to) t.push_back(time);
        }
    }
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    std::vector<double> sim;
    std::vector<double> meas;
    for (const double time : t) {
        sim.push_back(load_at(simulated, time));
        meas.push_back(load_at(measured, time));
    }
    const auto peak =
        static_cast<std::size_t>(std::max_element(meas.begin(), meas.end()) - meas.begin());
    c.measured_peak = meas[peak];
    c.measured_peak_time = t[peak];
    const auto sim_peak =
        static_cast<std::size_t>(std::max_element(sim.begin(), sim.end()) - sim.begin());
    c.simulated_peak = sim[sim_peak];
    c.simulated_peak_time = t[sim_peak];
    c.peak_ratio = ratio(c.simulated_peak, c.measured_peak);

    const Integrals whole = integrate(t, sim, meas, 0, t.size() - 1);
    c.simulated_impulse = whole.simulated;
    c.measured_impulse = whole.measured;
    c.impulse_ratio = ratio(whole.simulated, whole.measured);
    const Integrals loading = integrate(t, sim, meas, 0, peak);
    const Integrals after = integrate(t, sim, meas, peak, t.size() - 1);
    c.loading_ratio = loading.duration > 0.0 ? ratio(loading.simulated, loading.measured) : nan;
    c.after_peak_ratio = after.duration > 0.0 ? ratio(after.simulated, after.measured) : nan;

    double squares = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        squares += (sim[i] - meas[i]) * (sim[i] - meas[i]);
    }
    c.rms_difference = std::sqrt(squares / static_cast<double>(t.size()));
    return c;
}

}  // namespace rockfall::risk
