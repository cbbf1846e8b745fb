#pragma once
// The Bullet world of one run: the slope's static solids and any number of rocks as rigid
// bodies, advanced by fixed steps. Bullet types stay inside world.cpp (pImpl), so the rest of
// the engine reads Eigen values only.

#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>

namespace rockfall::engine {

// Kinematic state of one body, world frame, SI units.
struct BodyState {
    Vec3 position = Vec3::Zero();
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    Vec3 velocity = Vec3::Zero();
    Vec3 angular_velocity = Vec3::Zero();
};

class World {
  public:
    // Static solids: every box of the slope except the reaction wall, whose contact is the
    // compliant WallContactLaw applied by the caller as an external force; with a terrain mesh,
    // the mesh instead of the slope slabs.
    World(const Scenario& scenario, const shapes::Slope& slope);
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // Adds a rock (geometry in its principal body frame) and returns its index.
    int add_rock(const shapes::RockGeometry& geometry, const RockSpec& spec,
                 const BodyState& initial);
    // Takes a rock out of the simulation; its last state stays readable.
    void remove_rock(int rock);

    // Force (N) acting at a world point (m) during the next step only.
    void apply_force(int rock, const Vec3& force, const Vec3& point);
    // One step of dt seconds (stepSimulation(dt, 0): no sub-steps, no interpolation).
    void step(double dt);

    BodyState state(int rock) const;
    // Mass, kg.
    double mass(int rock) const;
    // Principal moments of inertia in the body frame, kg m2.
    Vec3 inertia(int rock) const;

  private:
    void add_terrain(const Scenario& scenario);

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rockfall::engine
