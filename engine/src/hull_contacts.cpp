#include "hull_contacts.hpp"

#include "face_contacts.hpp"

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>

namespace rockfall::engine {
namespace {

// Perturbed queries at the first step of a contact: Bullet's default count (three rotations
// about the separating normal).
constexpr int kPerturbations = 3;

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
              manifold_, info, body0, body1, penetration_solver, kPerturbations, 3)) {}

    ~HullContactAlgorithm() override { m_dispatcher->releaseManifold(manifold_); }
    HullContactAlgorithm(const HullContactAlgorithm&) = delete;
    HullContactAlgorithm& operator=(const HullContactAlgorithm&) = delete;

    void processCollision(const btCollisionObjectWrapper* body0,
                          const btCollisionObjectWrapper* body1, const btDispatcherInfo& info,
                          btManifoldResult* result) override {
        result->setPersistentManifold(manifold_);
        const bool was_empty = manifold_->getNumContacts() == 0;
        plain_->processCollision(body0, body1, info, result);
        if (was_empty && manifold_->getNumContacts() > 0) {
            // A new contact: find the rest of a touching face or edge now. Pairs that stay
            // apart (most pairs the broadphase reports) never pay for the perturbed queries.
            perturbing_->processCollision(body0, body1, info, result);
        }
        add_face_contacts(body0, body1);
        // The inner algorithms do not own the manifold, so they leave its refresh to us.
        result->refreshContactPoints();
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

}  // namespace rockfall::engine
