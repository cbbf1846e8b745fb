#pragma once
// Per-particle transfer kernels (quadratic B-splines, MLS-MPM / APIC) and per-node boundary
// helpers; private to the solver, inlined into its phase loops.

#include "grid.hpp"

#include <array>
#include <cassert>
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
// The kernels below use plain arrays: Eigen's per-coefficient range asserts, which stay on in
// RelWithDebInfo, would cost about a fifth of the step.
// A particle block's nodes: its own scatter buffer, or the grid velocities it reads (each node
// is the grid's (momentum or velocity, mass), so a 3D node is one packed 4-vector).
template <int Dim>
using LocalNodes = std::array<Node<Dim>, kLocalNodes<Dim>>;

// First of the three stencil nodes along an axis, floor(cells - 0.5) for a position of `cells`
// cell sizes from the grid origin. bin_particles keeps every particle at cells >= 1, where
// truncation is the floor: std::floor is a library call on the baseline x86-64 instruction set
// (SSE2) and cost about 5 % of a step (callgrind, seed soil flow).
inline int stencil_base(double cells) {
    assert(cells >= 0.5);
    return static_cast<int>(cells - 0.5);
}

// The dual cell of a particle within its particle block, 0 .. 2^Dim - 1: bit d set when its
// stencil starts at the block's second base node along axis d.
template <int Dim>
inline int dual_cell(const KernelFrame<Dim>& frame, const IVec<Dim>& first_node,
                     const Vec<Dim>& x) {
    // The same arithmetic as the binning and the stencil (times 1 / h, not divided by h), so
    // that a particle on a cell boundary falls on the same side in all three.
    const double inverse_h = 1.0 / frame.h;
    int cell = 0;
    for (int d = 0; d < Dim; ++d) {
        const int base = stencil_base((x[d] - frame.origin[d]) * inverse_h);
        assert(base - first_node[d] == 0 || base - first_node[d] == 1);
        cell |= (base - first_node[d]) << d;
    }
    return cell;
}

template <int Dim>
struct Stencil {
    int base[Dim];
    double fx[Dim];
    double w[Dim][3];
};

