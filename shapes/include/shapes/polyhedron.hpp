#pragma once
/// Convex polyhedra: the geometry of every rock, built from point clouds with Qhull.

#include <Eigen/Core>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::shapes {

using Vec3 = Eigen::Vector3d;

/// Bad geometry from user data (degenerate, non-finite or absurd); the message names the problem.
class GeometryError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// A closed convex polyhedron; triangles are counter-clockwise seen from outside.
struct ConvexPolyhedron {
    /// Vertex positions, m. Every vertex is a hull vertex.
    std::vector<Vec3> vertices;
    /// Outward-oriented triangles as indices into `vertices`.
    std::vector<std::array<int, 3>> triangles;
};

/// Convex hull of a point cloud, computed by Qhull. Throws GeometryError for fewer than four
/// points, non-finite coordinates, or points that are all collinear or coplanar (zero volume).
/// Vertices within 1e-9 (relative) of a hull edge are dropped, so that every triangle has a
/// well-defined normal; nothing is printed.
ConvexPolyhedron convex_hull(const std::vector<Vec3>& points);

/// The same polyhedron translated by `offset` and then rotated by `rotation` (p' = R (p + t)).
ConvexPolyhedron transformed(const ConvexPolyhedron& poly, const Eigen::Matrix3d& rotation,
                             const Vec3& offset);

}  // namespace rockfall::shapes
