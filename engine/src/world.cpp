#include "world.hpp"

#include "collision_shapes.hpp"
#include "contact_settings.hpp"
#include "coulomb_solver.hpp"
#include "hull_contacts.hpp"
#include "pair_dispatcher.hpp"
#include "rock_world.hpp"
#include "sheet_contacts.hpp"
#include "terrain_contacts.hpp"
#include "terrain_shape.hpp"

#include "shapes/lining.hpp"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <deque>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rockfall::engine {
namespace {

btVector3 to_bt(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

Vec3 to_eigen(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

btTransform to_bt(const Eigen::Matrix3d& rotation, const Vec3& position) {
    const btMatrix3x3 basis(rotation(0, 0), rotation(0, 1), rotation(0, 2), rotation(1, 0),
                            rotation(1, 1), rotation(1, 2), rotation(2, 0), rotation(2, 1),
                            rotation(2, 2));
    return btTransform(basis, to_bt(position));
}

const Material& material_of(const SurfaceMaterials& materials, shapes::SurfaceRole role) {
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

// userIndex3 tags: the reaction wall, and a rock whose wall contact is rigid. A rock-wall pair
// of any other rock gets no contact points (near_callback).
// Side of the square tiles (in x and y) that a lining's spheres are grouped into, m: a few
// times the largest rock of seed 001's clusters, so that a rock touches at most four tiles.
constexpr double kLiningTile = 0.12;

// Broadphase handles kept for kinematic boxes (a funnel has at most 256 facets).
constexpr std::size_t kKinematicBoxes = 256;

constexpr int kWallTag = 1;
constexpr int kRigidWallTag = 2;

bool is_wall(const btCollisionObject* object) { return object->getUserIndex3() == kWallTag; }

// Bullet's narrowphase for one pair, except that a rock touches the wall box only when its
// wall contact is rigid; otherwise the pair's contact points are dropped, so the compliant
// law alone acts.
void near_callback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher,
                   const btDispatcherInfo& info) {
    const auto* a = static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject);
    const auto* b = static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject);
    if (is_wall(a) || is_wall(b)) {
        const btCollisionObject* rock = is_wall(a) ? b : a;
        if (rock->getUserIndex3() != kRigidWallTag) {
            if (pair.m_algorithm) {
                btManifoldArray manifolds;
                pair.m_algorithm->getAllContactManifolds(manifolds);
                for (int i = 0; i < manifolds.size(); ++i) manifolds[i]->clearManifold();
            }
            return;
        }
    }
    btCollisionDispatcher::defaultNearCallback(pair, dispatcher, info);
}

struct StaticSolid {
    std::unique_ptr<btBoxShape> shape;
    std::unique_ptr<btRigidBody> body;
};

struct RockBody {
    std::unique_ptr<btConvexShape> shape;
    std::unique_ptr<btRigidBody> body;
    double mass = 0.0;
    Vec3 inertia = Vec3::Zero();
    bool in_world = false;
};

// Rocks a run of the scenario will hold, for Bullet's pools: a cluster given by its volume
// counts as a hundred rocks (more spill into the heap).
std::size_t expected_rocks(const Scenario& scenario) {
    std::size_t count = scenario.rocks.size();
    if (scenario.cluster) {
        const int drawn = scenario.cluster->grading.count;
        count += drawn > 0 ? static_cast<std::size_t>(drawn) : 100;
    }
    return count;
}

}  // namespace

