#pragma once
// Near-wall refinement of the time step (issue 2): the coarse step away from the reaction wall,
// a fine step that resolves the compliant wall contact by steps_per_contact steps while a rock
// touches it, and shrinking steps in between. Private to the engine.

#include "world.hpp"

#include "engine/wall_contact.hpp"

#include <vector>

namespace rockfall::engine {

// A rock's distance and speed relative to the wall before a step.
struct WallApproach {
    // Lower bound of the distance between the rock and the wall box, m.
    double gap = 0.0;
    // Upper bound of the rate at which the gap can shrink, m/s: |v|, plus |w| times the
    // bounding radius for hulls (their corners turn toward the wall).
    double closing_speed = 0.0;
    // Normal speed of the rock's nearest point toward the wall, m/s (<= 0: moving away).
    double approach_speed = 0.0;
};

// The rock's approach. Beyond two coarse steps (coarse_dt, s) of travel the gap is a lower
// bound (that of the bounding sphere, or to the slab of the wall's first axis, where
// approach_speed stays 0); closer, that of the rock itself.
WallApproach wall_approach(const shapes::OrientedBox& wall, const shapes::RockGeometry& rock,
                           const BodyState& state, double coarse_dt);

// Fine step for a contact approached at `approach_speed` m/s: the law's contact duration over
// steps_per_contact, never above the coarse step. Speeds below the law's kMinContactSpeed
// count as that speed, as they do for the law itself.
double fine_step(const WallContactLaw& law, double approach_speed, int steps_per_contact,
                 double coarse_dt);

// Step before a rock that does not touch the wall: half the shortest time in which it could
// reach the wall, between the fine step of a contact at its approach speed and the coarse
// step. Beyond two coarse steps of travel this is the coarse step; closer, the steps shrink
// geometrically, so the first touch happens within a fine step.
double approach_step(const WallContactLaw& law, const WallApproach& approach, int steps_per_contact,
                     double coarse_dt);

// Whether a rock in `state` may reach one of `boxes` within two coarse steps (coarse_dt, s,
// under `gravity`, m/s2): its gap to a box below the distance it can close in that time, at
// the rate at which its centre approaches the box (-n.v, n the box's outward normal at the
// point closest to the centre; 0 when it moves away), plus |w| times the bounding radius for
// hulls, plus what gravity adds. The gap is the sphere's, and for a hull a lower bound: its
// separation from the plane through that point. Approaches slower than 1 m/s never count: the
// rock moves under a millimetre per 1 ms step (a rock resting on or creeping over a bar).
bool may_reach(const std::vector<shapes::OrientedBox>& boxes, const shapes::RockGeometry& rock,
               const BodyState& state, double coarse_dt, double gravity);

}  // namespace rockfall::engine
