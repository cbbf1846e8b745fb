#include "flume.hpp"

#include "shapes/lining.hpp"
#include "shapes/slope.hpp"
#include "shapes/terrain.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using rockfall::shapes::Bumps;
using rockfall::shapes::PerforatedSheet;
using rockfall::shapes::SheetMesh;
using rockfall::shapes::Slope;
using rockfall::shapes::Sphere;
using rockfall::shapes::SphereLayer;
using rockfall::shapes::Terrain;
using rockfall::shapes::TriangleMesh;
using rockfall::shapes::Vec3;
using rockfall::shapes::test::deg;
using rockfall::shapes::test::flume;

namespace {

// Distance from p to the slope's reference surface: the profile polyline in the x-z plane,
// extruded along y.
double distance_to_profile(const Slope& slope, const Vec3& p) {
    const Eigen::Vector2d q(p.x(), p.z());
    double best = std::numeric_limits<double>::infinity();
    const auto& profile = slope.profile();
    for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
        const Eigen::Vector2d a = profile[i];
        const Eigen::Vector2d ab = profile[i + 1] - a;
        const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (q - (a + t * ab)).norm());
    }
    return best;
}

// Height along `normal` of the sheet above `origin`: the nearest hit of the line origin +
// w normal (w in [-1, 1] m) with a triangle (Moller and Trumbore 1997), and the hit
// triangle's unit normal.
struct Hit {
    double w;
    Vec3 normal;
};

std::optional<Hit> hit_along(const TriangleMesh& mesh, const Vec3& origin, const Vec3& normal) {
    std::optional<Hit> best;
    for (const auto& t : mesh.triangles) {
        const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
        const Vec3 e1 = mesh.vertices[static_cast<std::size_t>(t[1])] - a;
        const Vec3 e2 = mesh.vertices[static_cast<std::size_t>(t[2])] - a;
        const Vec3 p = normal.cross(e2);
        const double det = e1.dot(p);
        if (std::abs(det) < 1e-14) {
            continue;
        }
        const Vec3 s = origin - a;
        const double u = s.dot(p) / det;
        const Vec3 q = s.cross(e1);
        const double v = normal.dot(q) / det;
        const double w = e2.dot(q) / det;
        if (u < 0.0 || v < 0.0 || u + v > 1.0 || std::abs(w) > 1.0) {
            continue;
        }
        if (!best || std::abs(w) < std::abs(best->w)) {
            best = Hit{w, e1.cross(e2).normalized()};
        }
    }
    return best;
}

Vec3 triangle_normal(const TriangleMesh& mesh, const std::array<int, 3>& t, double* area) {
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Vec3 n = (mesh.vertices[static_cast<std::size_t>(t[1])] - a)
                       .cross(mesh.vertices[static_cast<std::size_t>(t[2])] - a);
    *area = 0.5 * n.norm();
    return n.normalized();
}

}  // namespace

