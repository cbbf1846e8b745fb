#include "step_size.hpp"

#include "release.hpp"

#include <algorithm>
#include <cmath>

namespace rockfall::engine {
namespace {

// Distance kept in reserve when the time to reach the wall is estimated, m: the change of
// velocity within a step (g dt^2 / 2 is 5e-6 m at 1 ms) must not close the last gap.
constexpr double kReserve = 1e-4;

// Slowest approach to an angle bar that refines the step, m/s: below it a rock moves under a
// millimetre per 1 ms step and no landing beside the bar falls into the step of its strike.
constexpr double kMinBarApproach = 1.0;

}  // namespace

WallApproach wall_approach(const shapes::OrientedBox& wall, const shapes::RockGeometry& rock,
                           const BodyState& state, double coarse_dt) {
    const bool sphere = rock.radius > 0.0;
    WallApproach approach;
    approach.closing_speed = state.velocity.norm() +
                             (sphere ? 0.0 : state.angular_velocity.norm() * rock.bounding_radius);
    // The distance to a box is at least the distance to the slab between its two faces normal
    // to its first axis; when even that bound leaves more than two coarse steps of travel,
    // approach_step takes the coarse step and the exact distance is not needed (it cost 0.4 %
    // of a run, measured with callgrind on the seed slope).
    const double slab_gap = std::abs(wall.rotation.col(0).dot(state.position - wall.center)) -
                            wall.half_extents.x() - rock.bounding_radius;
    if (slab_gap > 2.0 * approach.closing_speed * coarse_dt + kReserve) {
        approach.gap = slab_gap;
        return approach;
    }
    Vec3 normal = Vec3::Zero();
    const double centre_distance = shapes::signed_distance(wall, state.position, &normal);
    approach.approach_speed = -state.velocity.dot(normal);
    approach.gap = centre_distance - rock.bounding_radius;
    if (!sphere && approach.gap <= 2.0 * approach.closing_speed * coarse_dt + kReserve) {
        // Separation along the normal at the box's closest point bounds the distance from
        // below (the box's support in that direction is that point): exact facing the front.
        approach.gap = centre_distance - extent_along(rock, state.orientation, -normal);
        approach.approach_speed += state.angular_velocity.norm() * rock.bounding_radius;
    }
    return approach;
}

double fine_step(const WallContactLaw& law, double approach_speed, int steps_per_contact,
                 double coarse_dt) {
    const double duration =
        law.contact_duration(std::max(approach_speed, WallContactLaw::kMinContactSpeed));
    return std::min(coarse_dt, duration / steps_per_contact);
}

double approach_step(const WallContactLaw& law, const WallApproach& approach, int steps_per_contact,
                     double coarse_dt) {
    if (approach.closing_speed <= 0.0) {
        return coarse_dt;
    }
    const double half_time_to_reach = 0.5 * (approach.gap - kReserve) / approach.closing_speed;
    if (half_time_to_reach >= coarse_dt) {
        return coarse_dt;
    }
    return std::max(half_time_to_reach,
                    fine_step(law, approach.approach_speed, steps_per_contact, coarse_dt));
}

bool may_reach(const std::vector<shapes::OrientedBox>& boxes, const shapes::RockGeometry& rock,
               const BodyState& state, double coarse_dt, double gravity) {
    const bool sphere = rock.radius > 0.0;
    const double spin_reach = sphere ? 0.0 : state.angular_velocity.norm() * rock.bounding_radius;
    // The approach speed below is at most this.
    if (state.velocity.norm() + spin_reach < kMinBarApproach) return false;
    const double horizon = 2.0 * coarse_dt;
    return std::any_of(boxes.begin(), boxes.end(), [&](const shapes::OrientedBox& box) {
        Vec3 normal = Vec3::Zero();
        const double centre_distance = shapes::signed_distance(box, state.position, &normal);
        // The distance from a convex box is a convex function of the position, so along the
        // centre's path it falls no faster than it starts to, -n.v, plus what gravity adds;
        // a hull's corners can turn towards the box at up to |w| times its bounding radius.
        const double closing = std::max(0.0, -normal.dot(state.velocity)) + spin_reach;
        if (closing < kMinBarApproach) return false;
        const double travel = horizon * closing + 0.5 * gravity * horizon * horizon + kReserve;
        if (centre_distance - rock.bounding_radius >= travel) return false;
        if (sphere) return true;
        // A hull's bounding sphere reaches a bar long before the hull does (a slab's by up to
        // its half length): the separation along the normal at the box's closest point bounds
        // the gap from below, as for the wall (wall_approach).
        return centre_distance - extent_along(rock, state.orientation, -normal) < travel;
    });
}

}  // namespace rockfall::engine
