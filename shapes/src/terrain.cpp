#include "shapes/terrain.hpp"

#include "shapes/slope.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace rockfall::shapes {
namespace {

// A triangle with less area than this share of the terrain's squared extent has no reliable
// normal (Bullet's internal-edge utility and our queries divide by its area).
constexpr double kDegenerateArea = 1e-12;
// Points this close (relative barycentric weight) outside a triangle still count as inside, so
// that no query falls through the crack of a shared edge.
constexpr double kEdgeTolerance = 1e-9;
// Cells of the ground index per triangle: a few triangles per cell keep a query short.
constexpr double kTrianglesPerCell = 2.0;
// At most this many cells along each horizontal axis (a thin strip would otherwise ask for
// millions of tiny cells).
constexpr int kMaxCellsPerAxis = 2048;

[[noreturn]] void fail(std::string_view what, const std::string& problem) {
    throw GeometryError(std::string(what) + ": " + problem);
}

std::string describe(const Vec3& p) {
    std::ostringstream out;
    out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return out.str();
}

void check_placement(const TerrainPlacement& placement, std::string_view what) {
    if (!(std::isfinite(placement.scale) && placement.scale > 0.0)) {
        std::ostringstream problem;
        problem << "scale = " << placement.scale << ": must be finite and > 0";
        fail(what, problem.str());
    }
    if (!placement.offset.allFinite()) {
        fail(what, "offset = " + describe(placement.offset) + " m: must be finite");
    }
}

void check_indices(const TriangleMesh& mesh, std::string_view what) {
    const auto count = static_cast<int>(mesh.vertices.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (const int corner : mesh.triangles[t]) {
            if (corner < 0 || corner >= count) {
                fail(what, "triangle " + std::to_string(t) + " refers to vertex " +
                               std::to_string(corner) + ", outside [0, " + std::to_string(count) +
                               ") (vertices count from 0)");
            }
        }
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        if (!mesh.vertices[i].allFinite()) {
            fail(what, "vertex " + std::to_string(i) + " = " + describe(mesh.vertices[i]) +
                           " is not finite");
        }
    }
}

// The mesh with vertices at identical positions merged (an STL repeats each corner in every
// triangle that uses it) and unused vertices removed, in order of first use.
TriangleMesh merged(const TriangleMesh& mesh) {
    TriangleMesh out;
    std::map<std::array<double, 3>, int> index_of;
    out.triangles.reserve(mesh.triangles.size());
    for (const auto& triangle : mesh.triangles) {
        std::array<int, 3> corners{};
        for (std::size_t k = 0; k < 3; ++k) {
            const Vec3& p = mesh.vertices[static_cast<std::size_t>(triangle[k])];
            const auto [found, added] =
                index_of.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(out.vertices.size()));
            if (added) out.vertices.push_back(p);
            corners[k] = found->second;
        }
        out.triangles.push_back(corners);
    }
    return out;
}

Vec3 corner(const TriangleMesh& mesh, const std::array<int, 3>& triangle, std::size_t k) {
    return mesh.vertices[static_cast<std::size_t>(triangle[k])];
}

// Twice the triangle's area vector (b - a) x (c - a).
Vec3 area_vector(const TriangleMesh& mesh, const std::array<int, 3>& triangle) {
    const Vec3 a = corner(mesh, triangle, 0);
    return (corner(mesh, triangle, 1) - a).cross(corner(mesh, triangle, 2) - a);
}

}  // namespace

Terrain::Terrain(std::string name, TriangleMesh mesh, const TerrainPlacement& placement,
                 std::string_view what)
    : name_(std::move(name)) {
    check_placement(placement, what);
    check_indices(mesh, what);
    if (mesh.triangles.empty()) {
        fail(what, "contains no triangles (only points or lines): a terrain needs a surface");
    }
    for (Vec3& v : mesh.vertices) v = placement.scale * v + placement.offset;
    mesh = merged(mesh);

    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices) box.extend(v);
    const double extent = box.diagonal().norm();
    if (!(extent >= min_terrain_extent && extent <= max_terrain_extent)) {
        std::ostringstream problem;
        problem << "the terrain is " << extent << " m across (bounding-box diagonal), outside "
                << "the accepted [" << min_terrain_extent << ", " << max_terrain_extent
                << "] m (coordinates are read as metres times scale = " << placement.scale
                << "; give a scale such as 0.001 for millimetres)";
        fail(what, problem.str());
    }

    const double min_area = kDegenerateArea * extent * extent;
    const auto total = mesh.triangles.size();
    std::erase_if(mesh.triangles, [&](const std::array<int, 3>& triangle) {
        return !(area_vector(mesh, triangle).norm() > min_area);
    });
    dropped_ = static_cast<int>(total - mesh.triangles.size());
    if (mesh.triangles.empty()) {
        fail(what, "all " + std::to_string(total) +
                       " triangles are degenerate (zero area: repeated or collinear corners)");
    }
    if (mesh.triangles.size() > static_cast<std::size_t>(max_terrain_triangles)) {
        fail(what, "has " + std::to_string(mesh.triangles.size()) + " triangles; at most " +
                       std::to_string(max_terrain_triangles) +
                       " are allowed (Bullet's triangle index limit): simplify the mesh");
    }
    // Vertices used only by dropped triangles go too, so that the mesh is written back as used.
    mesh_ = dropped_ > 0 ? merged(mesh) : std::move(mesh);
    Eigen::AlignedBox3d used;
    for (const Vec3& v : mesh_.vertices) used.extend(v);
    lower_ = used.min();
    upper_ = used.max();

    // Ground index: a uniform grid over the horizontal bounding box.
    const double dx = upper_.x() - lower_.x();
    const double dy = upper_.y() - lower_.y();
    const double cells =
        std::max(1.0, static_cast<double>(mesh_.triangles.size()) / kTrianglesPerCell);
    cell_size_ =
        std::max({std::sqrt(dx * dy / cells), std::max(dx, dy) / kMaxCellsPerAxis, 1e-9 * extent});
    columns_ = static_cast<int>(dx / cell_size_) + 1;
    rows_ = static_cast<int>(dy / cell_size_) + 1;
    // Two passes (count, then fill) give each cell a contiguous range of triangle indices.
    std::vector<std::array<int, 4>> spans;
    spans.reserve(mesh_.triangles.size());
    cell_start_.assign(static_cast<std::size_t>(columns_ * rows_) + 1, 0);
    for (const auto& triangle : mesh_.triangles) {
        Eigen::AlignedBox2d flat;
        for (std::size_t k = 0; k < 3; ++k) flat.extend(corner(mesh_, triangle, k).head<2>());
        const std::array<int, 4> span{cell_of(flat.min().x(), 0), cell_of(flat.max().x(), 0),
                                      cell_of(flat.min().y(), 1), cell_of(flat.max().y(), 1)};
        spans.push_back(span);
        for (int i = span[0]; i <= span[1]; ++i) {
            for (int j = span[2]; j <= span[3]; ++j) ++cell_start_[i * rows_ + j + 1];
        }
    }
    for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    cell_triangles_.resize(static_cast<std::size_t>(cell_start_.back()));
    std::vector<int> filled(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t t = 0; t < spans.size(); ++t) {
        const std::array<int, 4>& span = spans[t];
        for (int i = span[0]; i <= span[1]; ++i) {
            for (int j = span[2]; j <= span[3]; ++j) {
                const auto cell = static_cast<std::size_t>(i * rows_ + j);
                cell_triangles_[static_cast<std::size_t>(filled[cell]++)] = static_cast<int>(t);
            }
        }
    }
}