TEST_CASE("the default sphere layer covers the flume like seed 001's grain layer", "[lining]") {
    const Slope slope = flume(45.0);
    const SphereLayer layer;
    const std::vector<Sphere> spheres = sphere_layer(slope, layer);
    // Close-packed 16 mm spheres: rows sqrt(3)/2 * 16 mm apart over 1.82 - 0.016 m, 37 and
    // 36 spheres in alternate rows across 0.60 - 0.016 m.
    const double row = layer.spacing * std::sqrt(3.0) / 2.0;
    const int rows = static_cast<int>(std::floor((1.82 - 2.0 * layer.radius) / row)) + 1;
    const int even = 2 * static_cast<int>(std::floor((0.30 - layer.radius) / layer.spacing)) + 1;
    const int odd =
        2 * static_cast<int>(std::floor((0.30 - layer.radius) / layer.spacing - 0.5)) + 2;
    const int expected = (rows + 1) / 2 * even + rows / 2 * odd;
    CHECK(static_cast<int>(spheres.size()) == expected);
    // Seed 001's DEM had 4880 spheres on the flume: within 5 %.
    CHECK_THAT(static_cast<double>(spheres.size()), WithinRel(4880.0, 0.05));

    const Vec3 normal(std::sin(deg(45.0)), 0.0, std::cos(deg(45.0)));
    const Vec3 tangent(std::cos(deg(45.0)), 0.0, -std::sin(deg(45.0)));
    const Vec3 crown(0.0, 0.0, slope.profile().front().y());
    for (const Sphere& sphere : spheres) {
        REQUIRE(sphere.segment == 0);
        REQUIRE(sphere.radius == layer.radius);
        // Touches the surface: its centre is one radius above the plane.
        REQUIRE_THAT((sphere.center - crown).dot(normal), WithinAbs(layer.radius, 1e-12));
        REQUIRE_THAT(distance_to_profile(slope, sphere.center), WithinAbs(layer.radius, 1e-12));
        // Inside the side walls and on the segment.
        REQUIRE(std::abs(sphere.center.y()) <= 0.30 - layer.radius + 1e-12);
        const double u = (sphere.center - crown).dot(tangent);
        REQUIRE(u >= layer.radius - 1e-12);
        REQUIRE(u <= 1.82 - layer.radius + 1e-12);
    }
}

TEST_CASE("sphere layer neighbours are one spacing apart, six around an inner sphere", "[lining]") {
    const Slope slope = flume(30.0);
    SphereLayer layer;
    layer.radius = 0.01;
    layer.spacing = 0.03;  // not touching
    const std::vector<Sphere> spheres = sphere_layer(slope, layer);
    REQUIRE(spheres.size() > 100);
    double closest = std::numeric_limits<double>::infinity();
    int inner = 0;
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        int neighbours = 0;
        for (std::size_t j = 0; j < spheres.size(); ++j) {
            if (i == j) {
                continue;
            }
            const double d = (spheres[i].center - spheres[j].center).norm();
            closest = std::min(closest, d);
            neighbours += std::abs(d - layer.spacing) < 1e-9 ? 1 : 0;
        }
        // Away from the layer's edges every sphere has six neighbours at the spacing.
        const double y = std::abs(spheres[i].center.y());
        const double x = spheres[i].center.x();
        if (y < 0.2 && x > 0.1 && x < 1.82 * std::cos(deg(30.0)) - 0.1) {
            REQUIRE(neighbours == 6);
            ++inner;
        }
    }
    CHECK_THAT(closest, WithinAbs(layer.spacing, 1e-9));
    CHECK(inner > 50);
}

TEST_CASE("a sphere layer on both flume segments has no overlaps at the kink", "[lining]") {
    for (const double angle : {30.0, 45.0, 60.0}) {
        const Slope slope = flume(angle);
        SphereLayer layer;
        layer.segments = {1, 0};
        const std::vector<Sphere> spheres = sphere_layer(slope, layer);
        int on_lower = 0;
        for (const Sphere& sphere : spheres) {
            on_lower += sphere.segment == 1 ? 1 : 0;
            // None penetrates either segment: the nearest surface point is one radius away.
            REQUIRE_THAT(distance_to_profile(slope, sphere.center), WithinAbs(layer.radius, 1e-12));
        }
        CHECK(on_lower > 4000);
        CHECK(on_lower < static_cast<int>(spheres.size()) - 4000);
        // Near the kink (the line y = anything through the toe) the spheres of the two
        // segments do not overlap.
        const auto near_kink = [&](const Sphere& s) {
            return std::hypot(s.center.x() - slope.toe_x(), s.center.z()) < 0.1;
        };
        int checked = 0;
        for (const Sphere& a : spheres) {
            if (a.segment != 0 || !near_kink(a)) {
                continue;
            }
            for (const Sphere& b : spheres) {
                if (b.segment == 1 && near_kink(b)) {
                    ++checked;
                    REQUIRE((a.center - b.center).norm() >= 2.0 * layer.radius - 1e-12);
                }
            }
        }
        CHECK(checked > 1000);
    }
}

