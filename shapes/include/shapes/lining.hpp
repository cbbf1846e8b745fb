#pragma once
/// Rough linings laid on chosen profile segments of a slope (seed 001's flume): a fixed
/// hexagonal layer of spheres (the paper's DEM), spherical bumps, and a perforated sheet as real
/// geometry (the experiment's ebonite sheet), in the slope frame of shapes/slope.hpp.
///
/// Every lining lies on the segments' reference surfaces (a terrain mesh is ignored) between
/// the side walls (|y| <= width / 2). On a segment, u is the distance along the surface from its
/// upper end and v = y; (u, v, normal) is right-handed. Lattices are hexagonal with rows across
/// the slope: rows at u0 + k spacing sqrt(3) / 2, sites at v = j spacing on even rows and
/// (j + 1/2) spacing on odd rows, centred across the slope (a site on y = 0) and along each
/// segment (equal margins at both ends). Parameter errors throw std::invalid_argument naming
/// the field, its value, unit and allowed range.

#include "shapes/mesh_io.hpp"
#include "shapes/polyhedron.hpp"
#include "shapes/slope.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace rockfall::shapes {

/// A fixed sphere of a lining.
struct Sphere {
    /// Centre in the slope frame, m.
    Vec3 center = Vec3::Zero();
    /// Radius, m (> 0).
    double radius = 0.0;
    /// The profile segment it lies on.
    int segment = 0;
};

/// The paper's "fixed hexagonal closed grain layer": spheres touching the surface of each
/// chosen segment on a hexagonal lattice. Defaults: close packed (spacing = 2 radius) 16 mm
/// spheres on segment 0: 4782 spheres on the 1.82 m x 0.60 m flume (seed 001's DEM: 4880).
struct SphereLayer {
    /// Sphere radius, m, in [1e-3, 0.5].
    double radius = 0.008;
    /// Centre distance of lattice neighbours, m, in [2 radius, 10 radius] (2 radius: touching).
    double spacing = 0.016;
    /// Indices of the lined segments, distinct, each in [0, segments - 1].
    std::vector<int> segments = {0};
};

/// Spherical-cap bumps of a given height and base diameter on a hexagonal lattice, as spheres
/// sunk into the slab: a cap of height h and base radius a is the part above the surface of a
/// sphere of radius (a^2 + h^2) / (2 h) whose centre lies (h - radius) above the surface
/// (h = a: hemispheres). The part below the surface is inside the slab solid.
struct Bumps {
    /// Cap height above the surface, m, in [1e-3, base_diameter / 2] (cap at most a hemisphere).
    double height = 0.010;
    /// Diameter of the cap's circle on the surface, m, in [2 height, 1].
    double base_diameter = 0.020;
    /// Centre distance of lattice neighbours, m, in [base_diameter, 10 base_diameter].
    double spacing = 0.040;
    /// Indices of the lined segments, distinct, each in [0, segments - 1].
    std::vector<int> segments = {0};
};

/// The experiment's lining (seed 001, "Perforated sheet"): an ebonite sheet 1.5 mm thick with
/// 50 mm holes at 80 mm centres in a hexagonal pattern, lying on the chosen segments.
struct PerforatedSheet {
    /// Sheet thickness, m, in [1e-4, 0.05].
    double thickness = 0.0015;
    /// Hole diameter, m, in [5 thickness, 0.5]; holes are regular polygons inscribed in it.
    double hole_diameter = 0.050;
    /// Centre distance of neighbouring holes, m: at least 1.1 hole_diameter 2 / sqrt(3), so that
    /// a row of holes (rows sqrt(3) / 2 spacing apart) keeps a rim of 5 % of the hole diameter.
    double hole_spacing = 0.080;
    /// Sides of each hole polygon, in [8, 64].
    int hole_sides = 16;
    /// Indices of the lined segments, distinct, each in [0, segments - 1].
    std::vector<int> segments = {0};
};

/// Largest number of spheres a sphere layer or bumps may have (4880 in seed 001's DEM).
inline constexpr std::size_t max_lining_spheres = 1'000'000;

/// The rough lining of a slope: any of the three kinds, each on its own segments (a segment
/// may carry more than one). Static geometry for the rigid-body engine; the soil solver does
/// not see it.
struct Lining {
    std::optional<SphereLayer> spheres;
    std::optional<Bumps> bumps;
    std::optional<PerforatedSheet> sheet;
};

