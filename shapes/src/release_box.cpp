#include "shapes/release_box.hpp"

#include "lining_frame.hpp"

#include "shapes/random.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rockfall::shapes {
namespace {

// Contact gap left between dropped spheres, m: they touch to round-off without overlapping.
constexpr double kClearance = 1e-9;

// Cells of the flat packing's height map along the box's longer floor side.
constexpr int kHeightMapCells = 200;

void check_box(const Slope& slope, const ReleaseBox& box) {
    const double first = slope.spec().segments.front().length;
    detail::check_range("release_box.start", box.start, "m", 0.0, first);
    detail::check_range("release_box.length", box.length, "m", 1e-3, first - box.start);
    detail::check_range("release_box.width", box.width, "m", 1e-3, slope.spec().width);
    detail::check_range("release_box.height", box.height, "m", 1e-3, 100.0);
    detail::check_range("release_box.floor", box.floor, "m", 0.0, 1.0);
}

std::string number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

// The order rocks are dropped in: as given sorted by `size` descending, or shuffled by
// Fisher-Yates from uniform01 (std::shuffle's algorithm is not fixed by the standard).
std::vector<std::size_t> drop_order(const std::vector<double>& size, PackingOrder order,
                                    std::mt19937_64& generator) {
    std::vector<std::size_t> indices(size.size());
    for (std::size_t i = 0; i < indices.size(); ++i) {
        indices[i] = i;
    }
    if (order == PackingOrder::largest_first) {
        std::stable_sort(indices.begin(), indices.end(),
                         [&](std::size_t a, std::size_t b) { return size[a] > size[b]; });
        return indices;
    }
    for (std::size_t i = indices.size(); i > 1; --i) {
        const auto j = std::min(
            static_cast<std::size_t>(uniform01(generator) * static_cast<double>(i)), i - 1);
        std::swap(indices[i - 1], indices[j]);
    }
    return indices;
}

// The drop order with the rocks that have a spot (spots empty, or one per rock) moved to the
// end, in index order. Throws std::invalid_argument when spots has the wrong size.
std::vector<std::size_t> spots_last(const std::vector<std::size_t>& order,
                                    const std::vector<std::optional<Vec2>>& spots) {
    if (spots.empty()) return order;
    if (spots.size() != order.size()) {
        throw std::invalid_argument("release box packing: " + std::to_string(spots.size()) +
                                    " spots for " + std::to_string(order.size()) + " rocks");
    }
    std::vector<std::size_t> result;
    for (const std::size_t index : order) {
        if (!spots[index]) result.push_back(index);
    }
    for (std::size_t index = 0; index < spots.size(); ++index) {
        if (spots[index]) result.push_back(index);
    }
    return result;
}

// The PackingError of a box that holds `placed` of the rocks, whose packing shapes (bounding
// spheres or boxes) have `volumes`; `placed_volume` of them lie below height `top`.
[[noreturn]] void throw_full(const ReleaseBox& box, std::size_t placed,
                             const std::vector<double>& volumes, double placed_volume, double top,
                             std::string_view shapes) {
    double total = 0.0;
    for (const double v : volumes) {
        total += v;
    }
    // The packing shapes' volume per box volume reached under the packing's top.
    const double density = top > 0.0 ? placed_volume / (box.length * box.width * top) : 0.5;
    const double needed = total / std::max(density, 1e-3);
    throw PackingError("release box " + number(box.length) + " x " + number(box.width) + " x " +
                           number(box.height) + " m (" +
                           number(box.length * box.width * box.height) + " m3) holds " +
                           std::to_string(placed) + " of the " + std::to_string(volumes.size()) +
                           " rocks: at the packing density reached (" + number(density) +
                           " of the box filled by their " + std::string(shapes) +
                           ") they need about " + number(needed) + " m3",
                       static_cast<int>(placed), needed);
}

// Box coordinates (x from the back face, y across, z from the floor) in the slope frame.
Vec3 to_slope(const detail::SegmentPlane& plane, const ReleaseBox& box, const Vec3& local) {
    return plane.point(box.start + local.x(), local.y(), box.floor + local.z());
}

struct Placed {
    Vec3 local;  // centre in box coordinates
    double radius;
};

// The lowest centre height of a sphere of radius r dropped at (x, y) onto the floor and the
// spheres placed so far (resting on the highest it meets).
double drop_height(const std::vector<Placed>& placed, double x, double y, double r) {
    double z = r;
    for (const Placed& other : placed) {
        const double reach = r + other.radius + kClearance;
        const double dx = x - other.local.x();
        const double dy = y - other.local.y();
        const double d2 = dx * dx + dy * dy;
        if (d2 < reach * reach) {
            z = std::max(z, other.local.z() + std::sqrt(reach * reach - d2));
        }
    }
    return z;
}

// Heights of the tops of the boxes placed so far over a grid of cells on the floor.
class HeightMap {
  public:
    HeightMap(double length, double width)
        : cell_(std::max(length, width) / kHeightMapCells),
          columns_(static_cast<int>(std::ceil(length / cell_))),
          rows_(static_cast<int>(std::ceil(width / cell_))),
          width_(width),
          top_(static_cast<std::size_t>(columns_ * rows_), 0.0) {}