// Members are declared in dependency order: Bullet's world is destroyed first, while the
// bodies, shapes, broadphase and dispatcher it refers to still exist.
struct World::Impl {
    btDefaultCollisionConfiguration configuration;
    HullContactCreateFunc hull_contacts;
    SphereBoxCreateFunc sphere_box_contacts;
    SphereBoxCreateFunc swapped_sphere_box_contacts;
    TerrainContactCreateFunc terrain_contacts;
    TerrainContactCreateFunc swapped_terrain_contacts;
    SheetContactCreateFunc sheet_contacts;
    PairDispatcher dispatcher{&configuration};
    // One rock among a few dozen static boxes: the sweep-and-prune broadphase updates one
    // moving AABB per step against sorted static intervals (measured on the seed slope: the
    // dynamic AABB tree costs 6 % more per run, the brute-force broadphase 75 % more).
    btAxisSweep3 broadphase;
    CoulombSolver solver;
    // deque: the material records must keep their addresses (Bullet user pointers).
    std::deque<ContactMaterial> materials;
    std::vector<StaticSolid> statics;
    // Static boxes added and removed during a run (release box walls); a removed one has no body.
    std::vector<StaticSolid> temporary;
    // The reaction wall among the statics, if any.
    const btRigidBody* wall = nullptr;
    // A mesh terrain replaces the slope slabs: its shape is shared with other worlds.
    std::shared_ptr<const TerrainShape> terrain_shape;
    std::unique_ptr<btRigidBody> terrain;
    // A lining: its spheres as compounds of shared sphere shapes (one per radius), one per
    // tile, and its perforated sheet as a triangle mesh; static bodies with the slope's
    // material.
    std::vector<std::unique_ptr<btSphereShape>> lining_spheres;
    std::vector<std::unique_ptr<btCompoundShape>> lining_tiles;
    // The sheet: structured (a SheetShape) or Bullet's triangles (numerics.sheet_contact).
    std::unique_ptr<SheetShape> lining_sheet;
    std::unique_ptr<TerrainShape> lining_sheet_mesh;
    std::vector<std::unique_ptr<btRigidBody>> lining_bodies;
    std::vector<RockBody> rocks;
    // Kinematic groups of boxes (a funnel), one body per box: the broadphase then pairs a rock
    // only with the boxes near it, where one compound of them paired every rock inside the
    // funnel and walked its child tree every step (17 % of a 500-cube heap's lift). A removed
    // group has no bodies.
    struct Kinematic {
        std::vector<Vec3> offsets;  // each box's centre in the group's frame, m
        std::vector<std::unique_ptr<btBoxShape>> shapes;
        std::vector<std::unique_ptr<btRigidBody>> bodies;
    };
    std::vector<Kinematic> kinematics;
    RockDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};

    Impl(const shapes::Slope& slope, std::size_t rock_count)
        : configuration(pool_sizes(rock_count)),
          // No ray casts: no need for the dynamic-tree copy Bullet keeps to accelerate them.
          broadphase(world_min(slope), world_max(slope), handle_count(slope, rock_count), nullptr,
                     true) {
        for (const auto& [a, b] :
             {std::pair{CONVEX_HULL_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE},
              std::pair{BOX_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE},
              std::pair{CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE}}) {
            dispatcher.registerCollisionCreateFunc(a, b, &hull_contacts);
        }
        swapped_sphere_box_contacts.m_swapped = true;
        dispatcher.registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE,
                                               &sphere_box_contacts);
        dispatcher.registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE,
                                               &swapped_sphere_box_contacts);
        swapped_terrain_contacts.m_swapped = true;
        dispatcher.registerCollisionCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE,
                                               TRIANGLE_MESH_SHAPE_PROXYTYPE, &terrain_contacts);
        dispatcher.registerCollisionCreateFunc(
            TRIANGLE_MESH_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE, &swapped_terrain_contacts);
        // A structured sheet (a SheetShape) with rock hulls and spheres, either order.
        for (const int rock : {CONVEX_HULL_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE}) {
            dispatcher.registerCollisionCreateFunc(rock, CUSTOM_CONCAVE_SHAPE_TYPE,
                                                   &sheet_contacts);
            dispatcher.registerCollisionCreateFunc(CUSTOM_CONCAVE_SHAPE_TYPE, rock,
                                                   &sheet_contacts);
        }
        dispatcher.setNearCallback(&near_callback);
    }

    // A static box with `material`, not yet in the world.
    StaticSolid make_solid(const shapes::OrientedBox& box, const Material& material) {
        StaticSolid solid;
        solid.shape = make_box_shape(box);
        const btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, solid.shape.get());
        solid.body = std::make_unique<btRigidBody>(info);
        solid.body->setWorldTransform(to_bt(box.rotation, box.center));
        attach_material(*solid.body, material, materials.emplace_back());
        return solid;
    }

    // Bullet's default pools hold 4096 manifolds and algorithms, cleared at every world's
    // construction; a run needs a few per rock (more spill into the heap).
    static btDefaultCollisionConstructionInfo pool_sizes(std::size_t rock_count) {
        btDefaultCollisionConstructionInfo info;
        const int pool = static_cast<int>(std::min<std::size_t>(4096, 16 + 8 * rock_count));
        info.m_defaultMaxPersistentManifoldPoolSize = pool;
        info.m_defaultMaxCollisionAlgorithmPoolSize = pool;
        info.m_customCollisionAlgorithmMaxElementSize =
            std::max({hull_contact_algorithm_size(), sheet_contact_algorithm_size(),
                      terrain_contact_algorithm_size(), sphere_box_algorithm_size()});
        return info;
    }

    ~Impl() {
        for (RockBody& rock : rocks) {
            if (rock.in_world) {
                world.removeRigidBody(rock.body.get());
            }
        }
        for (StaticSolid& solid : statics) {
            world.removeRigidBody(solid.body.get());
        }
        for (StaticSolid& solid : temporary) {
            if (solid.body) world.removeRigidBody(solid.body.get());
        }
        if (terrain) {
            world.removeRigidBody(terrain.get());
        }
        for (std::unique_ptr<btRigidBody>& body : lining_bodies) {
            world.removeRigidBody(body.get());
        }
        for (Kinematic& kinematic : kinematics) {
            for (std::unique_ptr<btRigidBody>& body : kinematic.bodies) {
                world.removeRigidBody(body.get());
            }
        }
    }

    // Bullet's default of 16384 broadphase handles is cleared at every world's construction;
    // a run needs one per static solid and rock, the terrain, the lining's sheet and sphere
    // tiles, the two walls of a release box and kKinematicBoxes.
    static unsigned short handle_count(const shapes::Slope& slope, std::size_t rock_count) {
        std::size_t tiles = 0;
        if (slope.spec().lining) {
            const auto cells = [](double extent) {
                return static_cast<std::size_t>(std::ceil(extent / kLiningTile)) + 1;
            };
            tiles = cells(slope.end_x()) * cells(slope.spec().width);
        }
        return static_cast<unsigned short>(std::min<std::size_t>(
            16384, slope.solids().size() + rock_count + tiles + 6 + kKinematicBoxes));
    }

    // Broadphase bounds: the slope's extent with room for rocks flying off it; objects beyond
    // them still collide, only less efficiently.
    static btVector3 world_min(const shapes::Slope& slope) {
        const double reach = 0.5 * slope.spec().width + 10.0;
        return {-10.0, -reach, -slope.spec().thickness - 10.0};
    }
    static btVector3 world_max(const shapes::Slope& slope) {
        const double reach = 0.5 * slope.spec().width + 10.0;
        return {slope.end_x() + 10.0, reach, slope.profile().front().y() + 20.0};
    }
};

