#pragma once
/// Rock shape generators: random rocks reproducible from a seed, and the seed paper's clump
/// shapes as true polyhedra.

#include "shapes/polyhedron.hpp"
#include "shapes/rocks.hpp"

#include <cstdint>
#include <string_view>

namespace rockfall::shapes {

/// The random point cloud a generated rock is the hull of: `points` directions uniform on the
/// unit sphere (Archimedes: z uniform in [-1, 1], azimuth uniform), each at radius
/// 1 - roughness * u with u uniform in [0, 1), three draws per point from make_generator(seed).
struct RandomRockOptions {
    /// Number of points, in [8, 10000]; more points give a rounder, smoother rock.
    int points = 80;
    /// Depth of the radial scatter below the surface, as a fraction of the radius, in [0, 0.9).
    double roughness = 0.1;
};

/// A random rock with the given axis ratios: the hull of the seed's point cloud stretched by
/// the ratios, then scaled along its own principal axes of inertia so that its long,
/// intermediate and short axes (axis_lengths) are exactly in the ratios. `axis_ratios` are
/// three finite numbers > 0 in any order and unit (only their ratios count); the shortest must
/// be at least 0.01 of the longest. The long axis is 1 m; rescale with make_rock. Throws
/// GeometryError for bad ratios or options.
ConvexPolyhedron ellipsoid_rock(const Vec3& axis_ratios, std::uint64_t seed,
                                const RandomRockOptions& options = {});

/// Result of rock_with_sphericity.
struct SphericityRock {
    /// The hull, long axis of order 1 m; rescale with make_rock.
    ConvexPolyhedron hull;
    /// Its Wadell sphericity, within 1e-4 of the target.
    double sphericity = 0.0;
    /// The stretch t of the point cloud: axes 1 : t : t^2, in (0, 1].
    double stretch = 1.0;
};

/// A random rock with a target Wadell sphericity: the seed's point cloud stretched to
/// 1 : t : t^2 (Zingg ratios b/a = c/b = t, neither disc- nor rod-like), with t found by
/// bisection so that the hull's sphericity meets the target within 1e-4. A linear stretch
/// keeps the hull's faces, so the sphericity is a smooth function of t. The targets a seed can
/// reach run from that of t = 0.02 (about 0.04) to that of the unstretched cloud (0.963 to
/// 0.976 over seeds 0-49 with the default options; more points and less roughness go higher).
/// Throws GeometryError for a target outside that range or bad options.
SphericityRock rock_with_sphericity(double sphericity, std::uint64_t seed,
                                    const RandomRockOptions& options = {});

/// The four particle shapes of seed 001 (10-ball tetrahedral, 27-ball cubic and 19-ball
/// octahedral clumps, and a sphere), here as the true solids the clumps approximate.
enum class ClumpShape {
    tetrahedral,  ///< regular tetrahedron, Wadell sphericity 0.671
    cubic,        ///< cube, 0.806
    octahedral,   ///< regular octahedron, 0.846
    sphere,       ///< exact sphere, 1
};

/// Lower-case name ("tetrahedral", "cubic", "octahedral", "sphere").
std::string_view to_string(ClumpShape shape);

/// The clump shape as a rock at a nominal (volume-equivalent) size, m, as seed 001 sized its
/// clumps: a Platonic solid of kind custom named "tetrahedron", "cube" or "octahedron", or
/// make_rock(RockKind::sphere, size). Throws GeometryError for a size outside the range.
RockGeometry clump_rock(ClumpShape shape, double nominal_size);

}  // namespace rockfall::shapes
