#include "terrain_contacts.hpp"

#include "face_contacts.hpp"

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btConvexConcaveCollisionAlgorithm.h>

#include <memory>
#include <vector>

namespace rockfall::engine {
namespace {

class TerrainContactAlgorithm : public btActivatingCollisionAlgorithm {
  public:
    TerrainContactAlgorithm(const btCollisionAlgorithmConstructionInfo& info,
                            const btCollisionObjectWrapper* body0,
                            const btCollisionObjectWrapper* body1, bool swapped)
        : btActivatingCollisionAlgorithm(info, body0, body1),
          bullet_(std::make_unique<btConvexConcaveCollisionAlgorithm>(info, body0, body1, swapped)),
          swapped_(swapped) {}

    ~TerrainContactAlgorithm() override {
        for (const Plane& plane : planes_) {
            m_dispatcher->releaseManifold(plane.manifold);
        }
    }
    TerrainContactAlgorithm(const TerrainContactAlgorithm&) = delete;
    TerrainContactAlgorithm& operator=(const TerrainContactAlgorithm&) = delete;

    void processCollision(const btCollisionObjectWrapper* body0,
                          const btCollisionObjectWrapper* body1, const btDispatcherInfo& info,
                          btManifoldResult* result) override {
        bullet_->processCollision(body0, body1, info, result);
        const btCollisionObjectWrapper* hull = swapped_ ? body1 : body0;
        const btCollisionObjectWrapper* mesh = swapped_ ? body0 : body1;
        btManifoldArray found;
        bullet_->getAllContactManifolds(found);
        btPersistentManifold* gjk = found.size() == 1 ? found[0] : nullptr;
        for (Plane& plane : planes_) {
            plane.used = false;
        }
        if (hull->getCollisionShape()->getShapeType() == CONVEX_HULL_SHAPE_PROXYTYPE &&
            gjk != nullptr && gjk->getNumContacts() > 0) {
            rebuild_planes(hull, mesh, *gjk);
        }
        for (Plane& plane : planes_) {
            if (!plane.used) {
                plane.manifold->clearManifold();
            }
        }
    }

    btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                   btManifoldResult*) override {
        // Continuous collision detection is off: discrete steps only.
        return 1.0;
    }

    void getAllContactManifolds(btManifoldArray& manifolds) override {
        bullet_->getAllContactManifolds(manifolds);
        for (const Plane& plane : planes_) {
            if (plane.manifold->getNumContacts() > 0) {
                manifolds.push_back(plane.manifold);
            }
        }
    }

  private:
    // A plane's manifold, hull first, kept while the hull touches that plane so that its
    // points keep their impulses.
    struct Plane {
        btVector3 normal;
        btPersistentManifold* manifold = nullptr;
        bool used = false;
    };

    void rebuild_planes(const btCollisionObjectWrapper* hull, const btCollisionObjectWrapper* mesh,
                        btPersistentManifold& gjk) {
        const btCollisionObject* surface = mesh->getCollisionObject();
        const bool gjk_hull_first = gjk.getBody0() == hull->getCollisionObject();
        // Material values are the pair's: every point has the same. Plane manifolds have the
        // hull first, so the reference is turned to that order.
        btManifoldPoint reference = gjk.getContactPoint(gjk.getNumContacts() - 1);
        if (!gjk_hull_first) {
            reference.m_normalWorldOnB = -reference.m_normalWorldOnB;
        }
        const btScalar threshold = gjk.getContactBreakingThreshold();
        // Reused from step to step: no allocation once grown.
        thread_local std::vector<Face> faces;
        thread_local std::vector<VertexContact> contacts;
        thread_local std::vector<VertexContact> on_plane;
        thread_local std::vector<VertexContact> rest;
        mesh_faces(hull, mesh, normal_out_of(gjk, surface), threshold, faces);
        vertex_contacts(hull, faces, threshold, contacts);
        while (!contacts.empty()) {
            // The contacts on the first one's plane.
            const btVector3 normal = contacts.front().face_normal;
            on_plane.clear();
            rest.clear();
            for (const VertexContact& contact : contacts) {
                (same_face_normal(contact.face_normal, normal) ? on_plane : rest)
                    .push_back(contact);
            }
            contacts.swap(rest);
            btPersistentManifold& manifold = plane_manifold(hull, surface, normal);
            rebuild_manifold(manifold, reference, true, hull, surface, on_plane, normal);
            manifold.refreshContactPoints(hull->getWorldTransform(), surface->getWorldTransform());
            // GJK's points on this plane are the plane manifold's now.
            for (int i = gjk.getNumContacts() - 1; i >= 0; --i) {
                const btVector3& n = gjk.getContactPoint(i).m_normalWorldOnB;
                if (same_face_normal(gjk_hull_first ? n : -n, normal)) {
                    gjk.removeContactPoint(i);
                }
            }
        }
    }

    // The manifold of the plane with `normal`: the one it had, or a free or new one.
    btPersistentManifold& plane_manifold(const btCollisionObjectWrapper* hull,
                                         const btCollisionObject* surface,
                                         const btVector3& normal) {
        Plane* free = nullptr;
        for (Plane& plane : planes_) {
            if (!plane.used && same_face_normal(plane.normal, normal)) {
                plane.used = true;
                return *plane.manifold;
            }
            if (!plane.used && plane.manifold->getNumContacts() == 0 && free == nullptr) {
                free = &plane;
            }
        }
        if (free == nullptr) {
            planes_.push_back(
                {normal, m_dispatcher->getNewManifold(hull->getCollisionObject(), surface)});
            free = &planes_.back();
        }
        free->normal = normal;
        free->used = true;
        return *free->manifold;
    }

    std::unique_ptr<btConvexConcaveCollisionAlgorithm> bullet_;
    bool swapped_;
    std::vector<Plane> planes_;
};

}  // namespace

btCollisionAlgorithm* TerrainContactCreateFunc::CreateCollisionAlgorithm(
    btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
    const btCollisionObjectWrapper* body1) {
    void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(terrain_contact_algorithm_size());
    return new (memory) TerrainContactAlgorithm(info, body0, body1, m_swapped);
}

int terrain_contact_algorithm_size() { return static_cast<int>(sizeof(TerrainContactAlgorithm)); }

}  // namespace rockfall::engine
