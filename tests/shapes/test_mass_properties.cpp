#include "shapes/mass_properties.hpp"
#include "shapes/polyhedron.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <unistd.h>
#include <utility>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using rockfall::shapes::ConvexPolyhedron;
using rockfall::shapes::GeometryError;
using rockfall::shapes::Vec3;

namespace {

std::vector<Vec3> box_corners(const Vec3& lo, const Vec3& hi) {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i) {
        corners.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                             i & 4 ? hi.z() : lo.z());
    }
    return corners;
}

const std::vector<Vec3> kRightTetrahedron = {Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(),
                                             Vec3::UnitZ()};

// Every triangle of a convex hull must face away from the interior and the surface must be a
// closed triangulated sphere: V - E + F = 2 with E = 3F/2.
void check_closed_and_outward(const ConvexPolyhedron& poly) {
    Vec3 inside = Vec3::Zero();
    for (const Vec3& v : poly.vertices) {
        inside += v;
    }
    inside /= static_cast<double>(poly.vertices.size());
    std::set<std::pair<int, int>> directed_edges;
    for (const auto& [a, b, c] : poly.triangles) {
        const Vec3& pa = poly.vertices[static_cast<std::size_t>(a)];
        const Vec3& pb = poly.vertices[static_cast<std::size_t>(b)];
        const Vec3& pc = poly.vertices[static_cast<std::size_t>(c)];
        CHECK((pb - pa).cross(pc - pa).dot(pa - inside) >= 0.0);
        directed_edges.insert({a, b});
        directed_edges.insert({b, c});
        directed_edges.insert({c, a});
    }
    // Each directed edge appears once and its reverse once: consistently oriented and closed.
    CHECK(directed_edges.size() == 3 * poly.triangles.size());
    for (const auto& [a, b] : directed_edges) {
        CHECK(directed_edges.count({b, a}) == 1);
    }
    const auto v = static_cast<long>(poly.vertices.size());
    const auto f = static_cast<long>(poly.triangles.size());
    CHECK(v - 3 * f / 2 + f == 2);
}

}  // namespace

TEST_CASE("unit cube: volume, area, centroid and inertia", "[shapes][verification]") {
    const ConvexPolyhedron cube =
        rockfall::shapes::convex_hull(box_corners(Vec3::Zero(), Vec3::Ones()));
    check_closed_and_outward(cube);
    CHECK(cube.vertices.size() == 8);
    CHECK(cube.triangles.size() == 12);
    const auto props = rockfall::shapes::mass_properties(cube);
    CHECK_THAT(props.volume, WithinRel(1.0, 1e-12));
    CHECK_THAT(props.surface_area, WithinRel(6.0, 1e-12));
    for (int i = 0; i < 3; ++i) {
        CHECK_THAT(props.centroid[i], WithinAbs(0.5, 1e-12));
        for (int j = 0; j < 3; ++j) {
            // I = m (a^2 + b^2) / 12 = 1/6 per unit density for a unit cube.
            CHECK_THAT(props.inertia(i, j), WithinAbs(i == j ? 1.0 / 6.0 : 0.0, 1e-12));
        }
        CHECK_THAT(props.principal_moments[i], WithinRel(1.0 / 6.0, 1e-12));
    }
    CHECK_THAT(props.principal_axes.determinant(), WithinAbs(1.0, 1e-12));
}

TEST_CASE("right tetrahedron against hand-integrated moments", "[shapes][verification]") {
    const auto props =
        rockfall::shapes::mass_properties(rockfall::shapes::convex_hull(kRightTetrahedron));
    CHECK_THAT(props.volume, WithinRel(1.0 / 6.0, 1e-12));
    CHECK_THAT(props.surface_area, WithinRel(1.5 + std::sqrt(3.0) / 2.0, 1e-12));
    for (int i = 0; i < 3; ++i) {
        CHECK_THAT(props.centroid[i], WithinAbs(0.25, 1e-12));
    }
    // Over the unit simplex, int x^2 = 2!/5! = 1/60 and int xy = 1/5! = 1/120; about the
    // centroid, int x'^2 = 1/60 - V/16 = 1/160 and int x'y' = 1/120 - V/16 = -1/480.
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            CHECK_THAT(props.inertia(i, j), WithinAbs(i == j ? 1.0 / 80.0 : 1.0 / 480.0, 1e-14));
        }
    }
    // Eigenvalues of the matrix a I + b (J - I): a - b (twice) and a + 2b (along (1,1,1)).
    CHECK_THAT(props.principal_moments[0], WithinRel(1.0 / 80.0 - 1.0 / 480.0, 1e-12));
    CHECK_THAT(props.principal_moments[1], WithinRel(1.0 / 80.0 - 1.0 / 480.0, 1e-12));
    CHECK_THAT(props.principal_moments[2], WithinRel(1.0 / 80.0 + 2.0 / 480.0, 1e-12));
    CHECK_THAT(std::abs(props.principal_axes.col(2).dot(Vec3::Ones().normalized())),
               WithinAbs(1.0, 1e-12));
}

