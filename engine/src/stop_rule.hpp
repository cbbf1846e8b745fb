#pragma once
// When one rock's simulation ends: at rest, out of the domain, time limit, numerical failure.
// Private to the engine.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "shapes/slope.hpp"

#include <optional>

namespace rockfall::engine {

class StopRule {
  public:
    // bounding_radius: the rock's bounding radius, m (turns spin into a surface speed).
    StopRule(const Numerics& numerics, const shapes::Slope& slope, double bounding_radius);

    // Called after each step of dt seconds with the rock's new state; returns why the rock
    // stops, or nothing while it goes on.
    std::optional<StopReason> check(const RockState& state, double dt);

  private:
    bool inside_footprint(const Vec3& p) const;

    const shapes::Slope& slope_;
    Numerics numerics_;
    double bounding_radius_;
    double half_width_;
    double domain_half_width_;
    double bottom_z_;
    double rest_time_ = 0.0;
};

}  // namespace rockfall::engine
