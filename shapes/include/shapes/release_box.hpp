#pragma once
/// The release box of a rock cluster (seed 001: the rocks are held in a box at the top of the
/// flume, and its front face is removed at t = 0), and the packing of the cluster into it.
///
/// The box stands on the first profile segment and is aligned with it: its floor is that
/// segment's surface (raised by the lining's height), its walls are perpendicular to it, and
/// its gate is the downslope face. Rocks are packed as their bounding spheres (no two rocks
/// overlap in any orientation) or lying flat as their bounding boxes (denser for elongated
/// rocks).

#include "shapes/polyhedron.hpp"
#include "shapes/slope.hpp"

#include <Eigen/Core>

#include <optional>
#include <random>
#include <string>
#include <vector>

namespace rockfall::shapes {

using Vec2 = Eigen::Vector2d;

/// The order in which rocks are dropped into the box.
enum class PackingOrder {
    shuffled,       ///< a random order from the generator (a cluster poured in)
    largest_first,  ///< by bounding radius descending (densest; the large rocks end up below)
};

/// The shapes rocks are packed as.
enum class Packing {
    spheres,  ///< bounding spheres, any orientation (pack_release_box)
    flat,     ///< bounding boxes lying flat (pack_release_box_flat): denser for elongated rocks
};

/// A release box in the slope frame. Seed 001 gives no size; the defaults (a box across the
/// flume's 0.60 m width, 0.40 m along the slope and 0.30 m high, the side walls' height) hold
/// cluster C2 with room to spare (docs/clusters.md).
struct ReleaseBox {
    /// Distance along the surface from the crown to the box's back (upslope) face, m, >= 0.
    double start = 0.0;
    /// Inside length along the surface, m, > 0; start + length within the first segment.
    double length = 0.40;
    /// Inside width across the slope, centred on y = 0, m, in (0, slope width].
    double width = 0.60;
    /// Inside height along the surface normal above the floor, m, > 0.
    double height = 0.30;
    /// Height of the floor above the first segment's surface, m, >= 0: the lining's top (a
    /// sphere layer's 2 radius, a sheet's thickness) so that rocks start clear of it.
    double floor = 0.0;
    /// The order rocks are dropped in.
    PackingOrder order = PackingOrder::shuffled;
    /// What the engine packs the cluster's rocks as.
    Packing packing = Packing::spheres;
};

/// The box's inside as an OrientedBox in the slope frame (role slope, segment 0): its local x
/// runs downslope, y across and z along the first segment's normal; the gate is the face at
/// local x = +half_extents.x(). Throws std::invalid_argument naming the field for a box that
/// does not fit the first segment or the slope's width.
OrientedBox release_box_region(const Slope& slope, const ReleaseBox& box);

/// The packing could not place every rock; the message gives the box volume needed.
class PackingError : public GeometryError {
  public:
    PackingError(const std::string& message, int placed, double needed_volume)
        : GeometryError(message), placed_(placed), needed_volume_(needed_volume) {}
    /// Rocks placed before the first that did not fit.
    int placed() const { return placed_; }
    /// Estimated inside volume of a box that holds them all, m3.
    double needed_volume() const { return needed_volume_; }

  private:
    int placed_;
    double needed_volume_;
};

/// Candidate spots tried per rock by pack_release_box.
inline constexpr int packing_candidates = 200;

/// Centres of the rocks' bounding spheres (m, slope frame; in the order of `radii`) packed in
/// the box by sequential deposition: in the box's order each rock tries packing_candidates
/// spots uniform over the floor and, at each, drops along the box's -z until it touches the
/// floor or an earlier rock; it stays at the lowest of them (the first spot on a tie). The
/// shuffled order and the spots come from `generator` (uniform01; a Fisher-Yates shuffle). Bounding
/// spheres do not overlap each other, the walls, the floor or the box's top. Reproducible: the same
/// radii and generator state give the same centres. Throws std::invalid_argument for a radius that
/// is not finite > 0 or a bad box, and PackingError when a rock fits nowhere (with the box volume
/// needed, from the packing density reached so far).
///
/// `spots` (empty, or one per rock): a rock with a spot (x from the box's back face along the
/// slope, y across from its centre line, m) is dropped there, after all rocks without one (so
/// it lies on top of the pile at that spot, where an overhead camera sees it: seed 001's marked
/// rocks), in index order. Throws std::invalid_argument naming the rock when its bounding
/// sphere at the spot would cross a wall.
std::vector<Vec3> pack_release_box(const Slope& slope, const ReleaseBox& box,
                                   const std::vector<double>& radii, std::mt19937_64& generator,
                                   const std::vector<std::optional<Vec2>>& spots = {});

/// Throws std::invalid_argument (PackingError when the rock cannot fit the floor at all)
/// unless a rock of bounding radius `radius` (m) dropped at `spot` (as pack_release_box's
/// spots) stays inside the box's walls; the message gives the allowed range.
void check_release_spot(const ReleaseBox& box, const Vec2& spot, double radius);

/// Where a packed rock starts: p_slope = center + rotation p_body for a point p_body of the
/// rock's body frame (RockGeometry: centroid at the origin, principal axes on x, y, z).
struct RockPose {
    /// The centroid in the slope frame, m.
    Vec3 center = Vec3::Zero();
    /// Body to slope frame, a proper rotation.
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};

/// Rocks packed lying flat, as their body-frame bounding boxes (RockGeometry::half_extents, m;
/// in the order given): each lies with its short axis (body z) along the box's normal and its
/// long axis (body x) along the slope or across it, turned half a turn about one of its axes
/// at random. Sequential deposition on a height map of 200 cells along the floor's longer
/// side: each rock tries packing_candidates spots uniform over the floor in both
/// orientations, rests on the highest box top under its footprint (every cell it overlaps,
/// so boxes never overlap) and stays at the lowest of them (the one nearest the back face on a
/// tie). Far denser than bounding spheres for elongated rocks (a rock of sphericity 0.72 from
/// rock_with_sphericity has a bounding sphere 12 times its volume, a bounding box 2.3 times).
/// Reproducible as pack_release_box; the order's size is a rock's largest half extent. Throws
/// std::invalid_argument for half extents that are not finite > 0 or a bad box, and
/// PackingError as pack_release_box.
///
/// `spots` as pack_release_box's: a rock with a spot lies there (long axis along the slope, or
/// across when it does not fit that way), after all the others.
std::vector<RockPose> pack_release_box_flat(const Slope& slope, const ReleaseBox& box,
                                            const std::vector<Vec3>& half_extents,
                                            std::mt19937_64& generator,
                                            const std::vector<std::optional<Vec2>>& spots = {});

}  // namespace rockfall::shapes