TEST_CASE("rotated box far from the origin: principal moments and axes", "[shapes]") {
    const Vec3 half(1.5, 0.7, 0.3);
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
    const Vec3 shift(1.0e3, -2.0e3, 5.0e2);
    std::vector<Vec3> corners = box_corners(-half, half);
    for (Vec3& c : corners) {
        c = rotation * c + shift;
    }
    const auto props = rockfall::shapes::mass_properties(rockfall::shapes::convex_hull(corners));
    const double volume = 8.0 * half.prod();
    CHECK_THAT(props.volume, WithinRel(volume, 1e-9));
    CHECK((props.centroid - shift).norm() < 1e-9);
    // Box: I_x = V (b^2 + c^2) / 3 with half-extents a, b, c; ascending: x, y, z here.
    const Vec3 expected(volume * (0.49 + 0.09) / 3.0, volume * (2.25 + 0.09) / 3.0,
                        volume * (2.25 + 0.49) / 3.0);
    for (int i = 0; i < 3; ++i) {
        CHECK_THAT(props.principal_moments[i], WithinRel(expected[i], 1e-9));
        CHECK_THAT(std::abs(props.principal_axes.col(i).dot(rotation.col(i))),
                   WithinAbs(1.0, 1e-9));
    }
    CHECK_THAT(props.principal_axes.determinant(), WithinAbs(1.0, 1e-12));
}

TEST_CASE("hull of a random cloud is closed, outward and contains every point", "[shapes]") {
    std::mt19937 rng(42);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<Vec3> points;
    for (int i = 0; i < 500; ++i) {
        points.emplace_back(normal(rng), normal(rng), 0.5 * normal(rng));
    }
    const ConvexPolyhedron hull = rockfall::shapes::convex_hull(points);
    check_closed_and_outward(hull);
    CHECK(hull.vertices.size() < points.size());
    for (const auto& [a, b, c] : hull.triangles) {
        const Vec3& pa = hull.vertices[static_cast<std::size_t>(a)];
        const Vec3 n = (hull.vertices[static_cast<std::size_t>(b)] - pa)
                           .cross(hull.vertices[static_cast<std::size_t>(c)] - pa);
        for (const Vec3& p : points) {
            REQUIRE(n.dot(p - pa) <= 1e-9 * n.norm());
        }
    }
}

TEST_CASE("nearly coplanar points give no sliver triangles", "[shapes]") {
    // Points on the faces and edges of a 2 m cube, jittered by 1e-11 m: Qhull's triangulation
    // of its merged facets would otherwise contain triangles of round-off height.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Vec3> points = box_corners(-Vec3::Ones(), Vec3::Ones());
    for (int i = 0; i < 300; ++i) {
        Vec3 p(u(rng), u(rng), u(rng));
        p[i % 3] = ((i / 3) % 2 ? 1.0 : -1.0) + 1e-11 * u(rng);
        points.push_back(p);
        points.emplace_back(u(rng), 1.0 + 1e-11 * u(rng), 1.0 + 1e-11 * u(rng));
    }
    const ConvexPolyhedron hull = rockfall::shapes::convex_hull(points);
    check_closed_and_outward(hull);
    for (const auto& [a, b, c] : hull.triangles) {
        const Vec3& pa = hull.vertices[static_cast<std::size_t>(a)];
        const Vec3& pb = hull.vertices[static_cast<std::size_t>(b)];
        const Vec3& pc = hull.vertices[static_cast<std::size_t>(c)];
        const double longest = std::max({(pb - pa).norm(), (pc - pb).norm(), (pa - pc).norm()});
        CHECK((pb - pa).cross(pc - pa).norm() > 1e-9 * longest * longest);
    }
    CHECK_THAT(rockfall::shapes::mass_properties(hull).volume, WithinRel(8.0, 1e-9));
}

