#pragma once
// Bullet's sequential-impulse solver with Coulomb's bound kept for every contact point.
// Private to the engine.

#include <btBulletDynamicsCommon.h>

namespace rockfall::engine {

// Bullet re-bounds a friction row by mu times its point's normal impulse only while that
// impulse is positive; when a point's normal impulse falls to zero in a later iteration (the
// load moves to other points of a face), its friction impulse stays and acts without any
// normal force. A block sliding on a 30 degree incline then accelerated 4 % (mu = 0.3) to 16 %
// (mu = 0.5) below g (sin t - mu cos t). After each iteration this solver removes the friction
// and rolling-friction impulses of points that carry no normal impulse.
//
// Bullet also caps each rolling-friction row at its coefficient (a length, mu_r r) times one
// unit of impulse, whatever the normal impulse: at an impact, where the normal impulse is
// tens of N s in one step, the rolling resistance all but vanished (a 0.2 m sphere kept 99.8 %
// of its spin through a landing that the law mu_r r N slows by 7 rad/s). After Bullet's pass
// this solver solves each rolling row again with the law's bound mu_r r times its point's
// normal impulse.
//
// Restitution: Bullet aims a bouncing point's rebound at e times its approach speed at the
// start of the step, when the point is already below the surface; it crossed the surface up
// to a step earlier at a lower speed (gravity has since added up to g dt). This solver aims at
// e times the speed at first touch instead, and drops the bounce when that speed is below the
// restitution threshold.
class CoulombSolver : public btSequentialImpulseConstraintSolver {
  protected:
    void convertContacts(btPersistentManifold** manifolds, int manifold_count,
                         const btContactSolverInfo& info) override;
    btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int body_count,
                                  btPersistentManifold** manifolds, int manifold_count,
                                  btTypedConstraint** constraints, int constraint_count,
                                  const btContactSolverInfo& info,
                                  btIDebugDraw* debug_drawer) override;

  private:
    void release_unloaded(btConstraintArray& rows);
    void bound_rolling_resistance();
    void aim_restitution_at_touch(const btContactSolverInfo& info);
};

}  // namespace rockfall::engine
