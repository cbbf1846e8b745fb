#pragma once
// Bullet collision shapes for rocks and static boxes. Private to the engine.

#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <btBulletCollisionCommon.h>

#include <memory>

namespace rockfall::engine {

// A sphere for spherical rocks (exact rolling); for hulls, the hull shrunk by the collision
// margin (every face moved inward by it) so that Bullet's shape, the shrunk hull grown by the
// margin, has the rock's true faces with edges rounded to the margin.
std::unique_ptr<btConvexShape> make_rock_shape(const shapes::RockGeometry& rock);

// A box with the solid's exact outer dimensions (btBoxShape keeps its margin inside).
std::unique_ptr<btBoxShape> make_box_shape(const shapes::OrientedBox& box);

}  // namespace rockfall::engine
