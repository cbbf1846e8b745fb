#pragma once
// Bullet's discrete dynamics world with pair margins scaled to the rocks. Private to the engine.
//
// Bullet widens every moving object's AABB by gContactBreakingThreshold, a fixed 0.02 m, so that
// a pair exists a little before its shapes touch. For rocks of a few centimetres (seed 001's
// flume and heap test: d50 25 to 53 mm) that widening is as large as the rocks themselves: a
// pile then has several times more broadphase pairs than touching ones, each paying a GJK
// query per step (a 300-cube heap: 58 % of its time in collision detection). This world widens
// a rock's AABB by kPairReach times its bounding radius, at most Bullet's 0.02 m (rocks of 0.1 m
// radius and more keep Bullet's margin), and leaves static bodies at their exact AABB (they do
// not move; a moving rock's own margin covers the pair).

#include <btBulletDynamicsCommon.h>

namespace rockfall::engine {

// A rock's AABB widening as a fraction of its bounding radius (Bullet's "angular motion disc").
inline constexpr double kPairReach = 0.2;

class RockDynamicsWorld : public btDiscreteDynamicsWorld {
  public:
    using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
    void updateAabbs() override;

  private:
    void update_aabb(btCollisionObject& object);
};

}  // namespace rockfall::engine
