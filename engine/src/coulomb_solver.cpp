#include "coulomb_solver.hpp"

#include <algorithm>
#include <cmath>

namespace rockfall::engine {
namespace {

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

}  // namespace

void CoulombSolver::convertContacts(btPersistentManifold** manifolds, int manifold_count,
                                    const btContactSolverInfo& info) {
    btSequentialImpulseConstraintSolver::convertContacts(manifolds, manifold_count, info);
    aim_restitution_at_touch(info);
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
    }
}

btScalar CoulombSolver::solveSingleIteration(int iteration, btCollisionObject** bodies,
                                             int body_count, btPersistentManifold** manifolds,
                                             int manifold_count, btTypedConstraint** constraints,
                                             int constraint_count, const btContactSolverInfo& info,
                                             btIDebugDraw* debug_drawer) {
    const btScalar residual = btSequentialImpulseConstraintSolver::solveSingleIteration(
        iteration, bodies, body_count, manifolds, manifold_count, constraints, constraint_count,
        info, debug_drawer);
    release_unloaded(m_tmpSolverContactFrictionConstraintPool);
    release_unloaded(m_tmpSolverContactRollingFrictionConstraintPool);
    bound_rolling_resistance();
    return residual;
}

void CoulombSolver::release_unloaded(btConstraintArray& rows) {
    for (int i = 0; i < rows.size(); ++i) {
        btSolverConstraint& row = rows[i];
        // m_frictionIndex of a friction row is the index of its point's normal row.
        const btScalar normal =
            m_tmpSolverContactConstraintPool[row.m_frictionIndex].m_appliedImpulse;
        if (normal <= 0.0 && row.m_appliedImpulse != 0.0) {
            // Solving the row with both limits at zero takes its whole impulse back.
            row.m_lowerLimit = 0.0;
            row.m_upperLimit = 0.0;
            resolveSingleConstraintRowGeneric(m_tmpSolverBodyPool[row.m_solverBodyIdA],
                                              m_tmpSolverBodyPool[row.m_solverBodyIdB], row);
        }
    }
}

void CoulombSolver::bound_rolling_resistance() {
    btConstraintArray& rows = m_tmpSolverContactRollingFrictionConstraintPool;
    for (int i = 0; i < rows.size(); ++i) {
        btSolverConstraint& row = rows[i];
        const btScalar normal =
            m_tmpSolverContactConstraintPool[row.m_frictionIndex].m_appliedImpulse;
        if (normal <= 0.0) {
            continue;
        }
        // The documented law: angular impulse up to mu_r r times the normal impulse
        // (m_friction is the length mu_r r), with no cap at m_friction itself.
        row.m_lowerLimit = -row.m_friction * normal;
        row.m_upperLimit = row.m_friction * normal;
        resolveSingleConstraintRowGeneric(m_tmpSolverBodyPool[row.m_solverBodyIdA],
                                          m_tmpSolverBodyPool[row.m_solverBodyIdB], row);
    }
}

}  // namespace rockfall::engine
