#include "coulomb_solver.hpp"

#include "contact_settings.hpp"
#include "friction_patch.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rockfall::engine {
namespace {

// Contact points whose normals agree within this angle (its cosine: 5 degrees) are one patch.
const double kPatchCosine = std::cos(5.0 * std::numbers::pi / 180.0);

const btVector3& normal_of(const btSolverConstraint& row) {
    return static_cast<const btManifoldPoint*>(row.m_originalContactPoint)->m_normalWorldOnB;
}

// Normal relative velocity of a row's two bodies (negative when approaching), m/s, without and
// with the external impulses (gravity, applied forces) of the coming step.
double normal_velocity(const btSolverConstraint& row, const btSolverBody& a, const btSolverBody& b,
                       bool external) {
    double v = row.m_contactNormal1.dot(a.m_linearVelocity) +
               row.m_relpos1CrossNormal.dot(a.m_angularVelocity) +
               row.m_contactNormal2.dot(b.m_linearVelocity) +
               row.m_relpos2CrossNormal.dot(b.m_angularVelocity);
    if (external) {
        if (a.m_originalBody) {
            v += row.m_contactNormal1.dot(a.m_externalForceImpulse) +
                 row.m_relpos1CrossNormal.dot(a.m_externalTorqueImpulse);
        }
        if (b.m_originalBody) {
            v += row.m_contactNormal2.dot(b.m_externalForceImpulse) +
                 row.m_relpos2CrossNormal.dot(b.m_externalTorqueImpulse);
        }
    }
    return v;
}

// Adds `delta` to a row's accumulated impulse `applied`, projected onto [lower, upper]; returns
// the change made (Bullet's projection, in its order of operations).
inline btScalar clamp_impulse(btScalar& applied, btScalar delta, btScalar lower, btScalar upper) {
    const btScalar sum = applied + delta;
    if (sum < lower) {
        delta = lower - applied;
        applied = lower;
    } else if (sum > upper) {
        delta = upper - applied;
        applied = upper;
    } else {
        applied = sum;
    }
    return delta;
}

// The bodies' shares of a change `delta` of a row's impulse.
inline void apply_impulse(btSolverBody& a, btSolverBody& b, const btSolverConstraint& row,
                          btScalar delta) {
    a.internalApplyImpulse(row.m_contactNormal1 * a.internalGetInvMass(), row.m_angularComponentA,
                           delta);
    b.internalApplyImpulse(row.m_contactNormal2 * b.internalGetInvMass(), row.m_angularComponentB,
                           delta);
}

// One projected Gauss-Seidel update of a row between its limits, as Bullet's scalar row solver
// makes it (the same operations in the same order, so the results stay bit for bit those of
// calling it), but inlined: the engine's own rows (patch friction, twist, rolling resistance)
// are most of a pile's row updates, and a call into Bullet's library for each cost 7 % of a
// heap's time. Returns the change of the row's velocity (m/s or rad/s), as Bullet's does.
inline btScalar solve_row(btSolverBody& a, btSolverBody& b, btSolverConstraint& row) {
    btScalar delta = row.m_rhs - btScalar(row.m_appliedImpulse) * row.m_cfm;
    const btScalar velocity_a = row.m_contactNormal1.dot(a.internalGetDeltaLinearVelocity()) +
                                row.m_relpos1CrossNormal.dot(a.internalGetDeltaAngularVelocity());
    const btScalar velocity_b = row.m_contactNormal2.dot(b.internalGetDeltaLinearVelocity()) +
                                row.m_relpos2CrossNormal.dot(b.internalGetDeltaAngularVelocity());
    delta -= velocity_a * row.m_jacDiagABInv;
    delta -= velocity_b * row.m_jacDiagABInv;
    delta = clamp_impulse(row.m_appliedImpulse, delta, row.m_lowerLimit, row.m_upperLimit);
    apply_impulse(a, b, row, delta);
    return delta * (btScalar(1.) / row.m_jacDiagABInv);
}

// Sets a row's impulse to `target`: what solve_row does with both limits at the target, whose
// projection discards the row's velocity (except where the unprojected sum equals the target to
// the last bit: solve_row then keeps its own rounding of the change, an ulp from this one's).
// Returns solve_row's change.
inline btScalar set_impulse(btSolverBody& a, btSolverBody& b, btSolverConstraint& row,
                            btScalar target) {
    const btScalar delta = target - row.m_appliedImpulse;
    row.m_appliedImpulse = target;
    apply_impulse(a, b, row, delta);
    return delta * (btScalar(1.) / row.m_jacDiagABInv);
}

// The body's share of an angular-only row's impulse, as internalApplyImpulse adds it (its
// linear share is zero).
inline void apply_angular(btSolverBody& body, const btVector3& angular, btScalar delta) {
    if (body.m_originalBody)
        body.m_deltaAngularVelocity += angular * (delta * body.m_angularFactor);
}

}  // namespace

