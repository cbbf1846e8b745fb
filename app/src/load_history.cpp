// Measured wall-load histories, their comparison with a simulated one, and the figure (see
// load_history.hpp).

#include "app/load_history.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace rockfall::app {
namespace {

constexpr double n_per_kn = 1.0e3;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

struct LoadColumn {
    const char* name;
    double scale;  // to N or N/m
    bool per_metre;
};
constexpr std::array<LoadColumn, 4> load_columns{{{"load_kN", n_per_kn, false},
                                                  {"load_N", 1.0, false},
                                                  {"load_kN_per_m", n_per_kn, true},
                                                  {"load_N_per_m", 1.0, true}}};

std::string column_names() {
    std::string names;
    for (const LoadColumn& c : load_columns) {
        names += (names.empty() ? "" : ", ") + std::string(c.name);
    }
    return names;
}

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

const char* load_unit(bool per_metre) { return per_metre ? "kN/m" : "kN"; }

}  // namespace

LoadHistory measured_history(const CsvTable& table) {
    const std::size_t time = table.require("time_s");
    std::optional<LoadColumn> chosen;
    std::size_t load = 0;
    for (const LoadColumn& c : load_columns) {
        if (const std::optional<std::size_t> index = table.find(c.name)) {
            if (chosen) {
                throw CsvError(table.source() + ": the header names both " + chosen->name +
                               " and " + c.name + "; give exactly one load column of " +
                               column_names());
            }
            chosen = c;
            load = *index;
        }
    }
    if (!chosen) {
        throw CsvError(table.source() + ": the header names no load column; give exactly one of " +
                       column_names());
    }
    if (table.rows() < 2) {
        throw CsvError(table.source() + ": a history needs at least two data rows (it has " +
                       std::to_string(table.rows()) + ")");
    }
    LoadHistory h;
    h.source = table.source();
    h.per_metre = chosen->per_metre;
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const double t = table.number(r, time);
        if (t < 0.0 || (!h.time.empty() && t <= h.time.back())) {
            std::ostringstream message;
            message << table.where(r, time) << " = " << t << " s: times must be >= 0 and increase "
                    << "from row to row (since the release)";
            if (!h.time.empty()) message << "; the row before has " << h.time.back() << " s";
            throw CsvError(message.str());
        }
        h.time.push_back(t);
        h.load.push_back(table.number(r, load) * chosen->scale);
    }
    return h;
}

LoadHistory read_measured_history(const std::filesystem::path& path) {
    return measured_history(CsvTable::read(path));
}

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

Plot load_history_plot(const std::string& title, const LoadHistory& sampled,
                       const std::string& sampled_label, const LoadHistory& filtered,
                       const std::string& filtered_label, const LoadHistory* measured) {
    auto series = [](const LoadHistory& h, std::string label, std::string color, double width) {
        Series s;
        s.label = std::move(label);
        s.color = std::move(color);
        s.line_width = width;
        s.x = h.time;
        for (const double f : h.load) {
            s.y.push_back(f / n_per_kn);
        }
        return s;
    };
    Plot plot;
    plot.title = title;
    plot.x_label = "time since release (s)";
    plot.y_label =
        std::string("wall load normal to the wall (") + load_unit(sampled.per_metre) + ")";
    plot.series.push_back(series(sampled, sampled_label, "#9e9e9e", 1.0));
    plot.series.push_back(series(filtered, filtered_label, "#1f77b4", 2.5));
    if (measured != nullptr) {
        const std::string name = std::filesystem::path(measured->source).filename().string();
        Series m = series(*measured, "measured (" + name + ")", "#d62728", 2.0);
        m.dash = "6 4";
        plot.series.push_back(std::move(m));
    }
    plot.y_min = 0.0;
    return plot;
}

}  // namespace rockfall::app
