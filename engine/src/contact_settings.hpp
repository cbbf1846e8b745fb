#pragma once
// Bullet's contact and solver settings for rockfall, and the material combination rule.
// Private to the engine: included only by files that compile against Bullet.

#include "engine/scenario.hpp"

#include <btBulletDynamicsCommon.h>

namespace rockfall::engine {

// What the material combiners read from a body of ours (Bullet user pointer). Bodies without
// it (a bare Bullet loop in the same process) keep Bullet's own combination rules.
struct ContactMaterial {
    // Dimensionless rolling resistance of the body's material.
    double rolling_resistance = 0.0;
    // Lever arm turning rolling resistance into Bullet's rolling friction (a length), m: the
    // rock's radius (half its nominal size); 0 for static solids.
    double rolling_lever = 0.0;
};

// Marks a body as ours and sets its per-body coefficients; `material` must outlive the body.
void attach_material(btCollisionObject& body, const Material& coefficients,
                     ContactMaterial& material);

// Installs the arithmetic-mean combination rule in Bullet's global callbacks; idempotent and
// thread-safe (a function-local static), called by every World before its first step.
void install_material_combiners();

// Solver settings that make the configured restitution independent of the time step (see
// docs/contact_model.md).
void configure_solver(btContactSolverInfo& info, const Numerics& numerics);

// A touching point's distance is zero to within this, m: a manifold's processing threshold
// (the distance up to which a point is solved; attach_material gives bodies 0) is at least
// this much wherever it is raised (face contacts, the speculative margin).
inline constexpr double kTouchRoundOff = 1e-9;

// Collision margin of rock hulls and static boxes, m: Bullet's default 0.04 m would round
// every edge of a 0.2 m rock by 4 cm (boxes) or inflate hulls by 4 cm.
inline constexpr double kCollisionMargin = 0.001;

}  // namespace rockfall::engine
