#include "shapes/slope.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using rockfall::shapes::OrientedBox;
using rockfall::shapes::signed_distance;
using rockfall::shapes::Slope;
using rockfall::shapes::SlopeSpec;
using rockfall::shapes::SurfaceRole;
using rockfall::shapes::Vec3;

namespace {

double deg(double degrees) { return degrees * std::numbers::pi / 180.0; }

const double kToeX = 5.0 * std::cos(deg(43.0)) + 5.7 * std::cos(deg(29.0));
const double kCrownZ = 5.0 * std::sin(deg(43.0)) + 5.7 * std::sin(deg(29.0));

std::vector<OrientedBox> solids_with(const Slope& slope, SurfaceRole role) {
    std::vector<OrientedBox> out;
    std::copy_if(slope.solids().begin(), slope.solids().end(), std::back_inserter(out),
                 [role](const OrientedBox& b) { return b.role == role; });
    return out;
}

double distance_to_union(const std::vector<OrientedBox>& boxes, const Vec3& p) {
    double d = std::numeric_limits<double>::infinity();
    for (const OrientedBox& box : boxes) {
        d = std::min(d, signed_distance(box, p));
    }
    return d;
}

}  // namespace

TEST_CASE("default slope profile matches the seed's scenario A", "[shapes][verification]") {
    const Slope slope{SlopeSpec{}};
    REQUIRE(slope.profile().size() == 4);
    CHECK_THAT(slope.toe_x(), WithinRel(kToeX, 1e-12));
    CHECK_THAT(slope.end_x(), WithinRel(kToeX + 7.5, 1e-12));
    CHECK_THAT(slope.wall_x(), WithinRel(kToeX + 5.0, 1e-12));
    CHECK_THAT(slope.surface_height(0.0), WithinRel(kCrownZ, 1e-12));
    CHECK_THAT(slope.profile().front().y(), WithinRel(kCrownZ, 1e-12));
    CHECK_THAT(slope.surface_height(kToeX), WithinAbs(0.0, 1e-12));
    CHECK_THAT(slope.profile().back().y(), WithinAbs(0.0, 1e-12));

    const double kink_x = 5.0 * std::cos(deg(43.0));
    const double kink_z = kCrownZ - 5.0 * std::sin(deg(43.0));
    CHECK_THAT(slope.surface_height(1.0), WithinRel(kCrownZ - std::tan(deg(43.0)), 1e-12));
    CHECK_THAT(slope.surface_height(kink_x), WithinRel(kink_z, 1e-12));
    CHECK_THAT(slope.surface_height(kink_x + 2.0),
               WithinRel(kink_z - 2.0 * std::tan(deg(29.0)), 1e-12));
    CHECK_THAT(slope.surface_height(kToeX + 3.0), WithinAbs(0.0, 1e-12));
    // Clamped beyond both ends.
    CHECK(slope.surface_height(-2.0) == slope.surface_height(0.0));
    CHECK(slope.surface_height(100.0) == slope.surface_height(slope.end_x()));

    CHECK(slope.segment_at(-1.0) == 0);
    CHECK(slope.segment_at(1.0) == 0);
    CHECK(slope.segment_at(kink_x + 0.1) == 1);
    CHECK(slope.segment_at(kToeX + 0.1) == 2);
    CHECK(slope.segment_at(100.0) == 2);
}

TEST_CASE("surface normal and tangent are orthonormal and point up and downslope", "[shapes]") {
    const Slope slope{SlopeSpec{}};
    for (const auto& [x, angle] : {std::pair{1.0, 43.0}, {5.0, 29.0}, {12.0, 0.0}}) {
        const Vec3 n = slope.surface_normal(x);
        const Vec3 t = slope.surface_tangent(x);
        CHECK_THAT(n.norm(), WithinRel(1.0, 1e-14));
        CHECK_THAT(t.norm(), WithinRel(1.0, 1e-14));
        CHECK_THAT(n.dot(t), WithinAbs(0.0, 1e-14));
        CHECK(n.y() == 0.0);
        CHECK_THAT(n.z(), WithinRel(std::cos(deg(angle)), 1e-14));
        CHECK_THAT(t.z(), WithinAbs(-std::sin(deg(angle)), 1e-14));
        CHECK(t.x() > 0.0);
        // The tangent follows the profile: a small step along it stays on the surface.
        const double h = 1e-3;
        CHECK_THAT(slope.surface_height(x + h * t.x()),
                   WithinAbs(slope.surface_height(x) + h * t.z(), 1e-12));
    }
}