void CoulombSolver::convertContacts(btPersistentManifold** manifolds, int manifold_count,
                                    const btContactSolverInfo& info) {
    solve_within_slop(manifolds, manifold_count, info);
    btSequentialImpulseConstraintSolver::convertContacts(manifolds, manifold_count, info);
    disable_point_friction();
    build_patches(manifolds, manifold_count, info);
    aim_restitution_at_touch(info);
    leave_slop(info);
    // The disabled point-friction rows would cost Bullet's iterations two row solves per point
    // for nothing (both limits zero, no impulse): hidden from them by the pool's size, kept in
    // memory for the points' write-back (report_patches). Bullet's setup sizes its friction
    // order from the pool after this, so the iterations see no friction row.
    point_friction_rows_ = m_tmpSolverContactFrictionConstraintPool.size();
    m_tmpSolverContactFrictionConstraintPool.resizeNoInitialize(0);
    // Bullet's rolling-resistance rows (three per point, bounded by min(mu_r r N, mu_r r)) are
    // replaced by the patches' (add_rolling_rows); its finish reads nothing back from them.
    m_tmpSolverContactRollingFrictionConstraintPool.resizeNoInitialize(0);
}

void CoulombSolver::aim_restitution_at_touch(const btContactSolverInfo& info) {
    const double threshold = info.m_restitutionVelocityThreshold;
    const double dt = info.m_timeStep;
    for (int i = 0; i < m_tmpSolverContactConstraintPool.size(); ++i) {
        btSolverConstraint& row = m_tmpSolverContactConstraintPool[i];
        const auto* point = static_cast<const btManifoldPoint*>(row.m_originalContactPoint);
        const btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
        const btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
        const double approach = -normal_velocity(row, a, b, false);
        const double e = point->m_combinedRestitution;
        // Bullet's target (restitutionCurve): e times the approach speed at or above the
        // threshold.
        const double bullet_target = approach >= threshold && e > 0.0 ? e * approach : 0.0;
        if (approach <= 0.0) {
            continue;
        }
        // Gain of approach speed per step from the external impulses, and the time since the
        // point crossed the surface at constant speed (at most one step).
        const double gain = normal_velocity(row, a, b, true) - normal_velocity(row, a, b, false);
        const double depth = std::max(0.0, -static_cast<double>(point->getDistance()));
        const double since_touch = std::min(dt, depth / approach);
        const double touch_speed = approach + gain * since_touch / dt;
        const double target = touch_speed >= threshold ? e * touch_speed : 0.0;
        row.m_rhs += (target - bullet_target) * row.m_jacDiagABInv;
        // Bullet lets a speculative point (apart by `gap`) close the gap in this step, which
        // would take gap / dt off the bounce: it bounces now instead.
        const double gap = point->getDistance() + info.m_linearSlop;
        if (target > 0.0 && gap > 0.0) row.m_rhs += gap / dt * row.m_jacDiagABInv;
    }
}

double CoulombSolver::slop(const btContactSolverInfo& info) const {
    return slop_rate_ * info.m_timeStep * info.m_timeStep;
}

