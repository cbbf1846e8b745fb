#pragma once
/// Mesh files: rock hulls from any format assimp reads (tested: OBJ, STL, PLY, OFF, glTF,
/// GLB), and the hull written back as OBJ or STL.

#include "shapes/polyhedron.hpp"

#include <array>
#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace rockfall::shapes {

/// The most vertices a mesh file (a rock or a terrain) may hold: 200000, counted over every
/// mesh in the file as placed by its nodes. Checked before any work on them: from a PLY file's
/// header and a binary STL's triangle count before assimp reads the file, and from assimp's
/// result before a hull or terrain is built. The convex hull of 200000 points all on it takes
/// Qhull about 5 s.
inline constexpr std::size_t max_mesh_vertices = 200'000;

/// The most vertices the convex hull of a rock read from a mesh file may have: 2000. The
/// engine's collision tests visit every hull vertex, so a simulated rock costs about 1 s of CPU
/// at 1000 hull vertices (0.1 s at 70, 13 s at 10000; bench machine, seed slope).
inline constexpr std::size_t max_hull_vertices = 2'000;

/// How a mesh's coordinates become the rock: coordinates are multiplied by `scale`, then the
/// hull is rescaled to `size` or `long_axis` when one of them is > 0 (not both).
struct MeshScaling {
    /// Factor from the file's units to metres, finite and > 0 (0.001 for a mesh in mm).
    double scale = 1.0;
    /// Target volume-equivalent diameter, m; 0 keeps the scaled mesh's own size; else within
    /// [min_nominal_size, max_nominal_size].
    double size = 0.0;
    /// Target long axis a (extent along the axis of least inertia), m; 0 keeps the size.
    double long_axis = 0.0;
};

/// A surface as triangles over shared vertices (a terrain, or any mesh file's faces).
struct TriangleMesh {
    /// Vertex positions, m.
    std::vector<Vec3> vertices;
    /// Triangles as indices into `vertices`, in the file's winding.
    std::vector<std::array<int, 3>> triangles;
};

/// Lower-case file extensions (with the dot) of every format assimp reads, e.g. ".obj".
std::vector<std::string> mesh_extensions();

/// Whether assimp reads files with this name's extension (case-insensitive).
bool is_mesh_file(const std::filesystem::path& file);

/// Every vertex of every mesh in the file, in metres as written (node transforms applied).
/// Throws GeometryError naming the file for a missing or unreadable file, an unknown format,
/// a file assimp cannot parse, a file without vertices, more than max_mesh_vertices vertices, a
/// PLY header that breaks the format's rules (no `end_header`, an unknown line, counts the file
/// cannot hold) and a non-finite coordinate. assimp reads coordinates in single precision
/// (Debian builds it with float ai_real).
std::vector<Vec3> read_mesh_vertices(const std::filesystem::path& file);

/// Every vertex and every triangle of every mesh in the file (node transforms applied;
/// polygons triangulated by assimp; points and lines dropped; vertices as the file lists them,
/// so an STL repeats each corner in every triangle that uses it). Throws GeometryError naming the
/// file for every problem of read_mesh_vertices and a mesh further from the origin than 1000 times
/// its extent (as read_mesh_hull). A file without triangles is not an error here: what needs them
/// says so.
TriangleMesh read_mesh_triangles(const std::filesystem::path& file);

/// The convex hull (Qhull) of a mesh file's vertices, scaled as `scaling` says. Throws
/// GeometryError naming the file for every problem of read_mesh_vertices, a bad scaling,
/// vertices that span no volume (collinear or coplanar), a hull of more than max_hull_vertices
/// vertices, a mesh that lies further from the
/// origin than 1000 times its own extent (single precision would blur its shape), and a rock
/// whose volume-equivalent diameter ends outside [min_nominal_size, max_nominal_size] m.
ConvexPolyhedron read_mesh_hull(const std::filesystem::path& file, const MeshScaling& scaling = {});

/// A hull scaled as `scaling` says; `what` names it in messages (e.g. "mesh 'rock.obj'").
/// Throws GeometryError for a bad scaling or a result outside the accepted size range.
ConvexPolyhedron scaled_hull(const ConvexPolyhedron& hull, const MeshScaling& scaling,
                             std::string_view what);

/// Writes the hull as Wavefront OBJ: one `v x y z` line per vertex (m, shortest exact
/// decimal), one `f i j k` line per outward triangle; `comment` (may be several lines) first.
void write_obj(std::ostream& out, const ConvexPolyhedron& hull, std::string_view comment);

/// Writes a triangle mesh as Wavefront OBJ: `v x y z` lines (m, shortest exact decimal), then
/// `f i j k` lines in the mesh's winding; `comment` (may be several lines) first.
void write_obj(std::ostream& out, const TriangleMesh& mesh, std::string_view comment);

/// Writes the hull as ASCII STL named `name`, with each triangle's outward unit normal.
void write_stl(std::ostream& out, const ConvexPolyhedron& hull, std::string_view name);

}  // namespace rockfall::shapes
