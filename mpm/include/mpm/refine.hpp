#pragma once
/// Grid-refinement studies of a soil flow: the same scenario run at a sequence of cell sizes,
/// and Richardson extrapolation with the observed order of convergence (Roache 1998,
/// Verification and Validation in Computational Science and Engineering, ch. 5; Celik et al.
/// 2008, J. Fluids Eng. 130, 078001, the grid convergence index procedure).

#include "mpm/soil.hpp"

#include <functional>
#include <vector>

namespace rockfall::mpm {

/// Richardson extrapolation of a quantity f computed on three grids h1 > h2 > h3 with a
/// constant refinement ratio r = h1 / h2 = h2 / h3.
struct RichardsonEstimate {
    /// Whether the three values converge monotonically ((f1 - f2) / (f2 - f3) > 1: same sign,
    /// shrinking differences); when false, order, extrapolated value and GCI are NaN. Two
    /// finest values that agree exactly count as converged: extrapolated = f3, order NaN.
    bool monotone = false;
    /// Observed order p = ln((f1 - f2) / (f2 - f3)) / ln r.
    double order = 0.0;
    /// Extrapolated value f3 + (f3 - f2) / (r^p - 1), in the unit of f.
    double extrapolated = 0.0;
    /// Relative change between the two finest grids, |f3 - f2| / |f3| (0 when f3 = 0).
    double finest_change = 0.0;
    /// Grid convergence index of the finest grid, 1.25 |f3 - f2| / (|f3| (r^p - 1)) (Roache's
    /// safety factor 1.25 for three grids); NaN when not monotone.
    double gci_fine = 0.0;
};

/// Extrapolates from values on the coarse, medium and fine grids (finite) and the refinement
/// ratio (> 1). Throws std::invalid_argument for a ratio <= 1 or non-finite values.
RichardsonEstimate richardson(double coarse, double medium, double fine, double ratio);

/// Smallest and largest value of a quantity over the runs of a level, in the quantity's unit.
struct ValueRange {
    double min = 0.0;
    double max = 0.0;
};

/// One level of a refinement study: the quantities compared between levels (with several runs
/// per level, their means).
struct RefinementLevel {
    /// Cell size, m.
    double cell_size = 0.0;
    /// Particles.
    long particles = 0;
    /// Steps taken.
    long steps = 0;
    /// How the run ended.
    SoilStatus status = SoilStatus::completed;
    /// Peak wall load (mean over each sample interval), N (N/m in 2D).
    double peak_wall_force = 0.0;
    /// Time of the peak, s.
    double peak_time = 0.0;
    /// Peak of the filtered wall load (output.filter_window's centred moving average), N (N/m).
    double peak_wall_force_filtered = 0.0;
    /// Steady wall load: mean of the sampled load over the last steady_window seconds, N (N/m).
    double steady_wall_force = 0.0;
    /// Runout past the toe, m.
    double runout_past_toe = 0.0;
    /// Runs averaged into this level (RefinementSettings::repeats).
    int runs = 1;
    /// Smallest and largest value of each quantity above over the runs (with one run, both are
    /// its value).
    ValueRange peak_wall_force_range;
    ValueRange peak_time_range;
    ValueRange peak_wall_force_filtered_range;
    ValueRange steady_wall_force_range;
    ValueRange runout_past_toe_range;
};

/// Settings of a refinement study.
struct RefinementSettings {
    /// Cell sizes, m, coarsest first, each > 0 and smaller than the previous; at least 2 (3 for
    /// the extrapolation, which uses the three finest with their mean ratio).
    std::vector<double> cell_sizes{0.2, 0.1, 0.05};
    /// Window at the end of the run over which the steady wall load is averaged, s, in (0,
    /// output.duration].
    double steady_window = 1.0;
    /// Runs per level, [1, kMaxRepeats]. Run k (from 0) takes numerics.cfl times (1 - k 1e-4):
    /// a change of the time step of at most 0.2 %, which a converged flow does not feel but a
    /// flow that amplifies small perturbations does; each level reports the means and ranges.
    int repeats = 1;
};

/// Largest RefinementSettings::repeats.
inline constexpr int kMaxRepeats = 20;

/// Relative change of numerics.cfl from one repeat of a level to the next.
inline constexpr double kRepeatTimeStepChange = 1e-4;

/// A refinement study: every level and, with three or more levels, the extrapolation of each
/// quantity from the three finest.
struct RefinementStudy {
    /// The levels, coarsest first.
    std::vector<RefinementLevel> levels;
    /// Whether the extrapolations below were computed (three or more levels, the three finest
    /// completed).
    bool extrapolated = false;
    /// Refinement ratio used for the extrapolation (geometric mean of the three finest).
    double ratio = 0.0;
    /// Extrapolations of peak, time of peak, filtered peak, steady load and runout.
    RichardsonEstimate peak_wall_force;
    RichardsonEstimate peak_time;
    RichardsonEstimate peak_wall_force_filtered;
    RichardsonEstimate steady_wall_force;
    RichardsonEstimate runout_past_toe;
};

/// Summarises one run as a level (steady window in s, > 0).
RefinementLevel refinement_level(const SoilOutcome& outcome, double cell_size,
                                 double steady_window);

/// The level of several runs at the same cell size (at least one): each quantity their mean and
/// range, particles of the first run, steps their mean (rounded), status the first that did not
/// complete (completed if all did).
RefinementLevel mean_of_runs(const std::vector<RefinementLevel>& runs);

/// Called after each level with its index and result; must not throw.
using RefinementProgress = std::function<void(int, const RefinementLevel&)>;

/// Runs `scenario` at every cell size of `settings` (numerics.cell_size replaced, the rest
/// unchanged) and extrapolates. Invalid settings or scenario throw std::invalid_argument
/// naming the field.
/// Fills the study's extrapolations from its levels (cell sizes decreasing): computed when there
/// are three or more levels and the three finest completed; otherwise `extrapolated` is false.
void extrapolate_study(RefinementStudy& study);

RefinementStudy run_refinement(const SoilScenario& scenario, const RefinementSettings& settings,
                               const RefinementProgress& progress = {});

}  // namespace rockfall::mpm
