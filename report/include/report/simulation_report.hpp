#pragma once
/// Human-readable and JSON reports of a simulation outcome. Every number carries its unit:
/// in text after the value, in JSON as a key suffix (`reach_m`, `peak_normal_force_N`).

#include "report/marked_rocks.hpp"
#include "report/rock_series.hpp"

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <ostream>
#include <vector>

namespace rockfall::report {

/// Facts about the run that are not part of the outcome.
struct RunInfo {
    /// Scenario file path as given.
    std::string scenario_path;
    /// Seed of the run.
    std::uint64_t seed = 0;
    /// Wall-clock time of the simulation, s.
    double runtime = 0.0;
};

/// What the trajectory samples of a run give (rock_series.hpp); empty when not recorded.
struct RunSeries {
    /// Per rock in outcome order: speed against distance travelled.
    std::vector<RockSeries> rocks;
    /// The front of the rocks against time (cluster_front).
    std::vector<FrontPoint> front;
    /// Frame interval of the camera that tracks the marked rocks, s (> 0; marked_rocks.hpp).
    double camera_interval = default_camera_interval;
};

/// Which rocks the text summary prints in full (stations, every wall hit, speed against
/// distance); the others get a row of the rock table only. The scenario's own rocks
/// (`[[rocks]]`: a single rock, the named or marked rocks beside a cluster) are always in full.
struct RockDetail {
    /// Every rock in full.
    bool all = false;
    /// Further rocks in full, 0-based in outcome order (cluster rocks follow `[[rocks]]`).
    std::vector<std::size_t> rocks;
};

/// Rows of the compact speed-against-distance table of a rock shown in full.
inline constexpr std::size_t summary_distance_rows = 11;
/// Rows of the text table of the front against time.
inline constexpr std::size_t summary_front_rows = 11;

/// Writes the readable summary: reach, stop reason, stations, V', Cr, wall hits, runtime; with
/// more than one rock a table of all rocks first (stop, reach, distance travelled, wall hits)
/// and the front against time; with series, each rock in full gets speed against distance.
void print_summary(std::ostream& out, const engine::Scenario& scenario,
                   const engine::Outcome& outcome, const RunInfo& info,
                   const RunSeries& series = {}, const RockDetail& detail = {});

/// The same as one JSON document (units in the key names), every rock and series in full.
nlohmann::json outcome_json(const engine::Scenario& scenario, const engine::Outcome& outcome,
                            const RunInfo& info, const RunSeries& series = {});

}  // namespace rockfall::report