    // The highest top under the footprint [x0, x1] x [y0, y1] (y from -width / 2): every cell
    // the footprint overlaps, so that boxes overlapping in plan share a cell.
    double highest(double x0, double x1, double y0, double y1) const {
        double z = 0.0;
        visit(x0, x1, y0, y1, [&](std::size_t c) { z = std::max(z, top_[c]); });
        return z;
    }

    void raise(double x0, double x1, double y0, double y1, double z) {
        visit(x0, x1, y0, y1, [&](std::size_t c) { top_[c] = std::max(top_[c], z); });
    }

  private:
    template <typename F>
    void visit(double x0, double x1, double y0, double y1, F&& f) const {
        const auto range = [&](double lo, double hi, double offset, int count) {
            const int first =
                std::clamp(static_cast<int>(std::floor((lo + offset) / cell_)), 0, count - 1);
            const int last = std::clamp(static_cast<int>(std::ceil((hi + offset) / cell_)) - 1,
                                        first, count - 1);
            return std::array<int, 2>{first, last};
        };
        const auto [i0, i1] = range(x0, x1, 0.0, columns_);
        const auto [j0, j1] = range(y0, y1, 0.5 * width_, rows_);
        for (int i = i0; i <= i1; ++i) {
            for (int j = j0; j <= j1; ++j) {
                f(static_cast<std::size_t>(i * rows_ + j));
            }
        }
    }

    double cell_;
    int columns_;
    int rows_;
    double width_;
    std::vector<double> top_;
};

// The four proper rotations that keep a box's axes on the box frame's axes and its third
// axis vertical (up or down), about the body's axes.
Eigen::Matrix3d flip(int k) {
    constexpr std::array<std::array<double, 3>, 4> signs = {
        {{1, 1, 1}, {-1, -1, 1}, {1, -1, -1}, {-1, 1, -1}}};
    const auto& s = signs[static_cast<std::size_t>(k)];
    return Vec3(s[0], s[1], s[2]).asDiagonal();
}

}  // namespace

void check_release_spot(const ReleaseBox& box, const Vec2& spot, double r) {
    if (box.length < 2.0 * r || box.width < 2.0 * r) {
        throw PackingError("a rock of bounding sphere " + number(2.0 * r) +
                               " m across does not fit the release box's floor (" +
                               number(box.length) + " x " + number(box.width) + " m)",
                           0, std::pow(2.0 * r, 3));
    }
    detail::check_range("spot along the box", spot.x(), "m", r, box.length - r);
    detail::check_range("spot across the box", spot.y(), "m", -0.5 * box.width + r,
                        0.5 * box.width - r);
}

OrientedBox release_box_region(const Slope& slope, const ReleaseBox& box) {
    check_box(slope, box);
    const detail::SegmentPlane plane = detail::segment_plane(slope, 0);
    OrientedBox region;
    region.center = plane.point(box.start + 0.5 * box.length, 0.0, box.floor + 0.5 * box.height);
    region.rotation.col(0) = plane.tangent;
    region.rotation.col(1) = Vec3::UnitY();
    region.rotation.col(2) = plane.normal;
    region.half_extents = Vec3(0.5 * box.length, 0.5 * box.width, 0.5 * box.height);
    region.role = SurfaceRole::slope;
    region.segment = 0;
    return region;
}

