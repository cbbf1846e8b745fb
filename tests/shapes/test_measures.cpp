#include "shapes/mass_properties.hpp"
#include "shapes/measures.hpp"
#include "shapes/platonic.hpp"
#include "shapes/polyhedron.hpp"
#include "shapes/rocks.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using rockfall::shapes::GeometryError;
using rockfall::shapes::PlatonicKind;
using rockfall::shapes::RockKind;
using rockfall::shapes::shape_measures;
using rockfall::shapes::Vec3;

namespace {

struct PlatonicCase {
    PlatonicKind kind;
    // Volume of the solid with unit edge (closed forms, e.g. Coxeter 1973, table I).
    double unit_volume;
    // Wadell sphericity to three decimals (Wadell 1935; the reference values).
    double sphericity;
    // Extent along the three perpendicular two- or four-fold symmetry axes per unit edge:
    // the edge of the circumscribed cube (Coxeter 1973, table I coordinates).
    double unit_axis;
};

std::vector<PlatonicCase> platonic_cases() {
    const double sqrt5 = std::sqrt(5.0);
    const double phi = std::numbers::phi;
    return {{PlatonicKind::tetrahedron, 1.0 / (6.0 * std::numbers::sqrt2), 0.671,
             1.0 / std::numbers::sqrt2},
            {PlatonicKind::cube, 1.0, 0.806, 1.0},
            {PlatonicKind::octahedron, std::numbers::sqrt2 / 3.0, 0.846, std::numbers::sqrt2},
            {PlatonicKind::dodecahedron, (15.0 + 7.0 * sqrt5) / 4.0, 0.910, phi * phi},
            {PlatonicKind::icosahedron, 5.0 * (3.0 + sqrt5) / 12.0, 0.939, phi}};
}

// Points on the ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 from a Fibonacci lattice on the
// unit sphere, stretched: near-uniform in angle, so the hull is a fine tessellation.
std::vector<Vec3> ellipsoid_points(const Vec3& half_axes, int count) {
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(count));
    const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / count;
        const double r = std::sqrt(1.0 - z * z);
        const double t = golden_angle * i;
        points.emplace_back(Vec3(r * std::cos(t), r * std::sin(t), z).cwiseProduct(half_axes));
    }
    return points;
}

}  // namespace

TEST_CASE("Platonic solids have their closed-form volumes and Wadell sphericities",
          "[shapes][measures]") {
    const double edge = 0.3;
    for (const PlatonicCase& c : platonic_cases()) {
        INFO(rockfall::shapes::to_string(c.kind));
        const auto m = shape_measures(rockfall::shapes::platonic_solid(c.kind, edge));
        CHECK_THAT(m.properties.volume, WithinRel(c.unit_volume * edge * edge * edge, 1e-12));
        CHECK_THAT(m.wadell_sphericity, WithinAbs(c.sphericity, 0.001));
        CHECK(m.properties.centroid.norm() < 1e-12);
        // Every Platonic solid has an isotropic inertia tensor.
        const Vec3 moments = m.properties.principal_moments;
        CHECK_THAT(moments[0], WithinRel(moments[2], 1e-9));
    }
}

TEST_CASE("Platonic solids in any orientation have equal axes and Krumbein sphericity 1",
          "[shapes][measures]") {
    // Their inertia is isotropic, so the axes come from the most equant principal frame.
    const double edge = 0.3;
    const Eigen::Matrix3d tilt =
        Eigen::AngleAxisd(0.4, Vec3(3.0, -1.0, 2.0).normalized()).toRotationMatrix();
    for (const PlatonicCase& c : platonic_cases()) {
        INFO(rockfall::shapes::to_string(c.kind));
        const auto solid = rockfall::shapes::platonic_solid(c.kind, edge);
        const auto m = shape_measures(rockfall::shapes::transformed(solid, tilt, Vec3(1, 2, 3)));
        for (int i = 0; i < 3; ++i) {
            CHECK_THAT(m.axis_lengths[i], WithinRel(c.unit_axis * edge, 1e-9));
        }
        CHECK_THAT(m.krumbein_sphericity, WithinRel(1.0, 1e-9));
    }
}

TEST_CASE("A bad Platonic edge length is a GeometryError", "[shapes][measures]") {
    CHECK_THROWS_AS(rockfall::shapes::platonic_solid(PlatonicKind::cube, 0.0), GeometryError);
    CHECK_THROWS_AS(rockfall::shapes::platonic_solid(PlatonicKind::cube, std::nan("")),
                    GeometryError);
}

TEST_CASE("A cube has equal axes and Krumbein sphericity 1 in any orientation",
          "[shapes][measures]") {
    const auto cube = rockfall::shapes::platonic_solid(PlatonicKind::cube, 0.5);
    const Eigen::Matrix3d tilt =
        Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
    for (const auto& hull : {cube, rockfall::shapes::transformed(cube, tilt, Vec3(1, -2, 3))}) {
        const auto m = shape_measures(hull);
        for (int i = 0; i < 3; ++i) {
            CHECK_THAT(m.axis_lengths[i], WithinRel(0.5, 1e-9));
        }
        CHECK_THAT(m.krumbein_sphericity, WithinRel(1.0, 1e-9));
        CHECK_THAT(m.flatness, WithinRel(1.0, 1e-9));
        CHECK_THAT(m.elongation, WithinRel(1.0, 1e-9));
    }
}

