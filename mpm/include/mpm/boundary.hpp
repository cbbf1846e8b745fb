#pragma once
/// Rigid boundaries of the MPM grid: static solids (slope, walls) and a hinged moving body
/// (the tilting release bed).
///
/// A grid node inside a solid (signed distance <= 0) is constrained each step after the grid
/// velocity update. Frictional: the approaching normal velocity relative to the solid is
/// removed and the tangential velocity is reduced by mu times the removed normal velocity,
/// stopping if it would reverse (Coulomb friction in velocity form: Bardenhagen et al. 2001,
/// J. Comput. Phys. 172, and Stomakhin et al. 2013, SIGGRAPH, sec. 8); separating nodes are
/// free. Fixed: the node takes the solid's velocity. Each solid belongs to a group; within a
/// group the solid the node is deepest in applies; groups apply in increasing order, and each
/// records the momentum it removes, so a node inside both the slope and the wall counts in the
/// wall's load only the wall's own velocity change.

#include "mpm/math.hpp"
#include "shapes/slope.hpp"

#include <vector>

namespace rockfall::mpm {

/// Number of boundary groups whose momentum the solver records.
inline constexpr int kBoundaryGroups = 4;

/// How a boundary acts on the soil.
enum class BoundaryKind {
    /// Coulomb friction, separation allowed.
    frictional,
    /// No slip, no separation: nodes move with the solid.
    fixed,
};

/// A static solid box.
struct StaticBoundary {
    /// The solid (scene frame).
    shapes::OrientedBox box;
    /// Frictional or fixed.
    BoundaryKind kind = BoundaryKind::frictional;
    /// Coulomb friction coefficient mu = tan(friction angle), >= 0 (0 = free slip).
    double friction_coefficient = 0.0;
    /// Group whose momentum it counts in, [0, kBoundaryGroups).
    int group = 0;
};

/// A spring-backed boundary group: its static solids form one rigid facing of mass `mass` that
/// translates along `direction`, held by a spring and a dashpot in parallel on a fixed support
/// (a load cell behind a panel). Its motion is solved each step together with the grid nodes it
/// constrains (m_f dw/dt = F_soil - k u - c w, trapezoidal rule, implicit in w: stable for any
/// stiffness and any mass of soil against it). Small displacements: the solids stay where
/// they are and only their velocity w direction acts on the nodes, so |u| must stay well
/// below the cell size.
struct SpringSupport {
    /// Boundary group whose static solids are the facing, [0, kBoundaryGroups).
    int group = 1;
    /// Direction of translation (scene frame, unit length); u > 0 moves the facing along it.
    Vec3 direction = Vec3::UnitX();
    /// Facing mass, kg (kg/m in 2D), > 0.
    double mass = 1.0;
    /// Spring stiffness, N/m (N/m per metre of width in 2D), > 0.
    double stiffness = 1.0;
    /// Dashpot coefficient, N s/m (per metre of width in 2D), >= 0.
    double damping = 0.0;
};

/// The box turned by rotation r about the point `pivot` (scene frame).
shapes::OrientedBox rotated_about(const shapes::OrientedBox& box, const Vec3& pivot, const Mat3& r);

/// A rigid body of boxes rotating about a horizontal axis parallel to scene y (the release
/// bed). A positive angle lifts the body's -x side: scene points rotate by R_y(angle) about
/// the hinge. The angle ramps linearly from start to end over [start_time, start_time +
/// duration] and is constant outside.
struct HingedBoundary {
    /// The boxes at angle 0 (scene frame).
    std::vector<shapes::OrientedBox> boxes;
    /// A point on the hinge axis (scene frame), m.
    Vec3 hinge = Vec3::Zero();
    /// Angle before the ramp, degrees.
    double start_angle_deg = 0.0;
    /// Angle after the ramp, degrees.
    double end_angle_deg = 0.0;
    /// Time the ramp starts, s (>= 0).
    double start_time = 0.0;
    /// Ramp duration, s (>= 0; 0 = a jump at start_time).
    double duration = 0.0;
    /// Frictional or fixed.
    BoundaryKind kind = BoundaryKind::frictional;
    /// Coulomb friction coefficient, >= 0.
    double friction_coefficient = 0.0;
    /// Group whose momentum it counts in, [0, kBoundaryGroups).
    int group = 0;

    /// Angle at time t, degrees.
    double angle_deg(double t) const;
    /// Angular velocity about +y at time t, rad/s.
    double angular_velocity(double t) const;
    /// The boxes placed at time t.
    std::vector<shapes::OrientedBox> boxes_at(double t) const;
};

}  // namespace rockfall::mpm
