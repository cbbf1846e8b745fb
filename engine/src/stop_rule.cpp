#include "stop_rule.hpp"

#include "shapes/terrain.hpp"

#include <algorithm>
#include <cmath>

namespace rockfall::engine {

StopRule::StopRule(const Numerics& numerics, const shapes::Slope& slope, double bounding_radius)
    : slope_(slope), numerics_(numerics), bounding_radius_(bounding_radius) {
    const shapes::SlopeSpec& spec = slope.spec();
    half_width_ = 0.5 * spec.width;
    domain_half_width_ = half_width_ + (spec.side_walls.enabled ? spec.side_walls.thickness : 0.0);
    double lowest = slope.profile().front().y();
    for (const Eigen::Vector2d& vertex : slope.profile()) {
        lowest = std::min(lowest, vertex.y());
    }
    if (spec.terrain) {
        lowest = std::min(lowest, spec.terrain->lower().z());
    }
    bottom_z_ = lowest - spec.thickness;
}

bool StopRule::inside_footprint(const Vec3& p) const {
    return p.x() >= 0.0 && p.x() <= slope_.end_x() && std::abs(p.y()) <= half_width_;
}

std::optional<StopReason> StopRule::check(const RockState& state, double dt) {
    const Vec3& p = state.position;
    if (!p.allFinite() || !state.velocity.allFinite() || !state.angular_velocity.allFinite() ||
        !state.orientation.coeffs().allFinite()) {
        return StopReason::numerical_failure;
    }
    if (inside_footprint(p)) {
        // Below the slab under it, inside the slope's footprint: it went through a solid. A
        // terrain mesh counts as the top of a slab of the slope's thickness.
        const shapes::Ground ground = shapes::ground_at(slope_, p.x(), p.y());
        const double slab_bottom = ground.height - slope_.spec().thickness / ground.normal.z();
        if (p.z() < slab_bottom) {
            return StopReason::numerical_failure;
        }
    }
    if (p.x() > slope_.end_x() || std::abs(p.y()) > domain_half_width_ || p.z() < bottom_z_) {
        return StopReason::left_domain;
    }
    // At rest when neither the centre nor any point of the rock moves faster than rest_speed.
    const double point_speed = state.angular_velocity.norm() * bounding_radius_;
    if (state.velocity.norm() < numerics_.rest_speed && point_speed < numerics_.rest_speed) {
        rest_time_ += dt;
        if (rest_time_ >= numerics_.rest_duration) {
            return StopReason::at_rest;
        }
    } else {
        rest_time_ = 0.0;
    }
    if (state.time >= numerics_.max_time) {
        return StopReason::time_limit;
    }
    return std::nullopt;
}

}  // namespace rockfall::engine
