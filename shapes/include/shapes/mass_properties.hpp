#pragma once
/// Exact mass properties and shape measures of convex polyhedra.

#include "shapes/polyhedron.hpp"

#include <Eigen/Core>

namespace rockfall::shapes {

/// Exact mass properties of a solid of uniform unit density.
struct MassProperties {
    /// Volume, m3 (> 0).
    double volume = 0.0;
    /// Surface area, m2.
    double surface_area = 0.0;
    /// Centre of mass (centroid of the solid), m.
    Vec3 centroid = Vec3::Zero();
    /// Inertia tensor about the centroid per unit density, m5 (multiply by density for kg m2).
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    /// Principal moments per unit density, m5, ascending.
    Vec3 principal_moments = Vec3::Zero();
    /// Principal axes as columns, matching `principal_moments`; a proper rotation (det = +1).
    Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();
};

/// Exact volume, area, centroid and inertia of a closed polyhedron by divergence-theorem
/// integrals over its triangles (Mirtich 1996; Eberly, "Polyhedral mass properties").
MassProperties mass_properties(const ConvexPolyhedron& poly);

/// Wadell sphericity psi = pi^(1/3) (6 V)^(2/3) / A: 1 for a sphere, < 1 otherwise.
/// volume in m3 (> 0), surface_area in m2 (> 0).
double wadell_sphericity(double volume, double surface_area);

/// Diameter of the sphere with the same volume, m: (6 V / pi)^(1/3).
double equivalent_diameter(double volume);

}  // namespace rockfall::shapes
