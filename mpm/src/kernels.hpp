#pragma once
// Per-particle transfer kernels (quadratic B-splines, MLS-MPM / APIC) and per-node boundary
// helpers; private to the solver, inlined into its phase loops.

#include "grid.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace rockfall::mpm::detail {

// Grid origin and cell size, as the kernels see them.
template <int Dim>
struct KernelFrame {
    Vec<Dim> origin;
    double h;
};

// Quadratic B-spline stencil of a particle: base node, fractional offset fx = x/h - base in
// [0.5, 1.5) and the three weights per axis (Steffen et al. 2008; Hu et al. 2018, eq. 5 ff.).
template <int Dim>
struct Stencil {
    IVec<Dim> base;
    Vec<Dim> fx;
    std::array<std::array<double, 3>, Dim> w;
};

template <int Dim>
inline Stencil<Dim> make_stencil(const KernelFrame<Dim>& frame, const Vec<Dim>& x) {
    Stencil<Dim> s;
    for (int d = 0; d < Dim; ++d) {
        const double xl = (x[d] - frame.origin[d]) / frame.h;
        s.base[d] = static_cast<int>(std::floor(xl - 0.5));
        const double f = xl - s.base[d];
        s.fx[d] = f;
        s.w[static_cast<std::size_t>(d)] = {
            0.5 * (1.5 - f) * (1.5 - f), 0.75 - (f - 1.0) * (f - 1.0), 0.5 * (f - 0.5) * (f - 0.5)};
    }
    return s;
}

// Local coordinates in [0, 4) of the j-th node of a block (last axis fastest).
template <int Dim>
inline IVec<Dim> block_local_coords(int j) {
    IVec<Dim> l;
    for (int d = Dim - 1; d >= 0; --d) {
        l[d] = j % kBlockEdge;
        j /= kBlockEdge;
    }
    return l;
}

// Adds one particle's mass and momentum to the 6^Dim local buffer of its particle block:
// w_ip [m v + Q (x_i - x_p); m] with Q = m C - dt V D^-1 sigma, D^-1 = 4/h^2 (Hu et al. 2018,
// eq. 29). The affine term is advanced incrementally along each axis.
template <int Dim>
inline void scatter_particle(const KernelFrame<Dim>& frame, const IVec<Dim>& first_node, double dt,
                             const Vec<Dim>& x, const Vec<Dim>& v, const Mat<Dim>& c,
                             const Mat3& stress, double m, double volume,
                             std::array<Node<Dim>, kLocalNodes<Dim>>& local) {
    const Stencil<Dim> s = make_stencil(frame, x);
    const double h = frame.h;
    const Mat<Dim> q =
        m * c - (dt * volume * 4.0 / (h * h)) * stress.template topLeftCorner<Dim, Dim>();
    Node<Dim> q0;
    q0.template head<Dim>() = m * v - h * (q * s.fx);
    q0[Dim] = m;
    std::array<Node<Dim>, Dim> step;
    for (int d = 0; d < Dim; ++d) {
        step[static_cast<std::size_t>(d)].template head<Dim>() = h * q.col(d);
        step[static_cast<std::size_t>(d)][Dim] = 0.0;
    }
    const IVec<Dim> l = s.base - first_node;
    const auto& w = s.w;
    if constexpr (Dim == 2) {
        for (int i = 0; i < 3; ++i) {
            const Node<2> qi = q0 + i * step[0];
            for (int j = 0; j < 3; ++j) {
                const int index = (l[0] + i) * kLocalEdge + (l[1] + j);
                local[static_cast<std::size_t>(index)] += (w[0][i] * w[1][j]) * (qi + j * step[1]);
            }
        }
    } else {
        for (int i = 0; i < 3; ++i) {
            const Node<3> qi = q0 + i * step[0];
            for (int j = 0; j < 3; ++j) {
                const Node<3> qij = qi + j * step[1];
                const double wij = w[0][i] * w[1][j];
                const int row = ((l[0] + i) * kLocalEdge + (l[1] + j)) * kLocalEdge + l[2];
                for (int k = 0; k < 3; ++k) {
                    local[static_cast<std::size_t>(row + k)] +=
                        (wij * w[2][k]) * (qij + k * step[2]);
                }
            }
        }
    }
}

// Calls f(local_index, slot_index, block_node_index) for every node of a particle block's 6^Dim
// local buffer, visiting the 2^Dim node blocks it spans.
template <int Dim, typename F>
inline void for_each_local_node(const std::array<std::int32_t, kColours<Dim>>& slots, F&& f) {
    for (int o = 0; o < kColours<Dim>; ++o) {
        IVec<Dim> from;
        IVec<Dim> to;
        for (int d = 0; d < Dim; ++d) {
            const bool second = ((o >> d) & 1) != 0;
            from[d] = second ? kBlockEdge : 0;
            to[d] = second ? kLocalEdge : kBlockEdge;
        }
        const std::size_t base =
            static_cast<std::size_t>(slots[static_cast<std::size_t>(o)]) * kBlockNodes<Dim>;
        if constexpr (Dim == 2) {
            for (int a = from[0]; a < to[0]; ++a) {
                for (int b = from[1]; b < to[1]; ++b) {
                    f(a * kLocalEdge + b,
                      base +
                          static_cast<std::size_t>((a % kBlockEdge) * kBlockEdge + b % kBlockEdge));
                }
            }
        } else {
            for (int a = from[0]; a < to[0]; ++a) {
                for (int b = from[1]; b < to[1]; ++b) {
                    for (int c = from[2]; c < to[2]; ++c) {
                        f((a * kLocalEdge + b) * kLocalEdge + c,
                          base + static_cast<std::size_t>(
                                     ((a % kBlockEdge) * kBlockEdge + b % kBlockEdge) * kBlockEdge +
                                     c % kBlockEdge));
                    }
                }
            }
        }
    }
}