void CoulombSolver::solve_within_slop(btPersistentManifold** manifolds, int manifold_count,
                                      const btContactSolverInfo& info) const {
    const double margin = slop(info);
    if (margin <= 0.0) return;
    for (int i = 0; i < manifold_count; ++i) {
        btPersistentManifold& manifold = *manifolds[i];
        // Set from the bodies every step: the slop changes with the step (wall sub-steps).
        const double bodies = std::min(manifold.getBody0()->getContactProcessingThreshold(),
                                       manifold.getBody1()->getContactProcessingThreshold());
        manifold.setContactProcessingThreshold(std::max({bodies, margin, kTouchRoundOff}));
    }
}

void CoulombSolver::leave_slop(const btContactSolverInfo& info) {
    const double depth = slop(info);
    if (depth <= 0.0) return;
    for (int i = 0; i < m_tmpSolverContactConstraintPool.size(); ++i) {
        btSolverConstraint& row = m_tmpSolverContactConstraintPool[i];
        // Split impulse at every depth: the position row's target is proportional to the
        // penetration -d (zero for a point at or above the surface); it now corrects -d - slop.
        const double d =
            static_cast<const btManifoldPoint*>(row.m_originalContactPoint)->getDistance();
        row.m_rhsPenetration = d < -depth ? row.m_rhsPenetration * (d + depth) / d : 0.0;
    }
}

btScalar CoulombSolver::solveSingleIteration(int iteration, btCollisionObject** bodies,
                                             int body_count, btPersistentManifold** manifolds,
                                             int manifold_count, btTypedConstraint** constraints,
                                             int constraint_count, const btContactSolverInfo& info,
                                             btIDebugDraw* debug_drawer) {
    if (iteration == 0) update_patch_normals();
    const btScalar friction = iteration < info.m_numIterations ? solve_patches() : 0.0;
    const btScalar residual = btSequentialImpulseConstraintSolver::solveSingleIteration(
        iteration, bodies, body_count, manifolds, manifold_count, constraints, constraint_count,
        info, debug_drawer);
    // Nothing changes the normal impulses between here and the next iteration's friction.
    update_patch_normals();
    const btScalar rolling = bound_rolling_resistance();
    return std::max({residual, friction, rolling});
}

btScalar CoulombSolver::bound_rolling_resistance() {
    btScalar residual = 0.0;
    for (RollingPatch& rolling : rolling_) {
        const double normal = patches_[static_cast<std::size_t>(rolling.patch)].normal;
        btSolverBody& a = m_tmpSolverBodyPool[rolling.body_a];
        btSolverBody& b = m_tmpSolverBodyPool[rolling.body_b];
        for (RollingRow& row : rolling.rows) {
            if (normal <= 0.0 && row.applied == 0.0) {
                continue;
            }
            // The documented law: angular impulse up to mu_r r times the normal impulse, with
            // no cap at mu_r r itself; a patch without normal impulse has both limits at zero,
            // and solving the row takes its impulse back. solve_row's operations on an
            // angular-only row.
            const btScalar bound = row.length * normal;
            btScalar delta = row.rhs - row.applied * row.cfm;
            delta -= row.axis_a.dot(a.m_deltaAngularVelocity) * row.jac_inv;
            delta -= row.axis_b.dot(b.m_deltaAngularVelocity) * row.jac_inv;
            delta = clamp_impulse(row.applied, delta, -bound, bound);
            apply_angular(a, row.angular_a, delta);
            apply_angular(b, row.angular_b, delta);
            // Counted in the iteration's residual, as Bullet counts its own pass over these
            // rows (the iterations stop early once no row changes a velocity by more than
            // 1e-4 m/s).
            const btScalar change = delta * (btScalar(1.) / row.jac_inv);
            residual = std::max(residual, change * change);
        }
    }
    return residual;
}

