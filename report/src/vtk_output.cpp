#include "report/vtk_output.hpp"

#include "shapes/lining.hpp"
#include "shapes/platonic.hpp"
#include "shapes/terrain.hpp"

#include <cassert>
#include <cmath>
#include <iomanip>
#include <limits>

namespace rockfall::report {
namespace {

// Appends triangles of `points` and `triangles` (indices into them) with one value per cell
// array for every triangle.
template <class Triangles>
void append(VtkSurface& surface, const std::vector<engine::Vec3>& points,
            const Triangles& triangles, const std::vector<double>& cell_values) {
    assert(cell_values.size() == surface.cells.size());
    const int base = static_cast<int>(surface.points.size());
    surface.points.insert(surface.points.end(), points.begin(), points.end());
    for (const auto& t : triangles) {
        surface.triangles.push_back({base + t[0], base + t[1], base + t[2]});
        for (std::size_t a = 0; a < cell_values.size(); ++a) {
            surface.cells[a].values.push_back(cell_values[a]);
        }
    }
}

// The 12 triangles of a box, outward.
void append_box(VtkSurface& surface, const shapes::OrientedBox& box,
                const std::vector<double>& cell_values) {
    std::vector<engine::Vec3> corners;
    for (int i = 0; i < 8; ++i) {
        const engine::Vec3 sign((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
        corners.push_back(box.center + box.rotation * sign.cwiseProduct(box.half_extents));
    }
    static const std::array<std::array<int, 3>, 12> faces = {{{0, 2, 3},
                                                              {0, 3, 1},
                                                              {4, 5, 7},
                                                              {4, 7, 6},
                                                              {0, 1, 5},
                                                              {0, 5, 4},
                                                              {2, 6, 7},
                                                              {2, 7, 3},
                                                              {0, 4, 6},
                                                              {0, 6, 2},
                                                              {1, 3, 7},
                                                              {1, 7, 5}}};
    append(surface, corners, faces, cell_values);
}

ScenePart part_of(shapes::SurfaceRole role) {
    switch (role) {
        case shapes::SurfaceRole::slope:
            return ScenePart::slope;
        case shapes::SurfaceRole::bar:
            return ScenePart::bar;
        case shapes::SurfaceRole::side_wall:
            return ScenePart::side_wall;
        case shapes::SurfaceRole::reaction_wall:
            return ScenePart::reaction_wall;
    }
    return ScenePart::slope;
}

std::vector<double> part_values(ScenePart part, int segment) {
    return {static_cast<double>(static_cast<int>(part)), static_cast<double>(segment)};
}

void put_array(std::ostream& out, const CellArray& array) {
    out << "        <DataArray type=\"" << (array.integer ? "Int32" : "Float64") << "\" Name=\""
        << array.name << "\" format=\"ascii\">\n";
    for (const double v : array.values) {
        if (array.integer) {
            out << static_cast<long>(v) << '\n';
        } else {
            out << v << '\n';
        }
    }
    out << "        </DataArray>\n";
}

}  // namespace

void write_vtp(std::ostream& out, const VtkSurface& surface, double time) {
    out << std::setprecision(10);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
           "  <PolyData>\n";
    if (std::isfinite(time)) {
        out << "    <FieldData>\n"
               "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
               "format=\"ascii\">"
            << time << "</DataArray>\n    </FieldData>\n";
    }
    out << "    <Piece NumberOfPoints=\"" << surface.points.size()
        << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\""
        << surface.triangles.size() << "\">\n"
        << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n";
    for (const engine::Vec3& p : surface.points) {
        out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    }
    out << "        </DataArray>\n      </Points>\n      <Polys>\n"
           "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& t : surface.triangles) out << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    out << "        </DataArray>\n"
           "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t i = 1; i <= surface.triangles.size(); ++i) out << 3 * i << '\n';
    out << "        </DataArray>\n      </Polys>\n      <CellData>\n";
    for (const CellArray& array : surface.cells) {
        assert(array.values.size() == surface.triangles.size());
        put_array(out, array);
    }
    out << "      </CellData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

void write_pvd(std::ostream& out, const std::vector<PvdEntry>& entries) {
    out << std::setprecision(10);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const PvdEntry& e : entries) {
        out << "    <DataSet timestep=\"" << e.time << "\" group=\"\" part=\"0\" file=\"" << e.file
            << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
}

FrameRecorder::FrameRecorder(double interval) : interval_(interval) { assert(interval > 0.0); }

void FrameRecorder::add(int rock, const engine::RockState& state) {
    // A sample a rounding error short of a multiple of the interval belongs to that frame.
    const auto k = static_cast<long>(std::floor(state.time / interval_ + 1e-9));
    RockFrame& frame = frames_[k];
    if (frame.rocks.empty() || state.time < frame.time) frame.time = state.time;
    frame.rocks.emplace(rock, state);
}

std::vector<RockFrame> FrameRecorder::frames() const {
    std::vector<RockFrame> out;
    out.reserve(frames_.size());
    for (const auto& [k, frame] : frames_) out.push_back(frame);
    return out;
}

VtkSurface rocks_surface(const std::vector<shapes::RockGeometry>& rocks, const RockFrame& frame) {
    VtkSurface surface;
    surface.cells = {{"rock", true, {}}, {"speed_m_s", false, {}}, {"size_m", false, {}}};
    std::vector<engine::Vec3> points;
    for (const auto& [index, state] : frame.rocks) {
        assert(index >= 0 && static_cast<std::size_t>(index) < rocks.size());
        const shapes::RockGeometry& rock = rocks[static_cast<std::size_t>(index)];
        const Eigen::Matrix3d rotation = state.orientation.toRotationMatrix();
        points.clear();
        for (const engine::Vec3& v : rock.hull.vertices) {
            points.push_back(state.position + rotation * v);
        }
        append(surface, points, rock.hull.triangles,
               {static_cast<double>(index + 1), state.velocity.norm(), rock.nominal_size});
    }
    return surface;
}

VtkSurface static_surface(const engine::Scenario& scenario,
                          const std::vector<shapes::OrientedBox>& extra) {
    const shapes::Slope slope(scenario.slope);
    VtkSurface surface;
    surface.cells = {{"part", true, {}}, {"segment", true, {}}};
    const bool terrain = scenario.slope.terrain != nullptr;
    for (const shapes::OrientedBox& box : slope.solids()) {
        if (terrain && box.role == shapes::SurfaceRole::slope) continue;
        append_box(surface, box, part_values(part_of(box.role), box.segment));
    }
    if (terrain) {
        const shapes::TriangleMesh& mesh = scenario.slope.terrain->mesh();
        append(surface, mesh.vertices, mesh.triangles, part_values(ScenePart::terrain, -1));
    }
    for (const shapes::OrientedBox& box : extra) {
        append_box(surface, box, part_values(ScenePart::release_box, box.segment));
    }
    if (const auto& lining = scenario.slope.lining) {
        // An icosahedron of circumradius 1 (edge 1 / sin(2 pi / 5)), scaled to each sphere.
        const shapes::ConvexPolyhedron unit = shapes::platonic_solid(
            shapes::PlatonicKind::icosahedron, 1.0 / std::sin(0.4 * std::acos(-1.0)));
        std::vector<engine::Vec3> points;
        for (const shapes::Sphere& sphere : shapes::lining_spheres(slope, *lining)) {
            points.clear();
            for (const engine::Vec3& v : unit.vertices) {
                points.push_back(sphere.center + sphere.radius * v);
            }
            append(surface, points, unit.triangles,
                   part_values(ScenePart::lining_sphere, sphere.segment));
        }
        if (lining->sheet) {
            const shapes::SheetMesh sheet = shapes::perforated_sheet(slope, *lining->sheet);
            append(surface, sheet.mesh.vertices, sheet.mesh.triangles,
                   part_values(ScenePart::sheet, lining->sheet->segments.size() == 1
                                                     ? lining->sheet->segments.front()
                                                     : -1));
        }
    }
    return surface;
}

}  // namespace rockfall::report
