#pragma once
// Shared set-ups for the MPM tests: boxes in the scene frame, from the library's verification
// cases (mpm/verification.hpp).

#include "mpm/boundary.hpp"
#include "mpm/verification.hpp"
#include "shapes/slope.hpp"

#include <cmath>
#include <numbers>

namespace rockfall::mpm::test {

using verification::axis_box;
using verification::inclined_box;
using verification::solid;

}  // namespace rockfall::mpm::test