void CoulombSolver::disable_point_friction() {
    btConstraintArray& rows = m_tmpSolverContactFrictionConstraintPool;
    for (int i = 0; i < rows.size(); ++i) {
        btSolverConstraint& row = rows[i];
        // Takes back Bullet's warm start; with no friction Bullet's iterations keep it at zero.
        row.m_friction = 0.0;
        row.m_lowerLimit = 0.0;
        row.m_upperLimit = 0.0;
        if (row.m_appliedImpulse != 0.0) {
            solve_row(m_tmpSolverBodyPool[row.m_solverBodyIdA],
                      m_tmpSolverBodyPool[row.m_solverBodyIdB], row);
        }
    }
}

void CoulombSolver::build_patches(btPersistentManifold** manifolds, int manifold_count,
                                  const btContactSolverInfo& info) {
    patches_.clear();
    rolling_.clear();
    // Bullet adds the normal rows manifold by manifold, each point that is close enough.
    const int row_total = m_tmpSolverContactConstraintPool.size();
    int row = 0;
    for (int m = 0; m < manifold_count && row < row_total; ++m) {
        btPersistentManifold& manifold = *manifolds[m];
        const int first = row;
        for (int j = 0; j < manifold.getNumContacts() && row < row_total; ++j) {
            if (m_tmpSolverContactConstraintPool[row].m_originalContactPoint ==
                &manifold.getContactPoint(j)) {
                ++row;
            }
        }
        // Rows whose normals agree within kPatchAngle are one face's: a rock resting on two
        // spheres of a lining has two patches.
        bool grouped[MANIFOLD_CACHE_SIZE] = {};
        for (int i = first; i < row; ++i) {
            if (grouped[i - first]) {
                continue;
            }
            const btVector3& normal = normal_of(m_tmpSolverContactConstraintPool[i]);
            int rows[MANIFOLD_CACHE_SIZE];
            int count = 0;
            for (int j = i; j < row && count < MANIFOLD_CACHE_SIZE; ++j) {
                if (!grouped[j - first] &&
                    normal_of(m_tmpSolverContactConstraintPool[j]).dot(normal) >= kPatchCosine) {
                    grouped[j - first] = true;
                    rows[count++] = j;
                }
            }
            add_patch(manifold, rows, count, info);
        }
    }
}

void CoulombSolver::add_patch(btPersistentManifold& manifold, const int* rows, int row_count,
                              const btContactSolverInfo& info) {
    btVector3 points[MANIFOLD_CACHE_SIZE];
    btVector3 normal(0, 0, 0);
    const int count = row_count;
    for (int k = 0; k < count; ++k) {
        const auto* point = static_cast<const btManifoldPoint*>(
            m_tmpSolverContactConstraintPool[rows[k]].m_originalContactPoint);
        points[k] = 0.5 * (point->getPositionWorldOnA() + point->getPositionWorldOnB());
        normal += point->m_normalWorldOnB;
    }
    if (normal.length2() < SIMD_EPSILON) {
        return;
    }
    normal.normalize();
    const btSolverConstraint& head = m_tmpSolverContactConstraintPool[rows[0]];
    const int id_a = head.m_solverBodyIdA;
    const int id_b = head.m_solverBodyIdB;
    const btRigidBody* moving_a = m_tmpSolverBodyPool[id_a].m_originalBody;
    const btRigidBody* moving_b = m_tmpSolverBodyPool[id_b].m_originalBody;
    btVector3 centre;
    const btVector3* projected = nullptr;
    if ((moving_a != nullptr) != (moving_b != nullptr)) {
        centre = (moving_a != nullptr ? moving_a : moving_b)->getCenterOfMassPosition();
        projected = &centre;
    }
    const PatchGeometry geometry = patch_geometry(points, count, normal, projected);

    auto* body0 = const_cast<btCollisionObject*>(manifold.getBody0());
    auto* body1 = const_cast<btCollisionObject*>(manifold.getBody1());
    const btVector3 rel_pos1 = geometry.anchor - body0->getWorldTransform().getOrigin();
    const btVector3 rel_pos2 = geometry.anchor - body1->getWorldTransform().getOrigin();
    const auto velocity = [](const btRigidBody* body, const btVector3& rel_pos) {
        return body != nullptr ? body->getVelocityInLocalPoint(rel_pos) : btVector3(0, 0, 0);
    };
    const btVector3 slip = velocity(moving_a, rel_pos1) - velocity(moving_b, rel_pos2);
    const btVector3 tangential = slip - normal * normal.dot(slip);

    Patch patch;
    std::copy(rows, rows + row_count, patch.rows);
    patch.row_count = row_count;
    // The first direction along the slip, as Bullet's rows: the cone bound then rarely binds
    // the second.
    if (tangential.length2() > SIMD_EPSILON) {
        patch.directions[0] = tangential.normalized();
        patch.directions[1] = patch.directions[0].cross(normal).normalized();
    } else {
        btPlaneSpace1(normal, patch.directions[0], patch.directions[1]);
    }
    auto& point = *static_cast<btManifoldPoint*>(head.m_originalContactPoint);
    for (int k = 0; k < 2; ++k) {
        setupFrictionConstraint(patch.slide[k], patch.directions[k], id_a, id_b, point, rel_pos1,
                                rel_pos2, body0, body1, info.m_sor, info);
    }
    patch.mu = point.m_combinedFriction;
    patch.twist_radius = geometry.twist_radius;
    // Bullet's condition for its rolling rows, spin included.
    if (point.m_combinedRollingFriction > 0.0) {
        patch.spin_length = point.m_combinedSpinningFriction;
        add_rolling_rows(patch, normal, point, body0, body1);
    }
    if (patch.twist_radius > 0.0 || patch.spin_length > 0.0) {
        setupTorsionalFrictionConstraint(patch.twist, normal, id_a, id_b, point, 0.0, rel_pos1,
                                         rel_pos2, body0, body1, info.m_sor);
    }
    patches_.push_back(patch);
}

