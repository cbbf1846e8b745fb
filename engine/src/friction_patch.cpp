#include "friction_patch.hpp"

#include "plane_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace rockfall::engine {
namespace {

// At most kMaxPoints points, no allocation (a patch has a manifold's four at most).
constexpr int kMaxPoints = 8;
struct Polygon {
    Point2 points[kMaxPoints];
    int size = 0;
    const Point2* begin() const { return points; }
    const Point2* end() const { return points + size; }
    const Point2& operator[](int i) const { return points[i]; }
};

Polygon hull_of(const Polygon& input) {
    int corners[kMaxPoints];
    const int count = convex_hull(input.points, input.size, corners);
    Polygon hull;
    for (int i = 0; i < count; ++i) {
        hull.points[hull.size++] = input.points[corners[i]];
    }
    return hull;
}

Point2 closest_on_segment(const Point2& a, const Point2& b, const Point2& p) {
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double length2 = dx * dx + dy * dy;
    const double t =
        length2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
    return {a.x + t * dx, a.y + t * dy};
}

double distance2(const Point2& a, const Point2& b) {
    return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

// The point of the polygon (or segment, or point) nearest `p`.
Point2 clamp_into(const Polygon& polygon, const Point2& p) {
    if (polygon.size == 1) {
        return polygon[0];
    }
    bool inside = polygon.size >= 3;
    Point2 nearest = polygon[0];
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < polygon.size; ++i) {
        const Point2& a = polygon[i];
        const Point2& b = polygon[(i + 1) % polygon.size];
        inside = inside && cross(a, b, p) >= 0.0;
        const Point2 c = closest_on_segment(a, b, p);
        if (distance2(c, p) < best) {
            best = distance2(c, p);
            nearest = c;
        }
    }
    return inside ? p : nearest;
}

double twist_radius(const Polygon& polygon) {
    if (polygon.size < 2) {
        return 0.0;
    }
    if (polygon.size == 2) {
        return std::sqrt(distance2(polygon[0], polygon[1])) / 4.0;
    }
    double twice_area = 0.0;
    for (int i = 0; i < polygon.size; ++i) {
        twice_area += cross(polygon[0], polygon[i], polygon[(i + 1) % polygon.size]);
    }
    return 2.0 / 3.0 * std::sqrt(0.5 * std::abs(twice_area) / std::numbers::pi);
}

}  // namespace

PatchGeometry patch_geometry(const btVector3* points, int count, const btVector3& normal,
                             const btVector3* centre) {
    btVector3 centroid(0, 0, 0);
    for (int i = 0; i < count; ++i) {
        centroid += points[i];
    }
    centroid /= btScalar(count);
    btVector3 u;
    btVector3 w;
    btPlaneSpace1(normal, u, w);
    // Points closer than a micrometre are one: a hull of near-duplicates has no area.
    Polygon distinct;
    for (int i = 0; i < count && distinct.size < kMaxPoints; ++i) {
        const btVector3 r = points[i] - centroid;
        const Point2 p{r.dot(u), r.dot(w)};
        const bool seen = std::any_of(distinct.begin(), distinct.end(),
                                      [&](const Point2& q) { return distance2(p, q) < 1e-12; });
        if (!seen) {
            distinct.points[distinct.size++] = p;
        }
    }
    const Polygon polygon = hull_of(distinct);
    Point2 target{0.0, 0.0};
    if (centre != nullptr) {
        const btVector3 r = *centre - centroid;
        target = {r.dot(u), r.dot(w)};
    }
    const Point2 anchor = clamp_into(polygon, target);
    return {centroid + u * anchor.x + w * anchor.y, twist_radius(polygon)};
}

}  // namespace rockfall::engine