/// The spheres of the sphere layer and of the bumps, together.
std::vector<Sphere> lining_spheres(const Slope& slope, const Lining& lining);

/// The spheres of a sphere layer: each touches its segment's surface (centre radius above it),
/// its whole footprint (u in [radius, length - radius], |v| <= width / 2 - radius) lies on the
/// segment between the side walls. Where two lined segments meet at a concave kink, spheres of
/// the lower segment that would overlap one of the upper segment are left out. Throws
/// std::invalid_argument for a bad parameter or more than max_lining_spheres spheres.
std::vector<Sphere> sphere_layer(const Slope& slope, const SphereLayer& layer);

/// The spheres of a bump lining, laid out as sphere_layer with the cap's base radius as the
/// footprint. Throws std::invalid_argument as sphere_layer.
std::vector<Sphere> bump_spheres(const Slope& slope, const Bumps& bumps);

/// The surface plane of one profile segment: p(u, v, w) = origin + u tangent + v y + w normal,
/// u along the surface from the segment's upper end, v = y, w along the upward normal.
struct SegmentPlane {
    Vec3 origin = Vec3::Zero();
    Vec3 tangent = Vec3::UnitX();
    Vec3 normal = Vec3::UnitZ();
    /// Length along the surface and half the slope's width, m.
    double length = 0.0;
    double half_width = 0.0;
    /// The segment's index.
    int index = 0;

    Vec3 point(double u, double v, double w) const {
        return origin + u * tangent + v * Vec3::UnitY() + w * normal;
    }
};

/// One hole of a perforated sheet: a regular polygon of `sides` vertices inscribed in the
/// circle of `radius` about `center`, vertex i at the angle (i + 1/2) 2 pi / sides from the
/// segment's tangent towards +y.
struct SheetHole {
    /// Centre of the hole on the segment's surface (the sheet's underside), m.
    Vec3 center = Vec3::Zero();
    /// The segment's upward unit normal (the hole's axis).
    Vec3 normal = Vec3::UnitZ();
    /// The segment it lies on.
    int segment = 0;
    /// Radius of the circle the polygon is inscribed in, m.
    double radius = 0.0;
    /// Vertices of the polygon.
    int sides = 0;
};

/// The part of a perforated sheet on one segment, as the rigid-body engine's structured contact
/// sees it: the sheet covers plane.point(u, v, w) for u in [0, length], |v| <= half_width and
/// w in [0, thickness], less its holes.
struct SheetPanel {
    SegmentPlane plane;
    /// Sheet thickness, m.
    double thickness = 0.0;
    /// Indices into SheetMesh::holes of the holes on this panel.
    std::vector<std::size_t> holes;
};

/// A perforated sheet as triangles, in the slope frame.
struct SheetMesh {
    /// The top face (normals along the segment's upward normal) with polygonal holes, and the
    /// hole walls (normals towards the hole's axis). No underside: it lies on the slope
    /// surface, which shows through the holes. Not watertight: cells meet with T-junctions.
    TriangleMesh mesh;
    /// The holes cut.
    std::vector<SheetHole> holes;
    /// One panel per lined segment, in the order of PerforatedSheet::segments.
    std::vector<SheetPanel> panels;
    /// Triangles of the top face and of the hole walls (sum: mesh.triangles.size()).
    std::size_t top_triangles = 0;
    std::size_t wall_triangles = 0;
};

/// The sheet on each chosen segment, over u in [0, length] and |v| <= width / 2. The top face
/// is split into one rectangular cell per lattice site (u within half a row spacing, v within
/// half the hole spacing of it); a hole is cut where its circle stays inside its cell and the
/// sheet with a rim of at least 5 % of its diameter, else the cell is solid (so a band up to
/// one hole spacing wide along the side walls and the segment ends has no holes). Throws
/// std::invalid_argument for a bad parameter or more than max_terrain_triangles triangles.
SheetMesh perforated_sheet(const Slope& slope, const PerforatedSheet& sheet);

/// Whether the point at (du, dv) from a hole's centre (along its panel's tangent and y) lies
/// inside the hole's polygon: its projection on the normal of the nearest edge (the edge whose
/// middle has the nearest angle) is below the apothem radius cos(pi / sides).
bool inside_hole(const SheetHole& hole, double du, double dv);

}  // namespace rockfall::shapes
