#pragma once
/// A grid-refinement study of a soil flow (mpm::run_refinement) as people read it: the table of
/// levels and the Richardson extrapolation, as text or JSON. What `rockfall soil --refine` and
/// bench/bench_refine print. Text loads are in kN (kN/m in 2D, per metre of width); JSON keys
/// carry their unit (N, or N_per_m in 2D).

#include "mpm/refine.hpp"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace rockfall::report {

/// What a study ran on, beside the study itself.
struct RefinementContext {
    /// Scenario file (or another name for where the scenario came from).
    std::string scenario;
    /// 2 (plane strain: loads per metre of width) or 3.
    int dimension = 3;
    /// Simulated time of every level, s.
    double duration = 0.0;
    /// Window of the steady load at the end of each run, s.
    double steady_window = 0.0;
    /// Width of the moving average of the filtered peak (output.filter_window), s.
    double filter_window = 0.0;
    /// Wall-clock time of each level, s; empty to leave the column out.
    std::vector<double> runtime;
};

/// One line for progress on standard error after level `index` (from 0) of `count`: cell,
/// particles, peak and steady load with units, runtime in s.
std::string refinement_progress_line(const mpm::RefinementLevel& level, int index, int count,
                                     int dimension, double runtime);

/// The table of levels (cell size, particles, steps, peak load and its time, steady load,
/// runout, runtime when known, a note for a run that did not complete), then the extrapolation
/// of each quantity from the three finest levels with its observed order, finest change and
/// GCI, or "not converging monotonically".
void print_refinement(std::ostream& out, const mpm::RefinementStudy& study,
                      const RefinementContext& context);

/// The same as one JSON document: `levels` (unit-suffixed keys) and `extrapolation` (null with
/// fewer than three levels; `refinement_ratio` and, under each quantity's unit-suffixed key,
/// `monotone`, `extrapolated` in that unit, `observed_order`, and `finest_change` and
/// `gci_fine` as fractions; null where undefined).
nlohmann::ordered_json refinement_json(const mpm::RefinementStudy& study,
                                       const RefinementContext& context);

}  // namespace rockfall::report
