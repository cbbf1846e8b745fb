#pragma once
// The solver's private state shared by its source files: the grid, the particle blocks and the
// per-step workspace.

#include "grid.hpp"
#include "kernels.hpp"

#include "mpm/solver.hpp"
#include "shapes/thread_pool.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace rockfall::mpm {

template <int Dim>
struct Solver<Dim>::Grid : detail::BlockGrid<Dim> {
    using detail::BlockGrid<Dim>::BlockGrid;
};

namespace detail {

// A non-empty particle block: the first node it writes (2 b per axis), its range in the sorted
// order and the slots of the storage blocks it writes (by per-axis offset bits; -1 unused).
template <int Dim>
struct ParticleBlock {
    IVec<Dim> first_node;
    int begin;
    int end;
    // Size of the active-slot list before this block's node blocks were added, and index of
    // its first chunk.
    std::int32_t first_active = 0;
    std::int32_t first_chunk = 0;
    std::array<std::int32_t, detail::kColours<Dim>> slots;
};

// Particles [begin, end) of the sorted order, all in particle block `block`: the tasks of the
// grid-to-particles phase, smaller than blocks so that the threads finish together.
struct ParticleChunk {
    std::int32_t block;
    std::int32_t begin;
    std::int32_t end;
};

// Consecutive particles [first, first + count) with the same particle block `key`, and where
// the first of them goes in the sorted order.
struct KeyRun {
    std::int32_t key;
    std::int32_t first;
    std::int32_t count;
    std::int32_t destination;
};

// A particle block's buffer overlapping a storage block: which particle block, and which of
// its storage blocks (offset bits, as ParticleBlock::slots).
struct Contribution {
    std::int32_t block;
    std::int32_t offset_bits;
};

// Current placement of a hinged body, computed once per step.
struct PlacedBody {
    std::vector<shapes::OrientedBox> boxes;
    detail::Bounds bounds;
    Vec3 hinge;
    double angular_velocity;
};

}  // namespace detail

template <int Dim>
struct Solver<Dim>::Workspace {
    IVec<Dim> particle_blocks;
    std::vector<std::int32_t> key;
    std::vector<std::int32_t> order;
    // Per particle block id: its particle count, then the next free place in `order`; zero
    // between steps.
    std::vector<std::int32_t> block_cursor;
    // Ids of the particle blocks holding particles this step, ascending.
    std::vector<std::int32_t> occupied;
    std::vector<detail::ParticleBlock<Dim>> blocks;
    // Per thread its range of `blocks` (about equal particle counts) and of `active_slots`
    // (the node blocks its particle blocks write first), computed once per step: a thread handles
    // the same particles and nodes in every phase (which thread runs a task never changes a
    // result).
    // Running particle count at each block's start, then the total (blocks.size() + 1).
    std::vector<std::int32_t> block_starts;
    std::vector<int> block_split;
    std::vector<int> slot_split;
    std::vector<detail::ParticleChunk> chunks;
    std::vector<int> chunk_split;
    std::array<std::vector<int>, detail::kColours<Dim>> colours;
    // One scatter buffer per entry of `blocks`.
    std::vector<detail::LocalNodes<Dim>> buffers;
    // With SolverSettings::flip > 0: per entry of `blocks` its particles' force impulses.
    std::vector<detail::LocalNodes<Dim>> force_buffers;
    std::vector<std::int32_t> active_slots;
    std::vector<long> slot_stamp;
    // Per slot, its index in active_slots (valid for this step's active slots).
    std::vector<std::int32_t> active_index;
    // Per active slot the buffers overlapping it, in colour order:
    // contributions[contribution_start[a], contribution_start[a + 1]).
    std::vector<std::int32_t> contribution_start;
    std::vector<detail::Contribution> contributions;
    std::vector<std::int32_t> contribution_cursor;
    std::vector<std::array<Vec3, kBoundaryGroups>> slot_impulse;
    // Per active slot, its nodes constrained by the spring-backed facing, left for
    // update_spring (index into the grid's node data, constraint normal, solid).
    struct SpringNode {
        std::size_t node;
        Vec<Dim> normal;
        int boundary;
    };
    std::vector<std::vector<SpringNode>> slot_spring_nodes;
    std::vector<detail::Bounds> static_bounds;
    std::vector<detail::PlacedBody> bodies;
    Particles<Dim> scratch;
    // One partial result per task, reduced in task order.
    std::vector<double> task_max;
    std::vector<double> task_density;
    std::vector<int> task_count;
    // Volumetric averaging: per particle its volume ratio det(I + dt C) over the step and its
    // dual cell within its block.
    std::vector<double> particle_jacobian;
    std::vector<std::int8_t> particle_cell;
    // Per task of the block-key pass, its runs of equal keys.
    std::vector<std::vector<detail::KeyRun>> key_runs;
    std::unique_ptr<shapes::ThreadPool> pool;
};

}  // namespace rockfall::mpm