TEST_CASE("bumps are spherical caps of the given height and base", "[lining]") {
    const Slope slope = flume(45.0);
    Bumps bumps;
    bumps.height = 0.006;
    bumps.base_diameter = 0.030;
    bumps.spacing = 0.05;
    const std::vector<Sphere> spheres = bump_spheres(slope, bumps);
    REQUIRE(!spheres.empty());
    const Vec3 normal(std::sin(deg(45.0)), 0.0, std::cos(deg(45.0)));
    const Vec3 crown(0.0, 0.0, slope.profile().front().y());
    for (const Sphere& sphere : spheres) {
        const double lift = (sphere.center - crown).dot(normal);
        // Top of the cap at `height` above the surface, its circle on the surface 30 mm across.
        REQUIRE_THAT(lift + sphere.radius, WithinAbs(bumps.height, 1e-12));
        REQUIRE_THAT(2.0 * std::sqrt(sphere.radius * sphere.radius - lift * lift),
                     WithinAbs(bumps.base_diameter, 1e-12));
        REQUIRE(std::abs(sphere.center.y()) <= 0.30 - 0.5 * bumps.base_diameter + 1e-12);
    }
    // Hemispheres: centre on the surface.
    bumps.height = 0.015;
    for (const Sphere& sphere : bump_spheres(slope, bumps)) {
        REQUIRE_THAT((sphere.center - crown).dot(normal), WithinAbs(0.0, 1e-12));
        REQUIRE_THAT(sphere.radius, WithinAbs(0.015, 1e-15));
    }
}

TEST_CASE("bad lining parameters name the field, value and range", "[lining]") {
    const Slope slope = flume(45.0);
    SphereLayer layer;
    layer.radius = -0.01;
    CHECK_THROWS_WITH(sphere_layer(slope, layer),
                      Contains("sphere_layer.radius = -0.01 m: must be in [0.001, 0.5]"));
    layer = SphereLayer{};
    layer.spacing = 0.01;
    CHECK_THROWS_WITH(sphere_layer(slope, layer),
                      Contains("sphere_layer.spacing = 0.01 m: must be in [0.016, 0.08]"));
    layer = SphereLayer{};
    layer.segments = {0, 2};
    CHECK_THROWS_WITH(sphere_layer(slope, layer),
                      Contains("sphere_layer.segments[1] = 2: must be a segment index in [0, 1]"));
    layer.segments = {1, 1};
    CHECK_THROWS_WITH(sphere_layer(slope, layer), Contains("segment listed twice"));
    Bumps bumps;
    bumps.height = 0.02;
    CHECK_THROWS_WITH(bump_spheres(slope, bumps), Contains("bumps.height = 0.02 m"));
    PerforatedSheet sheet;
    sheet.hole_spacing = 0.06;
    CHECK_THROWS_WITH(perforated_sheet(slope, sheet),
                      Contains("perforated_sheet.hole_spacing = 0.06 m: must be in [0.0635"));
    sheet = PerforatedSheet{};
    sheet.hole_sides = 4;
    CHECK_THROWS_WITH(perforated_sheet(slope, sheet),
                      Contains("perforated_sheet.hole_sides = 4: must be in [8, 64]"));
    sheet = PerforatedSheet{};
    sheet.thickness = std::nan("");
    CHECK_THROWS_AS(perforated_sheet(slope, sheet), std::invalid_argument);
}

