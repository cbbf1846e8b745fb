#include "release.hpp"

#include "shapes/terrain.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace rockfall::engine {

std::uint64_t Random::next() {
    state_ += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double Random::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

Eigen::Quaterniond uniform_rotation(double u1, double u2, double u3) {
    constexpr double two_pi = 2.0 * std::numbers::pi;
    const double a = std::sqrt(1.0 - u1);
    const double b = std::sqrt(u1);
    return Eigen::Quaterniond(b * std::cos(two_pi * u3), a * std::sin(two_pi * u2),
                              a * std::cos(two_pi * u2), b * std::sin(two_pi * u3));
}

Eigen::Quaterniond orientation_in_frame(const Eigen::Matrix3d& frame, const Vec3& angles_deg) {
    const Vec3 a = angles_deg * (std::numbers::pi / 180.0);
    const Eigen::Matrix3d local =
        (Eigen::AngleAxisd(a.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(a.y(), Vec3::UnitY()) *
         Eigen::AngleAxisd(a.x(), Vec3::UnitX()))
            .toRotationMatrix();
    return Eigen::Quaterniond(frame * local);
}

Eigen::Matrix3d surface_frame(const shapes::Slope& slope, double x) {
    Eigen::Matrix3d frame;
    frame.col(0) = slope.surface_tangent(x);
    frame.col(1) = Vec3::UnitY();
    frame.col(2) = slope.surface_normal(x);
    return frame;
}

double extent_along(const shapes::RockGeometry& rock, const Eigen::Quaterniond& orientation,
                    const Vec3& down) {
    if (rock.radius > 0.0) {
        return rock.radius;
    }
    const Vec3 local = orientation.conjugate() * down;
    double extent = 0.0;
    for (const Vec3& v : rock.hull.vertices) {
        extent = std::max(extent, v.dot(local));
    }
    return extent;
}

BodyState release_state(const shapes::Slope& slope, const shapes::RockGeometry& rock,
                        const Release& release, Random& random) {
    const double u1 = random.uniform();
    const double u2 = random.uniform();
    const double u3 = random.uniform();

    const Vec3 profile_point = slope.point_at_distance(release.distance);
    const Eigen::Matrix3d frame = surface_frame(slope, profile_point.x());
    Vec3 surface_point = profile_point + release.lateral * Vec3::UnitY();
    Vec3 normal = frame.col(2);
    if (slope.spec().terrain) {
        // On a terrain mesh the rock starts above the mesh, lifted along its normal there.
        const shapes::Ground ground =
            shapes::ground_at(slope, surface_point.x(), surface_point.y());
        surface_point.z() = ground.height;
        normal = ground.normal;
    }

    BodyState state;
    state.orientation = release.random_orientation
                            ? uniform_rotation(u1, u2, u3)
                            : orientation_in_frame(frame, release.orientation_deg);
    const double depth = extent_along(rock, state.orientation, -normal);
    state.position = surface_point + (release.height + depth) * normal;
    state.velocity = release.velocity;
    state.angular_velocity = release.spin;
    return state;
}

}  // namespace rockfall::engine