void CoulombSolver::add_rolling_rows(const Patch& patch, const btVector3& normal,
                                     btManifoldPoint& point, btCollisionObject* body0,
                                     btCollisionObject* body1) {
    // The rows of all the patch's points about one axis are one constraint (a rolling row has
    // no lever arm), bounded by the sum of their bounds: one row per axis.
    const int id_a = patch.slide[0].m_solverBodyIdA;
    const int id_b = patch.slide[0].m_solverBodyIdB;
    btVector3 axes[2];
    btPlaneSpace1(normal, axes[0], axes[1]);
    RollingPatch& rolling = rolling_.emplace_back();
    rolling.body_a = id_a;
    rolling.body_b = id_b;
    rolling.patch = static_cast<int>(patches_.size());
    const btVector3 unused(0, 0, 0);  // an angular row reads neither lever arm nor relaxation
    for (int k = 0; k < 2; ++k) {
        btSolverConstraint row;
        setupTorsionalFrictionConstraint(row, axes[k].normalized(), id_a, id_b, point,
                                         point.m_combinedRollingFriction, unused, unused, body0,
                                         body1, 1.0);
        RollingRow& copy = rolling.rows[k];
        copy.axis_a = row.m_relpos1CrossNormal;
        copy.axis_b = row.m_relpos2CrossNormal;
        copy.angular_a = row.m_angularComponentA;
        copy.angular_b = row.m_angularComponentB;
        copy.rhs = row.m_rhs;
        copy.cfm = row.m_cfm;
        copy.jac_inv = row.m_jacDiagABInv;
        copy.length = row.m_friction;
    }
}

void CoulombSolver::update_patch_normals() {
    for (Patch& patch : patches_) {
        patch.normal = 0.0;
        for (int k = 0; k < patch.row_count; ++k) {
            patch.normal += std::max<btScalar>(
                0.0, m_tmpSolverContactConstraintPool[patch.rows[k]].m_appliedImpulse);
        }
    }
}

