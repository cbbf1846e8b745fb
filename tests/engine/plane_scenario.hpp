#pragma once
// A rock on one long straight plane, for the motion and contact tests: no bars, side walls or
// reaction wall, and the engine's reported states sampled at a fixed interval.

#include "engine/simulation.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace rockfall::engine::test {

inline constexpr double kGravity = 9.81;  // m/s2

inline double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Unit vector down an incline at `angle_deg` in the x-z plane.
inline Vec3 downslope(double angle_deg) {
    return {std::cos(radians(angle_deg)), 0.0, -std::sin(radians(angle_deg))};
}

// One straight segment at `angle_deg`, 40 m long, without bars, side walls or reaction wall;
// rock and surface share `material` (so the mean rule gives it unchanged).
inline Scenario plane_scenario(double angle_deg, shapes::RockKind kind, const Material& material,
                               double time_step) {
    Scenario scenario;
    scenario.slope.segments = {{40.0, angle_deg}};
    scenario.slope.bars.enabled = false;
    scenario.slope.side_walls.enabled = false;
    scenario.slope.wall.enabled = false;
    scenario.materials.slope = material;
    scenario.rocks.front().rock.kind = kind;
    scenario.rocks.front().rock.size = 0.2;
    scenario.rocks.front().rock.material = material;
    scenario.rocks.front().release.distance = 5.0;
    scenario.stations = {};
    scenario.numerics.time_step = time_step;
    scenario.gravity = kGravity;
    return scenario;
}

// Every state the engine reports, sampled every `interval` seconds (every step when smaller
// than the step).
inline std::vector<RockState> trajectory(const Scenario& scenario, double interval) {
    std::vector<RockState> states;
    RunOptions options;
    options.trajectory_interval = interval;
    options.trajectory = [&](int, const RockState& state) { states.push_back(state); };
    simulate(scenario, 1, options);
    return states;
}

}  // namespace rockfall::engine::test
