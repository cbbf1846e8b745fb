// The rounded-polyhedron wall law on its own (no Bullet): the hull's features and penetration,
// and a 0.2 m cube driven into the wall along the normal (RK4, translation only: in these
// orientations the force passes through the centroid) face first, edge first and corner first
// against the closed forms of a flat punch, a line contact and Hertz.

#include "wall_fixtures.hpp"

#include "engine/wall_contact.hpp"
#include "shapes/polyhedron.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace rockfall::engine;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using rockfall::shapes::RockGeometry;

namespace {

using std::numbers::pi;
using test::effective_modulus_of;
using test::seed_wall;

constexpr double kHalf = 0.1;  // half the cube's side, m
constexpr double kDensity = 2600.0;
const double kMass = kDensity * 8.0 * kHalf * kHalf * kHalf;
constexpr double kSpeed = 5.0;
constexpr double kWallFace = 9.75;  // x of the wall's front face, which faces -x

// The cube as a hull rock in its body frame (centroid at the origin, faces on the axes).
RockGeometry cube() {
    std::vector<Vec3> corners;
    for (const double x : {-kHalf, kHalf}) {
        for (const double y : {-kHalf, kHalf}) {
            for (const double z : {-kHalf, kHalf}) {
                corners.emplace_back(x, y, z);
            }
        }
    }
    RockGeometry rock;
    rock.kind = rockfall::shapes::RockKind::custom;
    rock.hull = rockfall::shapes::convex_hull(corners);
    rock.nominal_size = std::cbrt(6.0 / pi * 8.0 * kHalf * kHalf * kHalf);
    rock.bounding_radius = std::sqrt(3.0) * kHalf;
    return rock;
}

WallContact rounded_spec() { return WallContact{.hull_model = WallContact::HullModel::rounded}; }

// Wall and rock frictionless with restitution e.
WallContactLaw make_law(const RockGeometry& rock, double restitution) {
    return {rounded_spec(), {0.0, restitution, 0.0}, {0.0, restitution, 0.0}, kMass, rock};
}

// Face first: identity. Edge first: a vertical edge leads (45 degrees about z). Corner first:
// the body diagonal (1, 1, 1) along +x, towards the wall.
Eigen::Quaterniond face_first() { return Eigen::Quaterniond::Identity(); }
Eigen::Quaterniond edge_first() {
    return Eigen::Quaterniond(Eigen::AngleAxisd(pi / 4.0, Vec3::UnitZ()));
}
Eigen::Quaterniond corner_first() {
    return Eigen::Quaterniond::FromTwoVectors(Vec3(1.0, 1.0, 1.0), Vec3::UnitX());
}

struct Impact {
    double peak_force = 0.0;
    HullContactClass peak_class = HullContactClass::corner;
    double restitution = 0.0;
    double largest_jump = 0.0;              // largest change of force between two steps, N
    std::vector<HullContactClass> classes;  // the classes that carried a force, in order
};

// m x'' = -F(x, x') for the centre's x, from first touch at kSpeed until the force vanishes
// while rebounding; `steps` RK4 steps per contact_duration.
Impact drive_into_wall(const WallContactLaw& law, const RockGeometry& rock,
                       const Eigen::Quaterniond& orientation, int steps) {
    const rockfall::shapes::OrientedBox wall = seed_wall();
    const Eigen::Matrix3d r = orientation.toRotationMatrix();
    double reach = 0.0;
    for (const Vec3& v : rock.hull.vertices) {
        reach = std::max(reach, (r * v).x());
    }
    const auto force = [&](double x, double v, HullContactClass* contact_class = nullptr) {
        const std::optional<WallOverlap> overlap =
            wall_overlap(wall, rock, Vec3(x, 0.0, 0.5), orientation, law.hull_features());
        if (!overlap) {
            return 0.0;
        }
        const RoundedForce f = law.rounded_normal_force(*overlap, v);
        if (contact_class != nullptr) {
            *contact_class = f.contact_class;
        }
        return f.normal;
    };
    const auto acceleration = [&](double x, double v) { return -force(x, v) / kMass; };
    const double dt = law.contact_duration(kSpeed) / steps;
    double x = kWallFace - reach;
    double v = kSpeed;
    double previous = 0.0;
    Impact impact;
    for (int step = 0; step < 100 * steps; ++step) {
        const test::Motion next = test::rk4_step(acceleration, {x, v}, dt);
        x = next.x;
        v = next.v;
        HullContactClass contact_class = HullContactClass::corner;
        const double f = force(x, v, &contact_class);
        impact.largest_jump = std::max(impact.largest_jump, std::abs(f - previous));
        previous = f;
        if (f > 0.0 && (impact.classes.empty() || impact.classes.back() != contact_class)) {
            impact.classes.push_back(contact_class);
        }
        if (f > impact.peak_force) {
            impact.peak_force = f;
            impact.peak_class = contact_class;
        }
        if (v < 0.0 && f <= 0.0) {
            impact.restitution = -v / kSpeed;
            return impact;
        }
    }
    FAIL("the impact did not end");
    return impact;
}

}  // namespace

