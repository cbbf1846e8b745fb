#pragma once
// Bullet's sequential-impulse solver with Coulomb's bound kept for every contact point.
// Private to the engine.

#include <btBulletDynamicsCommon.h>

#include <vector>

namespace rockfall::engine {

// Bullet re-bounds a friction row by mu times its point's normal impulse only while that
// impulse is positive; when a point's normal impulse falls to zero in a later iteration (the
// load moves to other points of a face), its friction impulse stays and acts without any
// normal force. A block sliding on a 30 degree incline then accelerated 4 % (mu = 0.3) to 16 %
// (mu = 0.5) below g (sin t - mu cos t). This solver's friction and rolling resistance are
// the patch's below, bounded by the patch's whole normal impulse.
//
// Bullet also caps each rolling-friction row at its coefficient (a length, mu_r r) times one
// unit of impulse, whatever the normal impulse: at an impact, where the normal impulse is
// tens of N s in one step, the rolling resistance all but vanished (a 0.2 m sphere kept 99.8 %
// of its spin through a landing that the law mu_r r N slows by 7 rad/s). This solver drops
// Bullet's rolling rows (three per point) and solves its own per patch, after Bullet's pass
// over the normal rows, with the law's bound mu_r r times the patch's normal impulse (zero
// without one): one row about each tangent (a rolling row has no lever arm, so the points'
// rows about one axis are one constraint), and the spin's bound added to the patch's twist.
//
// Bullet bounds each point's friction by that point's normal impulse, and the iterative
// solver spreads a face's normal impulse over its points arbitrarily (one corner one step,
// another the next): per-point friction then has a moment about the normal that no symmetric
// slide has, and a block sliding straight down a 30 degree incline turned 29 degrees in 2.4 s
// (mu = 0.3). This solver replaces the points' friction rows by one Coulomb force and one
// twisting torque per manifold (friction_patch.hpp), bounded by the manifold's whole normal
// impulse, with the force in Coulomb's cone (sqrt(f1^2 + f2^2) <= mu N), and reports the
// patch's impulse back on the points in proportion to their normal impulses.
//
// Restitution: Bullet aims a bouncing point's rebound at e times its approach speed at the
// start of the step, when the point is already below the surface; it crossed the surface up
// to a step earlier at a lower speed (gravity has since added up to g dt). This solver aims at
// e times the speed at first touch instead, and drops the bounce when that speed is below the
// restitution threshold.
//
// Slop: Bullet's split impulse removes 80 % of every penetration per step, so a resting
// contact is pushed to within round-off of the surface, found apart the next step (and left
// out of the solver: no normal force, no friction), and lands again the step after. A pile's
// rocks lost their support and friction one step in two, jittered at about g dt and crept.
// This solver corrects only the penetration beyond `slop` (Box2D's linear slop); the velocity
// rows, and so the bounces, are Bullet's.
//
// Speculative margin: a resting rock that tilts by a few milliradians lifts a corner of its
// contact by more than the slop, and a point at a positive distance was left out of the
// solver (processing threshold 0, for the bounces: attach_material), with its share of the
// load. In a 500-cube fill such points held 9.5 % of the normal impulse each step, and its
// rocks kept falling at about 7 g dt without coming to rest. Points within the slop of
// touching are now solved as speculative contacts (Box2D's speculative distance, Bullet's
// default for all points): they may close their gap in this step, no more. One that approaches
// faster than the restitution threshold bounces at once (at most a slop early) at e times its
// approach speed.
class CoulombSolver : public btSequentialImpulseConstraintSolver {
  public:
    // The slop per squared second of the step, m/s^2: the slop of a step dt is this times
    // dt^2 (numerics.contact_slop times g).
    void set_slop_rate(double rate) { slop_rate_ = rate; }

  protected:
    void convertContacts(btPersistentManifold** manifolds, int manifold_count,
                         const btContactSolverInfo& info) override;
    btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int body_count,
                                  btPersistentManifold** manifolds, int manifold_count,
                                  btTypedConstraint** constraints, int constraint_count,
                                  const btContactSolverInfo& info,
                                  btIDebugDraw* debug_drawer) override;

    btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int body_count,
                                           const btContactSolverInfo& info) override;

  private:
    // One face's friction: rows `rows` of the contact pool, points of one manifold.
    struct Patch {
        int rows[MANIFOLD_CACHE_SIZE] = {};
        int row_count = 0;
        btVector3 directions[2];
        btSolverConstraint slide[2];
        btSolverConstraint twist;
        double mu = 0.0;
        double twist_radius = 0.0;  // m
        double spin_length = 0.0;   // the rolling resistance's about the normal, mu_r r, m
        double normal = 0.0;        // its points' normal impulse after the last pass over them
    };

    void disable_point_friction();
    void build_patches(btPersistentManifold** manifolds, int manifold_count,
                       const btContactSolverInfo& info);
    void add_patch(btPersistentManifold& manifold, const int* rows, int row_count,
                   const btContactSolverInfo& info);
    btScalar solve_patches();
    double impulse_to_stop(const btSolverConstraint& row) const;
    void report_patches();
    btScalar bound_rolling_resistance();
    void aim_restitution_at_touch(const btContactSolverInfo& info);
    void leave_slop(const btContactSolverInfo& info);
    void solve_within_slop(btPersistentManifold** manifolds, int manifold_count,
                           const btContactSolverInfo& info) const;
    double slop(const btContactSolverInfo& info) const;

    // A rolling-resistance row in the few fields its solve reads: angular only (zero linear
    // parts), set up by Bullet's setupTorsionalFrictionConstraint and solved with solve_row's
    // operations without the zero linear terms (a pile's iterations spent more time reading
    // full rows than solving them: docs/heap_cost.md).
    struct RollingRow {
        btVector3 axis_a;     // m_relpos1CrossNormal
        btVector3 axis_b;     // m_relpos2CrossNormal
        btVector3 angular_a;  // m_angularComponentA
        btVector3 angular_b;  // m_angularComponentB
        btScalar rhs = 0.0;
        btScalar cfm = 0.0;
        btScalar jac_inv = 0.0;  // m_jacDiagABInv
        btScalar applied = 0.0;  // m_appliedImpulse
        btScalar length = 0.0;   // m_friction: mu_r r, m
    };
    // A patch's two rolling rows, about the tangents of its normal, both bounded by mu_r r
    // times the patch's whole normal impulse.
    struct RollingPatch {
        RollingRow rows[2];
        int body_a = 0;
        int body_b = 0;
        int patch = 0;  // its index in patches_
    };

    void add_rolling_rows(const Patch& patch, const btVector3& normal, btManifoldPoint& point,
                          btCollisionObject* body0, btCollisionObject* body1);
    // Each patch's normal: the sum of its points' positive normal impulses.
    void update_patch_normals();

    double slop_rate_ = 0.0;  // m/s^2
    std::vector<Patch> patches_;
    std::vector<RollingPatch> rolling_;
    // Bullet's point-friction rows of the current group, hidden from its iterations.
    int point_friction_rows_ = 0;
};

}  // namespace rockfall::engine