TEST_CASE("point_at_distance and distance_along_surface are inverse", "[shapes]") {
    const Slope slope{SlopeSpec{}};
    const double total = 5.0 + 5.7 + 7.5;
    for (double s = 0.0; s <= total; s += 0.37) {
        const Vec3 p = slope.point_at_distance(s);
        CHECK(p.y() == 0.0);
        CHECK_THAT(p.z(), WithinAbs(slope.surface_height(p.x()), 1e-12));
        CHECK_THAT(slope.distance_along_surface(p.x()), WithinAbs(s, 1e-12));
    }
    CHECK_THAT(slope.point_at_distance(5.0).x(), WithinRel(5.0 * std::cos(deg(43.0)), 1e-12));
    CHECK_THAT(slope.point_at_distance(10.7).x(), WithinRel(kToeX, 1e-12));
    CHECK_THAT(slope.distance_along_surface(kToeX + 4.0), WithinRel(14.7, 1e-12));
    CHECK(slope.point_at_distance(-1.0) == slope.point_at_distance(0.0));
    CHECK(slope.point_at_distance(total + 1.0) == slope.point_at_distance(total));
}

TEST_CASE("oriented box signed distance and normals", "[shapes]") {
    OrientedBox box;
    box.center = Vec3(1.0, 2.0, 3.0);
    box.rotation = Eigen::AngleAxisd(0.4, Vec3(1.0, 1.0, 0.2).normalized()).toRotationMatrix();
    box.half_extents = Vec3(2.0, 1.0, 0.5);
    const auto world = [&](const Vec3& local) { return box.center + box.rotation * local; };
    Vec3 n;

    // Outside a face, an edge and a corner: distance to the feature, normal along the offset.
    CHECK_THAT(signed_distance(box, world({2.3, 0.2, -0.1}), &n), WithinAbs(0.3, 1e-12));
    CHECK((n - box.rotation.col(0)).norm() < 1e-12);
    CHECK_THAT(signed_distance(box, world({0.0, -1.3, 0.9}), &n), WithinAbs(0.5, 1e-12));
    CHECK((n - box.rotation * Vec3(0.0, -0.6, 0.8)).norm() < 1e-12);
    CHECK_THAT(signed_distance(box, world({-3.0, 2.0, -1.5}), &n),
               WithinAbs(std::sqrt(3.0), 1e-12));
    CHECK((n - box.rotation * Vec3(-1.0, 1.0, -1.0).normalized()).norm() < 1e-12);

    // Inside: minus the distance to the nearest face, whose outward normal is returned.
    CHECK_THAT(signed_distance(box, world({0.5, 0.1, -0.4}), &n), WithinAbs(-0.1, 1e-12));
    CHECK((n + box.rotation.col(2)).norm() < 1e-12);
    CHECK_THAT(signed_distance(box, world({-1.8, 0.5, 0.0}), &n), WithinAbs(-0.2, 1e-12));
    CHECK((n + box.rotation.col(0)).norm() < 1e-12);
    CHECK_THAT(signed_distance(box, box.center), WithinAbs(-0.5, 1e-12));
    // On the surface.
    CHECK_THAT(signed_distance(box, world({0.3, 1.0, 0.1}), &n), WithinAbs(0.0, 1e-12));
    CHECK((n - box.rotation.col(1)).norm() < 1e-12);
}

