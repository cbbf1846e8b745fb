#pragma once
/// Fixed-size vector and tensor types of the MPM solver, in 2D (plane strain) or 3D.
///
/// The 2D solver works in the vertical x-z plane of the scene: solver axis 0 is scene x
/// (downslope), solver axis 1 is scene z (up); scene y is the out-of-plane direction.
/// Tensors (stress, strain increments) are always 3x3; in 2D their index 2 is the out-of-plane
/// direction, whose strain rate is zero (plane strain) and whose stress is kept.

#include <Eigen/Core>

#include <cmath>
#include <numbers>

namespace rockfall::mpm {

/// A point or vector in the solver's space (Dim = 2 or 3), m or m/s.
template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;
/// A Dim x Dim matrix (velocity gradient, affine velocity), 1/s.
template <int Dim>
using Mat = Eigen::Matrix<double, Dim, Dim>;
/// Integer grid coordinates.
template <int Dim>
using IVec = Eigen::Matrix<int, Dim, 1>;
/// A scene-frame vector (x downslope, y across, z up).
using Vec3 = Eigen::Vector3d;
/// A 3x3 tensor (Cauchy stress in Pa, tension positive; strain increments).
using Mat3 = Eigen::Matrix3d;

/// The scene point of a solver point: 3D unchanged, 2D (x, z) -> (x, 0, z).
template <int Dim>
Vec3 to_scene(const Vec<Dim>& v) {
    if constexpr (Dim == 3) {
        return v;
    } else {
        return {v[0], 0.0, v[1]};
    }
}

/// The solver vector of a scene vector: 3D unchanged, 2D keeps (x, z).
template <int Dim>
Vec<Dim> from_scene(const Vec3& v) {
    if constexpr (Dim == 3) {
        return v;
    } else {
        return {v[0], v[2]};
    }
}

/// Embeds a Dim x Dim tensor into 3x3; in 2D the out-of-plane row and column are zero.
template <int Dim>
Mat3 embed(const Mat<Dim>& m) {
    if constexpr (Dim == 3) {
        return m;
    } else {
        Mat3 out = Mat3::Zero();
        out.template topLeftCorner<2, 2>() = m;
        return out;
    }
}

/// Degrees to radians.
inline double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

/// Rotation about the scene's +y axis by `angle` rad (right-handed: x -> (cos, 0, -sin)).
inline Mat3 rotation_y(double angle) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    Mat3 r;
    r << c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c;
    return r;
}

}  // namespace rockfall::mpm
