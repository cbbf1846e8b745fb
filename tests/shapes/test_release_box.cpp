#include "flume.hpp"

#include "shapes/generators.hpp"
#include "shapes/grading.hpp"
#include "shapes/random.hpp"
#include "shapes/release_box.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using rockfall::shapes::make_generator;
using rockfall::shapes::OrientedBox;
using rockfall::shapes::PackingError;
using rockfall::shapes::PackingOrder;
using rockfall::shapes::ReleaseBox;
using rockfall::shapes::RockPose;
using rockfall::shapes::Slope;
using rockfall::shapes::Vec3;
using rockfall::shapes::test::deg;
using rockfall::shapes::test::flume;

namespace {

// Seed 001's least spherical marked rock (sphericity 0.72) at a 1 m nominal size: every C2
// rock is packed with its shape, the hardest case for the packing.
const rockfall::shapes::RockGeometry& elongated_rock() {
    static const rockfall::shapes::RockGeometry rock = [] {
        const auto shape = rockfall::shapes::rock_with_sphericity(0.72, 3);
        return rockfall::shapes::make_rock({"sphericity 0.72", shape.hull}, 1.0);
    }();
    return rock;
}

// The sizes of one C2 cluster drawn with `seed`, m.
std::vector<double> c2_sizes(std::uint64_t seed) {
    auto generator = make_generator(seed);
    return cluster_sizes(rockfall::shapes::seed001_c2(), generator);
}

// Bounding radii of a C2 cluster of cubes (seed 001's cubic clumps): 0.70 of the size.
std::vector<double> c2_radii(std::uint64_t seed) {
    const double ratio =
        rockfall::shapes::clump_rock(rockfall::shapes::ClumpShape::cubic, 1.0).bounding_radius;
    std::vector<double> radii = c2_sizes(seed);
    for (double& r : radii) {
        r *= ratio;
    }
    return radii;
}

// Half extents of a C2 cluster of elongated rocks.
std::vector<Vec3> c2_half_extents(std::uint64_t seed) {
    std::vector<Vec3> out;
    for (const double d : c2_sizes(seed)) {
        out.push_back(d * elongated_rock().half_extents);
    }
    return out;
}

// Every rock's bounding box (axis-aligned in the box's frame) inside the box region, none
// overlapping another; rotations proper, the short axis along the box's normal.
void require_packed_flat(const OrientedBox& region, const std::vector<RockPose>& poses,
                         const std::vector<Vec3>& half_extents) {
    REQUIRE(poses.size() == half_extents.size());
    std::vector<Vec3> lower;
    std::vector<Vec3> upper;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const Eigen::Matrix3d turn = region.rotation.transpose() * poses[i].rotation;
        REQUIRE_THAT((turn.transpose() * turn - Eigen::Matrix3d::Identity()).norm(),
                     WithinAbs(0.0, 1e-12));
        REQUIRE_THAT(turn.determinant(), WithinAbs(1.0, 1e-12));
        REQUIRE_THAT(std::abs(turn(2, 2)), WithinAbs(1.0, 1e-12));
        const Vec3 extent = turn.cwiseAbs() * half_extents[i];
        const Vec3 local = region.rotation.transpose() * (poses[i].center - region.center);
        for (int axis = 0; axis < 3; ++axis) {
            REQUIRE(std::abs(local[axis]) + extent[axis] <= region.half_extents[axis] + 1e-12);
        }
        lower.push_back(local - extent);
        upper.push_back(local + extent);
        for (std::size_t j = 0; j < i; ++j) {
            bool apart = false;
            for (int axis = 0; axis < 3; ++axis) {
                apart = apart || lower[i][axis] >= upper[j][axis] - 1e-12 ||
                        lower[j][axis] >= upper[i][axis] - 1e-12;
            }
            REQUIRE(apart);
        }
    }
}

