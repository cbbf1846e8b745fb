#include "bare_bullet.hpp"

#include "engine/wall_contact.hpp"

#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::bench {
namespace {

btVector3 to_bt(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

Vec3 to_eigen(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

btTransform to_bt(const Eigen::Quaterniond& q, const Vec3& position) {
    return btTransform(btQuaternion(q.x(), q.y(), q.z(), q.w()), to_bt(position));
}

// Margin of the rock hull, m. Bullet's default (0.04 m) grows every hull by 4 cm, which would
// make a 0.2 m rock 40 % larger; 1 mm keeps the rock the same within 1 %.
constexpr double kHullMargin = 0.001;

// Contact coefficients that make Bullet's DEFAULT combination rules give the project's rule
// (the mean of the two materials, scenario.hpp) for one rock against static solids: the rock
// carries the neutral values (friction 1, restitution 1, no rolling friction), the solid the
// combined ones. Bullet multiplies friction and restitution and combines rolling friction as
// rolling_a * friction_b + rolling_b * friction_a (btManifoldResult).
struct Coefficients {
    double friction = 1.0;
    double restitution = 1.0;
    double rolling = 0.0;  // a length, m: resisting torque = rolling * normal force
};

Coefficients combined(const engine::Material& rock, const engine::Material& surface,
                      double rolling_lever) {
    return {0.5 * (rock.friction + surface.friction),
            0.5 * (rock.restitution + surface.restitution),
            0.5 * (rock.rolling_resistance + surface.rolling_resistance) * rolling_lever};
}

void apply(btCollisionObject& body, const Coefficients& c) {
    body.setFriction(c.friction);
    body.setRestitution(c.restitution);
    body.setRollingFriction(c.rolling);
    body.setSpinningFriction(c.rolling);
}

const engine::Material& material_of(const engine::SurfaceMaterials& materials,
                                    shapes::SurfaceRole role) {
    switch (role) {
        case shapes::SurfaceRole::bar:
            return materials.bars;
        case shapes::SurfaceRole::side_wall:
            return materials.side_walls;
        case shapes::SurfaceRole::reaction_wall:
            return materials.wall;
        case shapes::SurfaceRole::slope:
            break;
    }
    return materials.slope;
}

std::unique_ptr<btConvexShape> make_rock_shape(const shapes::RockGeometry& rock) {
    if (rock.radius > 0.0) {
        return std::make_unique<btSphereShape>(rock.radius);
    }
    auto shape = std::make_unique<btConvexHullShape>();
    for (const Vec3& v : rock.hull.vertices) {
        shape->addPoint(to_bt(v), false);
    }
    shape->setMargin(kHullMargin);
    shape->recalcLocalAabb();
    return shape;
}

// The engine's stop rule as engine/outcome.hpp and stop_rule.hpp document it: a rock is at
// rest when its centre and its fastest point (|w| times the bounding radius) both stay below
// rest_speed for rest_duration; it has left the domain past the end of the slope, beyond the
// side walls or below the lowest slab; it failed when non-finite or under the slab below it.
class StopRule {
  public:
    StopRule(const engine::Numerics& numerics, const shapes::Slope& slope, double bounding_radius)
        : slope_(slope), numerics_(numerics), bounding_radius_(bounding_radius) {
        const shapes::SlopeSpec& spec = slope.spec();
        half_width_ = 0.5 * spec.width;
        domain_half_width_ =
            half_width_ + (spec.side_walls.enabled ? spec.side_walls.thickness : 0.0);
        double lowest = slope.profile().front().y();
        for (const Eigen::Vector2d& vertex : slope.profile()) {
            lowest = std::min(lowest, vertex.y());
        }
        bottom_z_ = lowest - spec.thickness;
    }

    std::optional<engine::StopReason> check(double time, const Vec3& p, const Vec3& v,
                                            const Vec3& w, double dt) {
        if (!p.allFinite() || !v.allFinite() || !w.allFinite()) {
            return engine::StopReason::numerical_failure;
        }
        if (p.x() >= 0.0 && p.x() <= slope_.end_x() && std::abs(p.y()) <= half_width_) {
            const double slab_bottom = slope_.surface_height(p.x()) -
                                       slope_.spec().thickness / slope_.surface_normal(p.x()).z();
            if (p.z() < slab_bottom) {
                return engine::StopReason::numerical_failure;
            }
        }
        if (p.x() > slope_.end_x() || std::abs(p.y()) > domain_half_width_ || p.z() < bottom_z_) {
            return engine::StopReason::left_domain;
        }
        if (v.norm() < numerics_.rest_speed && w.norm() * bounding_radius_ < numerics_.rest_speed) {
            rest_time_ += dt;
            if (rest_time_ >= numerics_.rest_duration) {
                return engine::StopReason::at_rest;
            }
        } else {
            rest_time_ = 0.0;
        }
        if (time >= numerics_.max_time) {
            return engine::StopReason::time_limit;
        }
        return std::nullopt;
    }

  private:
    const shapes::Slope& slope_;
    engine::Numerics numerics_;
    double bounding_radius_;
    double half_width_ = 0.0;
    double domain_half_width_ = 0.0;
    double bottom_z_ = 0.0;
    double rest_time_ = 0.0;
};

struct StaticSolid {
    std::unique_ptr<btBoxShape> shape;
    std::unique_ptr<btRigidBody> body;
};

// Bullet's default world, as in its HelloWorld example. Members in dependency order: the
// world is destroyed first, while everything it refers to still exists.
struct DefaultWorld {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    std::vector<StaticSolid> statics;
    std::unique_ptr<btConvexShape> rock_shape;
    std::unique_ptr<btRigidBody> rock;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
};

void add_static_solids(DefaultWorld& w, const engine::Scenario& scenario,
                       const shapes::Slope& slope, double rolling_lever) {
    const engine::Material& rock = scenario.rocks.front().rock.material;
    for (const shapes::OrientedBox& box : slope.solids()) {
        StaticSolid solid;
        // btBoxShape's own margin (at most 0.04 m, kept inside the box's outer faces).
        solid.shape = std::make_unique<btBoxShape>(to_bt(box.half_extents));
        solid.body = std::make_unique<btRigidBody>(
            btRigidBody::btRigidBodyConstructionInfo(0.0, nullptr, solid.shape.get()));
        solid.body->setWorldTransform(
            to_bt(Eigen::Quaterniond(box.rotation).normalized(), box.center));
        apply(*solid.body,
              combined(rock, material_of(scenario.materials, box.role), rolling_lever));
        w.world.addRigidBody(solid.body.get());
        w.statics.push_back(std::move(solid));
    }
}

// Checks that Bullet's default rules combine the coefficients as intended.
[[maybe_unused]] bool combines_to_mean(const btCollisionObject& rock,
                                       const btCollisionObject& solid) {
    const auto close = [](double a, double b) { return std::abs(a - b) <= 1e-12; };
    return close(btManifoldResult::calculateCombinedFriction(&rock, &solid), solid.getFriction()) &&
           close(btManifoldResult::calculateCombinedRestitution(&rock, &solid),
                 solid.getRestitution()) &&
           close(btManifoldResult::calculateCombinedRollingFriction(&rock, &solid),
                 solid.getRollingFriction());
}

}  // namespace

ReleasePose release_pose(const shapes::Slope& slope, const shapes::RockGeometry& rock,
                         const engine::Release& release, std::uint64_t seed, double skin) {
    const Vec3 surface_point = slope.point_at_distance(release.distance);
    Eigen::Matrix3d frame;
    frame.col(0) = slope.surface_tangent(surface_point.x());
    frame.col(1) = Vec3::UnitY();
    frame.col(2) = slope.surface_normal(surface_point.x());

    ReleasePose pose;
    if (release.random_orientation) {
        // A normalised 4-D Gaussian is uniform on the unit quaternions, hence on rotations.
        std::mt19937_64 generator(seed);
        std::normal_distribution<double> normal;
        Eigen::Quaterniond q(normal(generator), normal(generator), normal(generator),
                             normal(generator));
        pose.orientation = q.normalized();
    } else {
        const Vec3 a = release.orientation_deg * (std::numbers::pi / 180.0);
        const Eigen::Matrix3d local =
            (Eigen::AngleAxisd(a.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(a.y(), Vec3::UnitY()) *
             Eigen::AngleAxisd(a.x(), Vec3::UnitX()))
                .toRotationMatrix();
        pose.orientation = Eigen::Quaterniond(frame * local);
    }
    const Vec3 down = -frame.col(2);
    double depth = rock.radius;
    if (rock.radius <= 0.0) {
        const Vec3 local_down = pose.orientation.conjugate() * down;
        depth = 0.0;
        for (const Vec3& v : rock.hull.vertices) {
            depth = std::max(depth, v.dot(local_down));
        }
    }
    pose.position = surface_point + release.lateral * Vec3::UnitY() +
                    (release.height + depth + skin) * frame.col(2);
    return pose;
}

double fine_time_step(const engine::Scenario& scenario, double impact_speed) {
    const engine::RockSpec& spec = scenario.rocks.front().rock;
    const shapes::RockGeometry rock = shapes::make_rock(spec.kind, spec.size);
    const double mass = spec.density * rock.properties.volume;
    // wall_contact.hpp: the sphere radius, or half the nominal size for hulls.
    const double radius = rock.radius > 0.0 ? rock.radius : 0.5 * rock.nominal_size;
    const engine::WallContactLaw law(scenario.wall_contact, scenario.materials.wall, spec.material,
                                     mass, radius);
    return law.contact_duration(impact_speed) / scenario.wall_contact.steps_per_contact;
}

BareRun run_bare_bullet(const engine::Scenario& scenario, std::uint64_t seed, double time_step) {
    if (scenario.rocks.size() != 1) {
        throw std::invalid_argument("bare Bullet loop: scenario must have exactly one rock, has " +
                                    std::to_string(scenario.rocks.size()));
    }
    assert(time_step > 0.0);
    const engine::RockRelease& rock_release = scenario.rocks.front();
    const shapes::Slope slope(scenario.slope);
    const shapes::RockGeometry geometry =
        shapes::make_rock(rock_release.rock.kind, rock_release.rock.size);
    // A sphere's margin is its radius, already in `geometry.radius`.
    const double skin = geometry.radius > 0.0 ? 0.0 : kHullMargin;
    const ReleasePose pose = release_pose(slope, geometry, rock_release.release, seed, skin);

    DefaultWorld w;
    w.world.setGravity(btVector3(0.0, 0.0, -scenario.gravity));
    // engine/scenario.hpp: rolling resistance torque = coefficient * r * N with r the rock's
    // radius, half its nominal size.
    add_static_solids(w, scenario, slope, 0.5 * geometry.nominal_size);

    const double mass = rock_release.rock.density * geometry.properties.volume;
    // Our exact principal moments: Bullet's calculateLocalInertia is a bounding-box estimate.
    const Vec3 inertia = rock_release.rock.density * geometry.properties.inertia.diagonal();
    w.rock_shape = make_rock_shape(geometry);
    w.rock = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(
        mass, nullptr, w.rock_shape.get(), to_bt(inertia)));
    w.rock->setWorldTransform(to_bt(pose.orientation, pose.position));
    w.rock->setLinearVelocity(to_bt(rock_release.release.velocity));
    w.rock->setAngularVelocity(to_bt(rock_release.release.spin));
    // The stop rule, not Bullet's sleeping (which freezes a rock rolling below 0.8 m/s for
    // 2 s), decides when the rock is at rest.
    w.rock->setActivationState(DISABLE_DEACTIVATION);
    apply(*w.rock, Coefficients{});
    assert(std::all_of(w.statics.begin(), w.statics.end(),
                       [&](const StaticSolid& s) { return combines_to_mean(*w.rock, *s.body); }));
    w.world.addRigidBody(w.rock.get());

    StopRule stop_rule(scenario.numerics, slope, geometry.bounding_radius);
    BareRun run;
    run.reach = pose.position.x() - slope.toe_x();
    for (;;) {
        // maxSubSteps = 0: exactly one step of time_step, no interpolation.
        w.world.stepSimulation(time_step, 0);
        ++run.steps;
        const double time = static_cast<double>(run.steps) * time_step;
        const Vec3 p = to_eigen(w.rock->getCenterOfMassPosition());
        run.reach = std::max(run.reach, p.x() - slope.toe_x());
        const std::optional<engine::StopReason> stop =
            stop_rule.check(time, p, to_eigen(w.rock->getLinearVelocity()),
                            to_eigen(w.rock->getAngularVelocity()), time_step);
        if (stop) {
            run.stop = *stop;
            run.stop_time = time;
            return run;
        }
    }
}

}  // namespace rockfall::bench