template <int Dim>
inline Stencil<Dim> make_stencil(const KernelFrame<Dim>& frame, const Vec<Dim>& x) {
    Stencil<Dim> s;
    const double* xp = x.data();
    const double* origin = frame.origin.data();
    const double inverse_h = 1.0 / frame.h;
    for (int d = 0; d < Dim; ++d) {
        const double xl = (xp[d] - origin[d]) * inverse_h;
        s.base[d] = stencil_base(xl);
        const double f = xl - s.base[d];
        s.fx[d] = f;
        s.w[d][0] = 0.5 * (1.5 - f) * (1.5 - f);
        s.w[d][1] = 0.75 - (f - 1.0) * (f - 1.0);
        s.w[d][2] = 0.5 * (f - 0.5) * (f - 0.5);
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

// Adds one particle's mass and momentum to the 4^Dim buffer of its particle block:
// w_ip [m v + Q (x_i - x_p); m] with Q = m C - dt V D^-1 sigma, D^-1 = 4/h^2 (Hu et al. 2018,
// eq. 29). With x_i - x_p = h (s - fx) for the integer node offset s, the bracket is
// q0 + h Q s, advanced incrementally along each axis.
// With kForces (the FLIP update, SolverSettings::flip) the stress part alone,
// -w_ip dt V D^-1 sigma (x_i - x_p), is added to the `forces` buffer as well (mass lane 0); a
// template flag, so that the APIC path carries no test in its loops.
template <int Dim, bool kForces = false>
inline void scatter_particle(const KernelFrame<Dim>& frame, const IVec<Dim>& first_node, double dt,
                             const Vec<Dim>& x, const Vec<Dim>& v, const Mat<Dim>& c,
                             const Mat3& stress, double m, double volume, LocalNodes<Dim>& local,
                             LocalNodes<Dim>* forces = nullptr) {
    constexpr int N = Dim + 1;
    const Stencil<Dim> s = make_stencil(frame, x);
    const double h = frame.h;
    const double force = dt * volume * 4.0 / (h * h);
    const double* cm = c.data();
    const double* sigma = stress.data();
    const double* vp = v.data();
    // step[d][r] = h Q(r, d) (column-major storage of C and sigma).
    double step[Dim][N];
    for (int d = 0; d < Dim; ++d) {
        for (int r = 0; r < Dim; ++r) {
            step[d][r] = h * (m * cm[r + Dim * d] - force * sigma[r + 3 * d]);
        }
        step[d][Dim] = 0.0;
    }
    double q0[N];
    for (int r = 0; r < Dim; ++r) {
        q0[r] = m * vp[r];
        for (int d = 0; d < Dim; ++d) {
            q0[r] -= step[d][r] * s.fx[d];
        }
    }
    q0[Dim] = m;
    // The same bracket for the stress part only.
    double force_step[Dim][N];
    double force_q0[N];
    for (int d = 0; d < Dim; ++d) {
        for (int r = 0; r < Dim; ++r) {
            force_step[d][r] = -h * force * sigma[r + 3 * d];
        }
        force_step[d][Dim] = 0.0;
    }
    for (int r = 0; r < Dim; ++r) {
        force_q0[r] = 0.0;
        for (int d = 0; d < Dim; ++d) {
            force_q0[r] -= force_step[d][r] * s.fx[d];
        }
    }
    force_q0[Dim] = 0.0;
    double* force_out = forces ? (*forces)[0].data() : nullptr;
    int l[Dim];
    const int* first = first_node.data();
    for (int d = 0; d < Dim; ++d) {
        l[d] = s.base[d] - first[d];
    }
    double* out = local[0].data();
    if constexpr (Dim == 2) {
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                const double wij = s.w[0][i] * s.w[1][j];
                const int offset = N * ((l[0] + i) * kLocalEdge + (l[1] + j));
                double* node = out + offset;
                for (int r = 0; r < N; ++r) {
                    node[r] += wij * (q0[r] + i * step[0][r] + j * step[1][r]);
                }
                if constexpr (kForces) {
                    for (int r = 0; r < Dim; ++r) {
                        force_out[offset + r] +=
                            wij * (force_q0[r] + i * force_step[0][r] + j * force_step[1][r]);
                    }
                }
            }
        }
    } else {
        // Packed 4-vectors (momentum, mass): Eigen emits SIMD pairs where the scalar loop
        // stays scalar; maps carry no per-coefficient checks.
        using Packed = Eigen::Vector4d;
        const Eigen::Map<const Packed> base(q0);
        const Eigen::Map<const Packed> along_i(step[0]);
        const Eigen::Map<const Packed> along_j(step[1]);
        const Eigen::Map<const Packed> along_k(step[2]);
        const Eigen::Map<const Packed> force_base(force_q0);
        const Eigen::Map<const Packed> force_i(force_step[0]);
        const Eigen::Map<const Packed> force_j(force_step[1]);
        const Eigen::Map<const Packed> force_k(force_step[2]);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                const Packed qij = base + i * along_i + j * along_j;
                const double wij = s.w[0][i] * s.w[1][j];
                const int offset = N * (((l[0] + i) * kLocalEdge + (l[1] + j)) * kLocalEdge + l[2]);
                double* node = out + offset;
                Eigen::Map<Packed, Eigen::Aligned16>(node) += (wij * s.w[2][0]) * qij;
                Eigen::Map<Packed, Eigen::Aligned16>(node + N) +=
                    (wij * s.w[2][1]) * (qij + along_k);
                Eigen::Map<Packed, Eigen::Aligned16>(node + 2 * N) +=
                    (wij * s.w[2][2]) * (qij + 2.0 * along_k);
                if constexpr (kForces) {
                    const Packed fij = force_base + i * force_i + j * force_j;
                    double* f = force_out + offset;
                    Eigen::Map<Packed, Eigen::Aligned16>(f) += (wij * s.w[2][0]) * fij;
                    Eigen::Map<Packed, Eigen::Aligned16>(f + N) +=
                        (wij * s.w[2][1]) * (fij + force_k);
                    Eigen::Map<Packed, Eigen::Aligned16>(f + 2 * N) +=
                        (wij * s.w[2][2]) * (fij + 2.0 * force_k);
                }
            }
        }
    }
}

