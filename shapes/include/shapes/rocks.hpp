#pragma once
/// Rock geometries: the seed paper's three shapes at a nominal size.

#include "shapes/mass_properties.hpp"
#include "shapes/polyhedron.hpp"

#include <string>
#include <string_view>

namespace rockfall::shapes {

/// Shape family of a rock model (seed 000, Figure 3).
enum class RockKind {
    sphere,   ///< an exact sphere
    massive,  ///< blocky and roughly equant
    planar,   ///< slab-like
    custom,   ///< any convex hull given by the user: a mesh file, a catalogue entry, a generator
};

/// Lower-case name of a kind ("sphere", "massive", "planar", "custom").
std::string_view to_string(RockKind kind);

/// A rock in its body frame: centroid at the origin, principal axes along x, y, z with the
/// principal moments ascending, so x is the long axis and z the short one.
struct RockGeometry {
    /// Shape family.
    RockKind kind = RockKind::sphere;
    /// Nominal size: the volume-equivalent diameter, m.
    double nominal_size = 0.0;
    /// Radius, m; > 0 only for spheres, which the engine simulates as exact spheres.
    double radius = 0.0;
    /// The convex hull; for a sphere a fine tessellation, used for display and export only.
    ConvexPolyhedron hull;
    /// Exact mass properties per unit density (analytic for spheres); centroid is the origin
    /// and the inertia tensor is diagonal.
    MassProperties properties;
    /// Wadell sphericity (1 for a sphere).
    double sphericity = 1.0;
    /// Half-extents of the axis-aligned bounding box in the body frame, m.
    Vec3 half_extents = Vec3::Zero();
    /// Radius of the bounding sphere about the centroid, m.
    double bounding_radius = 0.0;
};

/// Smallest accepted nominal size (volume-equivalent diameter) of any rock, m.
inline constexpr double min_nominal_size = 1e-3;
/// Largest accepted nominal size of any rock, m.
inline constexpr double max_nominal_size = 100.0;

/// A rock shape given as a convex hull instead of a family (kind RockKind::custom).
struct CustomShape {
    /// Name shown in reports: the catalogue entry, the mesh file's stem or the generator.
    std::string name;
    /// The hull in metres, at any position, orientation and scale.
    ConvexPolyhedron hull;
};

/// The seed's shapes at a nominal (volume-equivalent) diameter in m, within [1e-3, 100].
/// Massive: a chamfered block with axis ratios 1 : 0.9 : 0.8. Planar: a chamfered slab with
/// axis ratios 1 : 0.8 : 0.35. Both have each corner cut off at 0.2 of the shortest half-axis
/// along its three edges. Deterministic: the same size gives the same hull. Throws
/// GeometryError for a size outside the range, or for kind custom (which needs a hull).
RockGeometry make_rock(RockKind kind, double nominal_size);
/// A custom shape as a rock of kind custom: rock_from_hull(shape.hull, custom, nominal_size).
RockGeometry make_rock(const CustomShape& shape, double nominal_size);

/// Wraps any convex hull as a rock: moves it to its centroid, rotates it onto its principal
/// axes and scales it to the given volume-equivalent diameter (unchanged when size <= 0;
/// otherwise within [1e-3, 100] m). Throws GeometryError for kind sphere (use make_rock).
RockGeometry rock_from_hull(const ConvexPolyhedron& hull, RockKind kind, double nominal_size);

}  // namespace rockfall::shapes
