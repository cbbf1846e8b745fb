#pragma once
/// Slope geometry, defined once for the rigid-body engine and the MPM solver.
///
/// Frame: x horizontal and downslope (x = 0 at the crown), y across the slope (y = 0 on the
/// centre line), z up (z = 0 on the final run-out segment's surface level at its end).

#include "shapes/polyhedron.hpp"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

namespace rockfall::shapes {

class Terrain;
struct Lining;

/// One straight segment of the slope profile.
struct SlopeSegment {
    /// Length along the surface, m (> 0).
    double length = 1.0;
    /// Inclination below the horizontal, degrees, in [0, 80].
    double angle_deg = 0.0;
};

/// Steel angle bars across the full width (protrusions that make rocks bounce).
struct AngleBars {
    /// Whether bars are installed.
    bool enabled = true;
    /// Leg length of the equal-leg angle profile, m (L 50x50x5: 0.05).
    double leg = 0.05;
    /// Leg thickness, m (L 50x50x5: 0.005).
    double thickness = 0.005;
    /// Spacing along the surface, m (> 0).
    double spacing = 1.0;
    /// Indices of the segments that carry bars (seed: both inclined segments).
    std::vector<int> segments = {0, 1};
};

/// Walls along both sides of the slope.
struct SideWalls {
    /// Whether side walls are present.
    bool enabled = true;
    /// Height above the slope surface, m (> 0).
    double height = 0.5;
    /// Thickness, m (> 0).
    double thickness = 0.1;
};

/// Reaction wall across the last segment, facing upslope.
struct ReactionWall {
    /// Whether the wall is present.
    bool enabled = true;
    /// Horizontal distance from the toe to the wall's front face, m (> 0).
    double distance_from_toe = 5.0;
    /// Height above the surface, m (> 0).
    double height = 1.5;
    /// Thickness, m (> 0).
    double thickness = 0.5;
};

/// The whole slope as a user describes it (defaults: seed 000, scenario A).
struct SlopeSpec {
    /// Segments from the crown down; the last is the run-out (seed: flat, 7.5 m).
    std::vector<SlopeSegment> segments = {{5.0, 43.0}, {5.7, 29.0}, {7.5, 0.0}};
    /// Width across the slope, m (> 0).
    double width = 5.0;
    /// Thickness of the slope slab under the surface, m (> 0); a solid, not a skin.
    double thickness = 0.5;
    SideWalls side_walls;
    AngleBars bars;
    ReactionWall wall;
    /// A triangle-mesh surface (shapes/terrain.hpp) that replaces the slope slabs for rocks,
    /// or null. The segments stay the reference profile (toe, stations, bars, walls); shared,
    /// as sweeps copy the scenario for every sample.
    std::shared_ptr<const Terrain> terrain;
    /// A rough lining on some segments (shapes/lining.hpp), or null; shared like the terrain.
    std::shared_ptr<const Lining> lining;
};

/// What a static solid is, for materials and for the wall load cell.
enum class SurfaceRole { slope, bar, side_wall, reaction_wall };

/// A static solid box.
struct OrientedBox {
    /// Centre, m.
    Vec3 center = Vec3::Zero();
    /// Columns are the box's local axes in the world frame.
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    /// Half-extents along the local axes, m (> 0).
    Vec3 half_extents = Vec3::Ones();
    /// What the box is.
    SurfaceRole role = SurfaceRole::slope;
    /// The profile segment it belongs to (slope, bars, side walls), or -1 (reaction wall).
    int segment = -1;
};

/// Signed distance from p to the box surface, m: negative inside. When `normal` is given it
/// receives the outward unit normal of the closest feature (the face normal inside).
double signed_distance(const OrientedBox& box, const Vec3& p, Vec3* normal = nullptr);

/// The slope built from a SlopeSpec: profile, static solids and queries on the surface.
class Slope {
  public:
    /// Builds the geometry; the spec must be valid (validated at load time).
    explicit Slope(const SlopeSpec& spec);

    /// The spec it was built from.
    const SlopeSpec& spec() const { return spec_; }
    /// Profile vertices (x, z) from the crown to the end of the last segment, m.
    const std::vector<Eigen::Vector2d>& profile() const { return profile_; }
    /// All static solids: slope slabs, bars, side walls, the reaction wall.
    const std::vector<OrientedBox>& solids() const { return solids_; }
    /// The reaction wall box, if enabled.
    const std::optional<OrientedBox>& wall() const { return wall_; }

    /// x of the toe (start of the last segment), m.
    double toe_x() const;
    /// x of the reaction wall's front face, m (toe_x + distance_from_toe).
    double wall_x() const;
    /// x of the end of the last segment, m.
    double end_x() const;
    /// Surface height z at horizontal position x, m (clamped to the ends of the profile).
    double surface_height(double x) const;
    /// Upward unit normal of the surface at x (in the x-z plane), of segment_at(x).
    Vec3 surface_normal(double x) const;
    /// Unit vector along the surface, pointing downslope, at x.
    Vec3 surface_tangent(double x) const;
    /// Point on the surface (centre line) at distance s along the surface from the crown, m
    /// (s clamped to [0, total length]).
    Vec3 point_at_distance(double s) const;
    /// Distance along the surface from the crown to the surface point below x, m (x clamped
    /// to [0, end_x]).
    double distance_along_surface(double x) const;
    /// Index of the segment under x (a kink belongs to the lower segment; 0 before the crown,
    /// the last beyond the end).
    int segment_at(double x) const;

  private:
    // Trigonometry of one segment, evaluated once: the surface queries run every step and
    // recomputing it cost ~1.3 % of a run in libm (callgrind, seed slope).
    struct SegmentTrig {
        // Downslope unit tangent and upward unit normal, (cos a, 0, -sin a) and (sin a, 0, cos a).
        Vec3 tangent;
        Vec3 normal;
        // tan a: height lost per metre of horizontal travel.
        double slope;
    };

    SlopeSpec spec_;
    std::vector<SegmentTrig> trig_;
    std::vector<Eigen::Vector2d> profile_;
    std::vector<OrientedBox> solids_;
    std::optional<OrientedBox> wall_;
};

}  // namespace rockfall::shapes
