// The geometry of a hull rock pressed into the wall's plane, for the rounded-polyhedron wall
// law (wall_contact.hpp): feature edges, inscribed radius and largest face once per rock; the
// penetrating edge, section and volume at each fine step, without allocation.

#include "engine/wall_contact.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace rockfall::engine {
namespace {

// Triangles whose unit normals agree within this (1 - cos, about 1.4 mrad) lie in one face:
// Qhull's hulls give coplanar triangles of one facet to round-off.
constexpr double kCoplanar = 1e-6;

Vec3 unit_normal(const shapes::ConvexPolyhedron& hull, const std::array<int, 3>& t) {
    const Vec3& a = hull.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = hull.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = hull.vertices[static_cast<std::size_t>(t[2])];
    return (b - a).cross(c - a).normalized();
}

double triangle_area(const shapes::ConvexPolyhedron& hull, const std::array<int, 3>& t) {
    const Vec3& a = hull.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = hull.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = hull.vertices[static_cast<std::size_t>(t[2])];
    return 0.5 * (b - a).cross(c - a).norm();
}

int root(std::vector<int>& parent, int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
        i = parent[static_cast<std::size_t>(i)] =
            parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    }
    return i;
}

// A triangle clipped to the half-space of positive depth: at most four corners.
struct Clipped {
    std::array<Vec3, 4> points;
    int count = 0;
};

// Sutherland-Hodgman against one plane; `depth` of each corner is > 0 inside.
Clipped clip(const std::array<Vec3, 3>& corners, const std::array<double, 3>& depth) {
    Clipped out;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const double di = depth[static_cast<std::size_t>(i)];
        const double dj = depth[static_cast<std::size_t>(j)];
        if (di > 0.0) {
            out.points[static_cast<std::size_t>(out.count++)] =
                corners[static_cast<std::size_t>(i)];
        }
        if ((di > 0.0) != (dj > 0.0)) {
            const double s = di / (di - dj);
            out.points[static_cast<std::size_t>(out.count++)] =
                corners[static_cast<std::size_t>(i)] +
                s * (corners[static_cast<std::size_t>(j)] - corners[static_cast<std::size_t>(i)]);
        }
    }
    return out;
}

}  // namespace

HullFeatures hull_features(const shapes::ConvexPolyhedron& hull) {
    HullFeatures features;
    const std::size_t n = hull.triangles.size();
    assert(n >= 4);
    std::vector<Vec3> normals;
    normals.reserve(n);
    features.inscribed_radius = std::numeric_limits<double>::infinity();
    for (const std::array<int, 3>& t : hull.triangles) {
        normals.push_back(unit_normal(hull, t));
        features.inscribed_radius =
            std::min(features.inscribed_radius,
                     normals.back().dot(hull.vertices[static_cast<std::size_t>(t[0])]));
    }
    assert(features.inscribed_radius > 0.0 && "the centroid must be inside the hull");
    // Each undirected edge and the triangles on its two sides.
    std::map<std::pair<int, int>, std::vector<int>> sides;
    for (std::size_t i = 0; i < n; ++i) {
        const std::array<int, 3>& t = hull.triangles[i];
        for (int k = 0; k < 3; ++k) {
            const int a = t[static_cast<std::size_t>(k)];
            const int b = t[static_cast<std::size_t>((k + 1) % 3)];
            sides[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(i));
        }
    }
    std::vector<int> face(n);
    std::iota(face.begin(), face.end(), 0);
    for (const auto& [edge, triangles] : sides) {
        assert(triangles.size() == 2 && "a closed hull has two triangles at every edge");
        const std::size_t p = static_cast<std::size_t>(triangles[0]);
        const std::size_t q = static_cast<std::size_t>(triangles[1]);
        if (1.0 - normals[p].dot(normals[q]) <= kCoplanar) {
            face[static_cast<std::size_t>(root(face, triangles[0]))] = root(face, triangles[1]);
            continue;
        }
        features.edges.push_back({edge.first, edge.second});
        const double length = (hull.vertices[static_cast<std::size_t>(edge.first)] -
                               hull.vertices[static_cast<std::size_t>(edge.second)])
                                  .norm();
        features.longest_edge = std::max(features.longest_edge, length);
    }
    std::vector<double> area(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        area[static_cast<std::size_t>(root(face, static_cast<int>(i)))] +=
            triangle_area(hull, hull.triangles[i]);
    }
    features.largest_face_area = *std::max_element(area.begin(), area.end());
    return features;
}

HullPenetration hull_penetration(const shapes::ConvexPolyhedron& hull, const HullFeatures& features,
                                 const Vec3& normal, double offset) {
    const auto depth_of = [&](int i) {
        return offset - normal.dot(hull.vertices[static_cast<std::size_t>(i)]);
    };
    HullPenetration result;
    // The edge: depth integrated along its penetrating part (linear between the vertices).
    double best_integral = 0.0;
    for (const std::array<int, 2>& e : features.edges) {
        double da = depth_of(e[0]);
        double db = depth_of(e[1]);
        if (da <= 0.0 && db <= 0.0) {
            continue;
        }
        if (da < db) {
            std::swap(da, db);
        }
        const double length = (hull.vertices[static_cast<std::size_t>(e[0])] -
                               hull.vertices[static_cast<std::size_t>(e[1])])
                                  .norm();
        const double inside = db > 0.0 ? length : length * da / (da - db);
        const double mean = db > 0.0 ? 0.5 * (da + db) : 0.5 * da;
        if (inside * mean > best_integral) {
            best_integral = inside * mean;
            result.edge_length = inside;
            result.edge_depth = mean;
        }
    }
    // Section and volume from the hull's surface beyond the plane: with the apex o on the
    // plane the cap adds no volume, and the cap's area is the projection of the rest onto the
    // plane (a closed surface's area vectors sum to zero).
    const Vec3 apex = offset * normal;
    double projected = 0.0;
    for (const std::array<int, 3>& t : hull.triangles) {
        const std::array<double, 3> depth{depth_of(t[0]), depth_of(t[1]), depth_of(t[2])};
        if (depth[0] <= 0.0 && depth[1] <= 0.0 && depth[2] <= 0.0) {
            continue;
        }
        const Clipped piece = clip({hull.vertices[static_cast<std::size_t>(t[0])],
                                    hull.vertices[static_cast<std::size_t>(t[1])],
                                    hull.vertices[static_cast<std::size_t>(t[2])]},
                                   depth);
        for (int k = 1; k + 1 < piece.count; ++k) {
            const Vec3 a = piece.points[0] - apex;
            const Vec3 b = piece.points[static_cast<std::size_t>(k)] - apex;
            const Vec3 c = piece.points[static_cast<std::size_t>(k + 1)] - apex;
            const Vec3 area = 0.5 * (b - a).cross(c - a);
            result.volume += a.dot(b.cross(c)) / 6.0;
            projected += area.dot(normal);
        }
    }
    result.section_area = std::max(0.0, -projected);
    result.volume = std::max(0.0, result.volume);
    return result;
}

}  // namespace rockfall::engine
