#include "coulomb_solver.hpp"

namespace rockfall::engine {

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
