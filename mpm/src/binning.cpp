// Sorting the particles into particle blocks, once per step, and storing them in that order.

#include "solver_workspace.hpp"

#include <algorithm>
#include <cmath>

namespace rockfall::mpm {

using detail::kBlockEdge;
using detail::kColours;
using detail::kLocalEdge;
using detail::kParticleBlockEdge;
using detail::ParticleBlock;

namespace {

// Particles per task when computing the block keys: a dozen tasks for the seed flow's 3,000
// particles, so that two threads share them evenly.
constexpr int kParticleGrain = 256;

// Most particles per grid-to-particles task: a full 2x2x2-cell block holds 216 particles at 3
// per cell edge; smaller tasks let the threads finish a phase within a few microseconds of
// each other, for the cost of gathering the block's nodes once per task.
constexpr int kChunkParticles = 64;

template <typename T>
void permute(std::vector<T>& values, std::vector<T>& scratch,
             const std::vector<std::int32_t>& order, shapes::ThreadPool& pool) {
    scratch.resize(values.size());
    pool.parallel_for(static_cast<int>(order.size()), kParticleGrain, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            scratch[static_cast<std::size_t>(i)] =
                values[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])];
        }
    });
    values.swap(scratch);
}

}  // namespace

// Sorts particles by particle block (stable counting sort: deterministic), lists the non-empty
// blocks by colour, activates the node blocks they write and lists, per node block, the
// particle blocks that write it in colour order.
template <int Dim>
void Solver<Dim>::bin_particles() {
    Grid& grid = *grid_;
    Workspace& w = *work_;
    const int n = static_cast<int>(particles_.size());
    w.key.resize(static_cast<std::size_t>(n));
    w.order.resize(static_cast<std::size_t>(n));
    const Vec<Dim> lo = grid.origin;
    const double h = grid.h;
    const double inverse_h = 1.0 / h;
    const int chunks = (n + kParticleGrain - 1) / kParticleGrain;
    w.task_count.assign(static_cast<std::size_t>(chunks), 0);
    w.key_runs.resize(static_cast<std::size_t>(chunks));
    w.pool->parallel_for(n, kParticleGrain, [&](int begin, int end) {
        int clamped = 0;
        for (int p = begin; p < end; ++p) {
            Vec<Dim>& x = particles_.position[static_cast<std::size_t>(p)];
            IVec<Dim> block;
            for (int d = 0; d < Dim; ++d) {
                // Keep the 3-node stencil inside the grid: x/h in [1, nodes - 2].
                const double low = lo[d] + h;
                const double high = lo[d] + (grid.nodes[d] - 2) * h;
                if (!(x[d] >= low && x[d] <= high)) {
                    x[d] = std::clamp(std::isfinite(x[d]) ? x[d] : low, low, high);
                    ++clamped;
                }
                // The same base node as the transfer kernels' stencil (make_stencil).
                const int base = detail::stencil_base((x[d] - lo[d]) * inverse_h);
                block[d] = base / kParticleBlockEdge;
            }
            int id = block[Dim - 1];
            for (int d = Dim - 2; d >= 0; --d) {
                id = id * w.particle_blocks[d] + block[d];
            }
            w.key[static_cast<std::size_t>(p)] = id;
        }
        const auto chunk = static_cast<std::size_t>(begin / kParticleGrain);
        w.task_count[chunk] = clamped;
        // Runs of equal keys: particles are stored sorted by block (reorder_particles), so a
        // chunk holds a few runs, and the counting sort below visits runs, not particles.
        auto& runs = w.key_runs[chunk];
        runs.clear();
        for (int p = begin; p < end; ++p) {
            const std::int32_t k = w.key[static_cast<std::size_t>(p)];
            if (runs.empty() || runs.back().key != k) {
                runs.push_back({k, p, 0, 0});
            }
            ++runs.back().count;
        }
    });
    report_.clamped_particles = 0;
    for (const int c : w.task_count) {
        report_.clamped_particles += c;
    }

    // Count per block, visiting only the blocks that hold particles (a few hundred of the tens
    // of thousands over the domain).
    w.occupied.clear();
    for (std::size_t c = 0; c < static_cast<std::size_t>(chunks); ++c) {
        for (const detail::KeyRun& run : w.key_runs[c]) {
            std::int32_t& count = w.block_cursor[static_cast<std::size_t>(run.key)];
            if (count == 0) {
                w.occupied.push_back(run.key);
            }
            count += run.count;
        }
    }
    std::sort(w.occupied.begin(), w.occupied.end());
    w.blocks.clear();
    for (auto& list : w.colours) {
        list.clear();
    }
    w.active_slots.clear();
    int start = 0;
    for (const std::int32_t id : w.occupied) {
        std::int32_t& cursor = w.block_cursor[static_cast<std::size_t>(id)];
        const int count = cursor;
        cursor = start;
        ParticleBlock<Dim> pb;
        int rest = id;
        int colour = 0;
        IVec<Dim> first_storage;
        // Along an axis the 4 written nodes span a second storage block unless 2b is a multiple
        // of 4.
        IVec<Dim> spans;
        for (int d = 0; d < Dim; ++d) {
            const int b = rest % w.particle_blocks[d];
            rest /= w.particle_blocks[d];
            colour |= (b & 1) << d;
            pb.first_node[d] = kParticleBlockEdge * b;
            first_storage[d] = pb.first_node[d] / kBlockEdge;
            spans[d] = (pb.first_node[d] + kLocalEdge - 1) / kBlockEdge - first_storage[d];
        }
        pb.begin = start;
        pb.end = start + count;
        pb.first_active = static_cast<std::int32_t>(w.active_slots.size());
        start += count;
        for (int o = 0; o < kColours<Dim>; ++o) {
            IVec<Dim> nb = first_storage;
            bool used = true;
            for (int d = 0; d < Dim; ++d) {
                const int bit = (o >> d) & 1;
                nb[d] += bit;
                used = used && bit <= spans[d];
            }
            if (!used) {
                pb.slots[static_cast<std::size_t>(o)] = -1;
                continue;
            }
            const int slot = grid.ensure_slot(grid.block_id(nb), statics_, w.static_bounds);
            pb.slots[static_cast<std::size_t>(o)] = slot;
            if (static_cast<std::size_t>(slot) >= w.slot_stamp.size()) {
                w.slot_stamp.resize(static_cast<std::size_t>(slot) + 1, -1);
                w.active_index.resize(static_cast<std::size_t>(slot) + 1, -1);
            }
            if (w.slot_stamp[static_cast<std::size_t>(slot)] != step_count_) {
                w.slot_stamp[static_cast<std::size_t>(slot)] = step_count_;
                w.active_index[static_cast<std::size_t>(slot)] =
                    static_cast<std::int32_t>(w.active_slots.size());
                w.active_slots.push_back(slot);
            }
        }
        w.colours[static_cast<std::size_t>(colour)].push_back(static_cast<int>(w.blocks.size()));
        w.blocks.push_back(pb);
    }
    // Each run's place in the sorted order, runs in particle order (so the sort is stable and
    // the same as placing the particles one by one), then the runs filled in parallel.
    for (std::size_t c = 0; c < static_cast<std::size_t>(chunks); ++c) {
        for (detail::KeyRun& run : w.key_runs[c]) {
            std::int32_t& cursor = w.block_cursor[static_cast<std::size_t>(run.key)];
            run.destination = cursor;
            cursor += run.count;
        }
    }
    w.pool->run(chunks, [&](int c) {
        for (const detail::KeyRun& run : w.key_runs[static_cast<std::size_t>(c)]) {
            for (int j = 0; j < run.count; ++j) {
                w.order[static_cast<std::size_t>(run.destination + j)] = run.first + j;
            }
        }
    });
    for (const std::int32_t id : w.occupied) {
        w.block_cursor[static_cast<std::size_t>(id)] = 0;
    }
    // Per thread a contiguous range of blocks with about equal particle counts (the blocks'
    // begins are the running particle count), and the same ranges of their chunks and of the
    // node blocks they list first: a node block goes to the thread of the first particle block
    // that writes it, so most buffers a thread sums in update_grid are ones it filled, and most
    // nodes it gathers from are ones it updated.
    w.block_starts.resize(w.blocks.size() + 1);
    w.chunks.clear();
    for (std::size_t b = 0; b < w.blocks.size(); ++b) {
        ParticleBlock<Dim>& pb = w.blocks[b];
        w.block_starts[b] = pb.begin;
        pb.first_chunk = static_cast<std::int32_t>(w.chunks.size());
        for (int k = pb.begin; k < pb.end; k += kChunkParticles) {
            w.chunks.push_back(
                {static_cast<std::int32_t>(b), k, std::min(k + kChunkParticles, pb.end)});
        }
    }
    w.block_starts.back() = n;
    w.pool->split_by_weight(w.block_starts, w.block_split);
    w.chunk_split.resize(w.block_split.size());
    w.slot_split.resize(w.block_split.size());
    for (std::size_t k = 0; k < w.block_split.size(); ++k) {
        const auto b = static_cast<std::size_t>(w.block_split[k]);
        const bool end = b == w.blocks.size();
        w.chunk_split[k] = end ? static_cast<int>(w.chunks.size()) : w.blocks[b].first_chunk;
        w.slot_split[k] = end ? static_cast<int>(w.active_slots.size()) : w.blocks[b].first_active;
    }

    // Writers of each active node block, colour by colour: a node receives at most one buffer
    // per colour, so it sums its contributions in colour order, the same for any thread count.
    const std::size_t active = w.active_slots.size();
    w.contribution_start.assign(active + 1, 0);
    for (const ParticleBlock<Dim>& pb : w.blocks) {
        for (const std::int32_t slot : pb.slots) {
            if (slot >= 0) {
                ++w.contribution_start[static_cast<std::size_t>(
                                           w.active_index[static_cast<std::size_t>(slot)]) +
                                       1];
            }
        }
    }
    for (std::size_t a = 0; a < active; ++a) {
        w.contribution_start[a + 1] += w.contribution_start[a];
    }
    w.contributions.resize(static_cast<std::size_t>(w.contribution_start[active]));
    std::vector<std::int32_t>& next = w.contribution_cursor;
    next.assign(w.contribution_start.begin(), w.contribution_start.end() - 1);
    for (const auto& list : w.colours) {
        for (const int b : list) {
            const ParticleBlock<Dim>& pb = w.blocks[static_cast<std::size_t>(b)];
            for (int o = 0; o < kColours<Dim>; ++o) {
                const std::int32_t slot = pb.slots[static_cast<std::size_t>(o)];
                if (slot >= 0) {
                    const auto a =
                        static_cast<std::size_t>(w.active_index[static_cast<std::size_t>(slot)]);
                    w.contributions[static_cast<std::size_t>(next[a]++)] = {b, o};
                }
            }
        }
    }
}

// Stores the particles in sorted order so that the phases stream through memory.
template <int Dim>
void Solver<Dim>::reorder_particles() {
    Workspace& w = *work_;
    Particles<Dim>& s = w.scratch;
    permute(particles_.position, s.position, w.order, *w.pool);
    permute(particles_.velocity, s.velocity, w.order, *w.pool);
    permute(particles_.affine, s.affine, w.order, *w.pool);
    permute(particles_.stress, s.stress, w.order, *w.pool);
    permute(particles_.mass, s.mass, w.order, *w.pool);
    permute(particles_.volume, s.volume, w.order, *w.pool);
    permute(particles_.plastic_shear_strain, s.plastic_shear_strain, w.order, *w.pool);
    for (std::size_t i = 0; i < w.order.size(); ++i) {
        w.order[i] = static_cast<std::int32_t>(i);
    }
}

template void Solver<2>::bin_particles();
template void Solver<3>::bin_particles();
template void Solver<2>::reorder_particles();
template void Solver<3>::reorder_particles();

}  // namespace rockfall::mpm