// Every sphere inside the box region and none overlapping another.
void require_packed(const OrientedBox& region, const std::vector<Vec3>& centers,
                    const std::vector<double>& radii) {
    REQUIRE(centers.size() == radii.size());
    for (std::size_t i = 0; i < centers.size(); ++i) {
        const Vec3 local = region.rotation.transpose() * (centers[i] - region.center);
        for (int axis = 0; axis < 3; ++axis) {
            REQUIRE(std::abs(local[axis]) <= region.half_extents[axis] - radii[i] + 1e-12);
        }
        for (std::size_t j = 0; j < i; ++j) {
            REQUIRE((centers[i] - centers[j]).norm() >= radii[i] + radii[j]);
        }
    }
}

}  // namespace

TEST_CASE("the release box stands on the first segment, aligned with it", "[release_box]") {
    const Slope slope = flume(45.0);
    ReleaseBox box;
    box.start = 0.1;
    box.floor = 0.016;
    const OrientedBox region = release_box_region(slope, box);
    const Vec3 normal(std::sin(deg(45.0)), 0.0, std::cos(deg(45.0)));
    const Vec3 tangent(std::cos(deg(45.0)), 0.0, -std::sin(deg(45.0)));
    CHECK_THAT(region.rotation.col(0).dot(tangent), WithinAbs(1.0, 1e-12));
    CHECK_THAT(region.rotation.col(2).dot(normal), WithinAbs(1.0, 1e-12));
    CHECK_THAT(region.half_extents.x(), WithinAbs(0.20, 1e-15));
    CHECK_THAT(region.half_extents.y(), WithinAbs(0.30, 1e-15));
    CHECK_THAT(region.half_extents.z(), WithinAbs(0.15, 1e-15));
    // Its floor centre lies `floor` above the surface point 0.1 + 0.2 m from the crown.
    const Vec3 floor = region.center - region.half_extents.z() * region.rotation.col(2);
    const Vec3 expected = slope.point_at_distance(0.3) + 0.016 * normal;
    CHECK_THAT((floor - expected).norm(), WithinAbs(0.0, 1e-12));
}

TEST_CASE("a C2 cluster of cubes packs into the default release box", "[release_box]") {
    const Slope slope = flume(45.0);
    for (const PackingOrder order : {PackingOrder::shuffled, PackingOrder::largest_first}) {
        ReleaseBox box;
        box.order = order;
        const OrientedBox region = release_box_region(slope, box);
        for (std::uint64_t seed = 0; seed < 10; ++seed) {
            const std::vector<double> radii = c2_radii(seed);
            REQUIRE(radii.size() == 99);
            auto generator = make_generator(1000 + seed);
            const std::vector<Vec3> centers = pack_release_box(slope, box, radii, generator);
            require_packed(region, centers, radii);
        }
    }
}

TEST_CASE("rocks dropped into the box rest on the floor or on another rock", "[release_box]") {
    const Slope slope = flume(30.0);
    const ReleaseBox box;
    const OrientedBox region = release_box_region(slope, box);
    const std::vector<double> radii = c2_radii(5);
    auto generator = make_generator(5);
    const std::vector<Vec3> centers = pack_release_box(slope, box, radii, generator);
    for (std::size_t i = 0; i < centers.size(); ++i) {
        const Vec3 local = region.rotation.transpose() * (centers[i] - region.center);
        bool supported = std::abs(local.z() + region.half_extents.z() - radii[i]) < 1e-9;
        for (std::size_t j = 0; j < centers.size() && !supported; ++j) {
            const double gap = (centers[i] - centers[j]).norm() - radii[i] - radii[j];
            supported = j != i && gap < 1e-8;
        }
        REQUIRE(supported);
    }
}

