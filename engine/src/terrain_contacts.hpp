#pragma once
// Narrow phase for rock hulls on terrain meshes. Private to the engine.
//
// Bullet's convex-concave algorithm gives a hull on a mesh one manifold, filled by GJK with one
// point per touching triangle and step: a block sliding on a face slides on a changing corner
// (face_contacts.hpp has what that does). This algorithm runs Bullet's, then gives every plane
// the hull touches (triangles whose normals are within about 1 degree of each other) its own
// manifold of vertex-face points, as the box slope has one manifold per box: a slab across the
// toe of a slope rests on both faces, with a friction patch on each. GJK's points on those
// planes leave Bullet's manifold; its others (an edge across an edge) stay.

#include <btBulletCollisionCommon.h>

namespace rockfall::engine {

// Creates the algorithm for a rock hull and a btBvhTriangleMeshShape; set m_swapped for the
// order mesh first.
class TerrainContactCreateFunc : public btCollisionAlgorithmCreateFunc {
  public:
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;
};

// Size of the algorithm object, for the collision configuration's pool.
int terrain_contact_algorithm_size();

}  // namespace rockfall::engine
