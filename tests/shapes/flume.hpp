#pragma once
// Seed 001's flume for the lining and release-box tests.

#include "shapes/slope.hpp"

#include <numbers>

namespace rockfall::shapes::test {

inline double deg(double degrees) { return degrees * std::numbers::pi / 180.0; }

// 1.82 m inclined at `angle_deg`, then a horizontal section as long; 0.60 m wide, side walls
// 0.30 m high; no bars and no reaction wall (not needed by the linings and the box).
inline Slope flume(double angle_deg = 45.0) {
    SlopeSpec spec;
    spec.segments = {{1.82, angle_deg}, {1.82, 0.0}};
    spec.width = 0.60;
    spec.side_walls.height = 0.30;
    spec.bars.enabled = false;
    spec.wall.enabled = false;
    return Slope(spec);
}

}  // namespace rockfall::shapes::test