// Calls f(local_index, grid_data_index) for every node of a particle block's local buffer.
// The buffer starts at node `first_node` (even); along each axis its 4 nodes fall in storage
// block first_node / 4 (offset 0) or the next (offset 1), whose slots are `slots` indexed by the
// offsets' bits.
template <int Dim, typename F>
inline void for_each_local_node(const IVec<Dim>& first_node,
                                const std::array<std::int32_t, kColours<Dim>>& slots, F&& f) {
    int offset[Dim][kLocalEdge];
    int index[Dim][kLocalEdge];
    for (int d = 0; d < Dim; ++d) {
        const int base_block = first_node[d] / kBlockEdge;
        for (int l = 0; l < kLocalEdge; ++l) {
            const int g = first_node[d] + l;
            offset[d][l] = g / kBlockEdge - base_block;
            index[d][l] = g % kBlockEdge;
        }
    }
    if constexpr (Dim == 2) {
        for (int a = 0; a < kLocalEdge; ++a) {
            for (int b = 0; b < kLocalEdge; ++b) {
                const int o = offset[0][a] | (offset[1][b] << 1);
                const auto slot = static_cast<std::size_t>(slots[static_cast<std::size_t>(o)]);
                f(a * kLocalEdge + b,
                  slot * kBlockNodes<2> +
                      static_cast<std::size_t>(index[0][a] * kBlockEdge + index[1][b]));
            }
        }
    } else {
        for (int a = 0; a < kLocalEdge; ++a) {
            for (int b = 0; b < kLocalEdge; ++b) {
                for (int c = 0; c < kLocalEdge; ++c) {
                    const int o = offset[0][a] | (offset[1][b] << 1) | (offset[2][c] << 2);
                    const auto slot = static_cast<std::size_t>(slots[static_cast<std::size_t>(o)]);
                    f((a * kLocalEdge + b) * kLocalEdge + c,
                      slot * kBlockNodes<3> +
                          static_cast<std::size_t>(
                              (index[0][a] * kBlockEdge + index[1][b]) * kBlockEdge + index[2][c]));
                }
            }
        }
    }
}

// Adds the part of a particle block's buffer that lies in one storage block to that block's
// nodes. Along each axis the buffer's nodes first_node + [0, 4) lie in storage block
// first_node / 4 (offset bit 0) or, when first_node is 2 mod 4, partly in the next (bit 1).
template <int Dim>
inline void add_buffer_part(const LocalNodes<Dim>& local, const IVec<Dim>& first_node,
                            int offset_bits, Node<Dim>* block_nodes) {
    // Buffer range [begin, end) along each axis and the storage index of buffer index 0.
    int begin[Dim];
    int end[Dim];
    int shift[Dim];
    for (int d = 0; d < Dim; ++d) {
        const int start = first_node[d] % kBlockEdge;
        if (((offset_bits >> d) & 1) == 0) {
            begin[d] = 0;
            end[d] = kBlockEdge - start;
            shift[d] = start;
        } else {
            begin[d] = kBlockEdge - start;
            end[d] = kLocalEdge;
            shift[d] = start - kBlockEdge;
        }
    }
    if constexpr (Dim == 2) {
        for (int a = begin[0]; a < end[0]; ++a) {
            for (int b = begin[1]; b < end[1]; ++b) {
                block_nodes[(a + shift[0]) * kBlockEdge + (b + shift[1])] +=
                    local[static_cast<std::size_t>(a * kLocalEdge + b)];
            }
        }
    } else {
        for (int a = begin[0]; a < end[0]; ++a) {
            for (int b = begin[1]; b < end[1]; ++b) {
                for (int c = begin[2]; c < end[2]; ++c) {
                    block_nodes[((a + shift[0]) * kBlockEdge + (b + shift[1])) * kBlockEdge +
                                (c + shift[2])] +=
                        local[static_cast<std::size_t>((a * kLocalEdge + b) * kLocalEdge + c)];
                }
            }
        }
    }
}

