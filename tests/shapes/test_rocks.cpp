#include "shapes/mass_properties.hpp"
#include "shapes/polyhedron.hpp"
#include "shapes/rocks.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using rockfall::shapes::GeometryError;
using rockfall::shapes::make_rock;
using rockfall::shapes::RockGeometry;
using rockfall::shapes::RockKind;
using rockfall::shapes::Vec3;

namespace {

double nominal_volume(double diameter) { return std::numbers::pi / 6.0 * std::pow(diameter, 3); }

// The stored properties must be those of the stored hull: recompute them from scratch.
void check_body_frame(const RockGeometry& rock) {
    const auto recomputed = rockfall::shapes::mass_properties(rock.hull);
    const double d = rock.nominal_size;
    const double scale = std::pow(d, 5);
    CHECK_THAT(recomputed.volume, WithinRel(rock.properties.volume, 1e-9));
    CHECK_THAT(recomputed.surface_area, WithinRel(rock.properties.surface_area, 1e-9));
    CHECK(recomputed.centroid.norm() < 1e-12 * d);
    CHECK(rock.properties.centroid.norm() == 0.0);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (i == j) {
                CHECK_THAT(recomputed.inertia(i, i),
                           WithinRel(rock.properties.principal_moments[i], 1e-9));
                CHECK(rock.properties.inertia(i, i) == rock.properties.principal_moments[i]);
            } else {
                CHECK(std::abs(recomputed.inertia(i, j)) < 1e-12 * scale);
                CHECK(rock.properties.inertia(i, j) == 0.0);
            }
        }
    }
    CHECK(rock.properties.principal_moments[0] <= rock.properties.principal_moments[1]);
    CHECK(rock.properties.principal_moments[1] <= rock.properties.principal_moments[2]);
    CHECK(rock.properties.principal_axes == Eigen::Matrix3d::Identity());
    CHECK_THAT(rock.sphericity, WithinRel(rockfall::shapes::wadell_sphericity(
                                              recomputed.volume, recomputed.surface_area),
                                          1e-9));
    double radius = 0.0;
    Vec3 extent = Vec3::Zero();
    for (const Vec3& v : rock.hull.vertices) {
        radius = std::max(radius, v.norm());
        extent = extent.cwiseMax(v.cwiseAbs());
    }
    CHECK_THAT(rock.bounding_radius, WithinRel(radius, 1e-12));
    CHECK((rock.half_extents - extent).norm() < 1e-12 * d);
}

}  // namespace

TEST_CASE("every rock kind has the nominal volume-equivalent diameter", "[shapes]") {
    for (const RockKind kind : {RockKind::sphere, RockKind::massive, RockKind::planar}) {
        for (const double d : {1e-3, 0.2, 0.4, 100.0}) {
            INFO(rockfall::shapes::to_string(kind) << " at " << d << " m");
            const RockGeometry rock = make_rock(kind, d);
            CHECK(rock.kind == kind);
            CHECK(rock.nominal_size == d);
            CHECK_THAT(rock.properties.volume, WithinRel(nominal_volume(d), 1e-9));
            CHECK_THAT(rockfall::shapes::equivalent_diameter(rock.properties.volume),
                       WithinRel(d, 1e-9));
        }
    }
}

TEST_CASE("exact sphere: analytic properties and a display tessellation", "[shapes]") {
    const double d = 0.4;
    const double r = 0.2;
    const RockGeometry rock = make_rock(RockKind::sphere, d);
    CHECK(rock.radius == r);
    CHECK_THAT(rock.properties.volume, WithinRel(4.0 / 3.0 * std::numbers::pi * r * r * r, 1e-14));
    CHECK_THAT(rock.properties.surface_area, WithinRel(4.0 * std::numbers::pi * r * r, 1e-14));
    for (int i = 0; i < 3; ++i) {
        CHECK_THAT(rock.properties.inertia(i, i),
                   WithinRel(0.4 * r * r * rock.properties.volume, 1e-14));
        CHECK(rock.half_extents[i] == r);
    }
    CHECK(rock.properties.inertia.isDiagonal(0.0));
    CHECK(rock.properties.centroid == Vec3::Zero());
    CHECK(rock.sphericity == 1.0);
    CHECK(rock.bounding_radius == r);
    CHECK(rock.hull.vertices.size() == 642);
    CHECK(rock.hull.triangles.size() == 1280);
    for (const Vec3& v : rock.hull.vertices) {
        CHECK_THAT(v.norm(), WithinRel(r, 1e-14));
    }
    // The inscribed tessellation is a little smaller than the sphere; a positive volume also
    // proves its triangles face outward.
    const auto tessellated = rockfall::shapes::mass_properties(rock.hull);
    CHECK(tessellated.volume < rock.properties.volume);
    CHECK(tessellated.volume > 0.99 * rock.properties.volume);
    CHECK(tessellated.centroid.norm() < 1e-14);
}

TEST_CASE("blocky rocks sit in their principal body frame", "[shapes]") {
    for (const RockKind kind : {RockKind::massive, RockKind::planar}) {
        for (const double d : {0.2, 0.4}) {
            INFO(rockfall::shapes::to_string(kind) << " at " << d << " m");
            const RockGeometry rock = make_rock(kind, d);
            CHECK(rock.radius == 0.0);
            check_body_frame(rock);
        }
    }
}

