#include "shapes/polyhedron.hpp"

#include <Eigen/Geometry>
#include <libqhull_r/libqhull_r.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <new>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace rockfall::shapes {
namespace {

// Hulls thinner than this fraction of their bounding-box diagonal (in volume, relative to the
// diagonal cubed) are treated as flat: Qhull can return a sliver of round-off thickness for
// coplanar input instead of failing.
constexpr double kMinRelativeVolume = 1e-12;
// Triangles lower than this fraction of their longest edge are slivers (see sliver_vertices).
constexpr double kSliverRatio = 1e-9;

std::string describe(const Vec3& p) {
    std::ostringstream out;
    out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return out.str();
}

void check_input(const std::vector<Vec3>& points) {
    if (points.size() < 4) {
        throw GeometryError("convex hull: " + std::to_string(points.size()) +
                            " points given, at least 4 are needed for a solid");
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!points[i].allFinite()) {
            throw GeometryError("convex hull: point " + std::to_string(i) + " = " +
                                describe(points[i]) + " m is not finite");
        }
    }
}

// Qhull reports errors by writing to a FILE* and longjmp-ing back into qh_new_qhull; an
// in-memory stream keeps its message for the exception instead of printing to stderr.
class MessageStream {
  public:
    MessageStream() : file_(open_memstream(&buffer_, &size_)) {
        // open_memstream fails only without memory; Qhull would then fall back to stderr.
        if (file_ == nullptr) {
            throw std::bad_alloc();
        }
    }
    MessageStream(const MessageStream&) = delete;
    MessageStream& operator=(const MessageStream&) = delete;
    ~MessageStream() {
        std::fclose(file_);
        std::free(buffer_);
    }
    FILE* file() const { return file_; }
    std::string text() const {
        std::fflush(file_);
        return std::string(buffer_, size_);
    }

  private:
    char* buffer_ = nullptr;
    std::size_t size_ = 0;
    FILE* file_ = nullptr;
};

// Owns one reentrant Qhull context and releases all of its memory, also after an error.
class QhullRun {
  public:
    explicit QhullRun(FILE* errors) : qh_(std::make_unique<qhT>()) { qh_zero(qh_.get(), errors); }
    QhullRun(const QhullRun&) = delete;
    QhullRun& operator=(const QhullRun&) = delete;
    ~QhullRun() {
        qh_freeqhull(qh_.get(), !qh_ALL);
        int current_long = 0;
        int total_long = 0;
        qh_memfreeshort(qh_.get(), &current_long, &total_long);
    }
    qhT* get() const { return qh_.get(); }

  private:
    std::unique_ptr<qhT> qh_;
};

std::string first_line(const std::string& text) {
    const auto end = text.find('\n');
    return text.substr(0, end);
}

ConvexPolyhedron extract(qhT* qh) {
    ConvexPolyhedron poly;
    // Vertices are numbered in order of first use by a facet, so only hull vertices appear.
    std::unordered_map<unsigned, int> index_of_vertex;
    const auto index_of = [&](const vertexT* v) {
        const auto [it, inserted] =
            index_of_vertex.emplace(v->id, static_cast<int>(poly.vertices.size()));
        if (inserted) {
            poly.vertices.emplace_back(v->point[0], v->point[1], v->point[2]);
        }
        return it->second;
    };
    for (facetT* facet = qh->facet_list; facet != nullptr && facet->next != nullptr;
         facet = facet->next) {
        assert(facet->simplicial);
        std::array<int, 3> tri{};
        int k = 0;
        vertexT* vertex = nullptr;
        vertexT** vertexp = nullptr;
        FOREACHvertex_(facet->vertices) {
            assert(k < 3);
            tri[static_cast<std::size_t>(k++)] = index_of(vertex);
        }
        assert(k == 3);
        // Tricoplanar facets share their owner's outward normal, which is more reliable than
        // the cross product of a sliver triangle.
        const Vec3 outward(facet->normal[0], facet->normal[1], facet->normal[2]);
        const Vec3& a = poly.vertices[static_cast<std::size_t>(tri[0])];
        const Vec3& b = poly.vertices[static_cast<std::size_t>(tri[1])];
        const Vec3& c = poly.vertices[static_cast<std::size_t>(tri[2])];
        if ((b - a).cross(c - a).dot(outward) < 0.0) {
            std::swap(tri[1], tri[2]);
        }
        poly.triangles.push_back(tri);
    }
    return poly;
}