TEST_CASE("slope slabs: top face is the surface, slab thickness below", "[shapes]") {
    const SlopeSpec spec;
    const Slope slope{spec};
    const auto slabs = solids_with(slope, SurfaceRole::slope);
    REQUIRE(slabs.size() == 3);
    // Both kinks of the seed profile are concave (43 -> 29 -> 0 deg): each slab reaches
    // thickness tan(dtheta / 2) past them, so neighbours meet on the bisecting plane.
    constexpr double pi = std::numbers::pi;
    const double first_kink = spec.thickness * std::tan(0.5 * (43.0 - 29.0) * pi / 180.0);
    const double second_kink = spec.thickness * std::tan(0.5 * 29.0 * pi / 180.0);
    const std::array<double, 3> extra{first_kink, first_kink + second_kink, second_kink};
    double s = 0.0;
    for (int i = 0; i < 3; ++i) {
        CHECK(slabs[i].segment == i);
        const double length = spec.segments[static_cast<std::size_t>(i)].length;
        CHECK_THAT(slabs[i].half_extents.x(),
                   WithinRel(0.5 * (length + extra[static_cast<std::size_t>(i)]), 1e-12));
        const Vec3 middle = slope.point_at_distance(s + 0.5 * length);
        const Vec3 n = slope.surface_normal(middle.x());
        for (const double y : {-2.4, 0.0, 2.4}) {
            Vec3 normal;
            const Vec3 p = middle + Vec3(0.0, y, 0.0);
            CHECK_THAT(signed_distance(slabs[i], p + 0.1 * n, &normal), WithinAbs(0.1, 1e-12));
            CHECK((normal - n).norm() < 1e-12);
            CHECK_THAT(signed_distance(slabs[i], p - 0.1 * n), WithinAbs(-0.1, 1e-12));
            CHECK_THAT(signed_distance(slabs[i], p - (spec.thickness + 0.1) * n),
                       WithinAbs(0.1, 1e-12));
        }
        s += length;
    }
    // The union of slabs has the profile as its top: points just above and below the surface,
    // the kinks included.
    std::vector<double> xs;
    for (double x = 0.05; x < slope.end_x(); x += 0.5) {
        xs.push_back(x);
    }
    for (std::size_t k = 1; k + 1 < slope.profile().size(); ++k) {
        for (const double dx : {-1e-2, 0.0, 1e-2}) {
            xs.push_back(slope.profile()[k].x() + dx);
        }
    }
    for (const double x : xs) {
        const Vec3 on(x, 1.0, slope.surface_height(x));
        CHECK(distance_to_union(slabs, on + Vec3(0, 0, 1e-3)) > 0.0);
        CHECK(distance_to_union(slabs, on - Vec3(0, 0, 1e-3)) < 0.0);
    }
}

TEST_CASE("slope slabs leave no gap below a concave kink", "[shapes]") {
    // Slabs cut square to their surfaces open a wedge below a kink where the slope flattens; a
    // rock corner crossing the kink was then pushed back through the lower slab's end face.
    const SlopeSpec spec;
    const Slope slope{spec};
    const auto slabs = solids_with(slope, SurfaceRole::slope);
    for (std::size_t k = 1; k + 1 < slope.profile().size(); ++k) {
        const Vec3 kink(slope.profile()[k].x(), 0.0, slope.profile()[k].y());
        const Vec3 down = -(slabs[k - 1].rotation.col(2) + slabs[k].rotation.col(2)).normalized();
        // Along the bisector, and a little to either side of it, down to the slabs' depth.
        const Vec3 along = slabs[k].rotation.col(0);
        for (double depth = 0.02; depth < 0.95 * spec.thickness; depth += 0.02) {
            for (const double side : {-0.01, 0.0, 0.01}) {
                INFO("kink " << k << ", depth " << depth << " m, offset " << side << " m");
                CHECK(distance_to_union(slabs, kink + depth * down + side * along) < 0.0);
            }
        }
    }
}

TEST_CASE("angle bars: count, position and shape", "[shapes]") {
    SlopeSpec spec;
    const Slope slope{spec};
    const auto bars = solids_with(slope, SurfaceRole::bar);
    // Two boxes per bar; bars at 1, 2, ... m while k + 0.05 <= length: 4 on 5.0 m, 5 on 5.7 m.
    const auto on_segment = [&](int i) {
        return std::count_if(bars.begin(), bars.end(),
                             [i](const OrientedBox& b) { return b.segment == i; });
    };
    CHECK(on_segment(0) == 2 * 4);
    CHECK(on_segment(1) == 2 * 5);
    CHECK(on_segment(2) == 0);

    // Bar 2 of segment 1: its standing leg faces upslope at 5.0 + 2.0 m along the surface.
    const Vec3 foot = slope.point_at_distance(7.0);
    const Vec3 t = slope.surface_tangent(foot.x());
    const Vec3 n = slope.surface_normal(foot.x());
    const Vec3 in_front = foot - 0.01 * t + 0.03 * n;
    Vec3 normal;
    CHECK_THAT(distance_to_union(bars, in_front), WithinAbs(0.01, 1e-12));
    for (const OrientedBox& bar : bars) {
        if (std::abs(signed_distance(bar, in_front, &normal) - 0.01) < 1e-9) {
            CHECK((normal + t).norm() < 1e-12);
        }
    }
    // Standing leg: 0.05 m high, 0.005 m thick; lying leg: 0.05 m long, 0.005 m thick.
    CHECK(distance_to_union(bars, foot + 0.049 * n + 0.001 * t) < 0.0);
    CHECK(distance_to_union(bars, foot + 0.051 * n + 0.001 * t) > 0.0);
    CHECK(distance_to_union(bars, foot + 0.049 * t + 0.004 * n) < 0.0);
    CHECK(distance_to_union(bars, foot + 0.051 * t + 0.004 * n) > 0.0);
    CHECK(distance_to_union(bars, foot + 0.02 * t + 0.006 * n) > 0.0);
    // Full width.
    CHECK(distance_to_union(bars, foot + 0.02 * n + 0.001 * t + Vec3(0, 2.499, 0)) < 0.0);
    CHECK(distance_to_union(bars, foot + 0.02 * n + 0.001 * t + Vec3(0, 2.501, 0)) > 0.0);

    spec.bars.spacing = 0.5;
    CHECK(solids_with(Slope{spec}, SurfaceRole::bar).size() == 2 * (9 + 11));
    spec.bars.enabled = false;
    CHECK(solids_with(Slope{spec}, SurfaceRole::bar).empty());
}