TEST_CASE("blocky rocks have the specified axis ratios, long axis along x", "[shapes]") {
    const Vec3 massive = make_rock(RockKind::massive, 0.2).half_extents;
    CHECK_THAT(massive.y() / massive.x(), WithinRel(0.9, 1e-9));
    CHECK_THAT(massive.z() / massive.x(), WithinRel(0.8, 1e-9));
    const Vec3 planar = make_rock(RockKind::planar, 0.2).half_extents;
    CHECK_THAT(planar.y() / planar.x(), WithinRel(0.8, 1e-9));
    CHECK_THAT(planar.z() / planar.x(), WithinRel(0.35, 1e-9));
    // Each of the 8 corners loses a tetrahedron with legs t = 0.2 c (c the shortest half-axis):
    // V = 8 a b c - 8 t^3 / 6.
    for (const RockKind kind : {RockKind::massive, RockKind::planar}) {
        const RockGeometry rock = make_rock(kind, 0.2);
        const Vec3 h = rock.half_extents;
        const double t = 0.2 * h.z();
        CHECK(rock.hull.vertices.size() == 24);
        CHECK_THAT(rock.properties.volume, WithinRel(8.0 * h.prod() - 8.0 * t * t * t / 6.0, 1e-9));
    }
}

TEST_CASE("sphericity orders sphere > massive > planar", "[shapes]") {
    const double sphere = make_rock(RockKind::sphere, 0.2).sphericity;
    const double massive = make_rock(RockKind::massive, 0.2).sphericity;
    const double planar = make_rock(RockKind::planar, 0.2).sphericity;
    CHECK(sphere > massive);
    CHECK(massive > planar);
    // Shape, not size: the same kind at another size has the same sphericity.
    CHECK_THAT(make_rock(RockKind::planar, 0.4).sphericity, WithinRel(planar, 1e-12));
    CHECK_THAT(massive, WithinAbs(0.808, 0.001));
    CHECK_THAT(planar, WithinAbs(0.725, 0.001));
}

TEST_CASE("make_rock is deterministic", "[shapes]") {
    for (const RockKind kind : {RockKind::sphere, RockKind::massive, RockKind::planar}) {
        const RockGeometry a = make_rock(kind, 0.4);
        const RockGeometry b = make_rock(kind, 0.4);
        CHECK(a.hull.vertices == b.hull.vertices);
        CHECK(a.hull.triangles == b.hull.triangles);
        CHECK(a.properties.principal_moments == b.properties.principal_moments);
    }
}

TEST_CASE("nominal size outside [1e-3, 100] m is rejected", "[shapes]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const double d : {0.0, -0.2, 9e-4, 100.5, nan}) {
        for (const RockKind kind : {RockKind::sphere, RockKind::massive, RockKind::planar}) {
            CHECK_THROWS_AS(make_rock(kind, d), GeometryError);
        }
    }
    CHECK_THROWS_WITH(make_rock(RockKind::massive, 200.0), Catch::Contains("nominal_size"));
}

TEST_CASE("rock_from_hull normalises any hull", "[shapes]") {
    // A rotated, shifted box 2 x 1 x 0.5 m: long axis must come out along x, short along z.
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(1.1, Vec3(0.3, -1.0, 0.4).normalized()).toRotationMatrix();
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i) {
        const Vec3 c(i & 1 ? 1.0 : -1.0, i & 2 ? 0.5 : -0.5, i & 4 ? 0.25 : -0.25);
        corners.push_back(rotation * c + Vec3(5.0, -3.0, 2.0));
    }
    const auto hull = rockfall::shapes::convex_hull(corners);

    const RockGeometry unchanged = rockfall::shapes::rock_from_hull(hull, RockKind::massive, 0.0);
    CHECK_THAT(unchanged.properties.volume, WithinRel(1.0, 1e-12));
    CHECK_THAT(unchanged.nominal_size, WithinRel(std::cbrt(6.0 / std::numbers::pi), 1e-12));
    CHECK((unchanged.half_extents - Vec3(1.0, 0.5, 0.25)).norm() < 1e-12);
    check_body_frame(unchanged);

    const RockGeometry scaled = rockfall::shapes::rock_from_hull(hull, RockKind::planar, 0.3);
    CHECK(scaled.kind == RockKind::planar);
    CHECK_THAT(scaled.properties.volume, WithinRel(nominal_volume(0.3), 1e-12));
    CHECK_THAT(scaled.half_extents.x() / scaled.half_extents.z(), WithinRel(4.0, 1e-12));
    check_body_frame(scaled);

    CHECK_THROWS_AS(rockfall::shapes::rock_from_hull(hull, RockKind::sphere, 0.3), GeometryError);
    CHECK_THROWS_AS(rockfall::shapes::rock_from_hull(hull, RockKind::massive, 500.0),
                    GeometryError);
}

TEST_CASE("rock kinds have lower-case names", "[shapes]") {
    CHECK(rockfall::shapes::to_string(RockKind::sphere) == "sphere");
    CHECK(rockfall::shapes::to_string(RockKind::massive) == "massive");
    CHECK(rockfall::shapes::to_string(RockKind::planar) == "planar");
}
