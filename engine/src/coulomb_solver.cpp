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

}  // namespace rockfall::engine