TEST_CASE("a cube's features: edges, inscribed radius, largest face", "[wall_contact][rounded]") {
    const RockGeometry rock = cube();
    const HullFeatures features = hull_features(rock.hull);
    // 12 edges; the face diagonals of the 12 triangles are no edges.
    CHECK(features.edges.size() == 12);
    CHECK_THAT(features.inscribed_radius, WithinRel(kHalf, 1e-12));
    CHECK_THAT(features.largest_face_area, WithinRel(4.0 * kHalf * kHalf, 1e-12));
    CHECK_THAT(features.longest_edge, WithinRel(2.0 * kHalf, 1e-12));
    const WallContactLaw law = make_law(rock, 0.5);
    CHECK_THAT(law.corner_radius(), WithinRel(0.38 * kHalf, 1e-12));
}

TEST_CASE("a cube's penetration face first and corner first", "[wall_contact][rounded]") {
    const RockGeometry rock = cube();
    const HullFeatures features = hull_features(rock.hull);
    const double d = 1e-3;
    // Face x = +h pressed d into the half-space x > h - d (normal -x, out of the wall).
    const HullPenetration face = hull_penetration(rock.hull, features, -Vec3::UnitX(), d - kHalf);
    CHECK_THAT(face.section_area, WithinRel(4.0 * kHalf * kHalf, 1e-9));
    CHECK_THAT(face.volume, WithinRel(4.0 * kHalf * kHalf * d, 1e-9));
    CHECK_THAT(face.edge_length, WithinRel(2.0 * kHalf, 1e-12));
    CHECK_THAT(face.edge_depth, WithinRel(d, 1e-9));
    // Corner (h, h, h) pressed d along the diagonal: a tetrahedron with legs sqrt(3) d.
    const Vec3 n = -Vec3(1.0, 1.0, 1.0).normalized();
    const HullPenetration corner =
        hull_penetration(rock.hull, features, n, n.dot(Vec3(kHalf, kHalf, kHalf)) + d);
    CHECK_THAT(corner.volume, WithinRel(std::sqrt(3.0) / 2.0 * d * d * d, 1e-6));
    CHECK_THAT(corner.section_area, WithinRel(1.5 * std::sqrt(3.0) * d * d, 1e-6));
    CHECK_THAT(corner.edge_length, WithinRel(std::sqrt(3.0) * d, 1e-6));
    CHECK_THAT(corner.edge_depth, WithinRel(0.5 * d, 1e-6));
    // Out of reach: nothing.
    const HullPenetration none = hull_penetration(rock.hull, features, -Vec3::UnitX(), -kHalf);
    CHECK(none.volume == 0.0);
    CHECK(none.section_area == 0.0);
    CHECK(none.edge_length == 0.0);
}

