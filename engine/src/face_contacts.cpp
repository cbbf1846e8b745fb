#include "face_contacts.hpp"

#include "contact_settings.hpp"
#include "plane_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rockfall::engine {
namespace {

// The contact normal must be this close to a face normal (cosine of 1.1 degrees) for a face
// contact: GJK's normal of a vertex or face on a face is the face normal to rounding, and a
// tilted one means the surface's edge or corner touches (or the hull's rounded margin does).
constexpr double kFaceAlignment = 0.9998;

// A vertex at most this share of the breaking threshold above the face (26 micrometres for a
// 0.2 m rock) touches it. The split impulse pushes a face's deeper corners out and, as the body
// turns, lifts its shallow ones a few micrometres clear; those then got no contact row for a
// step and fell freely, and a block sliding on its face rocked from side to side with a period
// of two steps, its lateral friction using up Coulomb's cone (it slid 27 % faster than
// g (sin t - mu cos t) at mu = 0.3).
constexpr double kTouchTolerance = 0.01;

// The stored point whose end on the hull is nearest `on_hull` (hull frame) within the
// breaking threshold, or -1.
int matching_point(const btPersistentManifold& manifold, bool hull_first,
                   const btVector3& on_hull) {
    const btScalar reach = manifold.getContactBreakingThreshold();
    btScalar nearest = reach * reach;
    int match = -1;
    for (int i = 0; i < manifold.getNumContacts(); ++i) {
        const btManifoldPoint& point = manifold.getContactPoint(i);
        const btVector3& stored = hull_first ? point.m_localPointA : point.m_localPointB;
        const btScalar distance = (stored - on_hull).length2();
        if (distance < nearest) {
            nearest = distance;
            match = i;
        }
    }
    return match;
}

// The (at most) four candidates a manifold keeps: all when there are four or fewer, otherwise
// the four spanning the largest area (corners of the candidates' convex hull), preferring
// points found last step among equal areas (a face with more corners than four then keeps the
// same four while it slides). Writes the indices to `kept`, returns how many.
int widest_four(const std::vector<Point2>& on_plane, const std::vector<int>& matches, int* kept) {
    const int n = static_cast<int>(on_plane.size());
    if (n <= MANIFOLD_CACHE_SIZE) {
        for (int i = 0; i < n; ++i) {
            kept[i] = i;
        }
        return n;
    }
    int hull[16];
    const int h = convex_hull(on_plane.data(), n, hull);
    if (h <= MANIFOLD_CACHE_SIZE) {
        std::copy(hull, hull + h, kept);
        return h;
    }
    double best_area = -1.0;
    int best_found = -1;
    // Four corners of a convex polygon in their cyclic order bound a convex quadrilateral.
    for (int a = 0; a < h; ++a) {
        for (int b = a + 1; b < h; ++b) {
            for (int c = b + 1; c < h; ++c) {
                for (int d = c + 1; d < h; ++d) {
                    const int pick[4] = {hull[a], hull[b], hull[c], hull[d]};
                    const Point2* p[4];
                    int found = 0;
                    for (int i = 0; i < 4; ++i) {
                        p[i] = &on_plane[static_cast<std::size_t>(pick[i])];
                        found += matches[static_cast<std::size_t>(pick[i])] >= 0;
                    }
                    const double area = cross(*p[0], *p[1], *p[2]) + cross(*p[0], *p[2], *p[3]);
                    const double tie = 1e-9 * std::max(area, best_area);
                    if (area > best_area + tie || (area > best_area - tie && found > best_found)) {
                        std::copy(pick, pick + 4, kept);
                        best_area = area;
                        best_found = found;
                    }
                }
            }
        }
    }
    return MANIFOLD_CACHE_SIZE;
}

// Whether `p` (on the face's plane) lies in the convex polygon, either winding.
bool inside(const Face& face, const btVector3& p) {
    bool positive = false;
    bool negative = false;
    for (int i = 0; i < face.corner_count; ++i) {
        const btVector3& a = face.corners[i];
        const btVector3& b = face.corners[(i + 1) % face.corner_count];
        const btScalar side = face.normal.dot((b - a).cross(p - a));
        positive = positive || side > 1e-12;
        negative = negative || side < -1e-12;
    }
    return !(positive && negative);
}

// Collects the triangles of a concave shape in an AABB, in world coordinates.
class TriangleCollector : public btTriangleCallback {
  public:
    TriangleCollector(const btTransform& frame, const btVector3& normal, std::vector<Face>& faces)
        : frame_(frame), normal_(normal), faces_(faces) {}