TEST_CASE("the perforated sheet has its holes where the pattern puts them", "[lining]") {
    const Slope slope = flume(45.0);
    const PerforatedSheet sheet;
    const SheetMesh out = perforated_sheet(slope, sheet);
    // 26 rows of holes 69.3 mm apart fit in 1.82 m; across 0.60 m, rows on y = 0 hold 7 holes
    // (y = 0, +-0.08, +-0.16, +-0.24 m) and the rows between them 6 (+-0.04, +-0.12,
    // +-0.20 m); +-0.28 m would cut the side walls' rim.
    CHECK(out.holes.size() == 13 * 13);
    CHECK(out.mesh.triangles.size() == out.top_triangles + out.wall_triangles);
    CHECK(out.wall_triangles == 2 * 16 * out.holes.size());
    CHECK(out.mesh.triangles.size() < 15000);

    const Vec3 normal(std::sin(deg(45.0)), 0.0, std::cos(deg(45.0)));
    const Vec3 across = Vec3::UnitY();
    for (const auto& hole : out.holes) {
        REQUIRE_THAT(hole.normal.dot(normal), WithinAbs(1.0, 1e-12));
        // Over a hole's centre nothing of the sheet is above or below the slope surface.
        REQUIRE(!hit_along(out.mesh, hole.center, normal));
        // 24 mm from the centre (inside the 25 mm circle's 16-gon, whose inradius is 24.5 mm)
        // still nothing; 26 mm away the sheet's top, 1.5 mm above the surface.
        REQUIRE(!hit_along(out.mesh, hole.center + 0.024 * across, normal));
        const std::optional<Hit> rim = hit_along(out.mesh, hole.center + 0.026 * across, normal);
        REQUIRE(rim);
        REQUIRE_THAT(rim->w, WithinAbs(sheet.thickness, 1e-12));
        // Between two holes of a row (38 and 42 mm from them) the sheet's top, facing up.
        // (Off the cells' shared edges, which the ray test may miss on both sides.)
        const Vec3 tangent(std::cos(deg(45.0)), 0.0, -std::sin(deg(45.0)));
        const Vec3 between =
            hole.center + (0.5 * sheet.hole_spacing - 0.002) * across + 0.001 * tangent;
        if (std::abs(between.y()) < 0.3) {
            const std::optional<Hit> top = hit_along(out.mesh, between, normal);
            REQUIRE(top);
            REQUIRE_THAT(top->w, WithinAbs(sheet.thickness, 1e-12));
            REQUIRE_THAT(top->normal.dot(normal), WithinAbs(1.0, 1e-12));
        }
    }
}

TEST_CASE("the sheet's top faces up and covers its area less the holes, walls face the holes",
          "[lining]") {
    for (const double angle : {30.0, 60.0}) {
        const Slope slope = flume(angle);
        PerforatedSheet sheet;
        sheet.segments = {0, 1};
        const SheetMesh out = perforated_sheet(slope, sheet);
        double top_area = 0.0;
        std::size_t top = 0;
        std::size_t walls = 0;
        for (const auto& t : out.mesh.triangles) {
            double area = 0.0;
            const Vec3 n = triangle_normal(out.mesh, t, &area);
            REQUIRE(area > 1e-10);
            const Vec3 centroid = (out.mesh.vertices[static_cast<std::size_t>(t[0])] +
                                   out.mesh.vertices[static_cast<std::size_t>(t[1])] +
                                   out.mesh.vertices[static_cast<std::size_t>(t[2])]) /
                                  3.0;
            const int segment = centroid.x() < slope.toe_x() - 1e-9 ? 0 : 1;
            const Vec3 up =
                slope.surface_normal(segment == 0 ? 0.5 * slope.toe_x() : slope.toe_x() + 0.5);
            if (n.dot(up) > 1.0 - 1e-9) {
                top_area += area;
                ++top;
                continue;
            }
            // A wall: perpendicular to the sheet, facing the axis of the nearest hole.
            REQUIRE_THAT(n.dot(up), WithinAbs(0.0, 1e-9));
            const auto nearest = std::min_element(
                out.holes.begin(), out.holes.end(), [&](const auto& a, const auto& b) {
                    return (a.center - centroid).norm() < (b.center - centroid).norm();
                });
            const Vec3 radial = centroid - nearest->center;
            REQUIRE(n.dot(radial - radial.dot(up) * up) < 0.0);
            ++walls;
        }
        CHECK(top == out.top_triangles);
        CHECK(walls == out.wall_triangles);
        // With one winding throughout, overlapping triangles would add area: the top face is
        // the two segments' 1.82 m x 0.60 m less the 16-gons (8 r^2 sin(pi / 8) each).
        const double r = 0.5 * sheet.hole_diameter;
        const double holes =
            static_cast<double>(out.holes.size()) * 8.0 * r * r * std::sin(std::numbers::pi / 8.0);
        CHECK_THAT(top_area, WithinRel(2.0 * 1.82 * 0.60 - holes, 1e-9));
        CHECK(out.holes.size() == 2 * 13 * 13);
    }
}

