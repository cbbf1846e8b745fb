// The compliant wall contact at one instant and sub-stepped inside a rigid-body step (see
// wall_substep.hpp).

#include "wall_substep.hpp"

#include "recorders.hpp"
#include "step_size.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace rockfall::engine {
namespace {

// Rotation by the rotation vector `theta` (rad), applied in the world frame.
Eigen::Quaterniond rotation(const Vec3& theta) {
    const double angle = theta.norm();
    if (angle == 0.0) {
        return Eigen::Quaterniond::Identity();
    }
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, theta / angle));
}

// Angular acceleration (rad/s2) of a body with principal moments `inertia` in orientation `q`
// under the torque `torque` (N m): I_w^-1 torque with I_w = R diag(inertia) R^T.
Vec3 angular_acceleration(const Eigen::Quaterniond& q, const Vec3& inertia, const Vec3& torque) {
    const Eigen::Matrix3d r = q.toRotationMatrix();
    return r * (r.transpose() * torque).cwiseQuotient(inertia);
}

}  // namespace

WallContactAt wall_contact_at(const shapes::OrientedBox& wall, const WallRock& rock,
                              const BodyState& state, double time, int steps_per_contact,
                              double coarse_dt) {
    WallContactTrack& track = rock.track;
    const std::optional<WallOverlap> overlap = wall_overlap(
        wall, rock.geometry, state.position, state.orientation, rock.law.hull_features());
    const bool first_touch = overlap && !track.touching;
    track.touching = overlap.has_value();
    WallContactAt at;
    if (!overlap) {
        return at;
    }
    if (overlap->depth > 0.5 * rock.geometry.nominal_size) {
        at.kind = WallContactAt::Kind::inside;
        return at;
    }
    const Vec3 point_velocity =
        state.velocity + state.angular_velocity.cross(overlap->point - state.position);
    if (first_touch) {
        const double normal_speed = std::max(0.0, -point_velocity.dot(overlap->normal));
        if (normal_speed < kRestingContactSpeed && rock.rigid_resting) {
            at.kind = WallContactAt::Kind::resting;
            return at;
        }
        const double speed = std::max(normal_speed, kRestingContactSpeed);
        rock.law.begin_contact(speed);
        track.step = fine_step(rock.law, speed, steps_per_contact, coarse_dt);
        track.start = time;
        track.duration = rock.law.longest_contact_duration(speed);
        track.speed = speed;
    }
    // Held against the wall: longer than an impact lasts, or deeper than one reaches.
    if (rock.rigid_resting && (time - track.start > kRestingContactDurations * track.duration ||
                               overlap->depth > track.speed * track.duration)) {
        at.kind = WallContactAt::Kind::resting;
        return at;
    }
    at.kind = WallContactAt::Kind::force;
    at.force = rock.law.force(*overlap, point_velocity);
    return at;
}

// Symplectic Euler on the rock alone, as Bullet integrates a body: v += a h, then x += v h and
// the orientation turns by w h. The parts of velocity and spin the wall added are summed
// separately (u, a), and so is the displacement they caused (the integrals of u and a), which
// the rigid-body step reproduces only as u dt and a dt.
WallSubsteps substep_wall(const shapes::OrientedBox& wall, const WallRock& rock,
                          const BodyState& start, double time, double dt, const Vec3& gravity,
                          int steps_per_contact, LoadCell& cell) {
    WallSubsteps result;
    BodyState s = start;
    RockState before = rock_state(s, time, rock.mass, rock.inertia);
    Vec3 wall_velocity = Vec3::Zero();
    Vec3 wall_spin = Vec3::Zero();
    Vec3 wall_displacement = Vec3::Zero();
    Vec3 wall_rotation = Vec3::Zero();
    double elapsed = 0.0;
    while (elapsed < dt) {
        const double remaining = dt - elapsed;
        double h = remaining;
        if (rock.track.touching || cell.in_contact()) {
            h = std::min(remaining, rock.track.step);
        } else {
            const WallApproach approach = wall_approach(wall, rock.geometry, s, remaining);
            h = approach_step(rock.law, approach, steps_per_contact, remaining);
        }
        // The last sub-step takes what is left of the step rather than a sliver after it.
        if (remaining - h < 1e-3 * h) {
            h = remaining;
        }
        const WallContactAt at =
            wall_contact_at(wall, rock, s, time + elapsed, steps_per_contact, dt);
        if (at.kind == WallContactAt::Kind::resting || at.kind == WallContactAt::Kind::inside) {
            result.end = at.kind;
            break;
        }
        Vec3 force = Vec3::Zero();
        Vec3 torque = Vec3::Zero();
        if (at.kind == WallContactAt::Kind::force) {
            force = at.force.force;
            torque = (at.force.point - s.position).cross(force);
            result.end = WallContactAt::Kind::force;
        }
        const Vec3 dv = force * (h / rock.mass);
        const Vec3 dw = angular_acceleration(s.orientation, rock.inertia, torque) * h;
        s.velocity += gravity * h + dv;
        s.angular_velocity += dw;
        s.position += s.velocity * h;
        s.orientation = (rotation(s.angular_velocity * h) * s.orientation).normalized();
        wall_velocity += dv;
        wall_spin += dw;
        wall_displacement += wall_velocity * h;
        wall_rotation += wall_spin * h;
        result.impulse += force * h;
        result.angular_impulse += torque * h;
        elapsed += h;
        ++result.substeps;
        const RockState after = rock_state(s, time + elapsed, rock.mass, rock.inertia);
        if (at.kind == WallContactAt::Kind::force || cell.in_contact()) {
            cell.record(
                h, at.kind == WallContactAt::Kind::force ? std::optional(at.force) : std::nullopt,
                before, after);
        }
        before = after;
    }
    // Stopped early (a resting contact), the rock carries what the wall gave it to the end.
    wall_displacement += wall_velocity * (dt - elapsed);
    wall_rotation += wall_spin * (dt - elapsed);
    result.position_shift = wall_displacement - wall_velocity * dt;
    result.rotation_shift = wall_rotation - wall_spin * dt;
    return result;
}

}  // namespace rockfall::engine
