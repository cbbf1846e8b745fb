#include "shapes/generators.hpp"

#include "shapes/mass_properties.hpp"
#include "shapes/platonic.hpp"
#include "shapes/random.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <numbers>
#include <sstream>
#include <vector>

namespace rockfall::shapes {
namespace {

constexpr int kMinPoints = 8;
constexpr int kMaxPoints = 10000;
constexpr double kMaxRoughness = 0.9;
// Thinnest ratio of the short to the long axis: thinner hulls are sheets, not rocks.
constexpr double kMinAxisRatio = 0.01;
// Bisection bracket for the stretch t of rock_with_sphericity (axes 1 : t : t^2).
constexpr double kMinStretch = 0.02;
constexpr double kSphericityTolerance = 1e-4;

void check_options(const RandomRockOptions& options) {
    std::ostringstream problem;
    if (options.points < kMinPoints || options.points > kMaxPoints) {
        problem << "random rock points = " << options.points << ": must be in [" << kMinPoints
                << ", " << kMaxPoints << "]";
    } else if (!(options.roughness >= 0.0 && options.roughness < kMaxRoughness)) {
        problem << "random rock roughness = " << options.roughness << ": must be in [0, "
                << kMaxRoughness << ")";
    }
    if (!problem.str().empty()) throw GeometryError(problem.str());
}

// The seed's point cloud about the unit sphere (RandomRockOptions states the draws).
std::vector<Vec3> unit_cloud(std::uint64_t seed, const RandomRockOptions& options) {
    std::mt19937_64 generator = make_generator(seed);
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(options.points));
    for (int i = 0; i < options.points; ++i) {
        const double z = 2.0 * uniform01(generator) - 1.0;
        const double azimuth = 2.0 * std::numbers::pi * uniform01(generator);
        const double radius = 1.0 - options.roughness * uniform01(generator);
        const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
        points.push_back(radius * Vec3(ring * std::cos(azimuth), ring * std::sin(azimuth), z));
    }
    return points;
}

// A linear map keeps a hull's faces, so the stretched hull is the stretched triangles.
ConvexPolyhedron stretched(const ConvexPolyhedron& hull, const Vec3& factors) {
    ConvexPolyhedron out = hull;
    for (Vec3& v : out.vertices) v = v.cwiseProduct(factors);
    return out;
}

double sphericity_of(const ConvexPolyhedron& hull) {
    const MassProperties properties = mass_properties(hull);
    return wadell_sphericity(properties.volume, properties.surface_area);
}

Vec3 normalised_ratios(const Vec3& axis_ratios) {
    if (!(axis_ratios.allFinite() && axis_ratios.minCoeff() > 0.0)) {
        std::ostringstream problem;
        problem << "axis ratios (" << axis_ratios.x() << ", " << axis_ratios.y() << ", "
                << axis_ratios.z() << "): must be three finite numbers > 0";
        throw GeometryError(problem.str());
    }
    Vec3 ratios = axis_ratios / axis_ratios.maxCoeff();
    std::sort(ratios.begin(), ratios.end(), std::greater<>());
    if (ratios.z() < kMinAxisRatio) {
        std::ostringstream problem;
        problem << "axis ratios 1 : " << ratios.y() << " : " << ratios.z()
                << ": the short axis must be at least " << kMinAxisRatio << " of the long one";
        throw GeometryError(problem.str());
    }
    return ratios;
}

}  // namespace

ConvexPolyhedron ellipsoid_rock(const Vec3& axis_ratios, std::uint64_t seed,
                                const RandomRockOptions& options) {
    check_options(options);
    const Vec3 ratios = normalised_ratios(axis_ratios);
    const ConvexPolyhedron hull = convex_hull(unit_cloud(seed, options));
    const ConvexPolyhedron ellipsoid = stretched(hull, ratios);
    // In the principal frame the second-moment matrix is diagonal, and a scaling along the
    // frame's axes keeps it diagonal (entries s_i s_j M_ij): the axes stay principal and the
    // extents along them, the axis lengths, become exactly the ratios.
    const MassProperties properties = mass_properties(ellipsoid);
    ConvexPolyhedron body =
        transformed(ellipsoid, properties.principal_axes.transpose(), -properties.centroid);
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 high = -low;
    for (const Vec3& v : body.vertices) {
        low = low.cwiseMin(v);
        high = high.cwiseMax(v);
    }
    const Vec3 extents = high - low;
    return stretched(body, ratios.cwiseQuotient(extents));
}

SphericityRock rock_with_sphericity(double sphericity, std::uint64_t seed,
                                    const RandomRockOptions& options) {
    check_options(options);
    const ConvexPolyhedron hull = convex_hull(unit_cloud(seed, options));
    const auto at = [&hull](double t) { return stretched(hull, Vec3(1.0, t, t * t)); };
    const double highest = sphericity_of(at(1.0));
    const double lowest = sphericity_of(at(kMinStretch));
    if (!(sphericity >= lowest && sphericity <= highest)) {
        std::ostringstream problem;
        problem << "target Wadell sphericity " << sphericity << ": seed " << seed << " with "
                << options.points << " points and roughness " << options.roughness << " reaches ["
                << lowest << ", " << highest << "]"
                << (sphericity > highest ? "; more points or less roughness reach higher" : "");
        throw GeometryError(problem.str());
    }
    // Bisection on the sign of f(t) - target; f is continuous in t, so the bracket always
    // holds a solution even where f is not monotonic.
    double low = kMinStretch;
    double high = 1.0;
    double t = high;
    for (int iteration = 0; iteration < 200; ++iteration) {
        t = 0.5 * (low + high);
        const double value = sphericity_of(at(t));
        if (std::abs(value - sphericity) <= 0.1 * kSphericityTolerance) break;
        (value < sphericity ? low : high) = t;
    }
    SphericityRock rock;
    // A fresh hull drops vertices that the stretch left within round-off of an edge.
    rock.hull = convex_hull(at(t).vertices);
    rock.sphericity = sphericity_of(rock.hull);
    rock.stretch = t;
    assert(std::abs(rock.sphericity - sphericity) <= kSphericityTolerance);
    return rock;
}

std::string_view to_string(ClumpShape shape) {
    switch (shape) {
        case ClumpShape::tetrahedral:
            return "tetrahedral";
        case ClumpShape::cubic:
            return "cubic";
        case ClumpShape::octahedral:
            return "octahedral";
        case ClumpShape::sphere:
            return "sphere";
    }
    assert(false && "unknown ClumpShape");
    return "unknown";
}

RockGeometry clump_rock(ClumpShape shape, double nominal_size) {
    const auto solid = [nominal_size](PlatonicKind kind) {
        return make_rock(CustomShape{std::string(to_string(kind)), platonic_solid(kind, 1.0)},
                         nominal_size);
    };
    switch (shape) {
        case ClumpShape::tetrahedral:
            return solid(PlatonicKind::tetrahedron);
        case ClumpShape::cubic:
            return solid(PlatonicKind::cube);
        case ClumpShape::octahedral:
            return solid(PlatonicKind::octahedron);
        case ClumpShape::sphere:
            return make_rock(RockKind::sphere, nominal_size);
    }
    assert(false && "unknown ClumpShape");
    return {};
}

}  // namespace rockfall::shapes
