#include "rock_world.hpp"

#include <algorithm>

namespace rockfall::engine {

void RockDynamicsWorld::updateAabbs() {
    for (int i = 0; i < m_collisionObjects.size(); ++i) {
        btCollisionObject& object = *m_collisionObjects[i];
        // A static body keeps the AABB it was added with (Bullet computes it then, unwidened).
        if (object.isStaticObject()) continue;
        if (m_forceUpdateAllAabbs || object.isActive()) update_aabb(object);
    }
}

// Bullet's btCollisionWorld::updateSingleAabb with the widening scaled to the object.
void RockDynamicsWorld::update_aabb(btCollisionObject& object) {
    const btCollisionShape& shape = *object.getCollisionShape();
    btVector3 lower, upper;
    shape.getAabb(object.getWorldTransform(), lower, upper);
    const bool moving = object.getInternalType() == btCollisionObject::CO_RIGID_BODY &&
                        !object.isStaticOrKinematicObject();
    const btScalar reach = moving ? std::min(gContactBreakingThreshold,
                                             btScalar(kPairReach) * shape.getAngularMotionDisc())
                                  : btScalar(0.0);
    const btVector3 widening(reach, reach, reach);
    lower -= widening;
    upper += widening;
    if (getDispatchInfo().m_useContinuous && moving) {
        btVector3 lower2, upper2;
        shape.getAabb(object.getInterpolationWorldTransform(), lower2, upper2);
        lower.setMin(lower2 - widening);
        upper.setMax(upper2 + widening);
    }
    // Bullet takes a moving AABB over 1e6 m across for a broken state and stops simulating
    // the object; so does this world (the engine reports the non-finite state).
    if ((upper - lower).length2() < btScalar(1e12)) {
        m_broadphasePairCache->setAabb(object.getBroadphaseHandle(), lower, upper, m_dispatcher1);
    } else {
        object.setActivationState(DISABLE_SIMULATION);
    }
}

}  // namespace rockfall::engine
