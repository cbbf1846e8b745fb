#include "hull_contacts.hpp"

#include "face_contacts.hpp"

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btSphereBoxCollisionAlgorithm.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <algorithm>
#include <cmath>

namespace rockfall::engine {
namespace {

// Perturbed queries at the first step of a contact: Bullet's default count (three rotations
// about the separating normal).
constexpr int kPerturbations = 3;

// The largest distance from a shape's origin to a point of it (margin included), m.
double reach_of(const btCollisionShape& shape) {
    btVector3 centre;
    btScalar radius = 0.0;
    shape.getBoundingSphere(centre, radius);
    return centre.length() + radius;
}

// How far any point of the second body, within `reach` of its origin, can have moved in the first
// body's frame between the relative transforms `before` and `now` (each the second body's
// transform in the first's frame), m: the translation plus the chord of the rotation between
// them at that reach. The chord of a rotation by theta is 2 sin(theta / 2) = sqrt(3 - trace).
double drift_bound(const btTransform& before, const btTransform& now, double reach) {
    const btMatrix3x3& a = before.getBasis();
    const btMatrix3x3& b = now.getBasis();
    double trace = 0.0;  // trace of b a^T
    for (int i = 0; i < 3; ++i) trace += a[i].dot(b[i]);
    const double chord = std::sqrt(std::max(0.0, 3.0 - trace));
    return (now.getOrigin() - before.getOrigin()).length() + chord * reach;
}

// The normal impulse of the last solve summed over the manifold's points, N s.
double held_impulse(const btPersistentManifold& manifold) {
    double sum = 0.0;
    for (int i = 0; i < manifold.getNumContacts(); ++i) {
        sum += manifold.getContactPoint(i).m_appliedImpulse;
    }
    return sum;
}

// Hands the normal impulse of the points this step's query dropped to the points it added
// (after the refresh: age 1), in equal shares, as their warm start. GJK returns one point per
// query, anywhere on a touching face, so a pile's face contacts replace a point in most steps
// and Bullet starts the new one from zero (measured in a 500-cube fill: 23 % of the points new
// each step, carrying away 30 % of the warm-start impulse).
void hand_over(btPersistentManifold& manifold, double held_before) {
    double kept = 0.0;
    int added = 0;
    for (int i = 0; i < manifold.getNumContacts(); ++i) {
        const btManifoldPoint& point = manifold.getContactPoint(i);
        if (point.getLifeTime() <= 1) {
            ++added;
        } else {
            kept += point.m_appliedImpulse;
        }
    }
    const double dropped = held_before - kept;
    if (added == 0 || dropped <= 0.0) return;
    for (int i = 0; i < manifold.getNumContacts(); ++i) {
        btManifoldPoint& point = manifold.getContactPoint(i);
        if (point.getLifeTime() <= 1) point.m_appliedImpulse = dropped / added;
    }
}

// Two Bullet convex-convex algorithms sharing one manifold: the plain one every step, the
// perturbing one in addition at the step a contact appears.
class HullContactAlgorithm : public btActivatingCollisionAlgorithm {
  public:
    HullContactAlgorithm(const btCollisionAlgorithmConstructionInfo& info,
                         const btCollisionObjectWrapper* body0,
                         const btCollisionObjectWrapper* body1,
                         btConvexPenetrationDepthSolver* penetration_solver)
        : btActivatingCollisionAlgorithm(info, body0, body1),
          manifold_(m_dispatcher->getNewManifold(body0->getCollisionObject(),
                                                 body1->getCollisionObject())),
          plain_(std::make_unique<btConvexConvexAlgorithm>(manifold_, info, body0, body1,
                                                           penetration_solver, 0, 0)),
          perturbing_(std::make_unique<btConvexConvexAlgorithm>(
              manifold_, info, body0, body1, penetration_solver, kPerturbations, 3)) {
        const double reach0 = reach_of(*body0->getCollisionShape());
        const double reach1 = reach_of(*body1->getCollisionShape());
        moving_first_ = reach0 < reach1;
        reach_ = std::min(reach0, reach1);
    }

    ~HullContactAlgorithm() override { m_dispatcher->releaseManifold(manifold_); }
    HullContactAlgorithm(const HullContactAlgorithm&) = delete;
    HullContactAlgorithm& operator=(const HullContactAlgorithm&) = delete;

    void processCollision(const btCollisionObjectWrapper* body0,
                          const btCollisionObjectWrapper* body1, const btDispatcherInfo& info,
                          btManifoldResult* result) override {
        result->setPersistentManifold(manifold_);
        const bool touching = manifold_->getNumContacts() > 0;
        if (!touching) {
            // Apart: while the pair stays farther apart than the breaking threshold the plain
            // query adds nothing, and the gap at the last measurement says for how long.
            const btTransform relative = relative_transform(body0, body1);
            if (gap_ > 0.0 && drift_bound(measured_at_, relative, reach_) < gap_) return;
            measured_at_ = relative;
            gap_ = separation(body0, body1) - manifold_->getContactBreakingThreshold();
            if (gap_ > 0.0) return;
        }
        gap_ = 0.0;
        const double held = held_impulse(*manifold_);
        plain_->processCollision(body0, body1, info, result);
        if (!touching && manifold_->getNumContacts() > 0) {
            // A new contact: find the rest of a touching face or edge now. Pairs that stay
            // apart (most pairs the broadphase reports) never pay for the perturbed queries.
            perturbing_->processCollision(body0, body1, info, result);
        }
        add_face_contacts(body0, body1);
        // The inner algorithms do not own the manifold, so they leave its refresh to us.
        result->refreshContactPoints();
        hand_over(*manifold_, held);
    }

    btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                   btManifoldResult*) override {
        // Continuous collision detection is off: discrete steps only.
        return 1.0;
    }

    void getAllContactManifolds(btManifoldArray& manifolds) override {
        manifolds.push_back(manifold_);
    }

  private:
    // The body with the smaller reach in the other's frame.
    btTransform relative_transform(const btCollisionObjectWrapper* body0,
                                   const btCollisionObjectWrapper* body1) const {
        const btTransform& t0 = body0->getWorldTransform();
        const btTransform& t1 = body1->getWorldTransform();
        return moving_first_ ? t1.inverseTimes(t0) : t0.inverseTimes(t1);
    }

    // Distance between the two shapes (margins included) by GJK, m; zero when they overlap
    // (GJK then has no answer without the penetration solver, and the plain query decides).
    static double separation(const btCollisionObjectWrapper* body0,
                             const btCollisionObjectWrapper* body1) {
        const auto* shape0 = static_cast<const btConvexShape*>(body0->getCollisionShape());
        const auto* shape1 = static_cast<const btConvexShape*>(body1->getCollisionShape());
        btVoronoiSimplexSolver simplex;
        btGjkPairDetector gjk(shape0, shape1, &simplex, nullptr);
        btGjkPairDetector::ClosestPointInput input;
        input.m_transformA = body0->getWorldTransform();
        input.m_transformB = body1->getWorldTransform();
        btPointCollector closest;
        gjk.getClosestPoints(input, closest, nullptr);
        return closest.m_hasResult ? std::max<double>(0.0, closest.m_distance) : 0.0;
    }

    // A hull on a box's face: every vertex on the face, not only GJK's one (face_contacts).
    void add_face_contacts(const btCollisionObjectWrapper* body0,
                           const btCollisionObjectWrapper* body1) {
        const int type0 = body0->getCollisionShape()->getShapeType();
        const int type1 = body1->getCollisionShape()->getShapeType();
        if (type0 == CONVEX_HULL_SHAPE_PROXYTYPE && type1 == BOX_SHAPE_PROXYTYPE) {
            add_box_face_contacts(body0, body1, *manifold_);
        } else if (type0 == BOX_SHAPE_PROXYTYPE && type1 == CONVEX_HULL_SHAPE_PROXYTYPE) {
            add_box_face_contacts(body1, body0, *manifold_);
        }
    }

    btPersistentManifold* manifold_;
    std::unique_ptr<btConvexConvexAlgorithm> plain_;
    std::unique_ptr<btConvexConvexAlgorithm> perturbing_;
    // Separation caching: which body's reach bounds the drift, that reach (m), the relative
    // transform when the gap was measured, and how far beyond the breaking threshold the pair
    // was then (m; zero when unknown or touching).
    bool moving_first_ = false;
    double reach_ = 0.0;
    btTransform measured_at_;
    double gap_ = 0.0;
};

// Bullet's sphere-box query on an emptied manifold: one point per step (hull_contacts.hpp).
class SphereBoxAlgorithm : public btSphereBoxCollisionAlgorithm {
  public:
    SphereBoxAlgorithm(const btCollisionAlgorithmConstructionInfo& info,
                       const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                       bool swapped)
        : btSphereBoxCollisionAlgorithm(nullptr, info, body0, body1, swapped) {
        // Bullet's algorithm makes its manifold here, once, or none when the pair needs no
        // collision; it never replaces it.
        btManifoldArray manifolds;
        getAllContactManifolds(manifolds);
        manifold_ = manifolds.size() == 1 ? manifolds[0] : nullptr;
    }

    void processCollision(const btCollisionObjectWrapper* body0,
                          const btCollisionObjectWrapper* body1, const btDispatcherInfo& info,
                          btManifoldResult* result) override {
        if (manifold_ == nullptr) return;
        double impulse = 0.0;
        for (int i = 0; i < manifold_->getNumContacts(); ++i) {
            impulse += manifold_->getContactPoint(i).m_appliedImpulse;
        }
        manifold_->clearManifold();
        btSphereBoxCollisionAlgorithm::processCollision(body0, body1, info, result);
        if (manifold_->getNumContacts() > 0) {
            manifold_->getContactPoint(0).m_appliedImpulse = impulse;
        }
    }

  private:
    btPersistentManifold* manifold_ = nullptr;
};

}  // namespace

HullContactCreateFunc::HullContactCreateFunc()
    : penetration_solver_(std::make_unique<btGjkEpaPenetrationDepthSolver>()) {}

HullContactCreateFunc::~HullContactCreateFunc() = default;

btCollisionAlgorithm* HullContactCreateFunc::CreateCollisionAlgorithm(
    btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
    const btCollisionObjectWrapper* body1) {
    void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(hull_contact_algorithm_size());
    return new (memory) HullContactAlgorithm(info, body0, body1, penetration_solver_.get());
}

int hull_contact_algorithm_size() { return static_cast<int>(sizeof(HullContactAlgorithm)); }

btCollisionAlgorithm* SphereBoxCreateFunc::CreateCollisionAlgorithm(
    btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
    const btCollisionObjectWrapper* body1) {
    void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sphere_box_algorithm_size());
    return new (memory) SphereBoxAlgorithm(info, body0, body1, m_swapped);
}

int sphere_box_algorithm_size() { return static_cast<int>(sizeof(SphereBoxAlgorithm)); }

}  // namespace rockfall::engine
