#pragma once
// The compliant wall contact of one rock: what the wall does at one instant (both stepping
// modes), and the rock's wall contact sub-stepped inside one rigid-body step, so that an
// impact does not hold the whole world at the fine step (numerics.wall_stepping = "per_rock",
// issue 13). Private to the engine; no Bullet here.

#include "world.hpp"

#include "engine/wall_contact.hpp"

namespace rockfall::engine {

// Approach speeds below this at first touch make a resting contact with the wall, m/s: the
// wall law's own floor (WallContactLaw::kMinContactSpeed), below which it has no impact to
// resolve.
inline constexpr double kRestingContactSpeed = WallContactLaw::kMinContactSpeed;

// A compliant contact that lasts this many times the duration of a free impact at its
// first-touch speed is held against the wall (by the rocks behind it, or its own weight on a
// wall leaning over it): a resting contact from then on.
inline constexpr double kRestingContactDurations = 2.0;

// So is a contact whose overlap is deeper than the first-touch speed times that duration: no
// free impact reaches it (the largest overlap of an impact is reached in less than its
// duration, at less than its first-touch speed; a third of that bound for Hertz, 1/pi for a
// linear spring). Something else drove the rock in: the rocks behind it, through rigid contacts
// that do not see the compliant wall. Left compliant, the overlap's elastic force threw the
// rock back out: in a 20-rock cluster a 74 g rock in the corner of the wall, a side wall and
// the floor took 1.0 N s from the wall in one step while moving away from it at 1.8 m/s, and
// 8.6 N s in the next (a free impact at 1.5 m/s gives it about 0.15 N s); such clusters threw
// about 1 rock in 1,000 out of the flume, at up to 44 m/s.

// One rock's compliant contact with the wall, carried from step to step.
struct WallContactTrack {
    // Whether the rock overlapped the wall at the last evaluation: the contact's speed and
    // step are fixed at first touch, not again while the overlap lingers after the force
    // vanished.
    bool touching = false;
    // Fine step fixed at first touch for the whole contact, s.
    double step = 0.0;
    // Time of first touch, s.
    double start = 0.0;
    // How long a free impact at the first-touch speed lasts, s.
    double duration = 0.0;
    // Normal speed at first touch (at least kRestingContactSpeed), m/s.
    double speed = 0.0;
};

// What the wall does to a rock at one instant.
struct WallContactAt {
    enum class Kind {
        free,     // no overlap
        force,    // the compliant law's force, in `force`
        resting,  // a slow first touch, or a contact outlasting an impact: Bullet's rigid
                  // contact takes over
        inside,   // deeper than half the rock's size: it went through the wall
    };
    Kind kind = Kind::free;
    WallForce force;
};

// The rock and its wall law, as the wall contact sees them.
struct WallRock {
    const shapes::RockGeometry& geometry;
    // Mass, kg, and principal moments of inertia in the body frame, kg m2.
    double mass = 0.0;
    Vec3 inertia = Vec3::Zero();
    WallContactLaw& law;
    WallContactTrack& track;
    // False: no resting contact; every touch stays with the compliant law (RunOptions).
    bool rigid_resting = true;
};

// The wall's action on `rock` in state `state` at `time` (s). At first touch the contact's
// fine step is fixed from the normal approach speed: the contact duration over
// steps_per_contact, at most coarse_dt.
WallContactAt wall_contact_at(const shapes::OrientedBox& wall, const WallRock& rock,
                              const BodyState& state, double time, int steps_per_contact,
                              double coarse_dt);

// The wall contact of one rock over one rigid-body step, sub-stepped on the rock alone
// (gravity and the wall; the rock's other contacts act in the rigid-body step).
struct WallSubsteps {
    // Impulse of the wall on the rock over the step, N s, and its angular impulse about the
    // centre of mass, N m s: applied in the rigid-body step as a constant force and torque,
    // so the step's momentum change is exactly the load cell's impulse.
    Vec3 impulse = Vec3::Zero();
    Vec3 angular_impulse = Vec3::Zero();
    // Where the wall's force put the rock by the end of the step, minus where the rigid-body
    // step's constant force puts it (m), and the same for its orientation (rotation vector,
    // world frame, rad): the rigid-body step gets the velocities right, this the pose.
    Vec3 position_shift = Vec3::Zero();
    Vec3 rotation_shift = Vec3::Zero();
    // free or force: the step was sub-stepped to its end; resting or inside: the sub-steps
    // stopped there (the impulse until then is applied).
    WallContactAt::Kind end = WallContactAt::Kind::free;
    // Sub-steps taken.
    int substeps = 0;
};

// Sub-steps the wall contact of `rock` from `start` at `time` over a step of dt (s): the
// contact's fine step while it touches, shrinking approach steps before (approach_step), and
// records every sub-step's force in `cell`. `gravity` in m/s2.
WallSubsteps substep_wall(const shapes::OrientedBox& wall, const WallRock& rock,
                          const BodyState& start, double time, double dt, const Vec3& gravity,
                          int steps_per_contact, LoadCell& cell);

}  // namespace rockfall::engine
