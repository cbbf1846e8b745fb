#pragma once
// A rock on one long straight plane, for the motion and contact tests: the library's
// verification scenes (engine/verification_scenes.hpp) under the tests' names.

#include "engine/simulation.hpp"
#include "engine/verification_scenes.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace rockfall::engine::test {

inline constexpr double kGravity = scenes::gravity;  // m/s2

using scenes::downslope;
using scenes::plane_scenario;
using scenes::radians;
using scenes::state_at;
using scenes::trajectory;

}  // namespace rockfall::engine::test