World::World(const Scenario& scenario, const shapes::Slope& slope)
    : impl_(std::make_unique<Impl>(slope, expected_rocks(scenario))) {
    install_material_combiners();
    impl_->world.setGravity(btVector3(0.0, 0.0, -scenario.gravity));
    configure_solver(impl_->world.getSolverInfo(), scenario.numerics);
    impl_->solver.set_slop_rate(scenario.numerics.contact_slop * scenario.gravity);
    // Static solids never move: their AABBs need no update each step.
    impl_->world.setForceUpdateAllAabbs(false);

    for (const shapes::OrientedBox& box : slope.solids()) {
        const bool replaced_by_terrain =
            box.role == shapes::SurfaceRole::slope && scenario.slope.terrain != nullptr;
        if (replaced_by_terrain) {
            continue;
        }
        StaticSolid solid = impl_->make_solid(box, material_of(scenario.materials, box.role));
        if (box.role == shapes::SurfaceRole::reaction_wall) {
            solid.body->setUserIndex3(kWallTag);
            impl_->wall = solid.body.get();
        }
        impl_->world.addRigidBody(solid.body.get());
        impl_->statics.push_back(std::move(solid));
    }
    if (scenario.slope.terrain) {
        add_terrain(scenario);
    }
    if (scenario.slope.lining) {
        add_lining(scenario, slope);
    }
}

