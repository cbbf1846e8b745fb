#pragma once
/// Running one release: a fresh world per run, fixed steps, recorders outside the step.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"

#include <cstdint>
#include <functional>
#include <memory>

namespace rockfall::engine {

/// Receives rock states after steps (recorders run outside the physics step).
using TrajectorySink = std::function<void(int rock_index, const RockState& state)>;

/// Options that do not change the physics.
struct RunOptions {
    /// Called every `trajectory_interval` of simulated time for each moving rock; may be empty.
    TrajectorySink trajectory;
    /// Interval between trajectory samples, s (> 0).
    double trajectory_interval = 0.01;
};

/// Simulates all rocks of a scenario until each one stops. The same scenario, seed and binary
/// give bit-identical outcomes. The scenario must be valid (see app::load_scenario).
Outcome simulate(const Scenario& scenario, std::uint64_t seed, const RunOptions& options = {});

}  // namespace rockfall::engine
