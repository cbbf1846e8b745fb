#include "lining_frame.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rockfall::shapes::detail {
namespace {

// A row that ends within this of the end of its interval still counts as fitting.
constexpr double kFitTolerance = 1e-9;

}  // namespace

SegmentPlane segment_plane(const Slope& slope, int index) {
    const auto i = static_cast<std::size_t>(index);
    const Eigen::Vector2d& upper = slope.profile()[i];
    const Eigen::Vector2d& lower = slope.profile()[i + 1];
    // The tangent and normal of the segment under its middle (segment_at of the kink itself
    // belongs to the lower segment).
    const double middle = 0.5 * (upper.x() + lower.x());
    SegmentPlane plane;
    plane.origin = Vec3(upper.x(), 0.0, upper.y());
    plane.tangent = slope.surface_tangent(middle);
    plane.normal = slope.surface_normal(middle);
    plane.length = slope.spec().segments[i].length;
    plane.half_width = 0.5 * slope.spec().width;
    plane.index = index;
    return plane;
}

void check_range(std::string_view field, double value, std::string_view unit, double lo,
                 double hi) {
    if (std::isfinite(value) && value >= lo && value <= hi) {
        return;
    }
    std::ostringstream message;
    message << field << " = " << value << (unit.empty() ? "" : " ") << unit << ": must be in ["
            << lo << ", " << hi << "]" << (unit.empty() ? "" : " ") << unit;
    throw std::invalid_argument(message.str());
}

void check_segments(const Slope& slope, const std::vector<int>& segments, std::string_view field) {
    const int count = static_cast<int>(slope.spec().segments.size());
    for (std::size_t k = 0; k < segments.size(); ++k) {
        const int index = segments[k];
        const std::string name = std::string(field) + "[" + std::to_string(k) + "]";
        if (index < 0 || index >= count) {
            throw std::invalid_argument(name + " = " + std::to_string(index) +
                                        ": must be a segment index in [0, " +
                                        std::to_string(count - 1) + "]");
        }
        if (std::find(segments.begin(), segments.begin() + static_cast<std::ptrdiff_t>(k), index) !=
            segments.begin() + static_cast<std::ptrdiff_t>(k)) {
            throw std::invalid_argument(name + " = " + std::to_string(index) +
                                        ": segment listed twice");
        }
    }
}

std::vector<double> centred_rows(double lo, double hi, double step) {
    std::vector<double> rows;
    if (hi < lo) {
        return rows;
    }
    const int count = static_cast<int>(std::floor((hi - lo) / step + kFitTolerance)) + 1;
    const double margin = 0.5 * ((hi - lo) - (count - 1) * step);
    rows.reserve(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) {
        rows.push_back(lo + margin + k * step);
    }
    return rows;
}

double hex_row_spacing(double spacing) { return spacing * std::sqrt(3.0) / 2.0; }

std::vector<double> hex_row_sites(int row, double spacing, double limit) {
    const double shift = row % 2 == 0 ? 0.0 : 0.5;
    std::vector<double> sites;
    const int last = static_cast<int>(std::floor(limit / spacing - shift + kFitTolerance));
    for (int j = -last - 1; j <= last; ++j) {
        const double v = (j + shift) * spacing;
        if (std::abs(v) <= limit + kFitTolerance * spacing) {
            sites.push_back(v);
        }
    }
    return sites;
}

}  // namespace rockfall::shapes::detail