// The lining's static bodies: they take the slope's material, like the terrain.
void World::add_lining(const Scenario& scenario, const shapes::Slope& slope) {
    const shapes::Lining& lining = *scenario.slope.lining;
    const auto add_body = [&](btCollisionShape& shape) {
        const btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, &shape);
        btRigidBody& body = *impl_->lining_bodies.emplace_back(std::make_unique<btRigidBody>(info));
        attach_material(body, scenario.materials.slope, impl_->materials.emplace_back());
        impl_->world.addRigidBody(&body);
        return &body;
    };
    // The spheres go into square tiles of kLiningTile, one static compound each: Bullet's
    // compound algorithm loops over all children of a compound for every rock whose box
    // overlaps it, every step (4782 spheres on the 45 deg flume cost 24 % of a cluster run as
    // one compound), while the broadphase pairs a rock only with the tiles it overlaps.
    std::map<std::pair<long, long>, std::vector<shapes::Sphere>> tiles;
    for (const shapes::Sphere& sphere : shapes::lining_spheres(slope, lining)) {
        const auto cell = [](double v) { return static_cast<long>(std::floor(v / kLiningTile)); };
        tiles[{cell(sphere.center.x()), cell(sphere.center.y())}].push_back(sphere);
    }
    for (const auto& [cell, spheres] : tiles) {
        btCompoundShape& tile = *impl_->lining_tiles.emplace_back(
            std::make_unique<btCompoundShape>(true, static_cast<int>(spheres.size())));
        for (const shapes::Sphere& sphere : spheres) {
            auto same = [&](const std::unique_ptr<btSphereShape>& s) {
                return s->getRadius() == sphere.radius;
            };
            auto found =
                std::find_if(impl_->lining_spheres.begin(), impl_->lining_spheres.end(), same);
            if (found == impl_->lining_spheres.end()) {
                found = impl_->lining_spheres.insert(
                    impl_->lining_spheres.end(), std::make_unique<btSphereShape>(sphere.radius));
            }
            btTransform place;
            place.setIdentity();
            place.setOrigin(to_bt(sphere.center));
            tile.addChildShape(place, found->get());
        }
        add_body(tile);
    }
    if (lining.sheet) {
        // T-junctions between the sheet's cells leave some edges without a neighbour, so the
        // internal-edge correction could not see them all: the sheet is used as triangles.
        const shapes::SheetMesh sheet = shapes::perforated_sheet(slope, *lining.sheet);
        if (scenario.numerics.sheet_contact == SheetContact::structured) {
            impl_->lining_sheet = std::make_unique<SheetShape>(sheet);
            add_body(*impl_->lining_sheet);
        } else {
            impl_->lining_sheet_mesh = std::make_unique<TerrainShape>(sheet.mesh, false);
            add_body(impl_->lining_sheet_mesh->shape());
        }
    }
}

// The terrain takes the slope's material, so its contacts go through the same combination
// rules, contact threshold and solver as the slabs it replaces.
void World::add_terrain(const Scenario& scenario) {
    impl_->terrain_shape = terrain_shape(scenario.slope.terrain);
    const btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr,
                                                        &impl_->terrain_shape->shape());
    impl_->terrain = std::make_unique<btRigidBody>(info);
    attach_material(*impl_->terrain, scenario.materials.slope, impl_->materials.emplace_back());
    if (impl_->terrain_shape->corrected()) {
        enable_internal_edge_correction(*impl_->terrain);
    }
    impl_->world.addRigidBody(impl_->terrain.get());
}

World::~World() = default;

int World::add_rock(const shapes::RockGeometry& geometry, const RockSpec& spec,
                    const BodyState& initial) {
    RockBody rock;
    rock.shape = make_rock_shape(geometry);
    rock.mass = spec.density * geometry.properties.volume;
    // Our exact principal moments: Bullet's calculateLocalInertia is a bounding-box estimate.
    rock.inertia = spec.density * geometry.properties.inertia.diagonal();
    btRigidBody::btRigidBodyConstructionInfo info(rock.mass, nullptr, rock.shape.get(),
                                                  to_bt(rock.inertia));
    rock.body = std::make_unique<btRigidBody>(info);
    rock.body->setWorldTransform(
        to_bt(initial.orientation.normalized().toRotationMatrix(), initial.position));
    rock.body->setLinearVelocity(to_bt(initial.velocity));
    rock.body->setAngularVelocity(to_bt(initial.angular_velocity));
    // Our own stop rule decides when a rock is at rest; Bullet must never freeze it.
    rock.body->setActivationState(DISABLE_DEACTIVATION);

    ContactMaterial& material = impl_->materials.emplace_back();
    attach_material(*rock.body, spec.material, material);
    material.rolling_lever = 0.5 * geometry.nominal_size;

    rock.body->setUserIndex(static_cast<int>(impl_->rocks.size()));
    impl_->world.addRigidBody(rock.body.get());
    rock.in_world = true;
    impl_->rocks.push_back(std::move(rock));
    return static_cast<int>(impl_->rocks.size()) - 1;
}

