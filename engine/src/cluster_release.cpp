// A scenario's cluster as placed rocks (see cluster_release.hpp).

#include "cluster_release.hpp"

#include "shapes/grading.hpp"
#include "shapes/random.hpp"
#include "shapes/release_box.hpp"

namespace rockfall::engine {
namespace {

// The cluster's own stream: apart from the release orientations of the scenario's rocks.
constexpr std::uint64_t kClusterStream = 0x636c7573746572ULL;  // "cluster"

constexpr double kWallThickness = 0.01;  // m

}  // namespace

std::vector<PlacedRock> cluster_rocks(const shapes::Slope& slope, const Cluster& cluster,
                                      std::uint64_t seed) {
    std::mt19937_64 generator = shapes::make_generator(seed ^ kClusterStream);
    const std::vector<double> sizes = shapes::cluster_sizes(cluster.grading, generator);
    std::vector<PlacedRock> rocks;
    rocks.reserve(sizes.size());
    std::vector<double> radii;
    Random random(seed ^ kClusterStream);
    for (const double size : sizes) {
        PlacedRock& rock = rocks.emplace_back();
        rock.spec.rock = cluster.rock;
        rock.spec.rock.size = size;
        rock.geometry = rock.spec.rock.geometry();
        rock.initial.orientation =
            uniform_rotation(random.uniform(), random.uniform(), random.uniform());
        radii.push_back(rock.geometry.bounding_radius);
    }
    const std::vector<Vec3> centres =
        shapes::pack_release_box(slope, cluster.box, radii, generator);
    for (std::size_t i = 0; i < rocks.size(); ++i) {
        rocks[i].initial.position = centres[i];
    }
    return rocks;
}

std::array<shapes::OrientedBox, 2> release_box_walls(const shapes::Slope& slope,
                                                     const shapes::ReleaseBox& box) {
    const shapes::OrientedBox region = shapes::release_box_region(slope, box);
    std::array<shapes::OrientedBox, 2> walls;
    for (int side = 0; side < 2; ++side) {
        shapes::OrientedBox& wall = walls[static_cast<std::size_t>(side)];
        wall = region;
        const double sign = side == 0 ? 1.0 : -1.0;
        const Vec3 axis = region.rotation.col(0);
        wall.half_extents.x() = 0.5 * kWallThickness;
        wall.center =
            region.center + sign * (region.half_extents.x() + 0.5 * kWallThickness) * axis;
        wall.role = shapes::SurfaceRole::side_wall;
        wall.segment = 0;
    }
    return walls;
}

}  // namespace rockfall::engine
