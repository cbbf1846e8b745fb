#pragma once
// Initial state of a rock from its release and the run's seed. Private to the engine.

#include "world.hpp"

#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <cstdint>

namespace rockfall::engine {

// Deterministic random numbers from a run's seed: SplitMix64 (Steele, Lea and Flood 2014,
// "Fast splittable pseudorandom number generators"). Our own conversion to doubles, so that
// results do not depend on a standard library's distributions.
class Random {
  public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next();
    // Uniform in [0, 1): the top 53 bits scaled by 2^-53.
    double uniform();

  private:
    std::uint64_t state_;
};

// Uniformly distributed rotation from three uniforms in [0, 1) (Shoemake 1992, "Uniform
// random rotations", Graphics Gems III).
Eigen::Quaterniond uniform_rotation(double u1, double u2, double u3);

// Orientation from x-y-z Euler angles in degrees about the fixed axes of `frame` (columns):
// first about x, then y, then z.
Eigen::Quaterniond orientation_in_frame(const Eigen::Matrix3d& frame, const Vec3& angles_deg);

// Surface frame at horizontal position x: columns downslope tangent, across (y), up normal.
Eigen::Matrix3d surface_frame(const shapes::Slope& slope, double x);

// Where and how a rock starts: on the surface point at release.distance, shifted by
// release.lateral, lifted along the normal until its lowest point is release.height above
// the surface (with a terrain mesh: the point of the mesh under it, along the mesh's normal).
// Always draws three uniforms from `random`, so each rock consumes the same amount of the stream
// whether or not its orientation is random.
BodyState release_state(const shapes::Slope& slope, const shapes::RockGeometry& rock,
                        const Release& release, Random& random);

// Extent of the rock below its centroid along the unit direction `down`, m (the radius for a
// sphere; the largest projection of a hull vertex otherwise).
double extent_along(const shapes::RockGeometry& rock, const Eigen::Quaterniond& orientation,
                    const Vec3& down);

}  // namespace rockfall::engine