TEST_CASE("rocks with a spot are dropped there after the others, on top", "[release_box]") {
    const Slope slope = flume(45.0);
    const ReleaseBox box;
    const OrientedBox region = release_box_region(slope, box);
    std::vector<double> radii = c2_radii(40);
    const std::size_t n = radii.size();
    radii.push_back(0.03);
    radii.push_back(0.04);
    std::vector<std::optional<rockfall::shapes::Vec2>> spots(radii.size());
    spots[n] = rockfall::shapes::Vec2(0.2, 0.0);
    spots[n + 1] = rockfall::shapes::Vec2(0.3, -0.2);
    auto generator = make_generator(11);
    const std::vector<Vec3> centers = pack_release_box(slope, box, radii, generator, spots);
    double top_of_others = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 local = region.rotation.transpose() * (centers[i] - region.center);
        top_of_others = std::max(top_of_others, local.z());
    }
    for (const std::size_t i : {n, n + 1}) {
        const Vec3 local = region.rotation.transpose() * (centers[i] - region.center);
        CHECK_THAT(local.x() + region.half_extents.x(), WithinAbs(spots[i]->x(), 1e-12));
        CHECK_THAT(local.y(), WithinAbs(spots[i]->y(), 1e-12));
        for (std::size_t j = 0; j < centers.size(); ++j) {
            if (j != i) CHECK((centers[i] - centers[j]).norm() >= radii[i] + radii[j]);
        }
    }
    // C2's 99 cubes (as bounding spheres) cover the floor, so the spot rocks lie on them.
    const Vec3 first = region.rotation.transpose() * (centers[n] - region.center);
    CHECK(first.z() + region.half_extents.z() > 0.03 + 0.03);
    CHECK(top_of_others > 0.0);

    // A spot whose rock would cross a wall is refused, naming the rock.
    spots[n + 1] = rockfall::shapes::Vec2(0.3, -0.29);
    auto again = make_generator(11);
    CHECK_THROWS_WITH(pack_release_box(slope, box, radii, again, spots),
                      Contains("rock " + std::to_string(n + 1) +
                               ": spot across the box = -0.29 m: must be in [-0.26, 0.26]"));
}

TEST_CASE("a C2 cluster of elongated rocks packs lying flat into the default box",
          "[release_box]") {
    const Slope slope = flume(45.0);
    for (const PackingOrder order : {PackingOrder::shuffled, PackingOrder::largest_first}) {
        ReleaseBox box;
        box.order = order;
        const OrientedBox region = release_box_region(slope, box);
        for (std::uint64_t seed = 0; seed < 5; ++seed) {
            const std::vector<Vec3> half_extents = c2_half_extents(seed);
            auto generator = make_generator(2000 + seed);
            require_packed_flat(region, pack_release_box_flat(slope, box, half_extents, generator),
                                half_extents);
        }
    }
    // Their bounding spheres do not fit: 2.3 of the size across, 12 times the rock's volume.
    CHECK(elongated_rock().bounding_radius > 1.1);
    std::vector<double> radii;
    for (const double d : c2_sizes(0)) {
        radii.push_back(d * elongated_rock().bounding_radius);
    }
    auto generator = make_generator(1);
    CHECK_THROWS_AS(pack_release_box(slope, ReleaseBox{}, radii, generator), PackingError);
}

TEST_CASE("a rock with a spot lies flat there, on top of the others", "[release_box]") {
    const Slope slope = flume(45.0);
    const ReleaseBox box;
    const OrientedBox region = release_box_region(slope, box);
    std::vector<Vec3> half_extents = c2_half_extents(3);
    const std::size_t n = half_extents.size();
    half_extents.push_back(Vec3(0.05, 0.03, 0.02));
    std::vector<std::optional<rockfall::shapes::Vec2>> spots(half_extents.size());
    spots[n] = rockfall::shapes::Vec2(0.1, 0.2);
    auto generator = make_generator(4);
    const std::vector<RockPose> poses =
        pack_release_box_flat(slope, box, half_extents, generator, spots);
    require_packed_flat(region, poses, half_extents);
    const Vec3 local = region.rotation.transpose() * (poses[n].center - region.center);
    CHECK_THAT(local.x() + region.half_extents.x(), WithinAbs(0.1, 1e-12));
    CHECK_THAT(local.y(), WithinAbs(0.2, 1e-12));
    // Above the floor: on the rocks packed before it.
    CHECK(local.z() + region.half_extents.z() > 0.02 + 1e-3);
    // Long axis along the slope where it fits that way.
    CHECK(std::abs((poses[n].rotation.col(0)).dot(region.rotation.col(0))) > 1.0 - 1e-12);

    spots[n] = rockfall::shapes::Vec2(0.02, 0.0);  // 0.05 m half length does not fit either way
    auto again = make_generator(4);
    CHECK_THROWS_WITH(pack_release_box_flat(slope, box, half_extents, again, spots),
                      Contains("rock " + std::to_string(n) + ": lying flat at its spot"));
}

