#include "shapes/measures.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace rockfall::shapes {
namespace {

// A frame counts as principal when the inertia tensor expressed in it has off-diagonal terms
// below this fraction of its trace: round-off level for exactly degenerate moments.
constexpr double kPrincipalTolerance = 1e-8;

// Extents of the hull's vertices along the columns of `frame`, m.
Vec3 extents_in(const ConvexPolyhedron& hull, const Eigen::Matrix3d& frame) {
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 high = -low;
    for (const Vec3& v : hull.vertices) {
        const Vec3 p = frame.transpose() * v;
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    return high - low;
}

bool is_principal(const Eigen::Matrix3d& inertia, const Eigen::Matrix3d& frame) {
    const Eigen::Matrix3d local = frame.transpose() * inertia * frame;
    const double limit = kPrincipalTolerance * std::abs(inertia.trace());
    return std::abs(local(0, 1)) <= limit && std::abs(local(0, 2)) <= limit &&
           std::abs(local(1, 2)) <= limit;
}

// Degenerate moments within this fraction of the trace leave the principal axes free.
constexpr double kDegenerateTolerance = 1e-8;
// Above this many candidate directions the pairwise search is skipped (it is quadratic), so
// that a fine symmetric mesh cannot stall; the eigen-solver's frame is used instead.
constexpr std::size_t kMaxCandidateDirections = 20000;

bool has_degenerate_moments(const Vec3& moments) {
    const double limit = kDegenerateTolerance * moments.sum();
    return moments[1] - moments[0] <= limit || moments[2] - moments[1] <= limit;
}

// Directions from the centroid that symmetry axes of a polyhedron pass through: vertices,
// edge midpoints and face normals, plus the edges themselves (for prisms).
std::vector<Vec3> candidate_directions(const ConvexPolyhedron& hull, const Vec3& centroid) {
    std::vector<Vec3> directions;
    const auto add = [&directions](const Vec3& d) {
        if (d.norm() > 0.0) {
            directions.push_back(d.normalized());
        }
    };
    for (const Vec3& v : hull.vertices) {
        add(v - centroid);
    }
    for (const auto& t : hull.triangles) {
        const Vec3& p0 = hull.vertices[static_cast<std::size_t>(t[0])];
        const Vec3& p1 = hull.vertices[static_cast<std::size_t>(t[1])];
        const Vec3& p2 = hull.vertices[static_cast<std::size_t>(t[2])];
        add((p1 - p0).cross(p2 - p0));
        for (const auto& [a, b] : {std::pair{&p0, &p1}, {&p1, &p2}, {&p2, &p0}}) {
            add(0.5 * (*a + *b) - centroid);
            add(*b - *a);
        }
    }
    return directions;
}

// The most equant (largest b c / a^2) principal frame spanned by two perpendicular candidate
// directions; empty when there is none.
std::optional<Vec3> most_equant_principal_extents(const ConvexPolyhedron& hull,
                                                  const MassProperties& properties) {
    const std::vector<Vec3> directions = candidate_directions(hull, properties.centroid);
    if (directions.size() > kMaxCandidateDirections) {
        return std::nullopt;
    }
    std::optional<Vec3> best;
    double best_equancy = -1.0;
    for (std::size_t i = 0; i < directions.size(); ++i) {
        for (std::size_t j = i + 1; j < directions.size(); ++j) {
            if (std::abs(directions[i].dot(directions[j])) > kPrincipalTolerance) {
                continue;
            }
            Eigen::Matrix3d frame;
            frame.col(0) = directions[i];
            frame.col(1) = directions[j];
            frame.col(2) = directions[i].cross(directions[j]);
            if (!is_principal(properties.inertia, frame)) {
                continue;
            }
            Vec3 extents = extents_in(hull, frame);
            std::sort(extents.begin(), extents.end(), std::greater<>());
            const double equancy = extents[1] * extents[2] / (extents[0] * extents[0]);
            if (equancy > best_equancy) {
                best_equancy = equancy;
                best = extents;
            }
        }
    }
    return best;
}

ShapeMeasures measures_from(const MassProperties& properties, const Vec3& axes) {
    ShapeMeasures m;
    m.properties = properties;
    m.equivalent_diameter = equivalent_diameter(properties.volume);
    m.axis_lengths = axes;
    m.wadell_sphericity = wadell_sphericity(properties.volume, properties.surface_area);
    const double a = axes[0];
    const double b = axes[1];
    const double c = axes[2];
    // Krumbein (1941): the sphericity of the triaxial ellipsoid with the rock's intercepts,
    // its volume over that of the sphere through the long axis.
    m.krumbein_sphericity = std::cbrt(b * c / (a * a));
    m.flatness = c / b;
    m.elongation = b / a;
    return m;
}

}  // namespace

Vec3 axis_lengths(const ConvexPolyhedron& hull, const MassProperties& properties) {
    assert(!hull.vertices.empty());
    // Equal moments leave the eigenvectors to round-off: a cube would report a tilted box.
    if (has_degenerate_moments(properties.principal_moments)) {
        if (const auto extents = most_equant_principal_extents(hull, properties)) {
            return *extents;
        }
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(properties.inertia);
    Vec3 extents = extents_in(hull, solver.eigenvectors());
    std::sort(extents.begin(), extents.end(), std::greater<>());
    return extents;
}

ShapeMeasures shape_measures(const ConvexPolyhedron& hull) {
    const MassProperties properties = mass_properties(hull);
    return measures_from(properties, axis_lengths(hull, properties));
}

ShapeMeasures shape_measures(const RockGeometry& rock) {
    if (rock.kind == RockKind::sphere) {
        return measures_from(rock.properties, Vec3::Constant(2.0 * rock.radius));
    }
    return measures_from(rock.properties, axis_lengths(rock.hull, rock.properties));
}

}  // namespace rockfall::shapes