    void processTriangle(btVector3* triangle, int /*part*/, int /*index*/) override {
        Face face;
        face.corner_count = 3;
        for (int i = 0; i < 3; ++i) {
            face.corners[i] = frame_ * triangle[i];
        }
        btVector3 normal =
            (face.corners[1] - face.corners[0]).cross(face.corners[2] - face.corners[0]);
        if (normal.length2() <= SIMD_EPSILON * SIMD_EPSILON) {
            return;
        }
        normal.normalize();
        if (normal.dot(normal_) < 0) {
            normal = -normal;
        }
        // Faces turned away from the contact normal (the far side of a ridge) are not under
        // the hull.
        if (normal.dot(normal_) > 0) {
            face.normal = normal;
            faces_.push_back(face);
        }
    }

  private:
    const btTransform& frame_;
    btVector3 normal_;
    std::vector<Face>& faces_;
};

}  // namespace

bool box_face(const btCollisionObjectWrapper* box, const btVector3& normal, Face& face) {
    const auto* box_shape = static_cast<const btBoxShape*>(box->getCollisionShape());
    const btTransform& frame = box->getWorldTransform();
    const btVector3 local_normal = frame.getBasis().transpose() * normal;
    const int axis = local_normal.absolute().maxAxis();
    if (std::abs(local_normal[axis]) < kFaceAlignment) {
        return false;
    }
    // btBoxShape's vertices include its margin: its half extents with margin are the solid's.
    const btVector3 half = box_shape->getHalfExtentsWithMargin();
    const int u = (axis + 1) % 3;
    const int w = (axis + 2) % 3;
    const btScalar signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    face.corner_count = 4;
    for (int i = 0; i < 4; ++i) {
        btVector3 corner(0, 0, 0);
        corner[axis] = local_normal[axis] > 0 ? half[axis] : -half[axis];
        corner[u] = signs[i][0] * half[u];
        corner[w] = signs[i][1] * half[w];
        face.corners[i] = frame * corner;
    }
    btVector3 face_local(0, 0, 0);
    face_local[axis] = local_normal[axis] > 0 ? 1 : -1;
    face.normal = frame.getBasis() * face_local;
    return true;
}

void mesh_faces(const btCollisionObjectWrapper* hull, const btCollisionObjectWrapper* mesh,
                const btVector3& normal, btScalar reach, std::vector<Face>& faces) {
    faces.clear();
    const btTransform& frame = mesh->getWorldTransform();
    btVector3 low;
    btVector3 high;
    hull->getCollisionShape()->getAabb(frame.inverse() * hull->getWorldTransform(), low, high);
    const btVector3 margin(reach, reach, reach);
    TriangleCollector collector(frame, normal, faces);
    static_cast<const btConcaveShape*>(mesh->getCollisionShape())
        ->processAllTriangles(&collector, low - margin, high + margin);
}

void vertex_contacts(const btCollisionObjectWrapper* hull, const std::vector<Face>& faces,
                     btScalar threshold, std::vector<VertexContact>& contacts) {
    contacts.clear();
    const auto* hull_shape = static_cast<const btConvexHullShape*>(hull->getCollisionShape());
    // The hull's points lie one margin inside its surface.
    const btScalar margin = hull_shape->getMargin();
    const btTransform& hull_frame = hull->getWorldTransform();
    for (int i = 0; i < hull_shape->getNumPoints(); ++i) {
        const btVector3& core = hull_shape->getUnscaledPoints()[i];
        const btVector3 vertex = hull_frame * core;
        // Of the faces the vertex lies over, the one it is farthest out of separates it.
        const Face* under = nullptr;
        btScalar depth = -BT_LARGE_FLOAT;
        for (const Face& face : faces) {
            const btScalar d = face.normal.dot(vertex - face.corners[0]) - margin;
            if (d > depth && d < threshold && inside(face, vertex - face.normal * (d + margin))) {
                under = &face;
                depth = d;
            }
        }
        if (under == nullptr) {
            continue;
        }
        // A corner just above the face touches (see kTouchTolerance).
        const btScalar gap = depth > 0 && depth <= kTouchTolerance * threshold ? 0 : depth;
        const btVector3 on_face = vertex - under->normal * (depth + margin);
        contacts.push_back(
            {on_face, under->normal, gap,
             core - hull_frame.getBasis().transpose() * under->normal * (depth + margin - gap)});
    }
}