// Copies the grid nodes a particle block reads into its buffer.
template <int Dim>
inline void gather_local_nodes(const std::vector<Node<Dim>>& data, const IVec<Dim>& first_node,
                               const std::array<std::int32_t, kColours<Dim>>& slots,
                               LocalNodes<Dim>& local) {
    for_each_local_node<Dim>(first_node, slots, [&](int l, std::size_t g) {
        local[static_cast<std::size_t>(l)] = data[g];
    });
}

// APIC / MLS-MPM G2P: v_p = sum w v_i, C_p = D^-1 sum w v_i (x_i - x_p)^T
// = (4/h) (sum w v_i s^T - v_p fx^T) with s the integer node offset (Jiang et al. 2015, eq. 10;
// Hu et al. 2018, eq. 17). The sums are separable: innermost axis first. `local` holds the grid
// nodes (velocity, mass) after the grid update.
// With kOld (the grid velocities before the step's forces in `old`, SolverSettings::flip) it
// also returns sum w v_i_old in *old_velocity.
template <int Dim, bool kOld = false>
inline void gather_particle(const KernelFrame<Dim>& frame, const IVec<Dim>& first_node,
                            const LocalNodes<Dim>& local, const Vec<Dim>& x, Vec<Dim>& v,
                            Mat<Dim>& c, const LocalNodes<Dim>* old = nullptr,
                            Vec<Dim>* old_velocity = nullptr) {
    constexpr int N = Dim + 1;
    const Stencil<Dim> s = make_stencil(frame, x);
    int l[Dim];
    const int* first = first_node.data();
    for (int d = 0; d < Dim; ++d) {
        l[d] = s.base[d] - first[d];
    }
    const double* velocity = local[0].data();
    const double* old_nodes = old ? (*old)[0].data() : nullptr;
    double old_sum[Dim] = {};
    double sum[Dim] = {};
    double moment[Dim][Dim] = {};  // moment[d][r] = sum w v_r s_d
    const auto& w = s.w;
    if constexpr (Dim == 2) {
        for (int i = 0; i < 3; ++i) {
            double row_sum[2] = {};
            double row_j[2] = {};
            double row_old[2] = {};
            for (int j = 0; j < 3; ++j) {
                const int offset = N * ((l[0] + i) * kLocalEdge + (l[1] + j));
                const double* vi = velocity + offset;
                for (int r = 0; r < 2; ++r) {
                    row_sum[r] += w[1][j] * vi[r];
                    row_j[r] += (j * w[1][j]) * vi[r];
                }
                if constexpr (kOld) {
                    for (int r = 0; r < 2; ++r) {
                        row_old[r] += w[1][j] * old_nodes[offset + r];
                    }
                }
            }
            for (int r = 0; r < 2; ++r) {
                sum[r] += w[0][i] * row_sum[r];
                moment[0][r] += (i * w[0][i]) * row_sum[r];
                moment[1][r] += w[0][i] * row_j[r];
                old_sum[r] += w[0][i] * row_old[r];
            }
        }
    } else {
        // Packed 4-vectors (velocity, mass) as in scatter_particle: SSE2 pairs where scalar
        // code stays scalar. Each component is computed with the same operations in the same
        // order as a scalar loop, so the results are the same; the mass lane is not used.
        using Packed = Eigen::Vector4d;
        using Node4 = Eigen::Map<const Packed, Eigen::Aligned16>;
        Packed total = Packed::Zero();
        Packed along_i = Packed::Zero();
        Packed along_j = Packed::Zero();
        Packed along_k = Packed::Zero();
        Packed total_old = Packed::Zero();
        const double w_k2 = 2.0 * w[2][2];
        for (int i = 0; i < 3; ++i) {
            Packed row_sum = Packed::Zero();
            Packed row_j = Packed::Zero();
            Packed row_k = Packed::Zero();
            Packed row_old = Packed::Zero();
            for (int j = 0; j < 3; ++j) {
                const int offset = N * (((l[0] + i) * kLocalEdge + (l[1] + j)) * kLocalEdge + l[2]);
                const double* v0 = velocity + offset;
                const Node4 v1(v0 + N);
                const Node4 v2(v0 + 2 * N);
                const Packed a = w[2][0] * Node4(v0) + w[2][1] * v1 + w[2][2] * v2;
                const Packed b = w[2][1] * v1 + w_k2 * v2;
                row_sum += w[1][j] * a;
                row_j += (j * w[1][j]) * a;
                row_k += w[1][j] * b;
                if constexpr (kOld) {
                    const double* o = old_nodes + offset;
                    row_old += w[1][j] * (w[2][0] * Node4(o) + w[2][1] * Node4(o + N) +
                                          w[2][2] * Node4(o + 2 * N));
                }
            }
            total += w[0][i] * row_sum;
            along_i += (i * w[0][i]) * row_sum;
            along_j += w[0][i] * row_j;
            along_k += w[0][i] * row_k;
            total_old += w[0][i] * row_old;
        }
        for (int r = 0; r < 3; ++r) {
            old_sum[r] = total_old[r];
            sum[r] = total[r];
            moment[0][r] = along_i[r];
            moment[1][r] = along_j[r];
            moment[2][r] = along_k[r];
        }
    }
    const double scale = 4.0 / frame.h;
    double* vp = v.data();
    double* cp = c.data();
    if constexpr (kOld) {
        for (int r = 0; r < Dim; ++r) (*old_velocity)[r] = old_sum[r];
    }
    for (int r = 0; r < Dim; ++r) {
        vp[r] = sum[r];
        for (int d = 0; d < Dim; ++d) {
            cp[r + Dim * d] = scale * (moment[d][r] - sum[r] * s.fx[d]);
        }
    }
}