btScalar CoulombSolver::solve_patches() {
    btScalar residual = 0.0;
    for (Patch& patch : patches_) {
        const double bound = patch.mu * patch.normal;
        // The impulse that stops the slip, both directions from the same velocities, projected
        // onto Coulomb's disc: the friction then opposes the slip. Solving the rows one after
        // the other let the second hold the slip's direction (a block sliding 5 degrees off
        // the fall line kept that heading instead of turning downhill).
        double target[2];
        for (int k = 0; k < 2; ++k) {
            target[k] = patch.slide[k].m_appliedImpulse + impulse_to_stop(patch.slide[k]);
        }
        const double magnitude = std::sqrt(target[0] * target[0] + target[1] * target[1]);
        const double scale = magnitude > bound ? bound / magnitude : 1.0;
        for (int k = 0; k < 2; ++k) {
            btSolverConstraint& row = patch.slide[k];
            const btScalar change =
                set_impulse(m_tmpSolverBodyPool[row.m_solverBodyIdA],
                            m_tmpSolverBodyPool[row.m_solverBodyIdB], row, scale * target[k]);
            residual = std::max(residual, change * change);
        }
        if (patch.twist_radius > 0.0 || patch.spin_length > 0.0) {
            // Coulomb's twist and the rolling resistance's spin, one constraint about the
            // normal.
            btSolverConstraint& row = patch.twist;
            const double twist = patch.normal * (patch.mu * patch.twist_radius + patch.spin_length);
            row.m_lowerLimit = -twist;
            row.m_upperLimit = twist;
            const btScalar change = solve_row(m_tmpSolverBodyPool[row.m_solverBodyIdA],
                                              m_tmpSolverBodyPool[row.m_solverBodyIdB], row);
            residual = std::max(residual, change * change);
        }
    }
    return residual;
}

double CoulombSolver::impulse_to_stop(const btSolverConstraint& row) const {
    // Bullet's resolveSingleConstraintRowGeneric before it clamps and applies.
    const btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    const btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    const btScalar velocity = row.m_contactNormal1.dot(a.m_deltaLinearVelocity) +
                              row.m_relpos1CrossNormal.dot(a.m_deltaAngularVelocity) +
                              row.m_contactNormal2.dot(b.m_deltaLinearVelocity) +
                              row.m_relpos2CrossNormal.dot(b.m_deltaAngularVelocity);
    return row.m_rhs - row.m_appliedImpulse * row.m_cfm - velocity * row.m_jacDiagABInv;
}

btScalar CoulombSolver::solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int body_count,
                                                      const btContactSolverInfo& info) {
    m_tmpSolverContactFrictionConstraintPool.resizeNoInitialize(point_friction_rows_);
    report_patches();
    return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyFinish(bodies, body_count,
                                                                              info);
}

void CoulombSolver::report_patches() {
    // Bullet's finish copies each point's friction rows into the point (m_appliedImpulseLateral1
    // and 2, along its m_lateralFrictionDir1 and 2), where the wall's load cell reads them.
    for (const Patch& patch : patches_) {
        const btVector3 impulse = patch.directions[0] * patch.slide[0].m_appliedImpulse +
                                  patch.directions[1] * patch.slide[1].m_appliedImpulse;
        // The normal impulses as the last iteration left them (solveSingleIteration).
        const double normal = patch.normal;
        for (int k = 0; k < patch.row_count; ++k) {
            const btSolverConstraint& row = m_tmpSolverContactConstraintPool[patch.rows[k]];
            const auto* point = static_cast<const btManifoldPoint*>(row.m_originalContactPoint);
            const double share = normal > 0.0
                                     ? std::max<btScalar>(0.0, row.m_appliedImpulse) / normal
                                     : 1.0 / patch.row_count;
            btSolverConstraint* lateral =
                &m_tmpSolverContactFrictionConstraintPool[row.m_frictionIndex];
            lateral[0].m_appliedImpulse = share * impulse.dot(point->m_lateralFrictionDir1);
            lateral[1].m_appliedImpulse = share * impulse.dot(point->m_lateralFrictionDir2);
        }
    }
    patches_.clear();
    rolling_.clear();
}

}  // namespace rockfall::engine
