#pragma once
// Shared set-ups for the MPM tests: boxes in the scene frame.

#include "mpm/boundary.hpp"
#include "shapes/slope.hpp"

#include <cmath>
#include <numbers>

namespace rockfall::mpm::test {

// Axis-aligned box between two corners (scene frame).
inline shapes::OrientedBox axis_box(const Vec3& lo, const Vec3& hi) {
    shapes::OrientedBox box;
    box.center = 0.5 * (lo + hi);
    box.half_extents = 0.5 * (hi - lo);
    return box;
}

// Box whose local x axis points down an incline of `angle_deg` (rotation about scene y), with
// the given centre and half extents along (downslope, across, normal).
inline shapes::OrientedBox inclined_box(double angle_deg, const Vec3& center, const Vec3& half) {
    const double a = angle_deg * std::numbers::pi / 180.0;
    shapes::OrientedBox box;
    box.rotation.col(0) = Vec3(std::cos(a), 0.0, -std::sin(a));
    box.rotation.col(1) = Vec3::UnitY();
    box.rotation.col(2) = Vec3(std::sin(a), 0.0, std::cos(a));
    box.center = center;
    box.half_extents = half;
    return box;
}

inline StaticBoundary solid(const shapes::OrientedBox& box, BoundaryKind kind, double mu,
                            int group) {
    StaticBoundary b;
    b.box = box;
    b.kind = kind;
    b.friction_coefficient = mu;
    b.group = group;
    return b;
}

}  // namespace rockfall::mpm::test