void World::remove_rock(int rock) {
    RockBody& body = impl_->rocks[static_cast<std::size_t>(rock)];
    assert(body.in_world);
    impl_->world.removeRigidBody(body.body.get());
    body.in_world = false;
}

int World::add_static_box(const shapes::OrientedBox& box, const Material& material) {
    StaticSolid solid = impl_->make_solid(box, material);
    impl_->world.addRigidBody(solid.body.get());
    impl_->temporary.push_back(std::move(solid));
    return static_cast<int>(impl_->temporary.size()) - 1;
}

void World::remove_static_box(int box) {
    StaticSolid& solid = impl_->temporary[static_cast<std::size_t>(box)];
    if (solid.body) {
        impl_->world.removeRigidBody(solid.body.get());
        solid.body.reset();
    }
}

int World::add_kinematic_boxes(const std::vector<shapes::OrientedBox>& boxes,
                               const Material& material, const Vec3& position) {
    std::size_t in_use = 0;
    for (const Impl::Kinematic& kinematic : impl_->kinematics) in_use += kinematic.bodies.size();
    if (in_use + boxes.size() > kKinematicBoxes) {
        throw std::invalid_argument("kinematic boxes: " + std::to_string(in_use + boxes.size()) +
                                    " in one world, at most " + std::to_string(kKinematicBoxes));
    }
    Impl::Kinematic& kinematic = impl_->kinematics.emplace_back();
    for (const shapes::OrientedBox& box : boxes) {
        kinematic.offsets.push_back(box.center);
        kinematic.shapes.push_back(make_box_shape(box));
        const btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr,
                                                            kinematic.shapes.back().get());
        btRigidBody& body = *kinematic.bodies.emplace_back(std::make_unique<btRigidBody>(info));
        body.setCollisionFlags(body.getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
        body.setActivationState(DISABLE_DEACTIVATION);
        const btTransform place = to_bt(box.rotation, position + box.center);
        body.setWorldTransform(place);
        body.setInterpolationWorldTransform(place);
        attach_material(body, material, impl_->materials.emplace_back());
        impl_->world.addRigidBody(&body);
    }
    return static_cast<int>(impl_->kinematics.size()) - 1;
}

void World::move_kinematic(int group, const Vec3& position) {
    Impl::Kinematic& kinematic = impl_->kinematics[static_cast<std::size_t>(group)];
    // Bullet's saveKinematicState takes each body's velocity from the interpolation transform
    // (where it was) to the world transform (where it will be) over the step.
    for (std::size_t k = 0; k < kinematic.bodies.size(); ++k) {
        btTransform place = kinematic.bodies[k]->getWorldTransform();
        place.setOrigin(to_bt(Vec3(position + kinematic.offsets[k])));
        kinematic.bodies[k]->setWorldTransform(place);
    }
}

void World::remove_kinematic(int group) {
    Impl::Kinematic& kinematic = impl_->kinematics[static_cast<std::size_t>(group)];
    for (std::unique_ptr<btRigidBody>& body : kinematic.bodies) {
        impl_->world.removeRigidBody(body.get());
    }
    kinematic.bodies.clear();
}

void World::set_rigid_wall_contact(int rock, bool rigid) {
    impl_->rocks[static_cast<std::size_t>(rock)].body->setUserIndex3(rigid ? kRigidWallTag : -1);
}

