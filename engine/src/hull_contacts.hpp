#pragma once
// Narrow phase for rock hulls against boxes and other hulls, and for spheres against boxes.
// Private to the engine.
//
// Bullet's GJK finds one contact point per step and its persistent manifold collects more over
// the following steps. At an impact that is too late: a block landing on a face is hit at one
// corner first and loses the bounce to rotation (measured: e = 0.5 came out as 0.42 at 1 ms and
// 0.39 at 0.5 ms). Bullet can perturb the pair to find the whole face at once, but doing so in
// every step with fewer than three points (also for pairs that are apart) doubles the cost of
// a tumbling rock. This algorithm runs plain GJK every step and perturbs only in the step where
// a contact appears in an empty manifold.
//
// Separation caching (temporal coherence, as Bullet's btConvexSeparatingDistanceUtil): most
// pairs the broadphase reports in a pile are apart (a 500-cube heap: about two in three), yet
// each paid a GJK query per step. A pair found apart has its gap measured by GJK (the distance
// beyond the contact breaking threshold) and the relative transform kept; until any point of the
// smaller body can have moved that far in the other's frame (the translation plus the rotation's
// chord at the body's reach) the pair is not queried: no contact can have appeared, so the skip
// is exact. Touching pairs are queried every step: their points jitter by more than 1e-3 of a
// rock's size per step (tried: keeping their points until they moved 5 % or 25 % of the breaking
// threshold skipped 0.2 % and 1.2 % of their queries).
//
// Warm-start hand-over: GJK's one point per step lands anywhere on a touching face, so in a
// pile a full manifold drops a point for it most steps, and Bullet starts the new point from
// zero impulse. The normal impulse of the points a step drops passes to the points it adds as
// their warm start (docs/contact_model.md, *Deep piles*).

#include <btBulletCollisionCommon.h>

#include <memory>

namespace rockfall::engine {

// Creates the impact-aware algorithm for a pair of convex shapes.
class HullContactCreateFunc : public btCollisionAlgorithmCreateFunc {
  public:
    HullContactCreateFunc();
    ~HullContactCreateFunc() override;
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;

  private:
    std::unique_ptr<btConvexPenetrationDepthSolver> penetration_solver_;
};

// Size of the algorithm object, for the collision configuration's pool.
int hull_contact_algorithm_size();

// Creates Bullet's sphere-box algorithm (btSphereBoxCollisionAlgorithm) keeping one contact
// point per step. A sphere touches a box at one point, which Bullet's algorithm finds anew
// every step, but its persistent manifold kept the points of earlier steps (up to four), each
// refreshed from where it was on the sphere and on the box. A sphere rolling or sliding at v
// left them v dt apart behind the true point, and the solver spread the normal impulse over
// them: at a landing the impulse on the stale points, off the line through the centre, spun
// the sphere. A frictionless 0.29 m sphere landing at 5.9 m/s with 5.3 m/s along the run-out
// gained 3.25 rad/s of spin at 1 ms and none at 0.125 ms, and in the seed sweep spheres kept
// 5 % more of their energy past the toe at 1 ms than at 0.125 ms (docs/sweeps.md, *Step
// size*). The manifold is now cleared before each query; the point found takes the normal
// impulse of the points it replaces as its warm start.
class SphereBoxCreateFunc : public btCollisionAlgorithmCreateFunc {
  public:
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;
};

// Size of that algorithm object, for the collision configuration's pool.
int sphere_box_algorithm_size();

}  // namespace rockfall::engine