TEST_CASE("A tilted box reports its edge lengths as axes", "[shapes][measures]") {
    std::vector<Vec3> corners;
    for (const double x : {-0.6, 0.6}) {
        for (const double y : {-0.25, 0.25}) {
            for (const double z : {-0.1, 0.1}) {
                corners.emplace_back(x, y, z);
            }
        }
    }
    const Eigen::Matrix3d tilt =
        Eigen::AngleAxisd(1.1, Vec3(-1.0, 0.5, 2.0).normalized()).toRotationMatrix();
    const auto box =
        rockfall::shapes::transformed(rockfall::shapes::convex_hull(corners), tilt, Vec3(4, 5, 6));
    const auto m = shape_measures(box);
    CHECK_THAT(m.axis_lengths[0], WithinRel(1.2, 1e-9));
    CHECK_THAT(m.axis_lengths[1], WithinRel(0.5, 1e-9));
    CHECK_THAT(m.axis_lengths[2], WithinRel(0.2, 1e-9));
    CHECK_THAT(m.krumbein_sphericity, WithinRel(std::cbrt(0.5 * 0.2 / (1.2 * 1.2)), 1e-9));
    CHECK_THAT(m.flatness, WithinRel(0.4, 1e-9));
    CHECK_THAT(m.elongation, WithinRel(0.5 / 1.2, 1e-9));
    CHECK_THAT(m.properties.volume, WithinRel(1.2 * 0.5 * 0.2, 1e-12));
}

TEST_CASE("A finely tessellated 1 : 0.7 : 0.5 ellipsoid has Wadell sphericity 0.940",
          "[shapes][measures]") {
    const Vec3 half_axes(1.0, 0.7, 0.5);
    const auto m =
        shape_measures(rockfall::shapes::convex_hull(ellipsoid_points(half_axes, 20000)));
    CHECK_THAT(m.wadell_sphericity, WithinAbs(0.940, 0.001));
    // The smooth ellipsoid's value by quadrature of its area (6.64138 m2) is 0.93972; the
    // inscribed tessellation loses a little more volume than area.
    CHECK_THAT(m.wadell_sphericity, WithinAbs(0.93972, 1e-4));
    CHECK_THAT(m.properties.volume,
               WithinRel(4.0 / 3.0 * std::numbers::pi * half_axes.prod(), 1e-3));
    CHECK_THAT(m.axis_lengths[0], WithinRel(2.0, 1e-3));
    CHECK_THAT(m.axis_lengths[1], WithinRel(1.4, 1e-3));
    CHECK_THAT(m.axis_lengths[2], WithinRel(1.0, 1e-3));
}

TEST_CASE("The seed rocks have their nominal axis ratios", "[shapes][measures]") {
    const double size = 0.2;
    SECTION("sphere: every axis is the diameter") {
        const auto m = shape_measures(rockfall::shapes::make_rock(RockKind::sphere, size));
        CHECK(m.axis_lengths == Vec3::Constant(size));
        CHECK(m.wadell_sphericity == 1.0);
        CHECK(m.krumbein_sphericity == 1.0);
        CHECK_THAT(m.equivalent_diameter, WithinRel(size, 1e-12));
    }
    SECTION("massive: 1 : 0.9 : 0.8") {
        const auto rock = rockfall::shapes::make_rock(RockKind::massive, size);
        const auto m = shape_measures(rock);
        CHECK_THAT(m.axis_lengths[0], WithinRel(2.0 * rock.half_extents[0], 1e-12));
        CHECK_THAT(m.axis_lengths[1] / m.axis_lengths[0], WithinRel(0.9, 1e-9));
        CHECK_THAT(m.axis_lengths[2] / m.axis_lengths[0], WithinRel(0.8, 1e-9));
        CHECK_THAT(m.krumbein_sphericity, WithinRel(std::cbrt(0.9 * 0.8), 1e-9));
        CHECK_THAT(m.wadell_sphericity, WithinRel(rock.sphericity, 1e-12));
        CHECK_THAT(m.equivalent_diameter, WithinRel(size, 1e-12));
    }
    SECTION("planar: flat (c/b = 0.35/0.8) and mildly elongated (b/a = 0.8)") {
        const auto m = shape_measures(rockfall::shapes::make_rock(RockKind::planar, size));
        CHECK_THAT(m.flatness, WithinRel(0.35 / 0.8, 1e-9));
        CHECK_THAT(m.elongation, WithinRel(0.8, 1e-9));
        CHECK_THAT(m.krumbein_sphericity, WithinRel(std::cbrt(0.8 * 0.35), 1e-9));
    }
}
