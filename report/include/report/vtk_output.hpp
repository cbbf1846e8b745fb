#pragma once
/// ParaView output of a rigid-body run: the rocks' hulls posed at each frame as VTK XML
/// PolyData (.vtp), a .pvd collection listing the frames with their times, and the static
/// geometry once (slope solids, lining, release-box wall). ASCII, metres, slope frame.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <array>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace rockfall::report {

/// One named value per triangle of a surface (VTK cell data).
struct CellArray {
    /// Name shown in ParaView, with its unit as elsewhere (`speed_m_s`).
    std::string name;
    /// Written as Int32 when true, else Float64.
    bool integer = false;
    /// One value per triangle.
    std::vector<double> values;
};

/// A triangle surface for one .vtp file.
struct VtkSurface {
    /// Vertex positions, m.
    std::vector<engine::Vec3> points;
    /// Triangles as indices into `points`.
    std::vector<std::array<int, 3>> triangles;
    /// Cell data, each with one value per triangle.
    std::vector<CellArray> cells;
};

/// Writes `surface` as an ASCII VTK XML PolyData file; `time` (s) goes into its field data as
/// TimeValue when finite.
void write_vtp(std::ostream& out, const VtkSurface& surface, double time);

/// One dataset of a .pvd collection.
struct PvdEntry {
    /// Time of the frame, s.
    double time = 0.0;
    /// File name, relative to the .pvd file.
    std::string file;
};

/// Writes a ParaView collection (.pvd) listing `entries` in the order given.
void write_pvd(std::ostream& out, const std::vector<PvdEntry>& entries);

/// The rocks of one frame: rock index (0-based, outcome order) and state.
struct RockFrame {
    /// Time of the frame, s: its earliest sample's.
    double time = 0.0;
    /// The rocks in the world at that time, by index.
    std::map<int, engine::RockState> rocks;
};

/// Collects trajectory samples into frames `interval` apart (a sink for
/// engine::RunOptions::trajectory): frame k holds each rock's first sample at or after
/// k interval (and before (k + 1) interval). Frames without samples do not appear.
class FrameRecorder {
  public:
    /// `interval` in s, > 0.
    explicit FrameRecorder(double interval);
    /// Takes a sample of rock `rock` (0-based, outcome order) into its frame, unless the rock
    /// already has an earlier sample there.
    void add(int rock, const engine::RockState& state);
    /// The frames in time order.
    std::vector<RockFrame> frames() const;

  private:
    double interval_;
    std::map<long, RockFrame> frames_;
};

/// Every rock of `frame` as its hull (`rocks[i].hull`, body frame) placed by its state:
/// p = position + orientation * p_body. Cell data: `rock` (1-based, as in the text summary),
/// `speed_m_s` (speed of the centre of mass), `size_m` (nominal size).
VtkSurface rocks_surface(const std::vector<shapes::RockGeometry>& rocks, const RockFrame& frame);

/// What a triangle of the static surface belongs to (cell data `part`).
enum class ScenePart {
    slope = 0,          ///< slope slabs (their top faces are the surface)
    bar = 1,            ///< angle bars
    side_wall = 2,      ///< side walls
    reaction_wall = 3,  ///< the reaction wall
    lining_sphere = 4,  ///< spheres of a sphere layer or bumps (icosahedra through them)
    sheet = 5,          ///< a perforated sheet
    release_box = 6,    ///< walls the run adds (a cluster's release-box back wall)
    terrain = 7,        ///< a terrain mesh (replaces the slabs)
};

/// The static geometry of the scenario's slope once: every solid box of shapes::Slope (slabs
/// left out under a terrain mesh, which is drawn instead), the lining's spheres (as icosahedra
/// with their vertices on the sphere) and sheet, and `extra` boxes (engine::RunGeometry::solids).
/// Cell data: `part` (ScenePart), `segment` (profile segment, -1 for none).
VtkSurface static_surface(const engine::Scenario& scenario,
                          const std::vector<shapes::OrientedBox>& extra);

}  // namespace rockfall::report