TEST_CASE("flat packing is reproducible and its errors name the rock", "[release_box]") {
    const Slope slope = flume(30.0);
    const std::vector<Vec3> half_extents = c2_half_extents(4);
    auto a = make_generator(3);
    auto b = make_generator(3);
    const auto first = pack_release_box_flat(slope, ReleaseBox{}, half_extents, a);
    const auto second = pack_release_box_flat(slope, ReleaseBox{}, half_extents, b);
    for (std::size_t i = 0; i < first.size(); ++i) {
        REQUIRE(first[i].center == second[i].center);
        REQUIRE(first[i].rotation == second[i].rotation);
    }
    CHECK_THROWS_WITH(pack_release_box_flat(slope, ReleaseBox{}, {Vec3(0.01, 0.0, 0.01)}, a),
                      Contains("half extents of rock 0 = (0.01, 0, 0.01) m: must be finite"));
    CHECK_THROWS_AS(pack_release_box_flat(slope, ReleaseBox{}, {Vec3(0.05, 0.05, 0.2)}, a),
                    PackingError);
    ReleaseBox small;
    small.length = 0.1;
    small.height = 0.1;
    try {
        pack_release_box_flat(slope, small, half_extents, a);
        FAIL("packed 99 rocks into 0.006 m3");
    } catch (const PackingError& error) {
        CHECK_THAT(error.what(), Contains("of the box filled by their bounding boxes"));
        CHECK(error.needed_volume() > 0.006);
    }
}

TEST_CASE("packing is reproducible from the generator", "[release_box]") {
    const Slope slope = flume(60.0);
    const std::vector<double> radii = c2_radii(1);
    auto a = make_generator(9);
    auto b = make_generator(9);
    auto c = make_generator(10);
    const auto first = pack_release_box(slope, ReleaseBox{}, radii, a);
    CHECK(first == pack_release_box(slope, ReleaseBox{}, radii, b));
    CHECK(first != pack_release_box(slope, ReleaseBox{}, radii, c));
}

TEST_CASE("a cluster that does not fit says the box volume it needs", "[release_box]") {
    const Slope slope = flume(45.0);
    ReleaseBox box;
    box.length = 0.15;
    box.height = 0.15;
    const std::vector<double> radii = c2_radii(2);
    auto generator = make_generator(2);
    try {
        pack_release_box(slope, box, radii, generator);
        FAIL("packed 99 rocks into 0.0135 m3");
    } catch (const PackingError& error) {
        CHECK_THAT(error.what(), Contains("release box 0.15 x 0.6 x 0.15 m (0.0135 m3) holds"));
        CHECK_THAT(error.what(), Contains("of the 99 rocks"));
        CHECK_THAT(error.what(), Contains("they need about"));
        CHECK(error.placed() < 99);
        CHECK(error.needed_volume() > 0.0135);
    }
    // A rock wider than the box.
    generator = make_generator(2);
    CHECK_THROWS_AS(pack_release_box(slope, box, {0.08}, generator), PackingError);
}

TEST_CASE("bad release boxes and radii name the field", "[release_box]") {
    const Slope slope = flume(45.0);
    auto generator = make_generator(1);
    ReleaseBox box;
    box.start = 1.6;
    CHECK_THROWS_WITH(release_box_region(slope, box),
                      Contains("release_box.length = 0.4 m: must be in [0.001, 0.22"));
    box = ReleaseBox{};
    box.width = 0.7;
    CHECK_THROWS_WITH(pack_release_box(slope, box, {0.01}, generator),
                      Contains("release_box.width = 0.7 m: must be in [0.001, 0.6] m"));
    CHECK_THROWS_WITH(pack_release_box(slope, ReleaseBox{}, {0.01, 0.0}, generator),
                      Contains("bounding radius of rock 1 = 0 m: must be finite and > 0"));
}
