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
#include <vector>

namespace rockfall::engine {

// Kinematic state of one body, world frame, SI units.
struct BodyState {
    Vec3 position = Vec3::Zero();
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    Vec3 velocity = Vec3::Zero();
    Vec3 angular_velocity = Vec3::Zero();
};

// What the reaction wall's rigid contact did to one rock during the last step: the wall's
// resting contacts (see World::set_rigid_wall_contact).
struct RigidWallContact {
    // Whether Bullet holds contact points between the rock and the wall.
    bool touching = false;
    // Impulse of the wall on the rock over the step, N s, world frame.
    Vec3 impulse = Vec3::Zero();
    // Its normal component (>= 0) along `normal`, the unit normal out of the wall, N s.
    double normal_impulse = 0.0;
    Vec3 normal = Vec3::Zero();
    // Where it acted: the normal-impulse-weighted mean of the contact points, m.
    Vec3 point = Vec3::Zero();
};

class World {
  public:
    // Static solids: every box of the slope, or with a terrain mesh the mesh instead of the
    // slope slabs. The reaction wall is a solid too, but a rock collides with it only while
    // its wall contact is rigid (set_rigid_wall_contact); otherwise the caller applies the
    // compliant WallContactLaw as an external force.
    World(const Scenario& scenario, const shapes::Slope& slope);
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // Adds a rock (geometry in its principal body frame) and returns its index.
    int add_rock(const shapes::RockGeometry& geometry, const RockSpec& spec,
                 const BodyState& initial);
    // Takes a rock out of the simulation; its last state stays readable.
    void remove_rock(int rock);

    // A temporary static box (the walls of a release box) with `material`; returns its index.
    int add_static_box(const shapes::OrientedBox& box, const Material& material);
    // Takes it out of the world.
    void remove_static_box(int box);

    // A kinematic group of `boxes` (in its own frame, unrotated) with `material`, its frame at
    // `position`: moved by move_kinematic, it pushes rocks and carries its velocity into their
    // contacts, but nothing pushes it (the heap test's funnel). One body per box; at most 256
    // boxes in a world (std::invalid_argument beyond). Returns its index.
    int add_kinematic_boxes(const std::vector<shapes::OrientedBox>& boxes, const Material& material,
                            const Vec3& position);
    // Puts kinematic group `group`'s frame at `position` by the end of the next step; Bullet
    // gives its boxes the velocity of that move over the step.
    void move_kinematic(int group, const Vec3& position);
    // Takes the group out of the world.
    void remove_kinematic(int group);

    // Whether Bullet's rigid contact holds the rock against the wall (a resting contact), or
    // the caller's compliant law (an impact; the default).
    void set_rigid_wall_contact(int rock, bool rigid);
    // The rigid wall contact of every rock in the last step, indexed by rock (empty for a rock
    // whose contact is compliant or that does not touch the wall), in one pass.
    std::vector<RigidWallContact> rigid_wall_contacts() const;
    // Lets Bullet put a rock to sleep with its island when it has stayed still (a rock at
    // rest kept as an obstacle), or keeps it awake (a moving rock; the default). A sleeping
    // rock wakes when a moving body touches it.
    void allow_sleep(int rock, bool allow, double rest_speed, double radius);

    // Force (N) acting at a world point (m) during the next step only.
    void apply_force(int rock, const Vec3& force, const Vec3& point);
    // Impulse (N s) through the centre of mass and angular impulse (N m s) spread evenly over
    // the next step of dt seconds (a constant force and torque during it).
    void apply_impulse_over_step(int rock, const Vec3& impulse, const Vec3& angular_impulse,
                                 double dt);
    // Moves a rock by `shift` (m) and turns it by the rotation vector `rotation` (rad, world
    // frame, about its centre of mass), keeping its velocities.
    void shift_pose(int rock, const Vec3& shift, const Vec3& rotation);
    // Threads for a step's collision detection (>= 1; 1, the default: the caller's alone). The
    // results are bit-identical whatever the count (pair_dispatcher.hpp).
    void set_collision_threads(int threads);
    // Solver iterations per step from the next step on, in [1, 100] (Numerics::solver_iterations).
    void set_solver_iterations(int iterations);
    // One step of dt seconds (stepSimulation(dt, 0): no sub-steps, no interpolation).
    void step(double dt);

    BodyState state(int rock) const;
    // Mass, kg.
    double mass(int rock) const;
    // Principal moments of inertia in the body frame, kg m2.
    Vec3 inertia(int rock) const;

  private:
    void add_terrain(const Scenario& scenario);
    void add_lining(const Scenario& scenario, const shapes::Slope& slope);

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rockfall::engine
