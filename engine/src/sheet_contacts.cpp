#include "sheet_contacts.hpp"

#include "collision_shapes.hpp"

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rockfall::engine {
namespace {

btVector3 to_bt(const shapes::Vec3& v) { return {v.x(), v.y(), v.z()}; }

// Depth of the material behind a hole's wall that an edge box stands for, as a fraction of the
// hole's radius: the sheet keeps a rim of a tenth of the radius around every hole.
constexpr double kEdgeDepthFraction = 0.1;

// The rock's points in the sheet's frame: a hull's (shrunk) vertices or a sphere's centre, each
// grown by the shape's margin.
struct RockPoints {
    const btVector3* points = nullptr;
    int count = 0;
    btScalar margin = 0.0;
};

RockPoints rock_points(const btConvexShape& shape) {
    static const btVector3 origin(0.0, 0.0, 0.0);
    if (shape.getShapeType() == CONVEX_HULL_SHAPE_PROXYTYPE) {
        const auto& hull = static_cast<const btConvexHullShape&>(shape);
        return {hull.getUnscaledPoints(), hull.getNumPoints(), hull.getMargin()};
    }
    // A sphere: its centre with the radius as margin (Bullet's own view of a sphere).
    return {&origin, 1, shape.getMargin()};
}

bool overlap(const btVector3& a_min, const btVector3& a_max, const btVector3& b_min,
             const btVector3& b_max) {
    return a_min.x() <= b_max.x() && b_min.x() <= a_max.x() && a_min.y() <= b_max.y() &&
           b_min.y() <= a_max.y() && a_min.z() <= b_max.z() && b_min.z() <= a_max.z();
}

}  // namespace

SheetShape::SheetShape(const shapes::SheetMesh& sheet)
    : holes_(sheet.holes), triangles_(std::make_unique<TerrainShape>(sheet.mesh, false)) {
    m_shapeType = CUSTOM_CONCAVE_SHAPE_TYPE;
    for (const shapes::SheetPanel& source : sheet.panels) {
        Panel& panel = panels_.emplace_back();
        panel.panel = source;
        double radius = 0.0;
        for (const std::size_t index : source.holes) {
            const shapes::SheetHole& hole = holes_[index];
            const shapes::Vec3 d = hole.center - source.plane.origin;
            panel.centers_uv.emplace_back(d.dot(source.plane.tangent), d.y(), 0.0);
            radius = std::max(radius, hole.radius);
        }
        panel.cell = radius > 0.0 ? 2.0 * radius : source.plane.length;
        panel.columns = std::max(1, static_cast<int>(std::ceil(source.plane.length / panel.cell)));
        panel.rows =
            std::max(1, static_cast<int>(std::ceil(2.0 * source.plane.half_width / panel.cell)));
        panel.grid.resize(static_cast<std::size_t>(panel.columns * panel.rows));
        const auto clamp_column = [&](double u) {
            return std::clamp(static_cast<int>(std::floor(u / panel.cell)), 0, panel.columns - 1);
        };
        const auto clamp_row = [&](double v) {
            return std::clamp(
                static_cast<int>(std::floor((v + source.plane.half_width) / panel.cell)), 0,
                panel.rows - 1);
        };
        for (std::size_t k = 0; k < source.holes.size(); ++k) {
            const btVector3& c = panel.centers_uv[k];
            const double r = holes_[source.holes[k]].radius;
            for (int i = clamp_column(c.x() - r); i <= clamp_column(c.x() + r); ++i) {
                for (int j = clamp_row(c.y() - r); j <= clamp_row(c.y() + r); ++j) {
                    panel.grid[static_cast<std::size_t>(i * panel.rows + j)].push_back(
                        static_cast<int>(k));
                }
            }
        }
        panel.aabb_min = btVector3(BT_LARGE_FLOAT, BT_LARGE_FLOAT, BT_LARGE_FLOAT);
        panel.aabb_max = -panel.aabb_min;
        for (const double u : {0.0, source.plane.length}) {
            for (const double v : {-source.plane.half_width, source.plane.half_width}) {
                for (const double w : {0.0, source.thickness}) {
                    const btVector3 p = to_bt(source.plane.point(u, v, w));
                    panel.aabb_min.setMin(p);
                    panel.aabb_max.setMax(p);
                }
            }
        }
    }
    if (!holes_.empty()) {
        const shapes::SheetHole& hole = holes_.front();
        const double half_sector = std::numbers::pi / hole.sides;
        edge_depth_ = kEdgeDepthFraction * hole.radius;
        shapes::OrientedBox box;
        box.half_extents = shapes::Vec3(hole.radius * std::sin(half_sector), 0.5 * edge_depth_,
                                        0.5 * sheet.panels.front().thickness);
        edge_box_ = make_box_shape(box);
    }
}

SheetShape::~SheetShape() = default;

void SheetShape::getAabb(const btTransform& transform, btVector3& aabb_min,
                         btVector3& aabb_max) const {
    triangles_->shape().getAabb(transform, aabb_min, aabb_max);
}

void SheetShape::processAllTriangles(btTriangleCallback* callback, const btVector3& aabb_min,
                                     const btVector3& aabb_max) const {
    triangles_->shape().processAllTriangles(callback, aabb_min, aabb_max);
}

void SheetShape::setLocalScaling(const btVector3&) {
    // A sheet is built at its size: scaling is not supported (and never asked for).
}

const btVector3& SheetShape::getLocalScaling() const {
    return triangles_->shape().getLocalScaling();
}

void SheetShape::calculateLocalInertia(btScalar, btVector3& inertia) const {
    inertia.setValue(0.0, 0.0, 0.0);  // static only
}

int SheetShape::hole_at(const Panel& panel, double u, double v) const {
    const int i = static_cast<int>(std::floor(u / panel.cell));
    const int j = static_cast<int>(std::floor((v + panel.panel.plane.half_width) / panel.cell));
    if (i < 0 || j < 0 || i >= panel.columns || j >= panel.rows) {
        return -1;
    }
    for (const int k : panel.grid[static_cast<std::size_t>(i * panel.rows + j)]) {
        const btVector3& c = panel.centers_uv[static_cast<std::size_t>(k)];
        if (shapes::inside_hole(holes_[panel.panel.holes[static_cast<std::size_t>(k)]], u - c.x(),
                                v - c.y())) {
            return k;
        }
    }
    return -1;
}

void SheetShape::collide(const btCollisionObjectWrapper& rock,
                         const btCollisionObjectWrapper& sheet, btScalar threshold,
                         btManifoldResult& result,
                         btConvexPenetrationDepthSolver& penetration_solver) const {
    const auto& convex = *static_cast<const btConvexShape*>(rock.getCollisionShape());
    const btTransform& sheet_to_world = sheet.getWorldTransform();
    const btTransform rock_to_sheet = sheet_to_world.inverseTimes(rock.getWorldTransform());
    btVector3 rock_min;
    btVector3 rock_max;
    convex.getAabb(rock_to_sheet, rock_min, rock_max);
    const btVector3 reach(threshold, threshold, threshold);
    rock_min -= reach;
    rock_max += reach;
    const RockPoints points = rock_points(convex);
    for (const Panel& panel : panels_) {
        if (!overlap(rock_min, rock_max, panel.aabb_min, panel.aabb_max)) {
            continue;
        }
        const shapes::SheetPanel& p = panel.panel;
        const btVector3 origin = to_bt(p.plane.origin);
        const btVector3 tangent = to_bt(p.plane.tangent);
        const btVector3 normal = to_bt(p.plane.normal);
        const btVector3 normal_world = sheet_to_world.getBasis() * normal;
        std::vector<int> engaged;
        for (int k = 0; k < points.count; ++k) {
            const btVector3 q = rock_to_sheet(points.points[k]) - origin;
            // Height of the bottom of the point's margin sphere above the top face.
            const btScalar height = q.dot(normal) - points.margin - p.thickness;
            if (height >= threshold) {
                continue;
            }
            const double u = q.dot(tangent);
            const double v = q.y();
            if (u < 0.0 || u > p.plane.length || std::abs(v) > p.plane.half_width) {
                continue;
            }
            const int hole = hole_at(panel, u, v);
            if (hole >= 0) {
                if (std::find(engaged.begin(), engaged.end(), hole) == engaged.end()) {
                    engaged.push_back(hole);
                }
                continue;
            }
            const btVector3 on_top =
                origin + u * tangent + v * btVector3(0.0, 1.0, 0.0) + p.thickness * normal;
            result.addContactPoint(normal_world, sheet_to_world(on_top), height);
        }
        for (const int hole : engaged) {
            collide_hole(panel, hole, rock, sheet_to_world, rock_min, rock_max, threshold, result,
                         penetration_solver);
        }
    }
}

void SheetShape::collide_hole(const Panel& panel, int hole, const btCollisionObjectWrapper& rock,
                              const btTransform& sheet_to_world, const btVector3& rock_min,
                              const btVector3& rock_max, btScalar threshold,
                              btManifoldResult& result,
                              btConvexPenetrationDepthSolver& penetration_solver) const {
    const shapes::SheetPanel& p = panel.panel;
    const shapes::SheetHole& h = holes_[p.holes[static_cast<std::size_t>(hole)]];
    const btVector3 tangent = to_bt(p.plane.tangent);
    const btVector3 across(0.0, 1.0, 0.0);
    const btVector3 normal = to_bt(p.plane.normal);
    const btVector3 center = to_bt(h.center);
    const double sector = 2.0 * std::numbers::pi / h.sides;
    const double apothem = h.radius * std::cos(0.5 * sector);
    const btVector3& half = edge_box_->getHalfExtentsWithMargin();
    const auto* convex = static_cast<const btConvexShape*>(rock.getCollisionShape());
    for (int i = 0; i < h.sides; ++i) {
        // Edge i joins the vertices at (i + 1/2) and (i + 3/2) sectors; its outward normal is
        // at (i + 1) sectors. The box's local axes: x along the edge, y outward, z up.
        const double angle = (i + 1) * sector;
        const btVector3 outward = std::cos(angle) * tangent + std::sin(angle) * across;
        const btVector3 along = outward.cross(normal);
        const btVector3 box_center = center + (apothem + half.y()) * outward + half.z() * normal;
        const btVector3 extent = half.x() * along.absolute() + half.y() * outward.absolute() +
                                 half.z() * normal.absolute();
        if (!overlap(rock_min, rock_max, box_center - extent, box_center + extent)) {
            continue;
        }
        const btMatrix3x3 basis(along.x(), outward.x(), normal.x(), along.y(), outward.y(),
                                normal.y(), along.z(), outward.z(), normal.z());
        btGjkPairDetector::ClosestPointInput input;
        input.m_transformA = rock.getWorldTransform();
        input.m_transformB = sheet_to_world * btTransform(basis, box_center);
        const btScalar reach = convex->getMargin() + edge_box_->getMargin() + threshold;
        input.m_maximumDistanceSquared = reach * reach;
        btVoronoiSimplexSolver simplex;
        btGjkPairDetector gjk(convex, edge_box_.get(), &simplex, &penetration_solver);
        gjk.getClosestPoints(input, result, nullptr);
    }
}

namespace {

// The structured contact of one rock with one sheet, in its own manifold (first body the rock).
class SheetContactAlgorithm : public btActivatingCollisionAlgorithm {
  public:
    SheetContactAlgorithm(const btCollisionAlgorithmConstructionInfo& info,
                          const btCollisionObjectWrapper* body0,
                          const btCollisionObjectWrapper* body1, bool rock_first,
                          btConvexPenetrationDepthSolver* penetration_solver)
        : btActivatingCollisionAlgorithm(info, body0, body1),
          rock_first_(rock_first),
          penetration_solver_(penetration_solver),
          manifold_(
              m_dispatcher->getNewManifold((rock_first ? body0 : body1)->getCollisionObject(),
                                           (rock_first ? body1 : body0)->getCollisionObject())) {}

    ~SheetContactAlgorithm() override { m_dispatcher->releaseManifold(manifold_); }
    SheetContactAlgorithm(const SheetContactAlgorithm&) = delete;
    SheetContactAlgorithm& operator=(const SheetContactAlgorithm&) = delete;

    void processCollision(const btCollisionObjectWrapper* body0,
                          const btCollisionObjectWrapper* body1, const btDispatcherInfo&,
                          btManifoldResult*) override {
        const btCollisionObjectWrapper* rock = rock_first_ ? body0 : body1;
        const btCollisionObjectWrapper* sheet = rock_first_ ? body1 : body0;
        // Our own result, rock first, so that the points need no swapping.
        btManifoldResult result(rock, sheet);
        result.setPersistentManifold(manifold_);
        const auto& shape = *static_cast<const SheetShape*>(sheet->getCollisionShape());
        shape.collide(*rock, *sheet, manifold_->getContactBreakingThreshold(), result,
                      *penetration_solver_);
        result.refreshContactPoints();
    }

    btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                   btManifoldResult*) override {
        return 1.0;  // continuous collision detection is off
    }

    void getAllContactManifolds(btManifoldArray& manifolds) override {
        manifolds.push_back(manifold_);
    }

  private:
    bool rock_first_;
    btConvexPenetrationDepthSolver* penetration_solver_;
    btPersistentManifold* manifold_;
};

}  // namespace

SheetContactCreateFunc::SheetContactCreateFunc()
    : penetration_solver_(std::make_unique<btGjkEpaPenetrationDepthSolver>()) {}

SheetContactCreateFunc::~SheetContactCreateFunc() = default;

btCollisionAlgorithm* SheetContactCreateFunc::CreateCollisionAlgorithm(
    btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
    const btCollisionObjectWrapper* body1) {
    const bool rock_first = body1->getCollisionShape()->getShapeType() == CUSTOM_CONCAVE_SHAPE_TYPE;
    void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sheet_contact_algorithm_size());
    return new (memory)
        SheetContactAlgorithm(info, body0, body1, rock_first, penetration_solver_.get());
}

int sheet_contact_algorithm_size() { return static_cast<int>(sizeof(SheetContactAlgorithm)); }

}  // namespace rockfall::engine
