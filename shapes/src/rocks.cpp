#include "shapes/rocks.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <utility>

namespace rockfall::shapes {
namespace {

// Half-axes of the seed's blocky shapes before scaling (seed 000, Figure 3: a roughly equant
// block and a slab; the paper gives no dimensions, these ratios are our reading of the photos).
const Vec3 kMassiveHalfAxes(1.0, 0.9, 0.8);
const Vec3 kPlanarHalfAxes(1.0, 0.8, 0.35);
// Each box corner is cut off by a plane through the three points at this fraction of the
// shortest half-axis from the corner along its edges: blocky, but not a perfect box.
constexpr double kCornerCut = 0.2;
// Subdivisions of the icosahedron for the display tessellation of a sphere: 10 * 4^n + 2
// vertices, 642 for n = 3.
constexpr int kIcosphereLevels = 3;

void check_nominal_size(double nominal_size) {
    if (!(nominal_size >= min_nominal_size && nominal_size <= max_nominal_size)) {
        std::ostringstream message;
        message << "rock nominal_size = " << nominal_size << " m: must be within ["
                << min_nominal_size << ", " << max_nominal_size << "] m";
        throw GeometryError(message.str());
    }
}

std::vector<Vec3> truncated_box_points(const Vec3& half_axes) {
    const double cut = kCornerCut * half_axes.minCoeff();
    std::vector<Vec3> points;
    points.reserve(24);
    for (const double sx : {-1.0, 1.0}) {
        for (const double sy : {-1.0, 1.0}) {
            for (const double sz : {-1.0, 1.0}) {
                const Vec3 sign(sx, sy, sz);
                const Vec3 corner = sign.cwiseProduct(half_axes);
                for (int axis = 0; axis < 3; ++axis) {
                    Vec3 p = corner;
                    p[axis] -= sign[axis] * cut;
                    points.push_back(p);
                }
            }
        }
    }
    return points;
}

// Midpoint subdivision of an outward-oriented icosahedron, projected on the unit
// sphere; keeps the outward orientation of every child triangle.
ConvexPolyhedron unit_icosphere(int levels) {
    const double phi = std::numbers::phi;
    std::vector<Vec3> corners;
    for (const double a : {-1.0, 1.0}) {
        for (const double b : {-phi, phi}) {
            corners.emplace_back(0.0, a, b);
            corners.emplace_back(a, b, 0.0);
            corners.emplace_back(b, 0.0, a);
        }
    }
    ConvexPolyhedron sphere = convex_hull(corners);
    for (Vec3& v : sphere.vertices) {
        v.normalize();
    }
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<int, int>, int> midpoint_of_edge;
        const auto midpoint = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            const auto [it, inserted] =
                midpoint_of_edge.emplace(key, static_cast<int>(sphere.vertices.size()));
            if (inserted) {
                const Vec3 mid = sphere.vertices[static_cast<std::size_t>(a)] +
                                 sphere.vertices[static_cast<std::size_t>(b)];
                sphere.vertices.push_back(mid.normalized());
            }
            return it->second;
        };
        std::vector<std::array<int, 3>> finer;
        finer.reserve(4 * sphere.triangles.size());
        for (const auto& [a, b, c] : sphere.triangles) {
            const int ab = midpoint(a, b);
            const int bc = midpoint(b, c);
            const int ca = midpoint(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({b, bc, ab});
            finer.push_back({c, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        sphere.triangles = std::move(finer);
    }
    return sphere;
}

RockGeometry make_sphere(double nominal_size) {
    const double r = 0.5 * nominal_size;
    RockGeometry rock;
    rock.kind = RockKind::sphere;
    rock.nominal_size = nominal_size;
    rock.radius = r;
    rock.hull = unit_icosphere(kIcosphereLevels);
    for (Vec3& v : rock.hull.vertices) {
        v *= r;
    }
    MassProperties& props = rock.properties;
    props.volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    props.surface_area = 4.0 * std::numbers::pi * r * r;
    // Solid sphere: I = 2/5 m r^2 about any axis through the centre.
    const double moment = 0.4 * props.volume * r * r;
    props.principal_moments = Vec3::Constant(moment);
    props.inertia = props.principal_moments.asDiagonal();
    rock.sphericity = 1.0;
    rock.half_extents = Vec3::Constant(r);
    rock.bounding_radius = r;
    return rock;
}

}  // namespace

std::string_view to_string(RockKind kind) {
    switch (kind) {
        case RockKind::sphere:
            return "sphere";
        case RockKind::massive:
            return "massive";
        case RockKind::planar:
            return "planar";
        case RockKind::custom:
            return "custom";
    }
    assert(false && "unknown RockKind");
    return "unknown";
}

RockGeometry make_rock(RockKind kind, double nominal_size) {
    check_nominal_size(nominal_size);
    switch (kind) {
        case RockKind::sphere:
            return make_sphere(nominal_size);
        case RockKind::massive:
            return rock_from_hull(convex_hull(truncated_box_points(kMassiveHalfAxes)), kind,
                                  nominal_size);
        case RockKind::planar:
            return rock_from_hull(convex_hull(truncated_box_points(kPlanarHalfAxes)), kind,
                                  nominal_size);
        case RockKind::custom:
            throw GeometryError(
                "rock kind 'custom' has no shape of its own: give it a hull (a mesh file, a "
                "catalogue entry or a generated rock)");
    }
    assert(false && "unknown RockKind");
    return {};
}

RockGeometry make_rock(const CustomShape& shape, double nominal_size) {
    check_nominal_size(nominal_size);
    return rock_from_hull(shape.hull, RockKind::custom, nominal_size);
}

RockGeometry rock_from_hull(const ConvexPolyhedron& hull, RockKind kind, double nominal_size) {
    if (kind == RockKind::sphere) {
        throw GeometryError(
            "rock shape 'sphere' is an exact sphere and cannot be given as a hull; use "
            "'massive' or 'planar' for a polyhedral rock");
    }
    if (nominal_size > 0.0 || std::isnan(nominal_size)) {
        check_nominal_size(nominal_size);
    }
    const MassProperties original = mass_properties(hull);
    const double scale =
        nominal_size > 0.0 ? nominal_size / equivalent_diameter(original.volume) : 1.0;

    RockGeometry rock;
    rock.kind = kind;
    rock.nominal_size = nominal_size > 0.0 ? nominal_size : equivalent_diameter(original.volume);
    // Body frame p' = s A^T (p - c): the principal axes become x, y, z with the moments
    // ascending, so x is the long axis and z the short one.
    rock.hull = transformed(hull, original.principal_axes.transpose(), -original.centroid);
    for (Vec3& v : rock.hull.vertices) {
        v *= scale;
        rock.half_extents = rock.half_extents.cwiseMax(v.cwiseAbs());
        rock.bounding_radius = std::max(rock.bounding_radius, v.norm());
    }

    // Volume scales with s^3, area with s^2 and inertia per unit density with s^5.
    MassProperties& props = rock.properties;
    props.volume = std::pow(scale, 3) * original.volume;
    props.surface_area = scale * scale * original.surface_area;
    props.principal_moments = std::pow(scale, 5) * original.principal_moments;
    props.inertia = props.principal_moments.asDiagonal();
    rock.sphericity = wadell_sphericity(props.volume, props.surface_area);
    return rock;
}

}  // namespace rockfall::shapes
