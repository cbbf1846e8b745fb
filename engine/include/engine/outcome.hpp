#pragma once
/// What one simulation produces: per-rock outcomes, stations and wall hits. SI units.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rockfall::engine {

using Vec3 = Eigen::Vector3d;

/// Why a rock's simulation ended.
enum class StopReason {
    at_rest,            ///< speed below rest_speed for rest_duration
    left_domain,        ///< past the end of the slope, off its sides, or below it
    time_limit,         ///< max_time reached while still moving
    numerical_failure,  ///< non-finite state or a rock inside a solid
};

/// Lower-case name ("at_rest", ...).
std::string_view to_string(StopReason reason);

/// Kinematic state of one rock at one time.
struct RockState {
    /// Simulated time, s.
    double time = 0.0;
    /// Centre of mass, m.
    Vec3 position = Vec3::Zero();
    /// Orientation of the body (principal) frame.
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    /// Velocity of the centre of mass, m/s.
    Vec3 velocity = Vec3::Zero();
    /// Angular velocity, world frame, rad/s.
    Vec3 angular_velocity = Vec3::Zero();
    /// Translational kinetic energy, J.
    double translational_energy = 0.0;
    /// Rotational kinetic energy, J.
    double rotational_energy = 0.0;
};

/// A rock crossing a station (a cross-section at a horizontal distance from the toe).
struct StationCrossing {
    /// Station's horizontal distance from the toe, m.
    double distance_from_toe = 0.0;
    /// Whether the rock crossed it; the other fields are meaningful only when true.
    bool reached = false;
    /// Time of crossing, s.
    double time = 0.0;
    /// Speed of the centre of mass, m/s.
    double speed = 0.0;
    /// Velocity component parallel to the surface, m/s.
    double parallel_speed = 0.0;
    /// Magnitude of the angular velocity, rad/s.
    double angular_speed = 0.0;
    /// Gap between the rock's lowest point and the surface, m (0 when in contact).
    double bounce_height = 0.0;
    /// Rolling coefficient Cr = w r / v with r = nominal_size / 2 (seed 000, eq. 2).
    double rolling_coefficient = 0.0;
    /// Translational and rotational kinetic energy at the crossing, J.
    double translational_energy = 0.0;
    double rotational_energy = 0.0;
};

/// One sample of the wall contact force.
struct ForceSample {
    /// Time, s.
    double time = 0.0;
    /// Normal force on the wall, N (>= 0).
    double normal = 0.0;
    /// Magnitude of the tangential (friction) force on the wall, N.
    double tangential = 0.0;
    /// Length of the step the force acted over from `time`, s.
    double duration = 0.0;
    /// Point of contact on the wall (world frame), m: the force-weighted mean of a resting
    /// contact's points; zero when the force is zero.
    Vec3 point = Vec3::Zero();
};

/// One contact event with the reaction wall, from first touch to separation (load cell).
struct WallHit {
    /// Time of first touch and of separation, s.
    double start_time = 0.0;
    double end_time = 0.0;
    /// Force-weighted mean point of contact on the wall, world frame, m.
    Vec3 point = Vec3::Zero();
    /// Normal impulse on the wall, N s (>= 0).
    double normal_impulse = 0.0;
    /// Tangential impulse on the wall (vector in the wall plane), N s.
    Vec3 tangential_impulse = Vec3::Zero();
    /// Velocities and angular velocities at first touch and at separation, m/s, rad/s.
    Vec3 velocity_before = Vec3::Zero();
    Vec3 velocity_after = Vec3::Zero();
    Vec3 angular_velocity_before = Vec3::Zero();
    Vec3 angular_velocity_after = Vec3::Zero();
    /// Total kinetic energy at first touch and at separation, J.
    double energy_before = 0.0;
    double energy_after = 0.0;
    /// Impact speed normal to the wall at first touch, m/s (>= 0).
    double normal_speed = 0.0;
    /// Peak normal force, N, and when it occurred, s.
    double peak_normal_force = 0.0;
    double peak_time = 0.0;
    /// Force history at every fine step of the event.
    std::vector<ForceSample> history;
};

/// Outcome for one rock.
struct RockOutcome {
    /// The rock's name (a named [[rocks]] entry or a marked cluster rock), or empty.
    std::string name;
    /// Nominal size (volume-equivalent diameter) of the rock as simulated, m: the scenario's, or
    /// the size a cluster rock was drawn with.
    double size = 0.0;
    /// Why its simulation ended.
    StopReason stop = StopReason::time_limit;
    /// Simulated time at the stop, s.
    double stop_time = 0.0;
    /// Furthest horizontal distance of the centre of mass past the toe, m (negative: above it).
    double reach = 0.0;
    /// Final state.
    RockState final_state;
    /// Highest speed, m/s.
    double max_speed = 0.0;
    /// Highest total (translational + rotational) kinetic energy, J.
    double max_kinetic_energy = 0.0;
    /// Highest gap between the rock's lowest point and the surface, m.
    double max_bounce_height = 0.0;
    /// One entry per scenario station, in the scenario's order.
    std::vector<StationCrossing> stations;
    /// Rate of velocity change V' = (b - a) / a between the first two stations (seed 000,
    /// eq. 1); NaN when either was not reached.
    double velocity_change = 0.0;
    /// Every hit on the reaction wall, in time order.
    std::vector<WallHit> wall_hits;
};

/// Outcome of one simulation.
struct Outcome {
    /// One per rock, in the scenario's order.
    std::vector<RockOutcome> rocks;
    /// Simulated time when the last rock stopped, s.
    double simulated_time = 0.0;
    /// World steps taken at the coarse time step, and fine steps near the wall: the world's
    /// (numerics.wall_stepping = "world") or the wall sub-steps of single rocks ("per_rock").
    std::int64_t coarse_steps = 0;
    std::int64_t fine_steps = 0;
    /// World steps times the rocks in the world during each (moving or at rest), after the
    /// gate opened: the work of the rigid-body solver.
    std::int64_t body_steps = 0;
    /// Hash of the final state of all rocks (bitwise): equal for equal runs.
    std::uint64_t state_hash = 0;
};

}  // namespace rockfall::engine