std::vector<Vec3> pack_release_box(const Slope& slope, const ReleaseBox& box,
                                   const std::vector<double>& radii, std::mt19937_64& generator,
                                   const std::vector<std::optional<Vec2>>& spots) {
    check_box(slope, box);
    const auto spot = [&](std::size_t i) -> const std::optional<Vec2>& {
        static const std::optional<Vec2> none;
        return spots.empty() ? none : spots[i];
    };
    const double smallest_side = std::min({box.length, box.width, box.height});
    std::vector<double> volumes;
    for (std::size_t i = 0; i < radii.size(); ++i) {
        if (!(std::isfinite(radii[i]) && radii[i] > 0.0)) {
            throw std::invalid_argument("bounding radius of rock " + std::to_string(i) + " = " +
                                        number(radii[i]) + " m: must be finite and > 0");
        }
        if (2.0 * radii[i] > smallest_side) {
            throw PackingError("rock " + std::to_string(i) + ": its bounding sphere (" +
                                   number(2.0 * radii[i]) +
                                   " m across) is larger than the release box's smallest side (" +
                                   number(smallest_side) + " m)",
                               0, std::pow(2.0 * radii[i], 3));
        }
        volumes.push_back(4.0 / 3.0 * std::numbers::pi * std::pow(radii[i], 3));
    }
    const double half_width = 0.5 * box.width;
    std::vector<Placed> placed;
    placed.reserve(radii.size());
    std::vector<Vec3> local(radii.size(), Vec3::Zero());
    double placed_volume = 0.0;
    double top = 0.0;
    for (const std::size_t index : spots_last(drop_order(radii, box.order, generator), spots)) {
        const double r = radii[index];
        Vec3 best(0.0, 0.0, std::numeric_limits<double>::infinity());
        if (const std::optional<Vec2>& at = spot(index)) {
            try {
                check_release_spot(box, *at, r);
            } catch (const std::invalid_argument& error) {
                throw std::invalid_argument("rock " + std::to_string(index) + ": " + error.what());
            }
            best = Vec3(at->x(), at->y(), drop_height(placed, at->x(), at->y(), r));
        }
        for (int k = 0; k < packing_candidates && !spot(index); ++k) {
            const double x = r + uniform01(generator) * (box.length - 2.0 * r);
            const double y = -half_width + r + uniform01(generator) * (box.width - 2.0 * r);
            const double z = drop_height(placed, x, y, r);
            if (z < best.z()) {
                best = Vec3(x, y, z);
            }
        }
        if (best.z() + r > box.height) {
            throw_full(box, placed.size(), volumes, placed_volume, top, "bounding spheres");
        }
        placed.push_back({best, r});
        placed_volume += volumes[index];
        top = std::max(top, best.z() + r);
        local[index] = best;
    }
    const detail::SegmentPlane plane = detail::segment_plane(slope, 0);
    std::vector<Vec3> centers;
    centers.reserve(radii.size());
    for (const Vec3& p : local) {
        centers.push_back(to_slope(plane, box, p));
    }
    return centers;
}

