// A scenario's cluster as placed rocks (see cluster_release.hpp).

#include "cluster_release.hpp"

#include "engine/simulation.hpp"
#include "shapes/generators.hpp"
#include "shapes/grading.hpp"
#include "shapes/random.hpp"
#include "shapes/release_box.hpp"

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

namespace rockfall::engine {
namespace {

// The cluster's own stream: apart from the release orientations of the scenario's rocks.
constexpr std::uint64_t kClusterStream = 0x636c7573746572ULL;  // "cluster"

// The stream of the drawn rocks' shapes when the cluster has a target sphericity.
constexpr std::uint64_t kShapeStream = 0x7368617065ULL;  // "shape"

constexpr double kWallThickness = 0.01;  // m

}  // namespace

std::vector<PlacedRock> cluster_rocks(const shapes::Slope& slope, const Cluster& cluster,
                                      std::uint64_t seed) {
    std::mt19937_64 generator = shapes::make_generator(seed ^ kClusterStream);
    const std::vector<double> sizes = shapes::cluster_sizes(cluster.grading, generator);
    std::vector<PlacedRock> rocks;
    rocks.reserve(sizes.size() + cluster.marked.size());
    std::vector<double> radii;
    std::vector<std::optional<shapes::Vec2>> spots;
    Random random(seed ^ kClusterStream);
    const auto add = [&](const RockSpec& spec) -> PlacedRock& {
        PlacedRock& rock = rocks.emplace_back();
        rock.spec.rock = spec;
        rock.geometry = spec.geometry();
        // Three uniforms for every rock, so a marked rock's orientation does not shift the
        // stream of those after it.
        const double u1 = random.uniform();
        const double u2 = random.uniform();
        const double u3 = random.uniform();
        rock.initial.orientation = uniform_rotation(u1, u2, u3);
        radii.push_back(rock.geometry.bounding_radius);
        spots.emplace_back();
        return rock;
    };
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        RockSpec spec = cluster.rock;
        spec.size = sizes[i];
        if (cluster.sphericity > 0.0) {
            const std::uint64_t shape_seed = (seed ^ kShapeStream) + i;
            spec.kind = shapes::RockKind::custom;
            spec.shape = std::make_shared<const shapes::CustomShape>(shapes::CustomShape{
                "sphericity " + std::to_string(cluster.sphericity).substr(0, 4),
                shapes::rock_with_sphericity(cluster.sphericity, shape_seed).hull});
        }
        add(spec);
    }
    const Eigen::Matrix3d frame =
        surface_frame(slope, slope.point_at_distance(cluster.box.start).x());
    for (const MarkedRock& marked : cluster.marked) {
        PlacedRock& rock = add(marked.rock);
        rock.spec.name = marked.name;
        if (marked.orientation_deg) {
            rock.initial.orientation = orientation_in_frame(frame, *marked.orientation_deg);
        }
        spots.back() = shapes::Vec2(marked.along, marked.across);
    }
    if (cluster.box.packing == shapes::Packing::flat) {
        // Lying flat as their bounding boxes, in the orientation the packing gives them.
        std::vector<Vec3> half_extents;
        for (const PlacedRock& rock : rocks) half_extents.push_back(rock.geometry.half_extents);
        const std::vector<shapes::RockPose> poses =
            shapes::pack_release_box_flat(slope, cluster.box, half_extents, generator, spots);
        for (std::size_t i = 0; i < rocks.size(); ++i) {
            rocks[i].initial.position = poses[i].center;
            rocks[i].initial.orientation = Eigen::Quaterniond(poses[i].rotation).normalized();
        }
        return rocks;
    }
    const std::vector<Vec3> centres =
        shapes::pack_release_box(slope, cluster.box, radii, generator, spots);
    for (std::size_t i = 0; i < rocks.size(); ++i) {
        rocks[i].initial.position = centres[i];
    }
    return rocks;
}

RockSpec simulated_rock(const Scenario& scenario, std::size_t index, std::size_t count,
                        double size) {
    if (index < scenario.rocks.size()) return scenario.rocks[index].rock;
    const Cluster& cluster = *scenario.cluster;
    if (index + cluster.marked.size() >= count) {
        return cluster.marked[index + cluster.marked.size() - count].rock;
    }
    RockSpec spec = cluster.rock;
    spec.size = size;
    if (cluster.sphericity > 0.0) {
        char name[32];
        std::snprintf(name, sizeof name, "sphericity %.2f", cluster.sphericity);
        spec.kind = shapes::RockKind::custom;
        spec.shape = std::make_shared<const shapes::CustomShape>(
            shapes::CustomShape{name, shapes::make_rock(cluster.rock.kind, 1.0).hull});
    }
    return spec;
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