TEST_CASE("seen from above, a terrain of the sheet has no ground over its holes", "[lining]") {
    const Slope slope = flume(45.0);
    const SheetMesh out = perforated_sheet(slope, PerforatedSheet{});
    const Terrain terrain("sheet", out.mesh, {}, "perforated sheet");
    for (const auto& hole : out.holes) {
        REQUIRE(!terrain.ground(hole.center.x(), hole.center.y()));
        const double y = hole.center.y() + 0.04;
        if (y < 0.3) {
            const auto ground = terrain.ground(hole.center.x(), y);
            REQUIRE(ground);
            // The top face, 1.5 mm above the surface along the normal.
            REQUIRE_THAT(ground->height - slope.surface_height(hole.center.x()),
                         WithinAbs(0.0015 / std::cos(deg(45.0)), 1e-9));
        }
    }
}

TEST_CASE("the sheet's panels and hole polygons describe the same sheet as its mesh", "[lining]") {
    // The engine's structured sheet contact reads the panels and inside_hole, not the mesh:
    // along the surface normal, the mesh has its top face over every point of a panel that no
    // hole's polygon contains, and nothing over a point that one contains.
    const Slope slope = flume(30.0);
    PerforatedSheet sheet;
    sheet.segments = {0, 1};
    const SheetMesh out = perforated_sheet(slope, sheet);
    REQUIRE(out.panels.size() == 2);
    std::size_t holes = 0;
    std::uint64_t state = 12345;
    const auto uniform = [&state] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    int inside = 0;
    for (const auto& panel : out.panels) {
        REQUIRE(panel.thickness == sheet.thickness);
        REQUIRE_THAT(
            panel.plane.normal.dot(slope.surface_normal(panel.plane.index == 0 ? 0.5 : 2.0)),
            WithinAbs(1.0, 1e-12));
        holes += panel.holes.size();
        for (int k = 0; k < 4000; ++k) {
            // Off the cells' shared edges, which the ray test may miss on both sides.
            const double u = 0.002 + uniform() * (panel.plane.length - 0.004);
            const double v = (uniform() - 0.5) * (2.0 * panel.plane.half_width - 0.004);
            const Vec3 p = panel.plane.origin + u * panel.plane.tangent + v * Vec3::UnitY();
            bool in_hole = false;
            for (const std::size_t index : panel.holes) {
                const auto& hole = out.holes[index];
                const Vec3 d = p - hole.center;
                in_hole = in_hole ||
                          rockfall::shapes::inside_hole(hole, d.dot(panel.plane.tangent), d.y());
            }
            inside += in_hole ? 1 : 0;
            const std::optional<Hit> hit = hit_along(out.mesh, p, panel.plane.normal);
            INFO("segment " << panel.plane.index << " u " << u << " v " << v);
            REQUIRE(static_cast<bool>(hit) == !in_hole);
            if (hit) REQUIRE_THAT(hit->w, WithinAbs(sheet.thickness, 1e-12));
        }
    }
    CHECK(holes == out.holes.size());
    // The holes' share of the area: 13 x 13 16-gons (8 r^2 sin(pi / 8)) in 1.82 m x 0.60 m.
    const double r = 0.5 * sheet.hole_diameter;
    const double share = 169.0 * 8.0 * r * r * std::sin(std::numbers::pi / 8.0) / (1.82 * 0.6);
    CHECK_THAT(inside / 8000.0, WithinAbs(share, 0.02));
}
