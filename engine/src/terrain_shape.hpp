#pragma once
// A terrain mesh as Bullet sees it: a static triangle mesh whose contacts at internal edges are
// corrected. Private to the engine.
//
// GJK and the sphere-triangle test treat each triangle alone, so a rock crossing the shared
// edge of two coplanar triangles also touches the edge of the next one and gets a contact
// normal tilted toward that edge: a spurious bounce at every edge (Bullet's "internal edge"
// problem). btGenerateInternalEdgeInfo records the angle between the faces at every edge, and
// btAdjustInternalEdgeContacts, run from Bullet's contact-added callback on each new contact
// point, clamps the normal into the range the neighbouring faces allow (the face normal on a
// flat or concave edge).

#include "shapes/terrain.hpp"

#include <btBulletCollisionCommon.h>

#include <memory>
#include <vector>

namespace rockfall::engine {

// Bullet's triangle mesh of one terrain, with its internal-edge information when the terrain
// asks for the correction. Bullet only reads a mesh shape during collision queries, so one
// shape serves every world built from the same terrain, on any thread.
class TerrainShape {
  public:
    explicit TerrainShape(const shapes::Terrain& terrain);
    // Any static triangle mesh (a lining sheet), with or without the correction.
    TerrainShape(const shapes::TriangleMesh& mesh, bool internal_edge_correction);
    ~TerrainShape();
    TerrainShape(const TerrainShape&) = delete;
    TerrainShape& operator=(const TerrainShape&) = delete;

    // The shape for the terrain's static body.
    btBvhTriangleMeshShape& shape() const { return *shape_; }
    // Whether contacts on it get the internal-edge correction.
    bool corrected() const { return info_ != nullptr; }

  private:
    std::vector<double> vertices_;
    std::vector<int> indices_;
    std::unique_ptr<btTriangleIndexVertexArray> mesh_;
    std::unique_ptr<btBvhTriangleMeshShape> shape_;
    std::unique_ptr<btTriangleInfoMap> info_;
};

// The Bullet shape of `terrain`: built on first use and kept while `terrain` lives, so that the
// worlds of a sweep (one per sample, several threads) share it. Thread-safe.
std::shared_ptr<const TerrainShape> terrain_shape(
    const std::shared_ptr<const shapes::Terrain>& terrain);

// Makes `body` (the static body of a corrected terrain shape) send its new contact points
// through the internal-edge correction; installs Bullet's global contact-added callback on
// first use (thread-safe). The callback acts on terrain triangles only.
void enable_internal_edge_correction(btCollisionObject& body);

}  // namespace rockfall::engine
