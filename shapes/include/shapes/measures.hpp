#pragma once
/// Shape measures of a rock: size, axis lengths, sphericities and form ratios.

#include "shapes/mass_properties.hpp"
#include "shapes/polyhedron.hpp"
#include "shapes/rocks.hpp"

#include <Eigen/Core>

namespace rockfall::shapes {

/// Every shape measure of one solid; lengths in m.
struct ShapeMeasures {
    /// Exact mass properties per unit density (volume m3, area m2, centroid m, moments m5).
    MassProperties properties;
    /// Volume-equivalent diameter, m.
    double equivalent_diameter = 0.0;
    /// Long, intermediate and short axis lengths a >= b >= c, m: the extents of the hull along
    /// its principal axes of inertia (see axis_lengths).
    Vec3 axis_lengths = Vec3::Zero();
    /// Wadell sphericity pi^(1/3) (6 V)^(2/3) / A, in (0, 1] (Wadell 1935).
    double wadell_sphericity = 1.0;
    /// Krumbein intercept sphericity (b c / a^2)^(1/3), in (0, 1] (Krumbein 1941).
    double krumbein_sphericity = 1.0;
    /// Zingg flatness ratio c / b, in (0, 1] (Zingg 1935).
    double flatness = 1.0;
    /// Zingg elongation ratio b / a, in (0, 1] (Zingg 1935).
    double elongation = 1.0;
};

/// Long, intermediate and short axis lengths a >= b >= c of a hull, m: its extents (max - min
/// of the vertex projections) along the principal axes of inertia in `properties` (which must
/// be the hull's). Where the principal axes are not unique (two or three equal moments, as for
/// every Platonic solid) the extents are those of the most equant (largest b c / a^2)
/// principal frame spanned by two perpendicular directions from the centroid to a vertex or
/// an edge midpoint, along a face normal or along an edge; if there is none (or the hull
/// gives over 20000 such directions) the eigen-solver's arbitrary principal frame is used.
Vec3 axis_lengths(const ConvexPolyhedron& hull, const MassProperties& properties);

/// Measures of a convex hull of any position and orientation.
ShapeMeasures shape_measures(const ConvexPolyhedron& hull);

/// Measures of a rock as the engine simulates it; a sphere uses its exact properties and
/// a = b = c = its diameter.
ShapeMeasures shape_measures(const RockGeometry& rock);

}  // namespace rockfall::shapes