int Terrain::cell_of(double coordinate, int axis) const {
    const double start = axis == 0 ? lower_.x() : lower_.y();
    const int count = axis == 0 ? columns_ : rows_;
    const double index = std::floor((coordinate - start) / cell_size_);
    return static_cast<int>(std::clamp(index, 0.0, static_cast<double>(count - 1)));
}

std::optional<Ground> Terrain::ground(double x, double y) const {
    const double slack = kEdgeTolerance * cell_size_;
    if (!(x >= lower_.x() - slack && x <= upper_.x() + slack && y >= lower_.y() - slack &&
          y <= upper_.y() + slack)) {
        return std::nullopt;
    }
    const auto cell = static_cast<std::size_t>(cell_of(x, 0) * rows_ + cell_of(y, 1));
    std::optional<Ground> best;
    for (int c = cell_start_[cell]; c < cell_start_[cell + 1]; ++c) {
        const auto& triangle =
            mesh_.triangles[static_cast<std::size_t>(cell_triangles_[static_cast<std::size_t>(c)])];
        const Vec3 a = corner(mesh_, triangle, 0);
        const Vec3 ab = corner(mesh_, triangle, 1) - a;
        const Vec3 ac = corner(mesh_, triangle, 2) - a;
        // Barycentric weights of (x, y) in the triangle's horizontal projection.
        const double det = ab.x() * ac.y() - ab.y() * ac.x();
        if (std::abs(det) <=
            kDegenerateArea * (ab.head<2>().squaredNorm() + ac.head<2>().squaredNorm())) {
            continue;  // a vertical face: no height to give
        }
        const double px = x - a.x();
        const double py = y - a.y();
        const double wb = (px * ac.y() - py * ac.x()) / det;
        const double wc = (ab.x() * py - ab.y() * px) / det;
        if (wb < -kEdgeTolerance || wc < -kEdgeTolerance || wb + wc > 1.0 + kEdgeTolerance) {
            continue;
        }
        const double height = a.z() + wb * ab.z() + wc * ac.z();
        if (!best || height > best->height) {
            Vec3 normal = ab.cross(ac).normalized();
            if (normal.z() < 0.0) normal = -normal;
            best = Ground{height, normal};
        }
    }
    return best;
}

Terrain read_terrain(const std::filesystem::path& file, const TerrainPlacement& placement,
                     const std::string& name) {
    return Terrain(name.empty() ? file.stem().string() : name, read_mesh_triangles(file), placement,
                   "terrain mesh file '" + file.string() + "'");
}

Ground ground_at(const Slope& slope, double x, double y) {
    if (const Terrain* terrain = slope.spec().terrain.get()) {
        if (const std::optional<Ground> ground = terrain->ground(x, y)) return *ground;
    }
    return {slope.surface_height(x), slope.surface_normal(x)};
}

ProfileDeviation profile_deviation(const Terrain& terrain, const Slope& slope) {
    ProfileDeviation out;
    double squares = 0.0;
    const double half = 0.5 * slope.spec().width;
    for (const Vec3& v : terrain.mesh().vertices) {
        if (v.x() < 0.0 || v.x() > slope.end_x() || std::abs(v.y()) > half) continue;
        const double dz = v.z() - slope.surface_height(v.x());
        out.max = std::max(out.max, std::abs(dz));
        squares += dz * dz;
        ++out.vertices;
    }
    if (out.vertices > 0) out.rms = std::sqrt(squares / static_cast<double>(out.vertices));
    return out;
}

}  // namespace rockfall::shapes
