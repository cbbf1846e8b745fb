#include "terrain_shape.hpp"

#include <BulletCollision/CollisionDispatch/btInternalEdgeUtility.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <utility>

namespace rockfall::engine {
namespace {

// A sphere's contact on a face is its point nearest the face's plane. The sphere-triangle test
// puts the contact of a triangle the sphere only grazes at the point nearest that triangle's
// edge, ahead of or behind the lowest point; once the normal is the face normal, a point there
// moves into the surface as the sphere rolls (at v sin(phi) for a point phi off the bottom),
// and the solver answers with a restitution impulse: a hop at every edge on coarse steps.
void move_to_lowest_point(btManifoldPoint& point, const btCollisionObjectWrapper* sphere,
                          const btCollisionObjectWrapper* triangle) {
    const btVector3& normal = point.m_normalWorldOnB;
    const auto& face = *static_cast<const btTriangleShape*>(triangle->getCollisionShape());
    const btVector3 corner = triangle->getWorldTransform() * face.m_vertices1[0];
    const btScalar radius =
        static_cast<const btSphereShape*>(sphere->getCollisionShape())->getRadius();
    point.m_positionWorldOnA = sphere->getWorldTransform().getOrigin() - radius * normal;
    point.m_distance1 = normal.dot(point.m_positionWorldOnA - corner);
    point.m_positionWorldOnB = point.m_positionWorldOnA - point.m_distance1 * normal;
    point.m_localPointA = sphere->getWorldTransform().invXform(point.m_positionWorldOnA);
    point.m_localPointB = triangle->getWorldTransform().invXform(point.m_positionWorldOnB);
}

// Bullet's manifold result calls this for every contact point it adds or refreshes on a pair
// where one body has CF_CUSTOM_MATERIAL_CALLBACK (only our terrain bodies set it).
bool correct_internal_edges(btManifoldPoint& point, const btCollisionObjectWrapper* body0,
                            int /*part0*/, int /*index0*/, const btCollisionObjectWrapper* body1,
                            int part1, int index1) {
    // A convex-concave manifold has the mesh as its body B (btConvexTriangleCallback), and the
    // wrappers come in the manifold's order, so a terrain triangle is always body1 here; the
    // utility reads the point's B-side normal and position accordingly. It leaves points alone
    // on meshes without internal-edge information.
    if (body1->getCollisionShape()->getShapeType() != TRIANGLE_SHAPE_PROXYTYPE) {
        return false;
    }
    const btVector3 original = point.m_normalWorldOnB;
    btAdjustInternalEdgeContacts(point, body1, body0, part1, index1);
    if (body0->getCollisionShape()->getShapeType() == SPHERE_SHAPE_PROXYTYPE &&
        point.m_normalWorldOnB != original) {
        btVector3 face_normal;
        static_cast<const btTriangleShape*>(body1->getCollisionShape())->calcNormal(face_normal);
        face_normal = body1->getWorldTransform().getBasis() * face_normal;
        // Only a contact turned onto the face normal is a contact with the face's plane; a
        // normal clamped at a convex edge stays where the edge is.
        if (std::abs(face_normal.dot(point.m_normalWorldOnB)) > 1.0 - 1e-9) {
            move_to_lowest_point(point, body0, body1);
        }
    }
    // Bullet ignores the return value.
    return false;
}

}  // namespace

TerrainShape::TerrainShape(const shapes::Terrain& terrain)
    : TerrainShape(terrain.mesh(), terrain.internal_edge_correction()) {}

TerrainShape::TerrainShape(const shapes::TriangleMesh& mesh, bool internal_edge_correction) {
    vertices_.reserve(3 * mesh.vertices.size());
    for (const shapes::Vec3& v : mesh.vertices) {
        vertices_.insert(vertices_.end(), {v.x(), v.y(), v.z()});
    }
    indices_.reserve(3 * mesh.triangles.size());
    for (const auto& triangle : mesh.triangles) {
        indices_.insert(indices_.end(), triangle.begin(), triangle.end());
    }
    // btTriangleIndexVertexArray only points at our arrays, in double precision as the build.
    btIndexedMesh part;
    part.m_numTriangles = static_cast<int>(mesh.triangles.size());
    part.m_triangleIndexBase = reinterpret_cast<const unsigned char*>(indices_.data());
    part.m_triangleIndexStride = 3 * static_cast<int>(sizeof(int));
    part.m_numVertices = static_cast<int>(mesh.vertices.size());
    part.m_vertexBase = reinterpret_cast<const unsigned char*>(vertices_.data());
    part.m_vertexStride = 3 * static_cast<int>(sizeof(double));
    part.m_indexType = PHY_INTEGER;
    part.m_vertexType = PHY_DOUBLE;
    mesh_ = std::make_unique<btTriangleIndexVertexArray>();
    mesh_->addIndexedMesh(part, PHY_INTEGER);
    // Quantized BVH: the mesh never changes, and its nodes take a quarter of the memory.
    shape_ = std::make_unique<btBvhTriangleMeshShape>(mesh_.get(), true);
    // No margin: the surface is where the survey puts it (the rocks carry their own margin).
    shape_->setMargin(0.0);
    if (internal_edge_correction) {
        info_ = std::make_unique<btTriangleInfoMap>();
        btGenerateInternalEdgeInfo(shape_.get(), info_.get());
    }
}

TerrainShape::~TerrainShape() = default;

std::shared_ptr<const TerrainShape> terrain_shape(
    const std::shared_ptr<const shapes::Terrain>& terrain) {
    // Entries live while their terrain does; an expired entry is dropped on the next call (its
    // terrain's address may be reused by a new one, which the weak pointer tells apart).
    using Entry = std::pair<std::weak_ptr<const shapes::Terrain>, std::shared_ptr<TerrainShape>>;
    static std::mutex mutex;
    static std::vector<Entry> cache;
    const std::lock_guard<std::mutex> lock(mutex);
    std::erase_if(cache, [](const Entry& entry) { return entry.first.expired(); });
    const auto found = std::find_if(cache.begin(), cache.end(), [&](const Entry& entry) {
        return entry.first.lock() == terrain;
    });
    if (found != cache.end()) return found->second;
    auto shape = std::make_shared<TerrainShape>(*terrain);
    cache.emplace_back(terrain, shape);
    return shape;
}

void enable_internal_edge_correction(btCollisionObject& body) {
    static const bool installed = [] {
        gContactAddedCallback = &correct_internal_edges;
        return true;
    }();
    (void)installed;
    body.setCollisionFlags(body.getCollisionFlags() |
                           btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
}

}  // namespace rockfall::engine
