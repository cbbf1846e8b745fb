#include "mpm/refine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::mpm {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A quantity of a level and its range over the level's runs.
struct LevelQuantity {
    double RefinementLevel::*value;
    ValueRange RefinementLevel::*range;
};

constexpr LevelQuantity kLevelQuantities[] = {
    {&RefinementLevel::peak_wall_force, &RefinementLevel::peak_wall_force_range},
    {&RefinementLevel::peak_time, &RefinementLevel::peak_time_range},
    {&RefinementLevel::peak_wall_force_filtered, &RefinementLevel::peak_wall_force_filtered_range},
    {&RefinementLevel::steady_wall_force, &RefinementLevel::steady_wall_force_range},
    {&RefinementLevel::runout_past_toe, &RefinementLevel::runout_past_toe_range},
};

RichardsonEstimate extrapolate(const std::vector<RefinementLevel>& levels, double ratio,
                               double RefinementLevel::*field) {
    const std::size_t n = levels.size();
    return richardson(levels[n - 3].*field, levels[n - 2].*field, levels[n - 1].*field, ratio);
}

}  // namespace

RichardsonEstimate richardson(double coarse, double medium, double fine, double ratio) {
    if (!(ratio > 1.0) || !std::isfinite(ratio)) {
        std::ostringstream message;
        message << "refinement ratio = " << ratio << ": must be > 1";
        throw std::invalid_argument(message.str());
    }
    if (!std::isfinite(coarse) || !std::isfinite(medium) || !std::isfinite(fine)) {
        throw std::invalid_argument("richardson: the three values must be finite");
    }
    RichardsonEstimate e;
    e.finest_change = fine != 0.0 ? std::abs(fine - medium) / std::abs(fine) : 0.0;
    const double d21 = coarse - medium;
    const double d32 = medium - fine;
    if (d32 == 0.0) {
        // Converged to the last digit on the two finest grids.
        e.monotone = true;
        e.order = kNaN;
        e.extrapolated = fine;
        e.gci_fine = 0.0;
        return e;
    }
    const double q = d21 / d32;
    // Monotone convergence: same sign and shrinking differences (Celik et al. 2008).
    if (!(q > 1.0)) {
        e.monotone = false;
        e.order = kNaN;
        e.extrapolated = kNaN;
        e.gci_fine = kNaN;
        return e;
    }
    e.monotone = true;
    e.order = std::log(q) / std::log(ratio);
    const double denominator = std::pow(ratio, e.order) - 1.0;
    e.extrapolated = fine + (fine - medium) / denominator;
    e.gci_fine =
        fine != 0.0 ? 1.25 * std::abs(fine - medium) / (std::abs(fine) * denominator) : kNaN;
    return e;
}

RefinementLevel refinement_level(const SoilOutcome& o, double cell_size, double steady_window) {
    RefinementLevel level;
    level.cell_size = cell_size;
    level.particles = o.particles;
    level.steps = o.steps;
    level.status = o.status;
    level.peak_wall_force = o.peak_wall_force;
    level.peak_time = o.peak_wall_force_time;
    level.peak_wall_force_filtered = o.peak_wall_force_filtered;
    level.runout_past_toe = o.deposit.runout_past_toe;
    if (!o.sample_time.empty()) {
        const double from = o.sample_time.back() - steady_window;
        double sum = 0.0;
        int count = 0;
        for (std::size_t k = 0; k < o.sample_time.size(); ++k) {
            if (o.sample_time[k] > from + 1e-12) {
                sum += o.wall_force[k];
                ++count;
            }
        }
        level.steady_wall_force = count > 0 ? sum / count : 0.0;
    }
    for (const LevelQuantity& q : kLevelQuantities) {
        level.*q.range = {level.*q.value, level.*q.value};
    }
    return level;
}

