#pragma once
/// Identification of one model parameter from a measured mean output of a noisy virtual
/// experiment (the drop test's restitution, the heap test's friction): a curve of the output
/// over the parameter brackets the target, then the Illinois variant of regula falsi narrows
/// the bracket. Shared by risk/drop_test.hpp and risk/heap_test.hpp.

#include "risk/parallel.hpp"
#include "risk/sample_summary.hpp"
#include "risk/statistics.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rockfall::risk {

/// Called on the calling thread with jobs done and jobs planned (the plan may grow).
using BatchProgress = ParallelProgress;

/// One point of a curve: a parameter value and the distribution of the output there.
struct SearchPoint {
    /// The parameter, in its own unit.
    double parameter = 0.0;
    /// The output's distribution over the experiment's repeats.
    SampleSummary value;
};

/// Evaluates the output at each of a batch of parameter values (it may run them in parallel);
/// returns one summary per value, in order.
using SearchEvaluator =
    std::function<std::vector<SampleSummary>(const std::vector<double>& parameters)>;

/// Called with the lowest and highest mean output of the curve, and the curve, when the target
/// lies outside them; it must throw (the caller's message names its option and the range, and
/// gives the curve: curve_text).
using UnreachableTarget =
    std::function<void(double lowest, double highest, const std::vector<SearchPoint>& curve)>;

/// The curve as "parameter: mean" pairs, "0.15: 14.1, 0.3: 17.2, ..." (4 significant digits),
/// so that a message about an unreachable target keeps what the curve cost to measure.
std::string curve_text(const std::vector<SearchPoint>& curve);

/// Settings of a search.
struct SearchOptions {
    /// The bracket is refined until narrower than this, in the parameter's unit (> 0).
    double tolerance = 1e-3;
    /// Most refinement steps after the curve (>= 0).
    int max_iterations = 20;
};

/// The parameter whose mean output matches the target.
struct ParameterSearch {
    /// The point whose mean is nearest the target among the bracket's ends and refinements.
    SearchPoint best;
    /// Parameters whose output is consistent with the target: from where the upper bound of
    /// the 95 % interval of the mean first reaches the target to where its lower bound last
    /// does, interpolated linearly between the curve and refinement points.
    Interval consistent;
    /// The curve (as given, sorted ascending), then every refinement point, sorted.
    std::vector<SearchPoint> curve;
    std::vector<SearchPoint> refinements;
};

/// Finds where the mean output crosses `target`: `evaluate` runs the curve at `curve`
/// (ascending parameter values, at least 2) in one batch, the first pair of neighbours whose
/// means bracket the target is kept (`unreachable` is called when none does), then Illinois
/// regula falsi (Dowell and Jarratt 1971) evaluates one value at a time until the bracket is
/// narrower than the tolerance, a mean equals the target, or max_iterations.
ParameterSearch search_parameter(const std::vector<double>& curve, double target,
                                 const SearchOptions& options, const SearchEvaluator& evaluate,
                                 const UnreachableTarget& unreachable);

/// All curve and refinement points of a search, sorted by parameter (stable: a refinement at
/// a curve value follows it).
std::vector<SearchPoint> all_points(const ParameterSearch& search);

}  // namespace rockfall::risk