// Volume as a sum of tetrahedra from the first vertex; used only to reject flat hulls before
// mass_properties, which requires a solid.
double hull_volume(const ConvexPolyhedron& poly) {
    const Vec3& apex = poly.vertices.front();
    double six_volume = 0.0;
    for (const auto& tri : poly.triangles) {
        const Vec3 a = poly.vertices[static_cast<std::size_t>(tri[0])] - apex;
        const Vec3 b = poly.vertices[static_cast<std::size_t>(tri[1])] - apex;
        const Vec3 c = poly.vertices[static_cast<std::size_t>(tri[2])] - apex;
        six_volume += a.dot(b.cross(c));
    }
    return six_volume / 6.0;
}

// One Qhull run on points already checked to be finite and not all coincident.
ConvexPolyhedron qhull_hull(const std::vector<Vec3>& points) {
    if (points.size() < 4) {
        throw GeometryError("convex hull: points span no volume (collinear or coplanar)");
    }
    std::vector<coordT> coordinates;
    coordinates.reserve(3 * points.size());
    for (const Vec3& p : points) {
        coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
    }
    MessageStream messages;
    QhullRun run(messages.file());
    // "Qt": triangulated output, so every facet is a triangle.
    char options[] = "qhull Qt";
    const int status = qh_new_qhull(run.get(), 3, static_cast<int>(points.size()),
                                    coordinates.data(), False, options, nullptr, messages.file());
    if (status != 0) {
        throw GeometryError("convex hull of " + std::to_string(points.size()) +
                            " points failed (collinear or coplanar points?): Qhull: " +
                            first_line(messages.text()));
    }
    return extract(run.get());
}

// Vertices that make a sliver triangle: the vertex opposite the longest edge of a triangle
// whose height over that edge is below kSliverRatio of its length. Qhull's "Qt" leaves such
// triangles where a vertex lies (nearly) on a ridge of merged facets; their cross-product
// normals are round-off, and the vertex is no extreme point, so dropping it changes the hull
// by less than that height.
std::vector<bool> sliver_vertices(const ConvexPolyhedron& poly) {
    std::vector<bool> sliver(poly.vertices.size(), false);
    for (const auto& tri : poly.triangles) {
        std::array<Vec3, 3> p;
        for (std::size_t k = 0; k < 3; ++k) {
            p[k] = poly.vertices[static_cast<std::size_t>(tri[k])];
        }
        std::size_t opposite = 0;
        double longest = 0.0;
        for (std::size_t k = 0; k < 3; ++k) {
            const double length = (p[(k + 2) % 3] - p[(k + 1) % 3]).norm();
            if (length > longest) {
                longest = length;
                opposite = k;
            }
        }
        const double twice_area = (p[1] - p[0]).cross(p[2] - p[0]).norm();
        if (twice_area <= kSliverRatio * longest * longest) {
            sliver[static_cast<std::size_t>(tri[opposite])] = true;
        }
    }
    return sliver;
}

}  // namespace

ConvexPolyhedron convex_hull(const std::vector<Vec3>& points) {
    check_input(points);

    Eigen::AlignedBox3d box;
    for (const Vec3& p : points) {
        box.extend(p);
    }
    const double diagonal = box.diagonal().norm();
    if (!(diagonal > 0.0)) {
        throw GeometryError("convex hull: all " + std::to_string(points.size()) +
                            " points coincide at " + describe(points.front()) + " m");
    }

    ConvexPolyhedron poly = qhull_hull(points);
    // Each pass drops at least one vertex, so this ends.
    for (std::vector<bool> sliver = sliver_vertices(poly);
         std::find(sliver.begin(), sliver.end(), true) != sliver.end();
         sliver = sliver_vertices(poly)) {
        std::vector<Vec3> kept;
        for (std::size_t i = 0; i < poly.vertices.size(); ++i) {
            if (!sliver[i]) {
                kept.push_back(poly.vertices[i]);
            }
        }
        poly = qhull_hull(kept);
    }

    if (poly.triangles.size() < 4) {
        throw GeometryError("convex hull: points span no volume (collinear or coplanar)");
    }
    const double volume = hull_volume(poly);
    if (!(volume > kMinRelativeVolume * diagonal * diagonal * diagonal)) {
        std::ostringstream message;
        message << "convex hull: points are coplanar (hull volume " << volume
                << " m3 for a bounding-box diagonal of " << diagonal << " m)";
        throw GeometryError(message.str());
    }
    return poly;
}

ConvexPolyhedron transformed(const ConvexPolyhedron& poly, const Eigen::Matrix3d& rotation,
                             const Vec3& offset) {
    assert(std::abs(rotation.determinant() - 1.0) < 1e-9);
    ConvexPolyhedron out;
    out.triangles = poly.triangles;
    out.vertices.reserve(poly.vertices.size());
    for (const Vec3& p : poly.vertices) {
        out.vertices.push_back(rotation * (p + offset));
    }
    return out;
}

}  // namespace rockfall::shapes
