#include "shapes/slope.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace rockfall::shapes {
namespace {

// Bars whose far edge overshoots the segment end by less than this still count as fitting, so
// that spacing * k + leg == length is not lost to round-off.
constexpr double kFitTolerance = 1e-9;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Downslope unit vector along a segment inclined `angle_deg` below the horizontal.
Vec3 tangent_of(const SlopeSegment& segment) {
    const double a = radians(segment.angle_deg);
    return {std::cos(a), 0.0, -std::sin(a)};
}

// Upward unit normal of the same segment.
Vec3 normal_of(const SlopeSegment& segment) {
    const double a = radians(segment.angle_deg);
    return {std::sin(a), 0.0, std::cos(a)};
}

// Segment frame: columns tangent (downslope), across (y) and normal (up); right-handed because
// tangent x across = normal.
Eigen::Matrix3d frame_of(const SlopeSegment& segment) {
    Eigen::Matrix3d frame;
    frame.col(0) = tangent_of(segment);
    frame.col(1) = Vec3::UnitY();
    frame.col(2) = normal_of(segment);
    return frame;
}

// Closed interval [lo, hi] in one coordinate of a segment frame.
struct Range {
    double lo;
    double hi;
    double middle() const { return 0.5 * (lo + hi); }
    double half() const { return 0.5 * (hi - lo); }
};

// A box aligned with a segment: `along` measured on the surface from the segment's upper end,
// `across` in y, `up` along the surface normal from the surface.
OrientedBox segment_box(const SlopeSegment& segment, const Eigen::Vector2d& upper_end, Range along,
                        Range across, Range up, SurfaceRole role, int index) {
    assert(along.hi > along.lo && across.hi > across.lo && up.hi > up.lo);
    OrientedBox box;
    box.rotation = frame_of(segment);
    const Vec3 origin(upper_end.x(), 0.0, upper_end.y());
    box.center = origin + box.rotation * Vec3(along.middle(), across.middle(), up.middle());
    box.half_extents = Vec3(along.half(), across.half(), up.half());
    box.role = role;
    box.segment = index;
    return box;
}

// How far a side wall must reach past a kink between two segments so that neighbouring walls
// meet on the bisecting plane up to `reach` from the surface on either side: reach tan(dtheta/2).
double kink_overlap(const SlopeSegment& a, const SlopeSegment& b, double reach) {
    return reach * std::tan(0.5 * std::abs(radians(b.angle_deg - a.angle_deg)));
}

// How far a slab reaches past a kink under its neighbour. Where the slope flattens (a concave
// kink) two slabs cut square to their surfaces leave a wedge-shaped gap below the kink, and
// the end face of the lower slab stands at the kink inside that gap: a rock whose corner
// crosses the kink is then separated through that face, pushed back upslope, instead of up
// through the surface (planar rocks lost most of their speed there). Reaching
// thickness tan(dtheta/2) past the kink, both slabs meet on the bisecting plane: the gap is
// closed and the end faces lie under the neighbour's surface, which neither extension raises.
// Where the slope steepens (convex) the slabs already overlap below the kink.
double slab_overlap(const SlopeSegment& a, const SlopeSegment& b, double thickness) {
    return b.angle_deg < a.angle_deg ? kink_overlap(a, b, thickness) : 0.0;
}

void check_spec([[maybe_unused]] const SlopeSpec& spec) {
    assert(!spec.segments.empty());
    for (const SlopeSegment& segment : spec.segments) {
        assert(segment.length > 0.0);
        assert(segment.angle_deg >= 0.0 && segment.angle_deg <= 80.0);
    }
    assert(spec.width > 0.0 && spec.thickness > 0.0);
    if (spec.bars.enabled) {
        assert(spec.bars.leg > 0.0 && spec.bars.thickness > 0.0);
        assert(spec.bars.thickness <= spec.bars.leg && spec.bars.spacing > 0.0);
        for (const int index : spec.bars.segments) {
            assert(index >= 0 && index < static_cast<int>(spec.segments.size()));
        }
    }
    if (spec.side_walls.enabled) {
        assert(spec.side_walls.height > 0.0 && spec.side_walls.thickness > 0.0);
    }
    if (spec.wall.enabled) {
        assert(spec.wall.distance_from_toe > 0.0);
        assert(spec.wall.height > 0.0 && spec.wall.thickness > 0.0);
    }
}

}  // namespace

