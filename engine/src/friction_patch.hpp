#pragma once
// Where the friction of a contact patch acts and how much twist it resists. Private to the
// engine.
//
// The points of one manifold (a rock on a face, a rock on a rock) are one contact patch. Its
// friction is one Coulomb force, bounded by mu times the patch's whole normal impulse, acting at
// one anchor, and one twisting torque about the normal, bounded by mu times the normal impulse
// times a twist radius: the patch friction of PhysX (PxFrictionType::ePATCH) and the soft-finger
// contact of grasping (Howe and Cutkosky 1996, "Practical force-motion models for sliding
// manipulation", Int. J. Robotics Research 15(6), with the circular limit surface; the force and
// the torque are bounded separately here, the sum of the two used fractions is not).
//
// The anchor is the projection of the moving body's centre of mass onto the patch, clamped into
// the patch's polygon. A body sliding on a face without tipping has its centre of pressure on
// the line through that projection along the slip (the moment balance about the in-plane axes),
// and a friction force along the slip acting anywhere on that line has no moment about the
// normal. Per-point friction instead acts where the iterative solver happens to put the normal
// impulse: on one corner or another from step to step, which turned a block sliding straight
// down a 30 degree incline by 29 degrees in 2.4 s (mu = 0.3).
//
// The twist radius is that of a disc of the polygon's area under uniform pressure, 2/3 of its
// radius (within 2 % of a square's exact mean lever arm); a line contact of length L (two
// points) resists with L/4, a single point not at all.

#include <btBulletDynamicsCommon.h>

namespace rockfall::engine {

struct PatchGeometry {
    btVector3 anchor;     // world, m
    double twist_radius;  // m
};

// `points`: the patch's contact points (world, m), `count` in [1, 8] (more are ignored); `normal`:
// unit; `centre`: the point to project (the moving body's centre of mass), or nullptr for the
// points' centroid.
PatchGeometry patch_geometry(const btVector3* points, int count, const btVector3& normal,
                             const btVector3* centre);

}  // namespace rockfall::engine
