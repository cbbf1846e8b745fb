#include "mpm/setup.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace rockfall::mpm {

template <int Dim>
int add_box_particles(Particles<Dim>& particles, const shapes::OrientedBox& box, double spacing,
                      double density) {
    assert(spacing > 0.0 && density > 0.0);
    // Local box axes spanned by the lattice: all three in 3D, x and z (the x-z plane) in 2D.
    constexpr std::array<int, Dim> axes = [] {
        if constexpr (Dim == 3) {
            return std::array<int, 3>{0, 1, 2};
        } else {
            return std::array<int, 2>{0, 2};
        }
    }();
    std::array<int, Dim> count{};
    std::array<double, Dim> step{};
    double volume = 1.0;
    for (int d = 0; d < Dim; ++d) {
        const double edge = 2.0 * box.half_extents[axes[static_cast<std::size_t>(d)]];
        count[static_cast<std::size_t>(d)] =
            std::max(1, static_cast<int>(std::lround(edge / spacing)));
        step[static_cast<std::size_t>(d)] = edge / count[static_cast<std::size_t>(d)];
        volume *= step[static_cast<std::size_t>(d)];
    }
    int added = 0;
    std::array<int, Dim> i{};
    const int total = [&] {
        int t = 1;
        for (const int c : count) {
            t *= c;
        }
        return t;
    }();
    for (int flat = 0; flat < total; ++flat) {
        int rest = flat;
        for (int d = Dim - 1; d >= 0; --d) {
            i[static_cast<std::size_t>(d)] = rest % count[static_cast<std::size_t>(d)];
            rest /= count[static_cast<std::size_t>(d)];
        }
        Vec3 local = Vec3::Zero();
        for (int d = 0; d < Dim; ++d) {
            const int axis = axes[static_cast<std::size_t>(d)];
            local[axis] = -box.half_extents[axis] + (i[static_cast<std::size_t>(d)] + 0.5) *
                                                        step[static_cast<std::size_t>(d)];
        }
        const Vec3 x = box.center + box.rotation * local;
        particles.add(from_scene<Dim>(x), volume, density);
        ++added;
    }
    return added;
}

template <int Dim>
void set_geostatic_stress(Particles<Dim>& particles, double surface_z, double g, double k0) {
    constexpr int vertical = Dim - 1;
    for (std::size_t p = 0; p < particles.size(); ++p) {
        const double rho = particles.mass[p] / particles.volume[p];
        const double depth = std::max(0.0, surface_z - particles.position[p][vertical]);
        const double sv = -rho * g * depth;
        Mat3 s = Mat3::Zero();
        s.diagonal().setConstant(k0 * sv);
        s(vertical, vertical) = sv;
        particles.stress[p] = s;
    }
}

template int add_box_particles<2>(Particles<2>&, const shapes::OrientedBox&, double, double);
template int add_box_particles<3>(Particles<3>&, const shapes::OrientedBox&, double, double);
template void set_geostatic_stress<2>(Particles<2>&, double, double, double);
template void set_geostatic_stress<3>(Particles<3>&, double, double, double);

}  // namespace rockfall::mpm