TEST_CASE("side walls bound the width on every segment", "[shapes]") {
    const SlopeSpec spec;
    const Slope slope{spec};
    const auto walls = solids_with(slope, SurfaceRole::side_wall);
    CHECK(walls.size() == 6);
    for (double x = 0.1; x < slope.end_x(); x += 0.7) {
        const Vec3 n = slope.surface_normal(x);
        const Vec3 p = Vec3(x, 0.0, slope.surface_height(x)) + 0.2 * n;
        for (const double side : {-1.0, 1.0}) {
            const Vec3 near(p.x(), side * (2.5 - 0.1), p.z());
            CHECK_THAT(distance_to_union(walls, near), WithinAbs(0.1, 1e-12));
            CHECK(distance_to_union(walls, Vec3(p.x(), side * 2.55, p.z())) < 0.0);
        }
        CHECK(distance_to_union(walls, p + 0.6 * n + Vec3(0, 2.55, 0)) > 0.0);
    }
}

TEST_CASE("side walls close the gap above a convex kink", "[shapes]") {
    SlopeSpec spec;
    spec.segments = {{4.0, 20.0}, {4.0, 50.0}, {3.0, 0.0}};
    spec.bars.enabled = false;
    spec.wall.distance_from_toe = 2.0;
    const Slope slope{spec};
    const auto walls = solids_with(slope, SurfaceRole::side_wall);
    // Above the kink, on the bisector of the two normals, inside the wall's thickness.
    const Vec3 kink(slope.profile()[1].x(), 2.55, slope.profile()[1].y());
    const Vec3 bisector =
        (slope.surface_normal(kink.x() - 0.1) + slope.surface_normal(kink.x() + 0.1)).normalized();
    for (const double h : {0.1, 0.3, 0.49}) {
        CHECK(distance_to_union(walls, kink + h * bisector) < 0.0);
    }
}

TEST_CASE("reaction wall: vertical front face at wall_x across the full width", "[shapes]") {
    const SlopeSpec spec;
    const Slope slope{spec};
    REQUIRE(slope.wall().has_value());
    const OrientedBox& wall = *slope.wall();
    CHECK(wall.role == SurfaceRole::reaction_wall);
    CHECK(solids_with(slope, SurfaceRole::reaction_wall).size() == 1);
    Vec3 normal;
    for (const double y : {-2.4, 0.0, 2.4}) {
        for (const double z : {0.05, 0.7, 1.45}) {
            CHECK_THAT(signed_distance(wall, Vec3(slope.wall_x() - 0.1, y, z), &normal),
                       WithinAbs(0.1, 1e-12));
            CHECK((normal - Vec3(-1.0, 0.0, 0.0)).norm() < 1e-12);
        }
    }
    CHECK(signed_distance(wall, Vec3(slope.wall_x() + 0.25, 0.0, 1.49)) < 0.0);
    CHECK(signed_distance(wall, Vec3(slope.wall_x() + 0.25, 0.0, 1.51)) > 0.0);
    CHECK(signed_distance(wall, Vec3(slope.wall_x() + 0.25, 0.0, -0.49)) < 0.0);
    CHECK(signed_distance(wall, Vec3(slope.wall_x() + 0.51, 0.0, 0.5)) > 0.0);

    SlopeSpec without = spec;
    without.wall.enabled = false;
    without.side_walls.enabled = false;
    without.bars.enabled = false;
    const Slope bare{without};
    CHECK_FALSE(bare.wall().has_value());
    CHECK(bare.solids().size() == 3);
}