std::vector<RigidWallContact> World::rigid_wall_contacts() const {
    std::vector<RigidWallContact> out(impl_->rocks.size());
    if (!impl_->wall) {
        return out;
    }
    // One pass over the manifolds for every rock; a rock body's user index is its rock index.
    btCollisionDispatcher& dispatcher = impl_->dispatcher;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
        const btPersistentManifold* manifold = dispatcher.getInternalManifoldPointer()[m];
        const bool rock_is_a = manifold->getBody1() == impl_->wall;
        if (!rock_is_a && manifold->getBody0() != impl_->wall) {
            continue;
        }
        const btCollisionObject* body = rock_is_a ? manifold->getBody0() : manifold->getBody1();
        if (body->getUserIndex3() != kRigidWallTag) {
            continue;
        }
        RigidWallContact& contact = out[static_cast<std::size_t>(body->getUserIndex())];
        // Bullet's normal points from body B to body A; the impulse acts on A along it.
        const double sign = rock_is_a ? 1.0 : -1.0;
        for (int i = 0; i < manifold->getNumContacts(); ++i) {
            const btManifoldPoint& point = manifold->getContactPoint(i);
            contact.touching = true;
            // A point beyond the processing threshold (a separated one: no speculative
            // contacts) was not solved this step and keeps the impulse of its last solve.
            if (point.getDistance() > manifold->getContactProcessingThreshold()) {
                continue;
            }
            const Vec3 normal = sign * to_eigen(point.m_normalWorldOnB);
            const double normal_impulse = point.m_appliedImpulse;
            contact.impulse +=
                normal_impulse * normal +
                sign * (point.m_appliedImpulseLateral1 * to_eigen(point.m_lateralFrictionDir1) +
                        point.m_appliedImpulseLateral2 * to_eigen(point.m_lateralFrictionDir2));
            contact.normal_impulse += normal_impulse;
            contact.point += normal_impulse * to_eigen(point.getPositionWorldOnB());
            contact.normal = normal;
        }
    }
    for (RigidWallContact& contact : out) {
        if (contact.normal_impulse > 0.0) {
            contact.point /= contact.normal_impulse;
        }
    }
    return out;
}

void World::allow_sleep(int rock, bool allow, double rest_speed, double radius) {
    btRigidBody& body = *impl_->rocks[static_cast<std::size_t>(rock)].body;
    if (!allow) {
        body.forceActivationState(DISABLE_DEACTIVATION);
        return;
    }
    body.forceActivationState(ACTIVE_TAG);
    body.setDeactivationTime(0.0);
    body.setSleepingThresholds(rest_speed, rest_speed / std::max(radius, 1e-6));
}

void World::apply_force(int rock, const Vec3& force, const Vec3& point) {
    btRigidBody& body = *impl_->rocks[static_cast<std::size_t>(rock)].body;
    body.applyForce(to_bt(force), to_bt(point) - body.getCenterOfMassPosition());
}

void World::apply_impulse_over_step(int rock, const Vec3& impulse, const Vec3& angular_impulse,
                                    double dt) {
    btRigidBody& body = *impl_->rocks[static_cast<std::size_t>(rock)].body;
    body.applyCentralForce(to_bt(impulse / dt));
    body.applyTorque(to_bt(angular_impulse / dt));
}

void World::shift_pose(int rock, const Vec3& shift, const Vec3& rotation) {
    btRigidBody& body = *impl_->rocks[static_cast<std::size_t>(rock)].body;
    btTransform transform = body.getWorldTransform();
    transform.setOrigin(transform.getOrigin() + to_bt(shift));
    const double angle = rotation.norm();
    if (angle > 0.0) {
        const btQuaternion turn(to_bt(rotation / angle), angle);
        transform.setRotation((turn * transform.getRotation()).normalized());
    }
    body.setWorldTransform(transform);
    body.setInterpolationWorldTransform(transform);
}

void World::set_collision_threads(int threads) { impl_->dispatcher.set_threads(threads); }

void World::set_solver_iterations(int iterations) {
    impl_->world.getSolverInfo().m_numIterations = iterations;
}

void World::step(double dt) {
    // maxSubSteps = 0: exactly one step of dt, no fixed-step accumulator, no interpolation.
    impl_->world.stepSimulation(dt, 0);
}

BodyState World::state(int rock) const {
    const btRigidBody& body = *impl_->rocks[static_cast<std::size_t>(rock)].body;
    const btTransform& transform = body.getWorldTransform();
    const btQuaternion q = transform.getRotation();
    BodyState state;
    state.position = to_eigen(transform.getOrigin());
    state.orientation = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z());
    state.velocity = to_eigen(body.getLinearVelocity());
    state.angular_velocity = to_eigen(body.getAngularVelocity());
    return state;
}

double World::mass(int rock) const { return impl_->rocks[static_cast<std::size_t>(rock)].mass; }

Vec3 World::inertia(int rock) const { return impl_->rocks[static_cast<std::size_t>(rock)].inertia; }

}  // namespace rockfall::engine
