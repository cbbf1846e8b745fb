#include "shapes/mass_properties.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <array>
#include <cassert>
#include <cmath>
#include <numbers>

namespace rockfall::shapes {
namespace {

// Per-axis subexpressions of Eberly's polyhedral mass properties: for a triangle with
// coordinates w0, w1, w2 along one axis, f1..f3 integrate w, w^2, w^3 and g0..g2 the mixed
// products (Eberly 2002, "Polyhedral Mass Properties (Revisited)", eqs. for f and g).
struct Subexpressions {
    double f1, f2, f3, g0, g1, g2;
};

Subexpressions subexpressions(double w0, double w1, double w2) {
    const double t0 = w0 + w1;
    const double f1 = t0 + w2;
    const double t1 = w0 * w0;
    const double t2 = t1 + w1 * t0;
    const double f2 = t2 + w2 * f1;
    const double f3 = w0 * t1 + w1 * t2 + w2 * f2;
    return {f1, f2, f3, f2 + w0 * (f1 + w0), f2 + w1 * (f1 + w1), f2 + w2 * (f1 + w2)};
}

// Makes each axis point into the half-space of its largest component and the frame right-handed,
// so that equal inputs always give the same axes.
Eigen::Matrix3d canonical_axes(Eigen::Matrix3d axes) {
    for (int k = 0; k < 3; ++k) {
        Eigen::Index largest = 0;
        axes.col(k).cwiseAbs().maxCoeff(&largest);
        if (axes(largest, k) < 0.0) {
            axes.col(k) = -axes.col(k);
        }
    }
    if (axes.determinant() < 0.0) {
        axes.col(2) = -axes.col(2);
    }
    return axes;
}

}  // namespace

MassProperties mass_properties(const ConvexPolyhedron& poly) {
    assert(!poly.vertices.empty());
    // Integrate about the vertex mean: the integrals of x^2 etc. then stay of the size of the
    // body, not of its distance from the origin, which keeps the parallel-axis step accurate.
    Vec3 origin = Vec3::Zero();
    for (const Vec3& v : poly.vertices) {
        origin += v;
    }
    origin /= static_cast<double>(poly.vertices.size());

    // Volume integrals of 1, x, y, z, x^2, y^2, z^2, xy, yz, zx over the solid.
    std::array<double, 10> integral{};
    double area = 0.0;
    for (const auto& tri : poly.triangles) {
        const Vec3 p0 = poly.vertices[static_cast<std::size_t>(tri[0])] - origin;
        const Vec3 p1 = poly.vertices[static_cast<std::size_t>(tri[1])] - origin;
        const Vec3 p2 = poly.vertices[static_cast<std::size_t>(tri[2])] - origin;
        const Vec3 d = (p1 - p0).cross(p2 - p0);
        area += 0.5 * d.norm();
        const Subexpressions x = subexpressions(p0.x(), p1.x(), p2.x());
        const Subexpressions y = subexpressions(p0.y(), p1.y(), p2.y());
        const Subexpressions z = subexpressions(p0.z(), p1.z(), p2.z());
        integral[0] += d.x() * x.f1;
        integral[1] += d.x() * x.f2;
        integral[2] += d.y() * y.f2;
        integral[3] += d.z() * z.f2;
        integral[4] += d.x() * x.f3;
        integral[5] += d.y() * y.f3;
        integral[6] += d.z() * z.f3;
        integral[7] += d.x() * (p0.y() * x.g0 + p1.y() * x.g1 + p2.y() * x.g2);
        integral[8] += d.y() * (p0.z() * y.g0 + p1.z() * y.g1 + p2.z() * y.g2);
        integral[9] += d.z() * (p0.x() * z.g0 + p1.x() * z.g1 + p2.x() * z.g2);
    }
    constexpr std::array<double, 10> scale = {1.0 / 6.0,   1.0 / 24.0, 1.0 / 24.0, 1.0 / 24.0,
                                              1.0 / 60.0,  1.0 / 60.0, 1.0 / 60.0, 1.0 / 120.0,
                                              1.0 / 120.0, 1.0 / 120.0};
    for (std::size_t i = 0; i < integral.size(); ++i) {
        integral[i] *= scale[i];
    }

    MassProperties props;
    props.volume = integral[0];
    props.surface_area = area;
    assert(props.volume > 0.0 && "mass_properties: polyhedron must be closed and outward");
    const Vec3 c = Vec3(integral[1], integral[2], integral[3]) / props.volume;
    props.centroid = origin + c;

    // Second moments about the centroid by the parallel-axis theorem.
    const double xx = integral[4] - props.volume * c.x() * c.x();
    const double yy = integral[5] - props.volume * c.y() * c.y();
    const double zz = integral[6] - props.volume * c.z() * c.z();
    const double xy = integral[7] - props.volume * c.x() * c.y();
    const double yz = integral[8] - props.volume * c.y() * c.z();
    const double zx = integral[9] - props.volume * c.z() * c.x();
    props.inertia << yy + zz, -xy, -zx, -xy, zz + xx, -yz, -zx, -yz, xx + yy;

    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(props.inertia);
    assert(solver.info() == Eigen::Success);
    props.principal_moments = solver.eigenvalues();
    props.principal_axes = canonical_axes(solver.eigenvectors());
    return props;
}

double wadell_sphericity(double volume, double surface_area) {
    assert(volume > 0.0 && surface_area > 0.0);
    return std::cbrt(std::numbers::pi) * std::pow(6.0 * volume, 2.0 / 3.0) / surface_area;
}

double equivalent_diameter(double volume) {
    assert(volume >= 0.0);
    return std::cbrt(6.0 * volume / std::numbers::pi);
}

}  // namespace rockfall::shapes
