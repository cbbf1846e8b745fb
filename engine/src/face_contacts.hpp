#pragma once
// The whole contact of a rock hull resting or sliding on a flat face (of a box, or of terrain
// triangles), every step. Private to the engine.
//
// Bullet's persistent manifold keeps a contact point while its two ends, one fixed on each
// body, stay within the breaking threshold (about 2.6 mm for a 0.2 m rock) of each other, and
// matches a new point to a stored one by its end on the manifold's first body. A rock sliding
// faster than the threshold per step (2.6 m/s at 1 ms) on a box that comes first loses every
// point the step after it was found, so it slides on the one point GJK finds each step: a
// corner that changes from step to step and carries the rock's whole weight. It then rocks,
// and turns about the face normal (a block sliding straight down a 30 degree incline turned
// 29 degrees in 2.4 s at mu = 0.3, where by symmetry it must not turn).
//
// This rebuilds, every step, the manifold of a hull on a face from each hull vertex within the
// threshold of the face (and over it) as a vertex-face point, matched to a stored point by its
// end on the hull (a corner stays the same corner while it slides) so that it keeps its
// impulses for warm starting; of more than four it keeps the four spanning the largest area.
// A box manifold with a point on one of the box's edges is left to GJK; on a terrain mesh each
// plane the hull touches gets its own manifold (terrain_contacts.hpp).

#include <btBulletCollisionCommon.h>

#include <vector>

namespace rockfall::engine {

// A convex flat face, world coordinates: outward unit normal and 3 or 4 corners in order.
struct Face {
    btVector3 normal;
    btVector3 corners[4];
    int corner_count = 0;
};

// The face of `box` (a btBoxShape) whose outward normal is within about 1 degree of `normal`;
// false when none is (an edge or corner of the box touches).
bool box_face(const btCollisionObjectWrapper* box, const btVector3& normal, Face& face);

// Sets `faces` to the triangles of `mesh` (a btConcaveShape) near `hull` (within `reach`, m)
// that face the side `normal` points to.
void mesh_faces(const btCollisionObjectWrapper* hull, const btCollisionObjectWrapper* mesh,
                const btVector3& normal, btScalar reach, std::vector<Face>& faces);

// A hull vertex over a face: where it touches the face (world), the face's normal, its gap
// above the face (m, negative inside), and its point on the hull (hull frame) that meets the
// face's point (one margin out of the vertex, and the gap).
struct VertexContact {
    btVector3 on_face;
    btVector3 face_normal;
    btScalar gap;
    btVector3 on_hull;
};

// Sets `contacts` to the vertices of `hull` (a btConvexHullShape) within `threshold` (m) of a
// face of `faces` they lie over, each on the face it is farthest out of.
void vertex_contacts(const btCollisionObjectWrapper* hull, const std::vector<Face>& faces,
                     btScalar threshold, std::vector<VertexContact>& contacts);

// Replaces the points of `manifold` (of `hull` and `surface`, hull first when `hull_first`) by
// `contacts` (the four spanning the largest area in the plane normal to `normal` when there
// are more), each with the material values of `reference` and keeping the impulses and age of
// the stored point with the same end on the hull. Returns the number of points; 0 and the
// manifold as it was when `contacts` is empty.
int rebuild_manifold(btPersistentManifold& manifold, const btManifoldPoint& reference,
                     bool hull_first, const btCollisionObjectWrapper* hull,
                     const btCollisionObject* surface, const std::vector<VertexContact>& contacts,
                     const btVector3& normal);

// The box case: rebuilds the manifold of `hull` on the face of `box` (a btBoxShape) that its
// points' normals are within about 1 degree of; leaves it as found when a point is not (the
// hull touches an edge or corner of the box). Returns the number of points from the face.
int add_box_face_contacts(const btCollisionObjectWrapper* hull, const btCollisionObjectWrapper* box,
                          btPersistentManifold& manifold);

// Whether two unit normals are within about 1 degree of each other.
bool same_face_normal(const btVector3& a, const btVector3& b);

// The normal of the manifold's newest point, pointing out of `surface` toward the other body.
inline btVector3 normal_out_of(const btPersistentManifold& manifold,
                               const btCollisionObject* surface) {
    const btVector3& n = manifold.getContactPoint(manifold.getNumContacts() - 1).m_normalWorldOnB;
    // m_normalWorldOnB points from the manifold's second body toward its first.
    return manifold.getBody1() == surface ? n : -n;
}

}  // namespace rockfall::engine
