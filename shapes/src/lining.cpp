#include "shapes/lining.hpp"

#include "lining_frame.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rockfall::shapes {
namespace {

// Spheres on a hexagonal lattice over each lined segment: radius `radius`, centre `lift`
// above the surface, footprint radius `footprint` kept on the segment and between the walls.
std::vector<Sphere> lattice_spheres(const Slope& slope, const std::vector<int>& segments,
                                    double radius, double lift, double footprint, double spacing,
                                    std::string_view what) {
    std::vector<Sphere> spheres;
    // In profile order, so that the segment above a kink is laid first.
    std::vector<int> ordered = segments;
    std::sort(ordered.begin(), ordered.end());
    for (const int index : ordered) {
        const detail::SegmentPlane plane = detail::segment_plane(slope, index);
        // Spheres already laid on the segment above, which a concave kink can overlap.
        std::vector<Sphere> upper;
        // Distance from the kink line (along y through the segment's upper end).
        const double near = 2.0 * (radius + spacing) + std::abs(lift);
        for (const Sphere& sphere : spheres) {
            Vec3 offset = sphere.center - plane.origin;
            offset.y() = 0.0;
            if (sphere.segment == index - 1 && offset.norm() < near) {
                upper.push_back(sphere);
            }
        }
        const std::vector<double> rows = detail::centred_rows(footprint, plane.length - footprint,
                                                              detail::hex_row_spacing(spacing));
        for (std::size_t k = 0; k < rows.size(); ++k) {
            for (const double v : detail::hex_row_sites(static_cast<int>(k), spacing,
                                                        plane.half_width - footprint)) {
                const Sphere sphere{plane.point(rows[k], v, lift), radius, index};
                bool clear = true;
                for (const Sphere& other : upper) {
                    const double gap =
                        (sphere.center - other.center).norm() - (sphere.radius + other.radius);
                    clear = clear && gap >= -1e-12;
                }
                if (clear) {
                    spheres.push_back(sphere);
                }
                if (spheres.size() > max_lining_spheres) {
                    throw std::invalid_argument(std::string(what) + " has more than " +
                                                std::to_string(max_lining_spheres) +
                                                " spheres: use a larger spacing");
                }
            }
        }
    }
    return spheres;
}

}  // namespace

std::vector<Sphere> sphere_layer(const Slope& slope, const SphereLayer& layer) {
    detail::check_range("sphere_layer.radius", layer.radius, "m", 1e-3, 0.5);
    detail::check_range("sphere_layer.spacing", layer.spacing, "m", 2.0 * layer.radius,
                        10.0 * layer.radius);
    detail::check_segments(slope, layer.segments, "sphere_layer.segments");
    return lattice_spheres(slope, layer.segments, layer.radius, layer.radius, layer.radius,
                           layer.spacing, "sphere_layer");
}

std::vector<Sphere> bump_spheres(const Slope& slope, const Bumps& bumps) {
    detail::check_range("bumps.base_diameter", bumps.base_diameter, "m", 2e-3, 1.0);
    detail::check_range("bumps.height", bumps.height, "m", 1e-3, 0.5 * bumps.base_diameter);
    detail::check_range("bumps.spacing", bumps.spacing, "m", bumps.base_diameter,
                        10.0 * bumps.base_diameter);
    detail::check_segments(slope, bumps.segments, "bumps.segments");
    // A cap of height h over a circle of radius a is cut from a sphere of radius
    // (a^2 + h^2) / (2 h) (intersecting chords).
    const double a = 0.5 * bumps.base_diameter;
    const double h = bumps.height;
    const double radius = (a * a + h * h) / (2.0 * h);
    return lattice_spheres(slope, bumps.segments, radius, h - radius, a, bumps.spacing, "bumps");
}

std::vector<Sphere> lining_spheres(const Slope& slope, const Lining& lining) {
    std::vector<Sphere> out;
    if (lining.spheres) out = sphere_layer(slope, *lining.spheres);
    if (lining.bumps) {
        const std::vector<Sphere> bumps = bump_spheres(slope, *lining.bumps);
        out.insert(out.end(), bumps.begin(), bumps.end());
    }
    return out;
}

}  // namespace rockfall::shapes