double signed_distance(const OrientedBox& box, const Vec3& p, Vec3* normal) {
    const Vec3 local = box.rotation.transpose() * (p - box.center);
    const Vec3 excess = local.cwiseAbs() - box.half_extents;
    const Vec3 outside = excess.cwiseMax(0.0);
    const double outside_distance = outside.norm();
    if (outside_distance > 0.0) {
        // Outside: the nearest feature (face, edge or corner) lies along the clamped offset.
        if (normal != nullptr) {
            const Vec3 direction = outside.cwiseProduct(local.cwiseSign()) / outside_distance;
            *normal = box.rotation * direction;
        }
        return outside_distance;
    }
    Eigen::Index axis = 0;
    const double inside_distance = excess.maxCoeff(&axis);
    if (normal != nullptr) {
        Vec3 direction = Vec3::Zero();
        direction[axis] = local[axis] < 0.0 ? -1.0 : 1.0;
        *normal = box.rotation * direction;
    }
    return inside_distance;
}

Slope::Slope(const SlopeSpec& spec) : spec_(spec) {
    check_spec(spec_);
    const auto& segments = spec_.segments;
    const int count = static_cast<int>(segments.size());

    for (const SlopeSegment& segment : segments) {
        trig_.push_back(
            {tangent_of(segment), normal_of(segment), std::tan(radians(segment.angle_deg))});
    }

    // Profile from the crown down, then shifted so that the end of the last segment is z = 0.
    profile_.emplace_back(0.0, 0.0);
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Vec3& t = trig_[i].tangent;
        profile_.push_back(profile_.back() + segments[i].length * Eigen::Vector2d(t.x(), t.z()));
    }
    const double end_z = profile_.back().y();
    for (Eigen::Vector2d& vertex : profile_) {
        vertex.y() -= end_z;
    }

    const double half_width = 0.5 * spec_.width;
    const Range full_width{-half_width, half_width};
    for (int i = 0; i < count; ++i) {
        const auto u = static_cast<std::size_t>(i);
        const SlopeSegment& segment = segments[u];
        const double before = i > 0 ? slab_overlap(segments[u - 1], segment, spec_.thickness) : 0.0;
        const double after =
            i + 1 < count ? slab_overlap(segment, segments[u + 1], spec_.thickness) : 0.0;
        solids_.push_back(segment_box(segment, profile_[u], {-before, segment.length + after},
                                      full_width, {-spec_.thickness, 0.0}, SurfaceRole::slope, i));
    }

    if (spec_.bars.enabled) {
        const AngleBars& bars = spec_.bars;
        for (const int i : bars.segments) {
            const SlopeSegment& segment = segments[static_cast<std::size_t>(i)];
            const Eigen::Vector2d& upper = profile_[static_cast<std::size_t>(i)];
            // Bar k stands at k * spacing from the segment's upper end; its standing leg faces
            // upslope there and its lying leg extends downslope on the surface.
            for (int k = 1; k * bars.spacing + bars.leg <= segment.length + kFitTolerance; ++k) {
                const double s = k * bars.spacing;
                solids_.push_back(segment_box(segment, upper, {s, s + bars.leg}, full_width,
                                              {0.0, bars.thickness}, SurfaceRole::bar, i));
                solids_.push_back(segment_box(segment, upper, {s, s + bars.thickness}, full_width,
                                              {0.0, bars.leg}, SurfaceRole::bar, i));
            }
        }
    }

    if (spec_.side_walls.enabled) {
        const SideWalls& walls = spec_.side_walls;
        const double reach = walls.height + spec_.thickness;
        for (int i = 0; i < count; ++i) {
            const auto u = static_cast<std::size_t>(i);
            const SlopeSegment& segment = segments[u];
            const double before = i > 0 ? kink_overlap(segments[u - 1], segment, reach) : 0.0;
            const double after =
                i + 1 < count ? kink_overlap(segment, segments[u + 1], reach) : 0.0;
            const Range along{-before, segment.length + after};
            const Range up{-spec_.thickness, walls.height};
            for (const double side : {-1.0, 1.0}) {
                const double inner = side * half_width;
                const double outer = side * (half_width + walls.thickness);
                solids_.push_back(segment_box(segment, profile_[u], along,
                                              {std::min(inner, outer), std::max(inner, outer)}, up,
                                              SurfaceRole::side_wall, i));
            }
        }
    }

    if (spec_.wall.enabled) {
        const ReactionWall& spec_wall = spec_.wall;
        const double front = wall_x();
        assert(front > toe_x() && front < end_x());
        const double back = front + spec_wall.thickness;
        // Vertical faces on a possibly inclined run-out: the bottom reaches the slab's
        // underside below the back face, the top is `height` above the surface at the front.
        const double bottom = surface_height(back) - spec_.thickness / trig_.back().normal.z();
        const double top = surface_height(front) + spec_wall.height;
        OrientedBox box;
        box.center = Vec3(0.5 * (front + back), 0.0, 0.5 * (bottom + top));
        box.half_extents = Vec3(0.5 * spec_wall.thickness, half_width, 0.5 * (top - bottom));
        box.role = SurfaceRole::reaction_wall;
        box.segment = -1;
        wall_ = box;
        solids_.push_back(box);
    }
}