int rebuild_manifold(btPersistentManifold& manifold, const btManifoldPoint& reference,
                     bool hull_first, const btCollisionObjectWrapper* hull,
                     const btCollisionObject* surface, const std::vector<VertexContact>& contacts,
                     const btVector3& normal) {
    if (contacts.empty()) {
        return 0;
    }
    btVector3 u;
    btVector3 w;
    btPlaneSpace1(normal, u, w);
    // Reused from step to step: no allocation once grown.
    thread_local std::vector<Point2> on_plane;
    thread_local std::vector<int> matches;
    on_plane.clear();
    matches.clear();
    for (const VertexContact& contact : contacts) {
        on_plane.push_back({contact.on_face.dot(u), contact.on_face.dot(w)});
        matches.push_back(matching_point(manifold, hull_first, contact.on_hull));
    }
    int kept[MANIFOLD_CACHE_SIZE];
    const int kept_count = widest_four(on_plane, matches, kept);
    btManifoldPoint points[MANIFOLD_CACHE_SIZE] = {reference, reference, reference, reference};
    const btTransform& hull_frame = hull->getWorldTransform();
    const btTransform to_surface = surface->getWorldTransform().inverse();
    for (int i = 0; i < kept_count; ++i) {
        const VertexContact& contact = contacts[static_cast<std::size_t>(kept[i])];
        const btVector3 on_hull = hull_frame * contact.on_hull;
        const btVector3 local_on_face = to_surface * contact.on_face;
        btManifoldPoint& point = points[i];
        point.m_localPointA = hull_first ? contact.on_hull : local_on_face;
        point.m_localPointB = hull_first ? local_on_face : contact.on_hull;
        point.m_positionWorldOnA = hull_first ? on_hull : contact.on_face;
        point.m_positionWorldOnB = hull_first ? contact.on_face : on_hull;
        point.m_normalWorldOnB = hull_first ? contact.face_normal : -contact.face_normal;
        point.m_distance1 = contact.gap;
        point.m_userPersistentData = nullptr;
        btPlaneSpace1(point.m_normalWorldOnB, point.m_lateralFrictionDir1,
                      point.m_lateralFrictionDir2);
        // A point found last step keeps its impulses for warm starting and its age.
        const int match = matches[static_cast<std::size_t>(kept[i])];
        const btManifoldPoint* stored = match >= 0 ? &manifold.getContactPoint(match) : nullptr;
        point.m_lifeTime = stored != nullptr ? stored->m_lifeTime : 0;
        point.m_appliedImpulse = stored != nullptr ? stored->m_appliedImpulse : 0;
        point.m_appliedImpulseLateral1 = stored != nullptr ? stored->m_appliedImpulseLateral1 : 0;
        point.m_appliedImpulseLateral2 = stored != nullptr ? stored->m_appliedImpulseLateral2 : 0;
        point.m_prevRHS = stored != nullptr ? stored->m_prevRHS : 0;
    }
    manifold.clearManifold();
    // The touching corners sit at distance 0, which the refresh recomputes to within round-off
    // of either sign: a positive one left a corner out of the solver for a step.
    manifold.setContactProcessingThreshold(
        std::max<btScalar>(manifold.getContactProcessingThreshold(), kTouchRoundOff));
    for (int i = 0; i < kept_count; ++i) {
        manifold.addManifoldPoint(points[i]);
    }
    return kept_count;
}

int add_box_face_contacts(const btCollisionObjectWrapper* hull, const btCollisionObjectWrapper* box,
                          btPersistentManifold& manifold) {
    if (manifold.getNumContacts() == 0) {
        return 0;
    }
    const bool hull_first = manifold.getBody0() == hull->getCollisionObject();
    const btVector3 normal = normal_out_of(manifold, box->getCollisionObject());
    thread_local std::vector<Face> faces(1);
    if (!box_face(box, normal, faces.front())) {
        return 0;
    }
    // Points of GJK's on a box edge (normals tilted off the face) are left as found.
    for (int i = 0; i < manifold.getNumContacts(); ++i) {
        const btVector3& n = manifold.getContactPoint(i).m_normalWorldOnB;
        if (!same_face_normal(hull_first ? n : -n, faces.front().normal)) {
            return 0;
        }
    }
    // Material values are the pair's: every point of the manifold has the same.
    const btManifoldPoint reference = manifold.getContactPoint(manifold.getNumContacts() - 1);
    thread_local std::vector<VertexContact> contacts;
    vertex_contacts(hull, faces, manifold.getContactBreakingThreshold(), contacts);
    return rebuild_manifold(manifold, reference, hull_first, hull, box->getCollisionObject(),
                            contacts, faces.front().normal);
}

bool same_face_normal(const btVector3& a, const btVector3& b) { return a.dot(b) >= kFaceAlignment; }

}  // namespace rockfall::engine