// Adds a particle block's local buffer to the grid (its node blocks are exclusive to it within
// one colour).
template <int Dim>
inline void add_local_to_grid(const std::array<Node<Dim>, kLocalNodes<Dim>>& local,
                              const std::array<std::int32_t, kColours<Dim>>& slots,
                              std::vector<Node<Dim>>& data) {
    for_each_local_node<Dim>(
        slots, [&](int l, std::size_t g) { data[g] += local[static_cast<std::size_t>(l)]; });
}

// Copies the grid velocities a particle block reads into its local buffer.
template <int Dim>
inline void gather_local_velocities(const std::vector<Node<Dim>>& data,
                                    const std::array<std::int32_t, kColours<Dim>>& slots,
                                    std::array<Vec<Dim>, kLocalNodes<Dim>>& local) {
    for_each_local_node<Dim>(slots, [&](int l, std::size_t g) {
        local[static_cast<std::size_t>(l)] = data[g].template head<Dim>();
    });
}

// APIC / MLS-MPM G2P: v_p = sum w v_i, C_p = D^-1 sum w v_i (x_i - x_p)^T
// = (4/h) (sum w v_i s^T - v_p fx^T) with s the integer node offset (Jiang et al. 2015, eq. 10;
// Hu et al. 2018, eq. 17).
template <int Dim>
inline void gather_particle(const KernelFrame<Dim>& frame, const IVec<Dim>& first_node,
                            const std::array<Vec<Dim>, kLocalNodes<Dim>>& local, const Vec<Dim>& x,
                            Vec<Dim>& v, Mat<Dim>& c) {
    const Stencil<Dim> s = make_stencil(frame, x);
    const IVec<Dim> l = s.base - first_node;
    const auto& w = s.w;
    Vec<Dim> sum = Vec<Dim>::Zero();
    Mat<Dim> moment = Mat<Dim>::Zero();
    if constexpr (Dim == 2) {
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                const int index = (l[0] + i) * kLocalEdge + (l[1] + j);
                const Vec<2> t = (w[0][i] * w[1][j]) * local[static_cast<std::size_t>(index)];
                sum += t;
                moment.col(0) += i * t;
                moment.col(1) += j * t;
            }
        }
    } else {
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                const double wij = w[0][i] * w[1][j];
                const int row = ((l[0] + i) * kLocalEdge + (l[1] + j)) * kLocalEdge + l[2];
                for (int k = 0; k < 3; ++k) {
                    const Vec<3> t = (wij * w[2][k]) * local[static_cast<std::size_t>(row + k)];
                    sum += t;
                    moment.col(0) += i * t;
                    moment.col(1) += j * t;
                    moment.col(2) += k * t;
                }
            }
        }
    }
    v = sum;
    c = (4.0 / frame.h) * (moment - sum * s.fx.transpose());
}

// Slip walls on the outer two node layers of the domain: no velocity out of the domain.
template <int Dim>
inline void apply_domain_faces(const IVec<Dim>& index, const IVec<Dim>& nodes, Vec<Dim>& v) {
    for (int d = 0; d < Dim; ++d) {
        if ((index[d] < 2 && v[d] < 0.0) || (index[d] > nodes[d] - 3 && v[d] > 0.0)) {
            v[d] = 0.0;
        }
    }
}

// A hinged body on a node at scene position x: the deepest of its boxes acts, moving with the
// body's rotation about the hinge (axis +y). Returns whether the node is inside the body.
template <int Dim>
inline bool apply_hinged(const std::vector<shapes::OrientedBox>& boxes, const Bounds& bounds,
                         const Vec3& hinge, double angular_velocity, BoundaryKind kind,
                         double friction_coefficient, const Vec3& x, Vec<Dim>& v) {
    if (!bounds.contains(x, 1e-12)) {
        return false;
    }
    double depth = 0.0;
    Vec3 normal = Vec3::Zero();
    bool inside = false;
    for (const auto& box : boxes) {
        Vec3 n;
        const double distance = shapes::signed_distance(box, x, &n);
        if (distance <= 0.0 && (!inside || distance < depth)) {
            Vec<Dim> in_plane = from_scene<Dim>(n);
            if (in_plane.norm() < 1e-6) {
                continue;
            }
            inside = true;
            depth = distance;
            normal = n;
        }
    }
    if (!inside) {
        return false;
    }
    const Vec3 r = x - hinge;
    const Vec3 v_solid = angular_velocity * Vec3(r.z(), 0.0, -r.x());
    const Vec<Dim> n = from_scene<Dim>(normal).normalized();
    apply_boundary<Dim>(v, n, from_scene<Dim>(v_solid), kind, friction_coefficient);
    return true;
}

}  // namespace rockfall::mpm::detail
