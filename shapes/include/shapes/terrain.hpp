#pragma once
/// Terrain from files: a triangle mesh (a survey) that replaces the slope slabs as the surface
/// rocks roll and bounce on, and the ground under a point for the recorders and stop rule.
///
/// The slope's profile segments stay the reference frame (crown, toe, stations, reach, bars,
/// walls); the mesh must lie in the same frame: x downslope from the crown, y across, z up.

#include "shapes/mesh_io.hpp"
#include "shapes/polyhedron.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rockfall::shapes {

class Slope;
struct SlopeSpec;

/// How a mesh's coordinates become slope-frame coordinates: p' = scale p + offset.
struct TerrainPlacement {
    /// Factor from the file's units to metres, finite and > 0 (0.001 for a mesh in mm).
    double scale = 1.0;
    /// Added after scaling, m, finite: moves a survey into the slope frame.
    Vec3 offset = Vec3::Zero();
};

/// Smallest accepted extent (bounding-box diagonal) of a terrain, m.
inline constexpr double min_terrain_extent = 1.0;
/// Largest accepted extent of a terrain, m.
inline constexpr double max_terrain_extent = 10000.0;
/// Most triangles a terrain may have: Bullet's quantized BVH keeps 21 bits for the index.
inline constexpr int max_terrain_triangles = (1 << 21) - 1;

/// The ground under a point: the height of the surface there and its upward unit normal.
struct Ground {
    /// Surface height z, m.
    double height = 0.0;
    /// Upward unit normal (z > 0).
    Vec3 normal = Vec3::UnitZ();
};

/// A terrain surface: a placed, cleaned triangle mesh with an index for vertical queries.
class Terrain {
  public:
    /// Places `mesh` as `placement` says, merges vertices at identical positions and drops
    /// zero-area triangles. `name` is shown in reports; `what` names the source in messages
    /// (e.g. "terrain mesh file 'survey.obj'"). Throws GeometryError for a bad placement, an
    /// index out of range, a non-finite vertex, no triangles, only degenerate triangles, more
    /// than max_terrain_triangles, or an extent outside [min_terrain_extent,
    /// max_terrain_extent] m.
    Terrain(std::string name, TriangleMesh mesh, const TerrainPlacement& placement,
            std::string_view what);

    /// Name shown in reports (the file's stem for a mesh file).
    const std::string& name() const { return name_; }
    /// The mesh in the slope frame, m, as the engine simulates it.
    const TriangleMesh& mesh() const { return mesh_; }
    /// Corners of the axis-aligned bounding box, m.
    const Vec3& lower() const { return lower_; }
    const Vec3& upper() const { return upper_; }
    /// Zero-area triangles dropped on construction (shown by `rockfall terrain`).
    int dropped_triangles() const { return dropped_; }

    /// The top surface over or under (x, y): the highest triangle whose horizontal projection
    /// contains the point; nothing outside the mesh, in a hole, or under vertical faces only.
    std::optional<Ground> ground(double x, double y) const;

    /// Whether the engine corrects contact normals at the mesh's internal edges (Bullet's
    /// internal-edge utility); default true. False only to show the artefact it removes.
    bool internal_edge_correction() const { return internal_edge_correction_; }
    void set_internal_edge_correction(bool on) { internal_edge_correction_ = on; }

  private:
    // Index of the grid column (axis 0) or row (axis 1) of a coordinate, clamped to the grid.
    int cell_of(double coordinate, int axis) const;

    std::string name_;
    TriangleMesh mesh_;
    Vec3 lower_ = Vec3::Zero();
    Vec3 upper_ = Vec3::Zero();
    int dropped_ = 0;
    bool internal_edge_correction_ = true;
    // Uniform grid over the horizontal bounding box: cell (i, j) lists the triangles whose
    // horizontal bounding box overlaps it, in cell_triangles_[cell_start_[c], cell_start_[c+1]).
    double cell_size_ = 1.0;
    int columns_ = 1;
    int rows_ = 1;
    std::vector<int> cell_start_;
    std::vector<int> cell_triangles_;
};

/// Reads a terrain from a mesh file (read_mesh_triangles) and places it; `name` defaults to the
/// file's stem. Throws GeometryError naming the file for every problem of read_mesh_triangles
/// and of Terrain's constructor.
Terrain read_terrain(const std::filesystem::path& file, const TerrainPlacement& placement = {},
                     const std::string& name = "");

/// The ground under (x, y): the terrain's top surface where the slope has a terrain that
/// covers (x, y); the reference profile's surface at x everywhere else.
Ground ground_at(const Slope& slope, double x, double y);

/// How far a terrain departs from the slope's reference profile: the height dz of its
/// vertices above the profile, over the slope's footprint (0 <= x <= end, |y| <= width / 2).
struct ProfileDeviation {
    /// Largest |dz| and root mean square of dz, m; 0 without vertices over the footprint.
    double max = 0.0;
    double rms = 0.0;
    /// Vertices over the footprint.
    std::size_t vertices = 0;
};

ProfileDeviation profile_deviation(const Terrain& terrain, const Slope& slope);

/// A regular triangulation of a slope's reference profile, for tests and sample terrains.
struct TerrainGrid {
    /// Largest edge of the grid along x (on the surface) and y, m (> 0).
    double spacing = 0.25;
    /// How far the mesh reaches past the crown, the end and both sides of the slope, m (>= 0).
    double margin = 0.5;
    /// Root-mean-square height of a smooth random relief added to the profile, m (>= 0).
    double roughness = 0.0;
    /// Shortest wavelength of the relief, m (> spacing); the longest is 8 times it.
    double wavelength = 1.0;
    /// Seed of the relief.
    std::uint64_t seed = 1;
};

/// The profile of `spec` over its width plus margins as a triangle mesh: vertices on every
/// kink, quads split along alternating diagonals, plus the relief. Throws GeometryError for a
/// bad grid.
TriangleMesh profile_terrain(const SlopeSpec& spec, const TerrainGrid& grid);

}  // namespace rockfall::shapes
