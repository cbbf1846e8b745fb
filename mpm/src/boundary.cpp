#include "mpm/boundary.hpp"

#include "grid.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace rockfall::mpm {
double HingedBoundary::angle_deg(double t) const {
    if (t <= start_time) {
        return start_angle_deg;
    }
    if (duration <= 0.0 || t >= start_time + duration) {
        return end_angle_deg;
    }
    return start_angle_deg + (end_angle_deg - start_angle_deg) * (t - start_time) / duration;
}

double HingedBoundary::angular_velocity(double t) const {
    if (duration <= 0.0 || t < start_time || t >= start_time + duration) {
        return 0.0;
    }
    return radians(end_angle_deg - start_angle_deg) / duration;
}

shapes::OrientedBox rotated_about(const shapes::OrientedBox& box, const Vec3& pivot,
                                  const Mat3& r) {
    shapes::OrientedBox turned = box;
    turned.center = pivot + r * (box.center - pivot);
    turned.rotation = r * box.rotation;
    return turned;
}

std::vector<shapes::OrientedBox> HingedBoundary::boxes_at(double t) const {
    const Mat3 r = rotation_y(radians(angle_deg(t)));
    std::vector<shapes::OrientedBox> placed;
    placed.reserve(boxes.size());
    for (const shapes::OrientedBox& box : boxes) {
        placed.push_back(rotated_about(box, hinge, r));
    }
    return placed;
}

namespace detail {

Bounds bounds_of(const shapes::OrientedBox& box) {
    const Vec3 reach = box.rotation.cwiseAbs() * box.half_extents;
    return {box.center - reach, box.center + reach};
}

template <int Dim>
NodeRule<Dim> classify_node(const Vec3& x, const std::vector<StaticBoundary>& statics,
                            const std::vector<Bounds>& bounds, double reach) {
    assert(statics.size() == bounds.size());
    std::array<double, kBoundaryGroups> depth;
    depth.fill(0.0);
    std::array<NodeConstraint<Dim>, kBoundaryGroups> best{};
    for (std::size_t i = 0; i < statics.size(); ++i) {
        if (!bounds[i].contains(x, reach + 1e-12)) {
            continue;
        }
        Vec3 normal;
        const double distance = shapes::signed_distance(statics[i].box, x, &normal);
        const int group = statics[i].group;
        if (distance > reach || (best[group].boundary >= 0 && distance >= depth[group])) {
            continue;
        }
        Vec<Dim> n = from_scene<Dim>(normal);
        const double length = n.norm();
        // In 2D a face whose normal is out of plane (scene y) does not act in the plane.
        if (length < 1e-6) {
            continue;
        }
        depth[group] = distance;
        best[group] = {n / length, static_cast<int>(i)};
    }
    NodeRule<Dim> rule;
    for (int group = 0; group < kBoundaryGroups; ++group) {
        if (best[group].boundary >= 0) {
            rule.constraints[rule.count++] = best[group];
        }
    }
    return rule;
}

template NodeRule<2> classify_node<2>(const Vec3&, const std::vector<StaticBoundary>&,
                                      const std::vector<Bounds>&, double);
template NodeRule<3> classify_node<3>(const Vec3&, const std::vector<StaticBoundary>&,
                                      const std::vector<Bounds>&, double);

}  // namespace detail
}  // namespace rockfall::mpm