RefinementLevel mean_of_runs(const std::vector<RefinementLevel>& runs) {
    if (runs.empty()) {
        throw std::invalid_argument("mean_of_runs: no runs");
    }
    RefinementLevel level = runs.front();
    level.runs = static_cast<int>(runs.size());
    double steps = 0.0;
    for (const RefinementLevel& run : runs) {
        steps += static_cast<double>(run.steps);
        if (level.status == SoilStatus::completed) level.status = run.status;
    }
    level.steps = std::lround(steps / static_cast<double>(runs.size()));
    for (const LevelQuantity& q : kLevelQuantities) {
        double sum = 0.0;
        ValueRange range{runs.front().*q.value, runs.front().*q.value};
        for (const RefinementLevel& run : runs) {
            const double v = run.*q.value;
            sum += v;
            range.min = std::min(range.min, v);
            range.max = std::max(range.max, v);
        }
        level.*q.value = sum / static_cast<double>(runs.size());
        level.*q.range = range;
    }
    return level;
}

void extrapolate_study(RefinementStudy& study) {
    const std::size_t n = study.levels.size();
    // A level that did not complete (left the domain, non-finite) has no converged value to
    // extrapolate from.
    study.extrapolated = n >= 3 && std::all_of(study.levels.end() - 3, study.levels.end(),
                                               [](const RefinementLevel& l) {
                                                   return l.status == SoilStatus::completed;
                                               });
    if (!study.extrapolated) {
        return;
    }
    study.ratio = std::sqrt(study.levels[n - 3].cell_size / study.levels[n - 1].cell_size);
    study.peak_wall_force =
        extrapolate(study.levels, study.ratio, &RefinementLevel::peak_wall_force);
    study.peak_time = extrapolate(study.levels, study.ratio, &RefinementLevel::peak_time);
    study.peak_wall_force_filtered =
        extrapolate(study.levels, study.ratio, &RefinementLevel::peak_wall_force_filtered);
    study.steady_wall_force =
        extrapolate(study.levels, study.ratio, &RefinementLevel::steady_wall_force);
    study.runout_past_toe =
        extrapolate(study.levels, study.ratio, &RefinementLevel::runout_past_toe);
}

RefinementStudy run_refinement(const SoilScenario& scenario, const RefinementSettings& settings,
                               const RefinementProgress& progress) {
    validate(scenario);
    const std::vector<double>& cells = settings.cell_sizes;
    if (cells.size() < 2) {
        throw std::invalid_argument("refine.cell_sizes: must list at least 2 cell sizes, has " +
                                    std::to_string(cells.size()));
    }
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const bool ok =
            std::isfinite(cells[i]) && cells[i] > 0.0 && (i == 0 || cells[i] < cells[i - 1]);
        if (!ok) {
            std::ostringstream message;
            message << "refine.cell_sizes[" << i << "] = " << cells[i]
                    << " m: must be > 0 and smaller than the one before";
            throw std::invalid_argument(message.str());
        }
    }
    if (!(settings.steady_window > 0.0 && settings.steady_window <= scenario.output.duration)) {
        std::ostringstream message;
        message << "refine.steady_window = " << settings.steady_window
                << " s: must be in (0, output.duration = " << scenario.output.duration << " s]";
        throw std::invalid_argument(message.str());
    }
    if (settings.repeats < 1 || settings.repeats > kMaxRepeats) {
        throw std::invalid_argument("refine.repeats = " + std::to_string(settings.repeats) +
                                    ": must be in [1, " + std::to_string(kMaxRepeats) + "]");
    }
    RefinementStudy study;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        std::vector<RefinementLevel> runs;
        for (int k = 0; k < settings.repeats; ++k) {
            SoilScenario level = scenario;
            level.numerics.cell_size = cells[i];
            level.numerics.cfl *= 1.0 - k * kRepeatTimeStepChange;
            runs.push_back(refinement_level(run_soil(level), cells[i], settings.steady_window));
        }
        study.levels.push_back(mean_of_runs(runs));
        if (progress) {
            progress(static_cast<int>(i), study.levels.back());
        }
    }
    extrapolate_study(study);
    return study;
}

}  // namespace rockfall::mpm
