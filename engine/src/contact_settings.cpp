#include "contact_settings.hpp"

#include <BulletCollision/CollisionDispatch/btManifoldResult.h>

#include <algorithm>

namespace rockfall::engine {
namespace {

// Bullet's user index 2 of every body of ours ("RFRK"); bodies without it are not ours.
constexpr int kOwnBodyTag = 0x5246524b;

const ContactMaterial* material_of(const btCollisionObject* body) {
    if (body->getUserIndex2() != kOwnBodyTag) {
        return nullptr;
    }
    return static_cast<const ContactMaterial*>(body->getUserPointer());
}

bool both_ours(const btCollisionObject* a, const btCollisionObject* b) {
    return material_of(a) != nullptr && material_of(b) != nullptr;
}

// The project's rule (scenario.hpp, Material): a contact uses the arithmetic mean of the two
// materials' coefficients. Bullet's defaults (product, or products with friction for rolling)
// stay in force for bodies that are not ours.
btScalar mean_friction(const btCollisionObject* a, const btCollisionObject* b) {
    if (!both_ours(a, b)) {
        return btManifoldResult::calculateCombinedFriction(a, b);
    }
    return 0.5 * (a->getFriction() + b->getFriction());
}

btScalar mean_restitution(const btCollisionObject* a, const btCollisionObject* b) {
    if (!both_ours(a, b)) {
        return btManifoldResult::calculateCombinedRestitution(a, b);
    }
    return 0.5 * (a->getRestitution() + b->getRestitution());
}

// Bullet limits the angular impulse about each tangent axis to (this value) * (normal
// impulse), so the value is a length: the resisting torque is mu_r * r * N with r the rock's
// radius (rock on a static solid) or the smaller radius (rock on rock).
btScalar rolling_length(const btCollisionObject* a, const btCollisionObject* b) {
    const ContactMaterial* ma = material_of(a);
    const ContactMaterial* mb = material_of(b);
    const double lever = (ma->rolling_lever > 0.0 && mb->rolling_lever > 0.0)
                             ? std::min(ma->rolling_lever, mb->rolling_lever)
                             : std::max(ma->rolling_lever, mb->rolling_lever);
    return 0.5 * (ma->rolling_resistance + mb->rolling_resistance) * lever;
}

btScalar mean_rolling_friction(const btCollisionObject* a, const btCollisionObject* b) {
    if (!both_ours(a, b)) {
        return btManifoldResult::calculateCombinedRollingFriction(a, b);
    }
    return rolling_length(a, b);
}

// Spin about the contact normal meets the same resistance as rolling: one isotropic
// rolling-resistance torque, mu_r r N, whatever the axis of the relative rotation.
btScalar mean_spinning_friction(const btCollisionObject* a, const btCollisionObject* b) {
    if (!both_ours(a, b)) {
        return btManifoldResult::calculateCombinedSpinningFriction(a, b);
    }
    return rolling_length(a, b);
}

}  // namespace

void attach_material(btCollisionObject& body, const Material& coefficients,
                     ContactMaterial& material) {
    material.rolling_resistance = coefficients.rolling_resistance;
    body.setFriction(coefficients.friction);
    body.setRestitution(coefficients.restitution);
    body.setRollingFriction(coefficients.rolling_resistance);
    body.setSpinningFriction(coefficients.rolling_resistance);
    body.setUserPointer(&material);
    body.setUserIndex2(kOwnBodyTag);
    // Only touching or penetrating points reach the solver: a speculative point (positive
    // distance) would get the restitution target while still apart and lose the bounce.
    body.setContactProcessingThreshold(0.0);
}

void install_material_combiners() {
    static const bool installed = [] {
        gCalculateCombinedFrictionCallback = &mean_friction;
        gCalculateCombinedRestitutionCallback = &mean_restitution;
        gCalculateCombinedRollingFrictionCallback = &mean_rolling_friction;
        gCalculateCombinedSpinningFrictionCallback = &mean_spinning_friction;
        return true;
    }();
    (void)installed;
}

void configure_solver(btContactSolverInfo& info, const Numerics& numerics) {
    info.m_numIterations = numerics.solver_iterations;
    // Split impulse: penetration is removed by a separate position-only impulse, so position
    // correction never adds kinetic energy. Bullet splits a contact only when its signed
    // distance is below this threshold (default -0.04 m) and corrects shallower ones through the
    // velocity (Baumgarte), which raised a drop test's e = 0.3 to 0.49 at 1 ms; +infinity
    // splits every contact.
    info.m_splitImpulse = 1;
    info.m_splitImpulsePenetrationThreshold = BT_LARGE_FLOAT;
    // Share of the penetration the split impulse removes per step.
    info.m_erp2 = 0.8;
    // Bounces below this normal speed are dropped (m/s).
    info.m_restitutionVelocityThreshold = numerics.restitution_threshold;
    // Two friction directions per contact: with one, a rolling contact (zero slip, so no
    // velocity to align with) gets an arbitrary direction and slips along the other.
    info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
    // Stop iterating once an iteration changes no velocity by more than 1e-4 m/s (the residual
    // is squared): a single rock's contacts converge in a few iterations.
    info.m_leastSquaresResidualThreshold = 1e-8;
    // Full warm starting: each contact row starts from last step's impulse, not 85 % of it
    // (Bullet's default; Box2D starts from all of it). In a pile at rest the iterations then
    // only correct what changed: with 0.85 they had to rebuild 15 % of every load each step,
    // and the rocks of a 300-cube pile kept moving at a median 4.5 mm/s instead of 1 mm/s.
    info.m_warmstartingFactor = 1.0;
}

}  // namespace rockfall::engine
