#pragma once
// Block-sparse background grid and the per-node boundary rules (private to the solver).

#include "mpm/boundary.hpp"
#include "mpm/math.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace rockfall::mpm::detail {

// Integer power for block sizes.
constexpr int power(int base, int exponent) {
    return exponent == 0 ? 1 : base * power(base, exponent - 1);
}

// Grid storage blocks are 4 nodes per axis. Particles are grouped in particle blocks of 2 base
// nodes per axis: particle block b writes nodes [2b, 2b + 3] on each axis (one or two storage
// blocks), so particle blocks of the same parity (colour) never write the same node.
inline constexpr int kBlockEdge = 4;
inline constexpr int kParticleBlockEdge = 2;
inline constexpr int kLocalEdge = kParticleBlockEdge + 2;

template <int Dim>
inline constexpr int kBlockNodes = power(kBlockEdge, Dim);
template <int Dim>
inline constexpr int kLocalNodes = power(kLocalEdge, Dim);
template <int Dim>
inline constexpr int kColours = power(2, Dim);

// A grid node: momentum (velocity after the grid update) then mass.
template <int Dim>
using Node = Eigen::Matrix<double, Dim + 1, 1>;

// One boundary acting on a node: the outward normal of the solid and which solid it is.
template <int Dim>
struct NodeConstraint {
    Vec<Dim> normal = Vec<Dim>::Zero();
    int boundary = -1;
};

// The static boundaries acting on one node, one per group, in increasing group order.
template <int Dim>
struct NodeRule {
    std::array<NodeConstraint<Dim>, kBoundaryGroups> constraints{};
    int count = 0;
};

// Axis-aligned bounds of a box, for cheap rejection before the signed distance.
struct Bounds {
    Vec3 lo;
    Vec3 hi;
    bool contains(const Vec3& p, double margin) const {
        return (p.array() >= lo.array() - margin).all() && (p.array() <= hi.array() + margin).all();
    }
};

Bounds bounds_of(const shapes::OrientedBox& box);

// The rule of a node at scene position x: per group the solid it is deepest in (signed
// distance <= reach, m). Returns count 0 when the node is in no solid.
template <int Dim>
NodeRule<Dim> classify_node(const Vec3& x, const std::vector<StaticBoundary>& statics,
                            const std::vector<Bounds>& bounds, double reach);

// Coulomb friction in velocity form relative to a solid moving at v_solid (see boundary.hpp).
template <int Dim>
inline void apply_boundary(Vec<Dim>& v, const Vec<Dim>& normal, const Vec<Dim>& v_solid,
                           BoundaryKind kind, double friction_coefficient) {
    if (kind == BoundaryKind::fixed) {
        v = v_solid;
        return;
    }
    const Vec<Dim> relative = v - v_solid;
    const double vn = relative.dot(normal);
    if (vn >= 0.0) {
        return;
    }
    const Vec<Dim> tangential = relative - vn * normal;
    const double vt = tangential.norm();
    // The tangential change is bounded by mu times the normal change (-vn).
    if (vt <= -friction_coefficient * vn) {
        v = v_solid;
    } else {
        v = v_solid + tangential * (1.0 + friction_coefficient * vn / vt);
    }
}

// Block-sparse grid: a dense table of 4^Dim-node blocks over the domain (one spare block per
// axis so that a particle block's second node block always exists); node storage is
// allocated per block on first touch and kept.
template <int Dim>
struct BlockGrid {
    Vec<Dim> origin = Vec<Dim>::Zero();
    double h = 1.0;
    IVec<Dim> nodes = IVec<Dim>::Zero();
    IVec<Dim> blocks = IVec<Dim>::Zero();
    std::vector<std::int32_t> slot_of_block;
    std::vector<IVec<Dim>> block_of_slot;
    std::vector<Node<Dim>> data;
    // With SolverSettings::flip > 0, per node the velocity before the step's forces (first the
    // force impulse scattered by the particles), as `data`; empty otherwise.
    std::vector<Node<Dim>> old_velocity;
    bool keep_old_velocity = false;
    std::vector<std::int32_t> rule_of_node;
    std::vector<NodeRule<Dim>> rules;
    // Signed distance up to which a node counts as inside a solid, m (SolverSettings).
    double boundary_reach = 0.0;

    BlockGrid(const Vec<Dim>& domain_min, double cell, const IVec<Dim>& node_count, double reach);

    int block_count() const { return static_cast<int>(slot_of_block.size()); }
    int block_id(const IVec<Dim>& b) const {
        int id = b[Dim - 1];
        for (int d = Dim - 2; d >= 0; --d) {
            id = id * blocks[d] + b[d];
        }
        return id;
    }
    // Slot of a block, allocating it (and classifying its nodes) on first use.
    int ensure_slot(int id, const std::vector<StaticBoundary>& statics,
                    const std::vector<Bounds>& bounds);
    Vec<Dim> node_position(const IVec<Dim>& node) const {
        return origin + h * node.template cast<double>();
    }
};

// Index of a node inside its block from its local coordinates in [0, 4).
template <int Dim>
inline int block_local_index(const IVec<Dim>& l) {
    int index = l[0];
    for (int d = 1; d < Dim; ++d) {
        index = index * kBlockEdge + l[d];
    }
    return index;
}

}  // namespace rockfall::mpm::detail