double Slope::toe_x() const { return profile_[profile_.size() - 2].x(); }

double Slope::wall_x() const { return toe_x() + spec_.wall.distance_from_toe; }

double Slope::end_x() const { return profile_.back().x(); }

int Slope::segment_at(double x) const {
    const int count = static_cast<int>(spec_.segments.size());
    for (int i = 0; i + 1 < count; ++i) {
        if (x < profile_[static_cast<std::size_t>(i + 1)].x()) {
            return i;
        }
    }
    return count - 1;
}

double Slope::surface_height(double x) const {
    const double clamped = std::clamp(x, 0.0, end_x());
    const auto i = static_cast<std::size_t>(segment_at(clamped));
    return profile_[i].y() - (clamped - profile_[i].x()) * trig_[i].slope;
}

Vec3 Slope::surface_normal(double x) const {
    return trig_[static_cast<std::size_t>(segment_at(x))].normal;
}

Vec3 Slope::surface_tangent(double x) const {
    return trig_[static_cast<std::size_t>(segment_at(x))].tangent;
}

Vec3 Slope::point_at_distance(double s) const {
    double start = 0.0;
    const std::size_t last = spec_.segments.size() - 1;
    for (std::size_t i = 0; i <= last; ++i) {
        const SlopeSegment& segment = spec_.segments[i];
        if (s < start + segment.length || i == last) {
            const double along = std::clamp(s - start, 0.0, segment.length);
            const Vec3 origin(profile_[i].x(), 0.0, profile_[i].y());
            return origin + along * trig_[i].tangent;
        }
        start += segment.length;
    }
    assert(false && "unreachable: the last segment always returns");
    return Vec3::Zero();
}

double Slope::distance_along_surface(double x) const {
    const double clamped = std::clamp(x, 0.0, end_x());
    const auto index = static_cast<std::size_t>(segment_at(clamped));
    double start = 0.0;
    for (std::size_t i = 0; i < index; ++i) {
        start += spec_.segments[i].length;
    }
    return start + (clamped - profile_[index].x()) / trig_[index].normal.z();
}

}  // namespace rockfall::shapes
