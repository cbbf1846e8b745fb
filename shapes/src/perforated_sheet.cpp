#include "lining_frame.hpp"

#include "shapes/lining.hpp"
#include "shapes/terrain.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace rockfall::shapes {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// A hole keeps a rim of this fraction of its radius to its cell's edges, so that every
// boundary point of the cell is at least 1.1 R from the hole's centre (see ring_cell).
constexpr double kRimFraction = 0.1;

// Appends a triangle to `mesh`, wound so that its normal points along `outward`.
void add_triangle(TriangleMesh& mesh, int a, int b, int c, const Vec3& outward) {
    const Vec3& pa = mesh.vertices[static_cast<std::size_t>(a)];
    const Vec3& pb = mesh.vertices[static_cast<std::size_t>(b)];
    const Vec3& pc = mesh.vertices[static_cast<std::size_t>(c)];
    if ((pb - pa).cross(pc - pa).dot(outward) < 0.0) {
        std::swap(b, c);
    }
    mesh.triangles.push_back({a, b, c});
}

int add_vertex(TriangleMesh& mesh, const Vec3& p) {
    mesh.vertices.push_back(p);
    return static_cast<int>(mesh.vertices.size()) - 1;
}

// A rectangle [u0, u1] x [v0, v1] of the top face of one segment's sheet.
struct Cell {
    double u0, u1, v0, v1;
};

void solid_cell(SheetMesh& out, const detail::SegmentPlane& plane, const Cell& cell, double top) {
    TriangleMesh& mesh = out.mesh;
    const int a = add_vertex(mesh, plane.point(cell.u0, cell.v0, top));
    const int b = add_vertex(mesh, plane.point(cell.u1, cell.v0, top));
    const int c = add_vertex(mesh, plane.point(cell.u1, cell.v1, top));
    const int d = add_vertex(mesh, plane.point(cell.u0, cell.v1, top));
    add_triangle(mesh, a, b, c, plane.normal);
    add_triangle(mesh, a, c, d, plane.normal);
    out.top_triangles += 2;
}

// Where the ray from `c` along `d` leaves the cell.
Eigen::Vector2d ray_exit(const Cell& cell, const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
    double t = std::numeric_limits<double>::infinity();
    if (d.x() > 0.0) t = std::min(t, (cell.u1 - c.x()) / d.x());
    if (d.x() < 0.0) t = std::min(t, (cell.u0 - c.x()) / d.x());
    if (d.y() > 0.0) t = std::min(t, (cell.v1 - c.y()) / d.y());
    if (d.y() < 0.0) t = std::min(t, (cell.v0 - c.y()) / d.y());
    return c + t * d;
}

// A cell with a hole of `sides` vertices a_i at angles phi_i = (2 i + 1) pi / sides on the
// circle of radius r about c. The top face is split along rays at the mid angles
// phi_i + pi / sides: a_i is fanned to the cell's boundary between the rays on either side of
// it, and each hole edge a_i a_{i+1} to the point where the ray between them meets the
// boundary. Every edge from a_i then meets the boundary within pi / sides of a_i's angle at a
// distance D >= 1.1 r (the rim), and D cos(pi / sides) >= r for sides >= 8: the edge stays
// outside the hole's circle (it is beyond the circle's tangent at a_i).
void ring_cell(SheetMesh& out, const detail::SegmentPlane& plane, const Cell& cell,
               const Eigen::Vector2d& c, double r, int sides, double top) {
    TriangleMesh& mesh = out.mesh;
    const double sector = kTwoPi / sides;
    std::vector<int> inner(static_cast<std::size_t>(sides));
    std::vector<int> bottom(static_cast<std::size_t>(sides));
    std::vector<int> ray(static_cast<std::size_t>(sides));
    for (int i = 0; i < sides; ++i) {
        const double phi = (i + 0.5) * sector;
        const Eigen::Vector2d a = c + r * Eigen::Vector2d(std::cos(phi), std::sin(phi));
        const Eigen::Vector2d edge = ray_exit(
            cell, c, Eigen::Vector2d(std::cos(phi + 0.5 * sector), std::sin(phi + 0.5 * sector)));
        const auto k = static_cast<std::size_t>(i);
        inner[k] = add_vertex(mesh, plane.point(a.x(), a.y(), top));
        bottom[k] = add_vertex(mesh, plane.point(a.x(), a.y(), 0.0));
        ray[k] = add_vertex(mesh, plane.point(edge.x(), edge.y(), top));
    }
    // The cell's corners in the sector of the inner vertex they are fanned from: vertex i owns
    // the angles [i sector, (i + 1) sector) (its mid angles on either side).
    std::vector<std::vector<std::pair<double, int>>> corners(static_cast<std::size_t>(sides));
    for (const auto& [u, v] : {std::pair{cell.u0, cell.v0}, std::pair{cell.u1, cell.v0},
                               std::pair{cell.u1, cell.v1}, std::pair{cell.u0, cell.v1}}) {
        double angle = std::atan2(v - c.y(), u - c.x());
        angle = angle < 0.0 ? angle + kTwoPi : angle;
        const double position = angle / sector;
        const double nearest = std::round(position);
        if (std::abs(position - nearest) < 1e-9) {
            continue;  // on a ray: the ray's boundary point is the corner itself
        }
        const auto owner = static_cast<std::size_t>(std::floor(position)) % corners.size();
        corners[owner].push_back({angle, add_vertex(mesh, plane.point(u, v, top))});
    }
    for (int i = 0; i < sides; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const auto next = static_cast<std::size_t>((i + 1) % sides);
        const auto previous = static_cast<std::size_t>((i + sides - 1) % sides);
        std::sort(corners[k].begin(), corners[k].end());
        // Fan from a_i over the boundary chain from the ray before it to the ray after it.
        int from = ray[previous];
        for (const auto& corner : corners[k]) {
            add_triangle(mesh, inner[k], from, corner.second, plane.normal);
            from = corner.second;
        }
        add_triangle(mesh, inner[k], from, ray[k], plane.normal);
        // The hole edge a_i a_{i+1} to the ray between them.
        add_triangle(mesh, inner[k], ray[k], inner[next], plane.normal);
        out.top_triangles += corners[k].size() + 2;
        // The wall under that edge, facing the hole's axis.
        const Eigen::Vector2d middle =
            0.5 * (Eigen::Vector2d(std::cos((i + 0.5) * sector), std::sin((i + 0.5) * sector)) +
                   Eigen::Vector2d(std::cos((i + 1.5) * sector), std::sin((i + 1.5) * sector)));
        const Vec3 inward = -(middle.x() * plane.tangent + middle.y() * Vec3::UnitY());
        add_triangle(mesh, bottom[k], bottom[next], inner[next], inward);
        add_triangle(mesh, bottom[k], inner[next], inner[k], inward);
        out.wall_triangles += 2;
    }
    SheetHole hole;
    hole.center = plane.point(c.x(), c.y(), 0.0);
    hole.normal = plane.normal;
    hole.segment = plane.index;
    hole.radius = r;
    hole.sides = sides;
    out.panels.back().holes.push_back(out.holes.size());
    out.holes.push_back(hole);
}

