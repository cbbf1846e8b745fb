#pragma once
/// Human-readable and JSON reports of a simulation outcome. Every number carries its unit:
/// in text after the value, in JSON as a key suffix (`reach_m`, `peak_normal_force_N`).

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"

#include <nlohmann/json.hpp>

#include <ostream>

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

/// Writes the readable summary: reach, stop reason, stations, V', Cr, wall hits, runtime.
void print_summary(std::ostream& out, const engine::Scenario& scenario,
                   const engine::Outcome& outcome, const RunInfo& info);

/// The same as one JSON document (units in the key names).
nlohmann::json outcome_json(const engine::Scenario& scenario, const engine::Outcome& outcome,
                            const RunInfo& info);

}  // namespace rockfall::report