TEST_CASE("Wadell sphericity of the Platonic solids", "[shapes][verification]") {
    using rockfall::shapes::wadell_sphericity;
    const auto sphericity_of = [](const std::vector<Vec3>& points) {
        const auto props = rockfall::shapes::mass_properties(rockfall::shapes::convex_hull(points));
        return wadell_sphericity(props.volume, props.surface_area);
    };
    const std::vector<Vec3> tetrahedron = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    const std::vector<Vec3> octahedron = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                          {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    CHECK_THAT(sphericity_of(tetrahedron), WithinAbs(0.671, 0.001));
    CHECK_THAT(sphericity_of(box_corners(Vec3::Zero(), Vec3::Ones())), WithinAbs(0.806, 0.001));
    CHECK_THAT(sphericity_of(octahedron), WithinAbs(0.846, 0.001));
    const double r = 0.3;
    CHECK_THAT(
        wadell_sphericity(4.0 / 3.0 * std::numbers::pi * r * r * r, 4.0 * std::numbers::pi * r * r),
        WithinRel(1.0, 1e-14));
    CHECK_THAT(rockfall::shapes::equivalent_diameter(std::numbers::pi / 6.0 * 0.008),
               WithinRel(0.2, 1e-14));
}

TEST_CASE("transformed translates, then rotates", "[shapes]") {
    const ConvexPolyhedron tet = rockfall::shapes::convex_hull(kRightTetrahedron);
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(0.5 * std::numbers::pi, Vec3::UnitZ()).toRotationMatrix();
    const Vec3 offset(1.0, 2.0, 3.0);
    const ConvexPolyhedron moved = rockfall::shapes::transformed(tet, rotation, offset);
    REQUIRE(moved.vertices.size() == tet.vertices.size());
    CHECK(moved.triangles == tet.triangles);
    for (std::size_t i = 0; i < tet.vertices.size(); ++i) {
        CHECK((moved.vertices[i] - rotation * (tet.vertices[i] + offset)).norm() < 1e-14);
    }
    const auto props = rockfall::shapes::mass_properties(moved);
    CHECK_THAT(props.volume, WithinRel(1.0 / 6.0, 1e-12));
    CHECK((props.centroid - rotation * (Vec3::Constant(0.25) + offset)).norm() < 1e-12);
}

TEST_CASE("degenerate point sets throw GeometryError without printing", "[shapes]") {
    using rockfall::shapes::convex_hull;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<Vec3> coplanar;
    std::vector<Vec3> collinear;
    for (int i = 0; i < 10; ++i) {
        coplanar.emplace_back(std::cos(i), std::sin(3 * i), 2.0);
        collinear.emplace_back(i, 2.0 * i, -i);
    }
    std::vector<Vec3> almost_coplanar = coplanar;
    almost_coplanar[3].z() += 1e-13;

    // Qhull reports through a FILE*; send stderr to a file to prove nothing reaches it.
    std::FILE* capture = std::tmpfile();
    REQUIRE(capture != nullptr);
    std::fflush(stderr);
    const int saved = dup(fileno(stderr));
    dup2(fileno(capture), fileno(stderr));

    CHECK_THROWS_AS(convex_hull({Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()}), GeometryError);
    CHECK_THROWS_AS(convex_hull(coplanar), GeometryError);
    CHECK_THROWS_AS(convex_hull(almost_coplanar), GeometryError);
    CHECK_THROWS_AS(convex_hull(collinear), GeometryError);
    CHECK_THROWS_AS(convex_hull(std::vector<Vec3>(6, Vec3(1.0, 2.0, 3.0))), GeometryError);
    CHECK_THROWS_AS(convex_hull({Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), Vec3(0, 0, nan)}),
                    GeometryError);
    CHECK_THROWS_AS(convex_hull({Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), Vec3(inf, 0, 1)}),
                    GeometryError);
    CHECK_THROWS_WITH(convex_hull(coplanar), Catch::Contains("coplanar"));

    std::fflush(stderr);
    dup2(saved, fileno(stderr));
    close(saved);
    CHECK(std::ftell(capture) == 0);
    std::fclose(capture);
}
