#pragma once
// Shared set-ups for the MPM tests: boxes in the scene frame, from the library's verification
// cases (mpm/verification.hpp).

#include "mpm/boundary.hpp"
#include "mpm/soil.hpp"
#include "mpm/verification.hpp"
#include "shapes/slope.hpp"

#include <cmath>
#include <numbers>

namespace rockfall::mpm::test {

using verification::axis_box;
using verification::inclined_box;
using verification::solid;

/// samples/soil/quick_2d.toml: the seed flow in 2D (scenario C along the slope's centre line),
/// the wall 0.5 m past the toe, 5 s, at `cell` m cells on `threads` threads.
inline SoilScenario quick_2d(double cell, int threads = 1) {
    SoilScenario s;
    s.numerics.dimension = 2;
    s.numerics.threads = threads;
    s.numerics.cell_size = cell;
    s.slope.wall.distance_from_toe = 0.5;
    s.output.duration = 5.0;
    return s;
}

}  // namespace rockfall::mpm::test
