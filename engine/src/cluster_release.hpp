#pragma once
// A scenario's cluster as rocks: sizes drawn from its grading by the run's seed, packed in the
// release box, and the box's walls that hold them while they settle. Private to the engine.

#include "release.hpp"
#include "world.hpp"

#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace rockfall::engine {

// One rock ready to be added to the world.
struct PlacedRock {
    RockRelease spec;
    shapes::RockGeometry geometry;
    BodyState initial;
};

// The cluster's rocks: sizes from cluster_sizes, each a rock of the cluster's family at that
// size in a random orientation, then the marked rocks (named, dropped at their spots, in their
// own orientation or a random one), placed by pack_release_box (bounding spheres), all from
// `seed`. Throws shapes::PackingError when they do not fit the box.
std::vector<PlacedRock> cluster_rocks(const shapes::Slope& slope, const Cluster& cluster,
                                      std::uint64_t seed);

// The walls that close the release box while the cluster settles: the gate across its
// downslope face (index 0) and the back across its upslope face (index 1), 1 cm thick, as
// high as the box, outside its inside region.
std::array<shapes::OrientedBox, 2> release_box_walls(const shapes::Slope& slope,
                                                     const shapes::ReleaseBox& box);

}  // namespace rockfall::engine