// Jaumann co-rotation sigma + dt (W sigma - sigma W) with W = skew(L); since W is skew and sigma
// symmetric, W sigma - sigma W = M + M^T with M = W sigma. Written out: small Eigen products are
// not inlined at -O2.
inline Mat3 corotate(const Mat3& sigma, const Mat3& l, double dt) {
    const double* g = l.data();
    const double* t = sigma.data();
    // Column-major: L(r, c) = g[r + 3c].
    const double a = 0.5 * (g[3] - g[1]);
    const double b = 0.5 * (g[6] - g[2]);
    const double c = 0.5 * (g[7] - g[5]);
    // W = [[0, a, b], [-a, 0, c], [-b, -c, 0]]; M = W sigma.
    double m[9];
    for (int col = 0; col < 3; ++col) {
        m[0 + 3 * col] = a * t[1 + 3 * col] + b * t[2 + 3 * col];
        m[1 + 3 * col] = -a * t[0 + 3 * col] + c * t[2 + 3 * col];
        m[2 + 3 * col] = -b * t[0 + 3 * col] - c * t[1 + 3 * col];
    }
    Mat3 out;
    double* o = out.data();
    for (int col = 0; col < 3; ++col) {
        for (int r = 0; r < 3; ++r) {
            o[r + 3 * col] = t[r + 3 * col] + dt * (m[r + 3 * col] + m[col + 3 * r]);
        }
    }
    return out;
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
// body's rotation about the hinge (axis +y). A node counts as inside within `reach` m of a
// box (as for static solids). Returns whether the node is inside the body.
template <int Dim>
inline bool apply_hinged(const std::vector<shapes::OrientedBox>& boxes, const Bounds& bounds,
                         const Vec3& hinge, double angular_velocity, BoundaryKind kind,
                         double friction_coefficient, double reach, const Vec3& x, Vec<Dim>& v) {
    if (!bounds.contains(x, reach + 1e-12)) {
        return false;
    }
    double depth = 0.0;
    Vec3 normal = Vec3::Zero();
    bool inside = false;
    for (const auto& box : boxes) {
        Vec3 n;
        const double distance = shapes::signed_distance(box, x, &n);
        if (distance <= reach && (!inside || distance < depth)) {
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
