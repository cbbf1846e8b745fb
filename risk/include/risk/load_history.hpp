#pragma once
/// Wall-load time histories and the comparison of a simulated one with a measured record
/// (seed 000, Figure 10: the paper compares its MPM wall load with the load cells' record,
/// finding the model larger at first and about equal later).

#include <string>
#include <vector>

namespace rockfall::risk {

/// A wall-load history: loads normal to the wall at increasing times.
struct LoadHistory {
    /// Where it comes from, for messages and legends (a file name, "simulated").
    std::string source;
    /// Times, s (finite, increasing).
    std::vector<double> time;
    /// Loads, N, or N/m when `per_metre` (finite; same size as `time`).
    std::vector<double> load;
    /// Whether the loads are per metre of width (a 2D plane-strain run).
    bool per_metre = false;
};

/// A simulated history against a measured one, over the times both cover. Both are taken as
/// linear between their points and compared at the union of their times, so that a sparse
/// record (points read off a published figure) counts as well as a dense one; impulses are
/// exact integrals of those piecewise-linear loads. The measured peak splits the record into the
/// loading phase (up to the peak) and the rest, as seed 000 discusses the two separately.
struct HistoryComparison {
    /// The times both histories cover, s.
    double from = 0.0;
    double to = 0.0;
    /// Measured points inside [from, to] (>= 2).
    int points = 0;
    /// Peaks inside [from, to] (N or N/m) and their times (s).
    double simulated_peak = 0.0;
    double simulated_peak_time = 0.0;
    double measured_peak = 0.0;
    double measured_peak_time = 0.0;
    /// simulated_peak / measured_peak (NaN when the measured peak is not > 0).
    double peak_ratio = 0.0;
    /// Impulses over [from, to], N s (N s/m), and simulated / measured.
    double simulated_impulse = 0.0;
    double measured_impulse = 0.0;
    double impulse_ratio = 0.0;
    /// Mean simulated load over mean measured load up to the measured peak, and after it (NaN
    /// where the measured mean is not > 0 or the phase has no length).
    double loading_ratio = 0.0;
    double after_peak_ratio = 0.0;
    /// Root mean square of simulated - measured over [from, to] (at the union of the times),
    /// N (N/m).
    double rms_difference = 0.0;
};

/// Throws std::invalid_argument unless `measured` is per metre exactly when the simulated
/// loads are (a 2D run; the message says which column a 2D or 3D run needs) and at least two
/// measured times lie in the simulated history's span [from, to] (s). Returns how many do.
/// A run checks this before it starts, with the span its sampled history will have.
int check_comparable(bool simulated_per_metre, double from, double to, const LoadHistory& measured);

/// Compares `simulated` with `measured`. Throws std::invalid_argument when check_comparable
/// fails or when they share fewer than two measured times.
HistoryComparison compare_histories(const LoadHistory& simulated, const LoadHistory& measured);

}  // namespace rockfall::risk
