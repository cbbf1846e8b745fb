#pragma once
/// The benchmark's reference: one rock on the slope in a bare Bullet world with Bullet's
/// default set-up, stepped at a fixed time step until the engine's stop rule ends it.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>

namespace rockfall::bench {

using Vec3 = Eigen::Vector3d;

/// Where and how a rock starts, world frame.
struct ReleasePose {
    /// Centre of mass, m.
    Vec3 position = Vec3::Zero();
    /// Orientation of the body (principal) frame.
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

/// The release as engine/scenario.hpp documents it: the surface point at release.distance,
/// shifted by release.lateral, lifted along the surface normal until the rock's lowest point
/// is release.height above the surface; Euler angles x, then y, then z about the fixed axes of
/// the surface frame (downslope tangent, y, normal). A random orientation is drawn from `seed`
/// with the benchmark's own generator: the same distribution as the engine's, not the same
/// sample. `skin` (m, >= 0) is the collision margin Bullet adds around a hull: the rock is
/// lifted by it so that the grown shape starts at the release height, not inside the slope.
ReleasePose release_pose(const shapes::Slope& slope, const shapes::RockGeometry& rock,
                         const engine::Release& release, std::uint64_t seed, double skin);

/// Fine time step of the engine near the wall for this rock, s: the contact duration of
/// engine::WallContactLaw at `impact_speed` (m/s, > 0) divided by steps_per_contact.
double fine_time_step(const engine::Scenario& scenario, double impact_speed);

/// Result of one bare-Bullet trajectory.
struct BareRun {
    /// Why it ended (the engine's stop rule).
    engine::StopReason stop = engine::StopReason::time_limit;
    /// Simulated time at the stop, s.
    double stop_time = 0.0;
    /// Steps taken.
    std::int64_t steps = 0;
    /// Furthest horizontal distance of the centre of mass past the toe, m.
    double reach = 0.0;
};

/// Simulates the scenario's single rock (throws std::invalid_argument for any other count)
/// in a fresh bare Bullet world stepped by stepSimulation(time_step, 0), time_step in s (> 0).
BareRun run_bare_bullet(const engine::Scenario& scenario, std::uint64_t seed, double time_step);

}  // namespace rockfall::bench
