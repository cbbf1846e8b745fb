#pragma once
/// Window means of a wall-load history recorded step by step. The solver reports one load per
/// step, constant over that step, so the load is piecewise constant in time and its integral
/// is piecewise linear: the mean over any window follows exactly from the cumulative impulse,
/// whatever the window's width or position. The peak over every window position is what a
/// logger averaging over that width sees at its worst phase; taking it only on a fixed sample
/// grid makes a short impact's peak depend on where the grid's boundaries fall (up to 17 % for
/// the 2D seed flow at 0.025 m cells, docs/soil_first_arrival.md).

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rockfall::mpm {

/// The cumulative integral of a piecewise-constant history: step k holds value[k] from
/// step_end_time[k - 1] (0 for the first step) to step_end_time[k]. T is double or a vector
/// type with + , - and scaling by double (Vec3).
template <class T>
class StepHistory {
  public:
    /// Throws std::invalid_argument if the sizes differ or the end times do not increase from
    /// a positive first one.
    StepHistory(const std::vector<double>& step_end_time, const std::vector<T>& value, T zero)
        : time_{0.0}, integral_{zero} {
        if (step_end_time.size() != value.size()) {
            throw std::invalid_argument("StepHistory: one value per step end time");
        }
        time_.reserve(step_end_time.size() + 1);
        integral_.reserve(step_end_time.size() + 1);
        for (std::size_t k = 0; k < value.size(); ++k) {
            const double dt = step_end_time[k] - time_.back();
            if (!(dt > 0.0)) {
                throw std::invalid_argument("StepHistory: step end times must increase from 0");
            }
            integral_.push_back(integral_.back() + value[k] * dt);
            time_.push_back(step_end_time[k]);
        }
    }

    /// End of the last step, s (0 without steps).
    double end() const { return time_.back(); }

    /// Integral of the history from 0 to t (t clamped to [0, end()]).
    T integral(double t) const {
        t = std::clamp(t, 0.0, end());
        const auto upper = std::upper_bound(time_.begin(), time_.end(), t);
        if (upper == time_.end()) {
            return integral_.back();
        }
        const auto k = static_cast<std::size_t>(upper - time_.begin());
        const double t0 = time_[k - 1];
        const double fraction = (t - t0) / (time_[k] - t0);
        return integral_[k - 1] + (integral_[k] - integral_[k - 1]) * fraction;
    }

    /// Mean over [centre - width / 2, centre + width / 2] clipped to [0, end()] (shorter at the
    /// ends, where it averages what exists); zero if the clipped window is empty or width is not
    /// positive.
    T window_mean(double centre, double width) const {
        const double a = std::max(0.0, centre - 0.5 * width);
        const double b = std::min(end(), centre + 0.5 * width);
        if (!(b > a)) {
            return integral_.front();  // the zero
        }
        return (integral(b) - integral(a)) * (1.0 / (b - a));
    }

    /// Step boundaries, s: 0 and every step's end time.
    const std::vector<double>& boundaries() const { return time_; }

  private:
    std::vector<double> time_;
    std::vector<T> integral_;
};

/// The largest mean of a history over a window of `width` s, and the centre of that window.
struct WindowPeak {
    double value = 0.0;
    double centre = 0.0;
};

/// The largest mean of `history` over any window of `width` s (> 0) lying within the run. The
/// mean over [s, s + width] is piecewise linear in s with breaks where an edge crosses a step
/// boundary, so its maximum has an edge on a boundary: those positions are all tried. A run
/// shorter than the window gives its overall mean (centre at half the run); no steps give 0.
/// Windows whose mean is not finite (a run that blew up) are skipped.
inline WindowPeak peak_window_mean(const StepHistory<double>& history, double width) {
    if (!(width > 0.0)) {
        throw std::invalid_argument("peak_window_mean: the window must be > 0 s");
    }
    const double end = history.end();
    WindowPeak peak;
    if (end <= width) {
        peak.centre = 0.5 * end;
        peak.value = end > 0.0 ? history.integral(end) / end : 0.0;
        return peak;
    }
    bool first = true;
    auto consider = [&](double start) {
        start = std::clamp(start, 0.0, end - width);
        const double mean = (history.integral(start + width) - history.integral(start)) / width;
        if (std::isfinite(mean) && (first || mean > peak.value)) {
            peak.value = mean;
            peak.centre = start + 0.5 * width;
            first = false;
        }
    };
    for (const double b : history.boundaries()) {
        consider(b);
        consider(b - width);
    }
    return peak;
}

}  // namespace rockfall::mpm