void check_sheet(const Slope& slope, const PerforatedSheet& sheet) {
    detail::check_range("perforated_sheet.thickness", sheet.thickness, "m", 1e-4, 0.05);
    detail::check_range("perforated_sheet.hole_diameter", sheet.hole_diameter, "m",
                        5.0 * sheet.thickness, 0.5);
    detail::check_range("perforated_sheet.hole_spacing", sheet.hole_spacing, "m",
                        (1.0 + kRimFraction) * sheet.hole_diameter * 2.0 / std::sqrt(3.0),
                        100.0 * sheet.hole_diameter);
    detail::check_range("perforated_sheet.hole_sides", sheet.hole_sides, "", 8, 64);
    detail::check_segments(slope, sheet.segments, "perforated_sheet.segments");
    // Triangles before building: at most (rows + 2) (sites per row + 2) cells, each with
    // 2 sides + 4 top and 2 sides wall triangles.
    double estimate = 0.0;
    for (const int index : sheet.segments) {
        const detail::SegmentPlane plane = detail::segment_plane(slope, index);
        const double rows = plane.length / detail::hex_row_spacing(sheet.hole_spacing) + 2.0;
        const double sites = 2.0 * plane.half_width / sheet.hole_spacing + 2.0;
        estimate += rows * sites * (4.0 * sheet.hole_sides + 4.0);
    }
    if (estimate > max_terrain_triangles) {
        throw std::invalid_argument(
            "perforated_sheet.hole_spacing = " + std::to_string(sheet.hole_spacing) +
            " m: the sheet would have about " + std::to_string(static_cast<long long>(estimate)) +
            " triangles, more than " + std::to_string(max_terrain_triangles) +
            ": use larger holes and spacing or fewer hole_sides");
    }
}

}  // namespace

SheetMesh perforated_sheet(const Slope& slope, const PerforatedSheet& sheet) {
    check_sheet(slope, sheet);
    SheetMesh out;
    const double top = sheet.thickness;
    const double r = 0.5 * sheet.hole_diameter;
    const double rim = kRimFraction * r;
    const double s = sheet.hole_spacing;
    const double row = detail::hex_row_spacing(s);
    for (const int index : sheet.segments) {
        const detail::SegmentPlane plane = detail::segment_plane(slope, index);
        SheetPanel& panel = out.panels.emplace_back();
        panel.plane = plane;
        panel.thickness = top;
        const double w = plane.half_width;
        const std::vector<double> rows =
            detail::centred_rows(0.5 * row, plane.length - 0.5 * row, row);
        // The strips left at the segment's ends, shorter than a row: solid.
        const double first = rows.empty() ? plane.length : rows.front() - 0.5 * row;
        const double last = rows.empty() ? plane.length : rows.back() + 0.5 * row;
        if (first > 1e-12) {
            solid_cell(out, plane, {0.0, first, -w, w}, top);
        }
        if (!rows.empty() && plane.length - last > 1e-12) {
            solid_cell(out, plane, {last, plane.length, -w, w}, top);
        }
        for (std::size_t k = 0; k < rows.size(); ++k) {
            for (const double v : detail::hex_row_sites(static_cast<int>(k), s, w + 0.5 * s)) {
                const Cell cell{rows[k] - 0.5 * row, rows[k] + 0.5 * row, std::max(v - 0.5 * s, -w),
                                std::min(v + 0.5 * s, w)};
                if (cell.v1 - cell.v0 <= 1e-12) {
                    continue;
                }
                if (v - r - rim >= cell.v0 - 1e-12 && v + r + rim <= cell.v1 + 1e-12) {
                    ring_cell(out, plane, cell, {rows[k], v}, r, sheet.hole_sides, top);
                } else {
                    solid_cell(out, plane, cell, top);
                }
            }
        }
    }
    return out;
}

bool inside_hole(const SheetHole& hole, double du, double dv) {
    // Edge i joins the vertices at (i + 1/2) and (i + 3/2) sectors: its middle is at the angle
    // (i + 1) sectors.
    const double sector = kTwoPi / hole.sides;
    const double nearest = std::round(std::atan2(dv, du) / sector) * sector;
    const double apothem = hole.radius * std::cos(0.5 * sector);
    return du * std::cos(nearest) + dv * std::sin(nearest) < apothem;
}

}  // namespace rockfall::shapes
