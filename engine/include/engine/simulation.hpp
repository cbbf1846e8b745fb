#pragma once
/// Running one release: a fresh world per run, fixed steps, recorders outside the step.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace rockfall::engine {

/// Receives rock states after steps (recorders run outside the physics step).
using TrajectorySink = std::function<void(int rock_index, const RockState& state)>;

/// The bodies of a run as the engine builds them, before its first step.
struct RunGeometry {
    /// Every rock's geometry in its body frame (centroid at the origin, principal axes on x, y,
    /// z; a RockState's position and orientation place it), in outcome order.
    std::vector<shapes::RockGeometry> rocks;
    /// Static boxes the run adds to the scenario's slope for the whole run: a cluster's
    /// release-box back wall (its gate is removed at t = 0 and is not listed).
    std::vector<shapes::OrientedBox> solids;
};

/// Receives the run's geometry once, before the first step.
using GeometrySink = std::function<void(const RunGeometry& geometry)>;

/// Options that do not change the physics.
struct RunOptions {
    /// Called once with the rocks' geometries and the run's extra solids; may be empty.
    GeometrySink geometry;
    /// Called every `trajectory_interval` of simulated time for each moving rock; may be empty.
    TrajectorySink trajectory;
    /// Interval between trajectory samples, s (> 0).
    double trajectory_interval = 0.01;
    /// When false, a slow touch or a long contact with the wall stays with the compliant law
    /// instead of Bullet's rigid resting contact: the design before issue 13, in which a deposit
    /// against the wall kept it at the fine step. For bench_cluster's comparison only.
    bool rigid_resting_wall = true;
    /// Threads for each step's collision detection (>= 1): not physics, the outcome is
    /// bit-identical whatever the count. Worth it for clusters (a pile of hundreds of rocks
    /// ran 1.38 times faster on 2); a step with fewer than 64 broadphase pairs stays on the
    /// calling thread.
    int collision_threads = 1;
};

/// The rock of outcome entry `index` (of `count` rocks in the outcome) as simulated, drawn at
/// nominal size `size` (m, RockOutcome::size): the scenario's [[rocks]] entry, a marked cluster
/// rock (the last ones), or a drawn cluster rock (the cluster's spec at that size). A drawn rock
/// of a target sphericity has a hull of its own; its spec here is kind custom named
/// "sphericity S" with the cluster family's hull as a stand-in (same volume, so the same mass,
/// not the same shape).
RockSpec simulated_rock(const Scenario& scenario, std::size_t index, std::size_t count,
                        double size);

/// Simulates all rocks of a scenario until each one stops. The same scenario, seed and binary
/// give bit-identical outcomes. The scenario must be valid (see app::load_scenario).
Outcome simulate(const Scenario& scenario, std::uint64_t seed, const RunOptions& options = {});

}  // namespace rockfall::engine