std::vector<RockPose> pack_release_box_flat(const Slope& slope, const ReleaseBox& box,
                                            const std::vector<Vec3>& half_extents,
                                            std::mt19937_64& generator,
                                            const std::vector<std::optional<Vec2>>& spots) {
    check_box(slope, box);
    std::vector<double> volumes;
    std::vector<double> longest;
    for (std::size_t i = 0; i < half_extents.size(); ++i) {
        const Vec3& h = half_extents[i];
        if (!(h.allFinite() && h.minCoeff() > 0.0)) {
            throw std::invalid_argument("half extents of rock " + std::to_string(i) + " = (" +
                                        number(h.x()) + ", " + number(h.y()) + ", " +
                                        number(h.z()) + ") m: must be finite and > 0");
        }
        const double across = std::min(h.x(), h.y());
        if (2.0 * std::max(h.x(), h.y()) > std::max(box.length, box.width) ||
            2.0 * across > std::min(box.length, box.width) || 2.0 * h.z() > box.height) {
            throw PackingError("rock " + std::to_string(i) + ": lying flat it does not fit the " +
                                   "release box in any of its two orientations (" +
                                   number(2.0 * h.x()) + " x " + number(2.0 * h.y()) + " x " +
                                   number(2.0 * h.z()) + " m)",
                               0, 8.0 * h.prod());
        }
        volumes.push_back(8.0 * h.prod());
        longest.push_back(h.maxCoeff());
    }
    HeightMap map(box.length, box.width);
    const double half_width = 0.5 * box.width;
    std::vector<Vec3> local(half_extents.size(), Vec3::Zero());
    std::vector<Eigen::Matrix3d> turn(half_extents.size(), Eigen::Matrix3d::Identity());
    std::size_t placed = 0;
    double placed_volume = 0.0;
    double top = 0.0;
    for (const std::size_t index : spots_last(drop_order(longest, box.order, generator), spots)) {
        const Vec3& h = half_extents[index];
        Vec3 best(0.0, 0.0, std::numeric_limits<double>::infinity());
        bool across = false;
        const bool has_spot = !spots.empty() && spots[index];
        if (has_spot) {
            const Vec2& at = *spots[index];
            for (const bool turned : {false, true}) {
                const double hx = turned ? h.y() : h.x();
                const double hy = turned ? h.x() : h.y();
                const bool fits = at.x() >= hx && at.x() <= box.length - hx &&
                                  std::abs(at.y()) <= half_width - hy;
                if (fits && !std::isfinite(best.z())) {
                    best = Vec3(
                        at.x(), at.y(),
                        map.highest(at.x() - hx, at.x() + hx, at.y() - hy, at.y() + hy) + h.z());
                    across = turned;
                }
            }
            if (!std::isfinite(best.z())) {
                throw std::invalid_argument("rock " + std::to_string(index) +
                                            ": lying flat at its spot (" + number(at.x()) + ", " +
                                            number(at.y()) + ") m it crosses a wall of the box");
            }
        }
        for (int k = 0; k < packing_candidates && !has_spot; ++k) {
            const double u = uniform01(generator);
            const double v = uniform01(generator);
            // The rock's long axis along the slope, then across it; the lower rest wins.
            for (const bool turned : {false, true}) {
                const double hx = turned ? h.y() : h.x();
                const double hy = turned ? h.x() : h.y();
                if (2.0 * hx > box.length || 2.0 * hy > box.width) {
                    continue;
                }
                const double x = hx + u * (box.length - 2.0 * hx);
                const double y = -half_width + hy + v * (box.width - 2.0 * hy);
                const double z = map.highest(x - hx, x + hx, y - hy, y + hy) + h.z();
                if (z < best.z() || (z == best.z() && x < best.x())) {
                    best = Vec3(x, y, z);
                    across = turned;
                }
            }
        }
        if (best.z() + h.z() > box.height) {
            throw_full(box, placed, volumes, placed_volume, top, "bounding boxes");
        }
        const double hx = across ? h.y() : h.x();
        const double hy = across ? h.x() : h.y();
        map.raise(best.x() - hx, best.x() + hx, best.y() - hy, best.y() + hy,
                  best.z() + h.z() + kClearance);
        ++placed;
        placed_volume += volumes[index];
        top = std::max(top, best.z() + h.z());
        local[index] = best;
        // A quarter turn about the normal puts the body's x across the slope.
        Eigen::Matrix3d yaw = Eigen::Matrix3d::Identity();
        if (across) {
            yaw << 0, -1, 0, 1, 0, 0, 0, 0, 1;
        }
        turn[index] = yaw * flip(static_cast<int>(uniform01(generator) * 4.0) % 4);
    }
    const detail::SegmentPlane plane = detail::segment_plane(slope, 0);
    Eigen::Matrix3d frame;
    frame.col(0) = plane.tangent;
    frame.col(1) = Vec3::UnitY();
    frame.col(2) = plane.normal;
    std::vector<RockPose> poses;
    poses.reserve(half_extents.size());
    for (std::size_t i = 0; i < half_extents.size(); ++i) {
        poses.push_back({to_slope(plane, box, local[i]), frame * turn[i]});
    }
    return poses;
}

}  // namespace rockfall::shapes
