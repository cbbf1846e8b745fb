#pragma once
/// Small scenes with analytic answers, shared by the engine's verification tests and
/// `rockfall validate`'s report: a rock on one long straight plane, a sphere sliding into the
/// reaction wall, and the measurements read from their trajectories. SI units.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"

#include <vector>

namespace rockfall::engine::scenes {

/// Gravitational acceleration of every scene, m/s2.
inline constexpr double gravity = 9.81;

/// Degrees to radians.
double radians(double degrees);

/// Unit vector down an incline at `angle_deg` in the x-z plane.
Vec3 downslope(double angle_deg);

/// Unit normal out of an incline at `angle_deg` in the x-z plane.
Vec3 upward_normal(double angle_deg);

/// One straight segment at `angle_deg`, 40 m long, without bars, side walls or reaction wall;
/// one rock of `kind`, 0.2 m, released 5 m along it; rock and surface share `material` (so the
/// mean rule gives it unchanged); step `time_step`, s.
Scenario plane_scenario(double angle_deg, shapes::RockKind kind, const Material& material,
                        double time_step);

/// Every state of rock 0 the engine reports in a run of `scenario` with seed 1, sampled every
/// `interval` seconds (every step when smaller than the step).
std::vector<RockState> trajectory(const Scenario& scenario, double interval);

/// The sampled state closest to time `t` (s) of a non-empty trajectory.
const RockState& state_at(const std::vector<RockState>& states, double t);

/// Mean acceleration along `direction` between the states closest to t0 and t1, m/s2.
double mean_acceleration(const std::vector<RockState>& states, const Vec3& direction, double t0,
                         double t1);

/// A pure normal wall impact: a sphere of `size` (m) and `density` (kg/m3) slides without
/// friction along a flat 4 m run-out at `speed` (m/s) into the reaction wall, whose face is 3 m
/// from the run-out's start; its front starts 0.8 m upslope of it. `restitution` is both the
/// wall's and the rock's; the run ends 0.2 s after the sphere would reach the wall.
Scenario wall_scenario(const WallContact& contact, double restitution, double size, double speed,
                       double density);

/// The first bounce of a rock dropped onto a plane: its rebound height along the normal and
/// the ratio of normal speeds after and before.
struct Bounce {
    /// Rise of the centre above its height at first touch, along the normal, m.
    double rebound_height = 0.0;
    /// Normal speed after the bounce over normal speed before it.
    double velocity_ratio = 0.0;
    /// The states of the run, every step.
    std::vector<RockState> states;
};

/// Drops a rock of `kind` from `height` (gap above the surface, m) onto the plane_scenario at
/// `angle_deg` with friction 0.5 and `restitution`, step `time_step` (s), and measures its first
/// bounce. Throws std::runtime_error when it never rebounds within 1.5 s.
Bounce first_bounce(double angle_deg, shapes::RockKind kind, double restitution, double time_step,
                    double height);

}  // namespace rockfall::engine::scenes
