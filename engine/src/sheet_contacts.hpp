#pragma once
// Narrow phase for rocks on a perforated sheet (numerics.sheet_contact = "structured", the
// default). Private to the engine.
//
// As a triangle mesh the sheet costs a GJK query per triangle near a rock every step: a 16-gon
// hole's cell is 68 thin triangles, a 53 mm rock's box overlaps dozens, and a deposit of C2's
// 99 rocks on the sheet spent 60 % of a cluster run there (measured with perf, issue 13). The
// sheet is a plate with regular polygonal holes, so its contacts follow from its structure:
// - a rock point (hull vertex, or a sphere's centre, with the shape's margin) less than the
//   contact threshold above the top face, over the panel and outside every hole, touches the
//   top face: one contact along the panel's normal, depth its height above the face;
// - a hole with such a point over it is engaged: the rock may touch its rim or walls, which are
//   found by GJK against one thin box per polygon edge (the sheet's material behind the hole's
//   wall: inner face on the wall, top face on the sheet's top), only for boxes whose bounds
//   overlap the rock's.
// The plate's underside lies on the slope surface, which the slab under it represents.

#include "terrain_shape.hpp"

#include "shapes/lining.hpp"

#include <btBulletCollisionCommon.h>

#include <memory>
#include <vector>

class btConvexPenetrationDepthSolver;

namespace rockfall::engine {

// The sheet as a Bullet shape of custom concave type. Its triangles (the mesh) serve any pair
// without a structured algorithm (Bullet's convex-concave algorithm over processAllTriangles).
class SheetShape : public btConcaveShape {
  public:
    explicit SheetShape(const shapes::SheetMesh& sheet);
    ~SheetShape() override;
    SheetShape(const SheetShape&) = delete;
    SheetShape& operator=(const SheetShape&) = delete;

    void getAabb(const btTransform& transform, btVector3& aabb_min,
                 btVector3& aabb_max) const override;
    void processAllTriangles(btTriangleCallback* callback, const btVector3& aabb_min,
                             const btVector3& aabb_max) const override;
    void setLocalScaling(const btVector3& scaling) override;
    const btVector3& getLocalScaling() const override;
    void calculateLocalInertia(btScalar mass, btVector3& inertia) const override;
    const char* getName() const override { return "PerforatedSheet"; }

    // Adds the contacts of a convex hull or sphere (`rock`) with the sheet (`sheet`, this shape)
    // to `result`, whose first body is the rock's.
    void collide(const btCollisionObjectWrapper& rock, const btCollisionObjectWrapper& sheet,
                 btScalar threshold, btManifoldResult& result,
                 btConvexPenetrationDepthSolver& penetration_solver) const;

    // A panel with its holes' centres in (u, v) and a grid of square cells (side `cell`) listing
    // the holes whose circle overlaps each cell.
    struct Panel {
        shapes::SheetPanel panel;
        std::vector<btVector3> centers_uv;  // (u, v, 0) of each of panel.holes
        double cell = 1.0;
        int columns = 0;
        int rows = 0;
        std::vector<std::vector<int>> grid;  // indices into panel.holes, row-major (u, v)
        btVector3 aabb_min, aabb_max;        // bounds of the plate in the sheet's frame
    };

  private:
    // The hole of `panel` whose polygon contains (u, v), or -1.
    int hole_at(const Panel& panel, double u, double v) const;
    // The edge boxes of one engaged hole against the rock.
    void collide_hole(const Panel& panel, int hole, const btCollisionObjectWrapper& rock,
                      const btTransform& sheet_to_world, const btVector3& rock_min,
                      const btVector3& rock_max, btScalar threshold, btManifoldResult& result,
                      btConvexPenetrationDepthSolver& penetration_solver) const;

    std::vector<shapes::SheetHole> holes_;
    std::vector<Panel> panels_;
    // Every hole of a sheet has the same polygon, so one box serves every edge.
    std::unique_ptr<btBoxShape> edge_box_;
    double edge_depth_ = 0.0;
    // The mesh for other pairs.
    std::unique_ptr<TerrainShape> triangles_;
};

// Creates the structured algorithm for a rock (hull or sphere) and a SheetShape, either order.
class SheetContactCreateFunc : public btCollisionAlgorithmCreateFunc {
  public:
    SheetContactCreateFunc();
    ~SheetContactCreateFunc() override;
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;

  private:
    std::unique_ptr<btConvexPenetrationDepthSolver> penetration_solver_;
};

// Size of the algorithm object, for the collision configuration's pool.
int sheet_contact_algorithm_size();

}  // namespace rockfall::engine