TEST_CASE("rounded law: a cube face first, edge first and corner first against closed forms",
          "[wall_contact][rounded]") {
    const RockGeometry rock = cube();
    const WallContactLaw law = make_law(rock, 1.0);
    const double e_star = effective_modulus_of(rounded_spec());
    // Face: flat punch k = 2 E* a, a = sqrt(A / pi); energy 1/2 m v^2 = 1/2 k d^2 gives
    // F = v sqrt(m k).
    const double k_face = 2.0 * e_star * std::sqrt(4.0 * kHalf * kHalf / pi);
    const Impact face = drive_into_wall(law, rock, face_first(), 2000);
    CHECK(face.peak_class == HullContactClass::face);
    CHECK_THAT(face.peak_force, WithinRel(kSpeed * std::sqrt(kMass * k_face), 0.01));
    // Edge: line contact k = pi/4 E* L.
    const double k_edge = pi / 4.0 * e_star * 2.0 * kHalf;
    const Impact edge = drive_into_wall(law, rock, edge_first(), 2000);
    CHECK(edge.peak_class == HullContactClass::edge);
    CHECK_THAT(edge.peak_force, WithinRel(kSpeed * std::sqrt(kMass * k_edge), 0.01));
    // Corner: Hertz at the corner radius r_c = 0.38 h.
    const HertzImpact hertz = hertz_impact(e_star, law.corner_radius(), kMass, kSpeed);
    const Impact corner = drive_into_wall(law, rock, corner_first(), 2000);
    CHECK(corner.peak_class == HullContactClass::corner);
    CHECK_THAT(corner.peak_force, WithinRel(hertz.peak_force, 0.01));
    // The old law: Hertz at half the nominal size.
    const HertzImpact sphere = hertz_impact(e_star, 0.5 * rock.nominal_size, kMass, kSpeed);
    CAPTURE(face.peak_force, edge.peak_force, corner.peak_force, sphere.peak_force);
    for (const Impact* impact : {&face, &edge, &corner}) {
        CHECK_THAT(impact->restitution, WithinRel(1.0, 1e-3));
    }
}

TEST_CASE("rounded law: restitution is the configured one in every class",
          "[wall_contact][rounded]") {
    const RockGeometry rock = cube();
    for (const double e : {0.3, 0.5, 0.8}) {
        const WallContactLaw law = make_law(rock, e);
        for (const Eigen::Quaterniond& q : {face_first(), edge_first(), corner_first()}) {
            const Impact impact = drive_into_wall(law, rock, q, 2000);
            CAPTURE(e, impact.peak_class, impact.restitution);
            CHECK_THAT(impact.restitution, WithinRel(e, 0.02));
        }
    }
}

TEST_CASE("rounded law: no force jump as a tilted face comes down corner, edge, face",
          "[wall_contact][rounded]") {
    // Tilted about two axes, one corner touches first, then an edge, then the face; elastic,
    // so the force starts from zero. Between classes the force changes no more than within
    // one: at 2000 steps per contact no step changes it by more than 1 % of the peak, and the
    // peak converges when the step is halved.
    const RockGeometry rock = cube();
    const WallContactLaw law = make_law(rock, 1.0);
    const Eigen::Quaterniond tilt = Eigen::Quaterniond(Eigen::AngleAxisd(5e-4, Vec3::UnitY())) *
                                    Eigen::Quaterniond(Eigen::AngleAxisd(2.5e-4, Vec3::UnitZ()));
    const Impact coarse = drive_into_wall(law, rock, tilt, 2000);
    const Impact fine = drive_into_wall(law, rock, tilt, 4000);
    CAPTURE(coarse.peak_force, coarse.largest_jump, fine.peak_force, coarse.peak_class);
    CHECK(coarse.peak_class == HullContactClass::face);
    // The corner carries the force only for the first nanometres: the edge's integral grows as
    // d^2 / (tilt x side), Hertz as d^1.5.
    CHECK(coarse.classes.size() >= 2);
    CHECK(std::find(coarse.classes.begin(), coarse.classes.end(), HullContactClass::edge) !=
          coarse.classes.end());
    CHECK(coarse.largest_jump < 0.01 * coarse.peak_force);
    CHECK_THAT(coarse.peak_force, WithinRel(fine.peak_force, 0.01));
    CHECK_THAT(coarse.restitution, WithinAbs(1.0, 0.01));
}

TEST_CASE("rounded law: spheres keep Hertz, and the hull model needs the Hertz model",
          "[wall_contact][rounded]") {
    RockGeometry sphere;
    sphere.radius = 0.1;
    sphere.nominal_size = 0.2;
    const Material material{0.0, 0.5, 0.0};
    const WallContactLaw rounded(rounded_spec(), material, material, kMass, sphere);
    const WallContactLaw plain(WallContact{}, material, material, kMass, 0.1);
    CHECK(rounded.hull_features() == nullptr);
    CHECK(rounded.corner_radius() == 0.0);
    for (const double d : {1e-5, 1e-3}) {
        CHECK(rounded.normal_force(d, 1.0) == plain.normal_force(d, 1.0));
    }
    CHECK(rounded.contact_duration(kSpeed) == plain.contact_duration(kSpeed));
    WallContact linear = rounded_spec();
    linear.model = WallContact::Model::linear;
    CHECK_THROWS_WITH(WallContactLaw(linear, material, material, kMass, cube()),
                      Catch::Contains("needs model = \"hertz\""));
}
