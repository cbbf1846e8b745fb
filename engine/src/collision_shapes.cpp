#include "collision_shapes.hpp"

#include "contact_settings.hpp"

#include "shapes/polyhedron.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <vector>

namespace rockfall::engine {
namespace {

using shapes::Vec3;

struct Plane {
    Vec3 normal;    // outward unit normal
    double offset;  // distance from the centroid (origin), > 0
};

std::vector<Plane> face_planes(const shapes::ConvexPolyhedron& hull) {
    std::vector<Plane> planes;
    planes.reserve(hull.triangles.size());
    for (const auto& tri : hull.triangles) {
        const Vec3& a = hull.vertices[static_cast<std::size_t>(tri[0])];
        const Vec3& b = hull.vertices[static_cast<std::size_t>(tri[1])];
        const Vec3& c = hull.vertices[static_cast<std::size_t>(tri[2])];
        const Vec3 normal = (b - a).cross(c - a).normalized();
        planes.push_back({normal, normal.dot(a)});
    }
    return planes;
}

// Keeps one of each group of points closer than `tolerance`.
std::vector<Vec3> unique_points(const std::vector<Vec3>& points, double tolerance) {
    std::vector<Vec3> unique;
    for (const Vec3& p : points) {
        const bool seen = std::any_of(unique.begin(), unique.end(), [&](const Vec3& q) {
            return (p - q).squaredNorm() <= tolerance * tolerance;
        });
        if (!seen) {
            unique.push_back(p);
        }
    }
    return unique;
}

// Vertices of the intersection of the half-spaces n.x <= d - margin, by polar duality: the
// half-space maps to the dual point n / (d - margin); each facet y.a = 1 of the dual points'
// convex hull is a vertex a of the intersection (the origin, the centroid, is inside both).
std::vector<Vec3> shrunk_vertices(const std::vector<Plane>& planes, double margin, double size) {
    std::vector<Vec3> dual;
    dual.reserve(planes.size());
    for (const Plane& plane : planes) {
        dual.push_back(plane.normal / (plane.offset - margin));
    }
    // Coplanar triangles give the same dual point; their spread is round-off of order 1e-16.
    const double dual_scale = dual.front().norm();
    const shapes::ConvexPolyhedron dual_hull =
        shapes::convex_hull(unique_points(dual, 1e-9 * dual_scale));
    std::vector<Vec3> vertices;
    vertices.reserve(dual_hull.triangles.size());
    for (const auto& tri : dual_hull.triangles) {
        const Vec3& a = dual_hull.vertices[static_cast<std::size_t>(tri[0])];
        const Vec3& b = dual_hull.vertices[static_cast<std::size_t>(tri[1])];
        const Vec3& c = dual_hull.vertices[static_cast<std::size_t>(tri[2])];
        const Vec3 normal = (b - a).cross(c - a);
        vertices.push_back(normal / normal.dot(a));
    }
    return unique_points(vertices, 1e-9 * size);
}

}  // namespace

std::unique_ptr<btConvexShape> make_rock_shape(const shapes::RockGeometry& rock) {
    if (rock.radius > 0.0) {
        return std::make_unique<btSphereShape>(rock.radius);
    }
    const std::vector<Plane> planes = face_planes(rock.hull);
    const double inradius =
        std::min_element(planes.begin(), planes.end(), [](const Plane& a, const Plane& b) {
            return a.offset < b.offset;
        })->offset;
    assert(inradius > 0.0 && "rock body frame must have its centroid inside the hull");
    // A quarter of the distance to the nearest face keeps thin slabs from collapsing.
    const double margin = std::min(kCollisionMargin, 0.25 * inradius);
    const std::vector<Vec3> vertices = shrunk_vertices(planes, margin, 2.0 * rock.bounding_radius);
    for ([[maybe_unused]] const Vec3& v : vertices) {
        assert(std::all_of(planes.begin(), planes.end(), [&](const Plane& p) {
            return p.normal.dot(v) <= p.offset - margin + 1e-9 * rock.bounding_radius;
        }));
    }
    auto shape = std::make_unique<btConvexHullShape>();
    for (const Vec3& v : vertices) {
        shape->addPoint(btVector3(v.x(), v.y(), v.z()), false);
    }
    shape->setMargin(margin);
    shape->recalcLocalAabb();
    return shape;
}

std::unique_ptr<btBoxShape> make_box_shape(const shapes::OrientedBox& box) {
    const Vec3& h = box.half_extents;
    auto shape = std::make_unique<btBoxShape>(btVector3(h.x(), h.y(), h.z()));
    // btBoxShape::setMargin keeps the outer dimensions; a tenth of the thinnest half-extent
    // keeps the 5 mm legs of angle bars solid.
    shape->setMargin(std::min(kCollisionMargin, 0.1 * h.minCoeff()));
    return shape;
}

}  // namespace rockfall::engine
