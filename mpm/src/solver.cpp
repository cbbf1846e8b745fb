#include "mpm/solver.hpp"

#include "grid.hpp"
#include "kernels.hpp"
#include "thread_pool.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace rockfall::mpm {

using detail::kBlockEdge;
using detail::kBlockNodes;
using detail::kColours;
using detail::kLocalEdge;
using detail::kLocalNodes;
using detail::kParticleBlockEdge;
using detail::Node;

template <int Dim>
struct Solver<Dim>::Grid : detail::BlockGrid<Dim> {
    using detail::BlockGrid<Dim>::BlockGrid;
};

// A non-empty particle block: the first node it writes (2 b per axis), its range in the sorted
// order and the slots of the storage blocks it writes (by per-axis offset bits; -1 unused).
template <int Dim>
struct ParticleBlock {
    IVec<Dim> first_node;
    int begin;
    int end;
    std::array<std::int32_t, kColours<Dim>> slots;
};

// Current placement of a hinged body, computed once per step.
struct PlacedBody {
    std::vector<shapes::OrientedBox> boxes;
    detail::Bounds bounds;
    Vec3 hinge;
    double angular_velocity;
};

template <int Dim>
struct Solver<Dim>::Workspace {
    IVec<Dim> particle_blocks;
    std::vector<std::int32_t> key;
    std::vector<std::int32_t> order;
    std::vector<std::int32_t> block_start;
    std::vector<ParticleBlock<Dim>> blocks;
    std::array<std::vector<int>, kColours<Dim>> colours;
    std::vector<std::int32_t> active_slots;
    std::vector<long> slot_stamp;
    std::vector<std::array<Vec3, kBoundaryGroups>> slot_impulse;
    std::vector<detail::Bounds> static_bounds;
    std::vector<PlacedBody> bodies;
    Particles<Dim> scratch;
    // One partial result per task, reduced in task order.
    std::vector<double> task_max;
    std::vector<int> task_count;
    std::unique_ptr<detail::ThreadPool> pool;
};

namespace {

// Particles per task in particle-wise phases.
constexpr int kParticleGrain = 1024;
// Storage blocks per task in the grid phases.
constexpr int kBlockGrain = 8;

void require(bool ok, const char* field, double value, const char* unit, const char* range) {
    if (!ok) {
        std::ostringstream message;
        message << "solver." << field << " = " << value << (unit[0] != '\0' ? " " : "") << unit
                << ": must be " << range;
        throw std::invalid_argument(message.str());
    }
}

template <typename T>
void permute(std::vector<T>& values, std::vector<T>& scratch,
             const std::vector<std::int32_t>& order) {
    scratch.resize(values.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        scratch[i] = values[static_cast<std::size_t>(order[i])];
    }
    values.swap(scratch);
}

}  // namespace

template <int Dim>
Solver<Dim>::Solver(const SolverSettings& settings, const Material& material,
                    Particles<Dim> particles, std::vector<StaticBoundary> statics,
                    std::vector<HingedBoundary> hinged)
    : settings_(settings),
      material_(material),
      particles_(std::move(particles)),
      statics_(std::move(statics)),
      hinged_(std::move(hinged)),
      work_(std::make_unique<Workspace>()) {
    const SolverSettings& s = settings_;
    require(std::isfinite(s.cell_size) && s.cell_size > 0.0, "cell_size", s.cell_size, "m", "> 0");
    require(s.cfl > 0.0 && s.cfl <= 1.0, "cfl", s.cfl, "", "in (0, 1]");
    require(s.max_time_step > 0.0, "max_time_step", s.max_time_step, "s", "> 0");
    require(s.damping >= 0.0, "damping", s.damping, "1/s", ">= 0");
    require(s.threads >= 0, "threads", s.threads, "", ">= 0");
    require(s.reorder_interval >= 1, "reorder_interval", s.reorder_interval, "", ">= 1");
    validate(material_);

    const Vec<Dim> lo = from_scene<Dim>(s.domain_min);
    const Vec<Dim> hi = from_scene<Dim>(s.domain_max);
    IVec<Dim> nodes;
    for (int d = 0; d < Dim; ++d) {
        const double extent = hi[d] - lo[d];
        require(extent >= 4.0 * s.cell_size, "domain_max - domain_min", extent, "m",
                ">= 4 cell sizes on every axis");
        nodes[d] = static_cast<int>(std::ceil(extent / s.cell_size - 1e-9)) + 1;
    }
    grid_ = std::make_unique<Grid>(lo, s.cell_size, nodes);
    for (int d = 0; d < Dim; ++d) {
        work_->particle_blocks[d] = (nodes[d] + kParticleBlockEdge - 1) / kParticleBlockEdge;
    }

    for (const StaticBoundary& b : statics_) {
        require(b.group >= 0 && b.group < kBoundaryGroups, "statics[].group", b.group, "",
                "in [0, kBoundaryGroups)");
        require(b.friction_coefficient >= 0.0, "statics[].friction_coefficient",
                b.friction_coefficient, "", ">= 0");
        work_->static_bounds.push_back(detail::bounds_of(b.box));
    }
    for (const HingedBoundary& b : hinged_) {
        require(b.group >= 0 && b.group < kBoundaryGroups, "hinged[].group", b.group, "",
                "in [0, kBoundaryGroups)");
        require(b.duration >= 0.0, "hinged[].duration", b.duration, "s", ">= 0");
        require(b.friction_coefficient >= 0.0, "hinged[].friction_coefficient",
                b.friction_coefficient, "", ">= 0");
    }
    work_->bodies.resize(hinged_.size());

    const double h = s.cell_size;
    for (std::size_t p = 0; p < particles_.size(); ++p) {
        const Vec<Dim> x = (particles_.position[p] - lo) / h;
        for (int d = 0; d < Dim; ++d) {
            require(x[d] >= 1.0 && x[d] <= nodes[d] - 2.0, "particle position",
                    particles_.position[p][d], "m", "at least one cell inside the domain");
        }
        require(particles_.mass[p] > 0.0 && particles_.volume[p] > 0.0, "particle mass",
                particles_.mass[p], "kg", "> 0 with volume > 0");
        max_density_ = std::max(max_density_, particles_.mass[p] / particles_.volume[p]);
        max_speed_ = std::max(max_speed_, particles_.velocity[p].norm());
    }
    threads_ = s.threads > 0 ? s.threads
                             : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    // Below about 512 particles per thread the fork-join overhead of a phase outweighs its
    // work; fewer threads give the same (thread-count independent) results sooner.
    threads_ = std::clamp(static_cast<int>(particles_.size()) / 512, 1, threads_);
    work_->pool = std::make_unique<detail::ThreadPool>(threads_);
}

template <int Dim>
Solver<Dim>::~Solver() = default;

template <int Dim>
long Solver<Dim>::allocated_nodes() const {
    return static_cast<long>(grid_->data.size());
}

template <int Dim>
double Solver<Dim>::stable_time_step() const {
    const double wave_speed =
        max_density_ > 0.0 ? std::sqrt(p_wave_modulus(material_) / max_density_) : 0.0;
    const double dt = settings_.cfl * settings_.cell_size / (wave_speed + max_speed_);
    return std::min(dt, settings_.max_time_step);
}

template <int Dim>
const StepReport& Solver<Dim>::step(double dt) {
    assert(dt > 0.0 && std::isfinite(dt));
    report_ = StepReport{};
    report_.dt = dt;
    bin_particles();
    if (step_count_ % settings_.reorder_interval == 0) {
        reorder_particles();
    }
    clear_grid();
    particles_to_grid(dt);
    update_grid(dt);
    grid_to_particles(dt);
    update_stress(dt);
    time_ += dt;
    ++step_count_;
    report_.max_speed = max_speed_;
    return report_;
}

// Sorts particles by particle block (stable counting sort: deterministic), lists the non-empty
// blocks by colour and activates the node blocks they write.
template <int Dim>
void Solver<Dim>::bin_particles() {
    Grid& grid = *grid_;
    Workspace& w = *work_;
    const int n = static_cast<int>(particles_.size());
    w.key.resize(static_cast<std::size_t>(n));
    w.order.resize(static_cast<std::size_t>(n));
    const Vec<Dim> lo = grid.origin;
    const double h = grid.h;
    const int chunks = (n + kParticleGrain - 1) / kParticleGrain;
    w.task_count.assign(static_cast<std::size_t>(chunks), 0);
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
                const int base = static_cast<int>(std::floor((x[d] - lo[d]) / h - 0.5));
                block[d] = base / kParticleBlockEdge;
            }
            int id = block[Dim - 1];
            for (int d = Dim - 2; d >= 0; --d) {
                id = id * w.particle_blocks[d] + block[d];
            }
            w.key[static_cast<std::size_t>(p)] = id;
        }
        w.task_count[static_cast<std::size_t>(begin / kParticleGrain)] = clamped;
    });
    report_.clamped_particles = 0;
    for (const int c : w.task_count) {
        report_.clamped_particles += c;
    }

    int particle_block_count = 1;
    for (int d = 0; d < Dim; ++d) {
        particle_block_count *= w.particle_blocks[d];
    }
    w.block_start.assign(static_cast<std::size_t>(particle_block_count) + 1, 0);
    for (const std::int32_t k : w.key) {
        ++w.block_start[static_cast<std::size_t>(k) + 1];
    }
    w.blocks.clear();
    for (auto& list : w.colours) {
        list.clear();
    }
    w.active_slots.clear();
    for (int id = 0; id < particle_block_count; ++id) {
        const auto u = static_cast<std::size_t>(id);
        const int count = w.block_start[u + 1];
        w.block_start[u + 1] = w.block_start[u] + count;
        if (count == 0) {
            continue;
        }
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
        pb.begin = w.block_start[u];
        pb.end = w.block_start[u + 1];
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
            }
            if (w.slot_stamp[static_cast<std::size_t>(slot)] != step_count_) {
                w.slot_stamp[static_cast<std::size_t>(slot)] = step_count_;
                w.active_slots.push_back(slot);
            }
        }
        w.colours[static_cast<std::size_t>(colour)].push_back(static_cast<int>(w.blocks.size()));
        w.blocks.push_back(pb);
    }
    for (int p = 0; p < n; ++p) {
        const auto k = static_cast<std::size_t>(w.key[static_cast<std::size_t>(p)]);
        w.order[static_cast<std::size_t>(w.block_start[k]++)] = p;
    }
    // block_start was advanced to each block's end; blocks keep their own [begin, end).
}

// Stores the particles in sorted order so that the phases stream through memory.
template <int Dim>
void Solver<Dim>::reorder_particles() {
    Workspace& w = *work_;
    Particles<Dim>& s = w.scratch;
    permute(particles_.position, s.position, w.order);
    permute(particles_.velocity, s.velocity, w.order);
    permute(particles_.affine, s.affine, w.order);
    permute(particles_.stress, s.stress, w.order);
    permute(particles_.mass, s.mass, w.order);
    permute(particles_.volume, s.volume, w.order);
    permute(particles_.plastic_shear_strain, s.plastic_shear_strain, w.order);
    for (std::size_t i = 0; i < w.order.size(); ++i) {
        w.order[i] = static_cast<std::int32_t>(i);
    }
}

template <int Dim>
void Solver<Dim>::clear_grid() {
    Grid& grid = *grid_;
    const auto& active = work_->active_slots;
    const int count = static_cast<int>(active.size());
    work_->pool->parallel_for(count, kBlockGrain, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            Node<Dim>* nodes =
                grid.data.data() +
                static_cast<std::size_t>(active[static_cast<std::size_t>(i)]) * kBlockNodes<Dim>;
            for (int j = 0; j < kBlockNodes<Dim>; ++j) {
                nodes[j].setZero();
            }
        }
    });
}

// Hu et al. 2018, eq. 29 (MLS-MPM P2G with APIC momentum and the stress force folded into the
// affine term), one colour at a time.
template <int Dim>
void Solver<Dim>::particles_to_grid(double dt) {
    Grid& grid = *grid_;
    Workspace& w = *work_;
    const detail::KernelFrame<Dim> frame{grid.origin, grid.h};
    for (const auto& list : w.colours) {
        w.pool->run(static_cast<int>(list.size()), [&](int i) {
            const ParticleBlock<Dim>& pb =
                w.blocks[static_cast<std::size_t>(list[static_cast<std::size_t>(i)])];
            std::array<Node<Dim>, kLocalNodes<Dim>> local;
            for (auto& node : local) {
                node.setZero();
            }
            for (int k = pb.begin; k < pb.end; ++k) {
                const auto p = static_cast<std::size_t>(w.order[static_cast<std::size_t>(k)]);
                detail::scatter_particle<Dim>(frame, pb.first_node, dt, particles_.position[p],
                                              particles_.velocity[p], particles_.affine[p],
                                              particles_.stress[p], particles_.mass[p],
                                              particles_.volume[p], local);
            }
            detail::add_local_to_grid<Dim>(local, pb.first_node, pb.slots, grid.data);
        });
    }
}

template <int Dim>
void Solver<Dim>::update_grid(double dt) {
    Grid& grid = *grid_;
    Workspace& w = *work_;
    for (std::size_t b = 0; b < hinged_.size(); ++b) {
        PlacedBody& placed = w.bodies[b];
        placed.boxes = hinged_[b].boxes_at(time_);
        placed.hinge = hinged_[b].hinge;
        placed.angular_velocity = hinged_[b].angular_velocity(time_);
        placed.bounds = {Vec3::Constant(1e300), Vec3::Constant(-1e300)};
        for (const auto& box : placed.boxes) {
            const detail::Bounds bb = detail::bounds_of(box);
            placed.bounds.lo = placed.bounds.lo.cwiseMin(bb.lo);
            placed.bounds.hi = placed.bounds.hi.cwiseMax(bb.hi);
        }
    }
    const auto& active = w.active_slots;
    const int count = static_cast<int>(active.size());
    if (w.slot_impulse.size() < active.size()) {
        w.slot_impulse.resize(active.size());
    }
    const Vec<Dim> gravity = from_scene<Dim>(settings_.gravity);
    w.pool->run(count, [&](int i) {
        const auto slot = static_cast<std::size_t>(active[static_cast<std::size_t>(i)]);
        auto& impulse = w.slot_impulse[static_cast<std::size_t>(i)];
        for (auto& g : impulse) {
            g.setZero();
        }
        const IVec<Dim> first_node = kBlockEdge * grid.block_of_slot[slot];
        for (int j = 0; j < kBlockNodes<Dim>; ++j) {
            Node<Dim>& node = grid.data[slot * kBlockNodes<Dim> + static_cast<std::size_t>(j)];
            const double m = node[Dim];
            if (m <= 0.0) {
                continue;
            }
            const IVec<Dim> index = first_node + detail::block_local_coords<Dim>(j);
            Vec<Dim> v = node.template head<Dim>() / m + dt * gravity;
            detail::apply_domain_faces<Dim>(index, grid.nodes, v);
            const std::int32_t rule =
                grid.rule_of_node[slot * kBlockNodes<Dim> + static_cast<std::size_t>(j)];
            if (rule >= 0) {
                const auto& r = grid.rules[static_cast<std::size_t>(rule)];
                for (int c = 0; c < r.count; ++c) {
                    const auto& constraint = r.constraints[static_cast<std::size_t>(c)];
                    const StaticBoundary& solid =
                        statics_[static_cast<std::size_t>(constraint.boundary)];
                    const Vec<Dim> before = v;
                    detail::apply_boundary<Dim>(v, constraint.normal, Vec<Dim>::Zero(), solid.kind,
                                                solid.friction_coefficient);
                    impulse[static_cast<std::size_t>(solid.group)] +=
                        to_scene<Dim>(m * (before - v));
                }
            }
            if (!hinged_.empty()) {
                const Vec3 x = to_scene<Dim>(grid.node_position(index));
                for (std::size_t b = 0; b < hinged_.size(); ++b) {
                    const Vec<Dim> before = v;
                    if (detail::apply_hinged<Dim>(w.bodies[b].boxes, w.bodies[b].bounds,
                                                  w.bodies[b].hinge, w.bodies[b].angular_velocity,
                                                  hinged_[b].kind, hinged_[b].friction_coefficient,
                                                  x, v)) {
                        impulse[static_cast<std::size_t>(hinged_[b].group)] +=
                            to_scene<Dim>(m * (before - v));
                    }
                }
            }
            node.template head<Dim>() = v;
        }
    });
    // Fixed-order reduction over the active blocks: independent of the thread count.
    for (int i = 0; i < count; ++i) {
        for (int g = 0; g < kBoundaryGroups; ++g) {
            report_.impulse[static_cast<std::size_t>(g)] +=
                w.slot_impulse[static_cast<std::size_t>(i)][static_cast<std::size_t>(g)];
        }
    }
}

template <int Dim>
void Solver<Dim>::grid_to_particles(double dt) {
    Grid& grid = *grid_;
    Workspace& w = *work_;
    const detail::KernelFrame<Dim> frame{grid.origin, grid.h};
    const int count = static_cast<int>(w.blocks.size());
    // Damping acts on the particles after the transfer, so the boundary impulses of a body at
    // rest are its full reactions.
    const double damping = 1.0 / (1.0 + settings_.damping * dt);
    w.task_max.assign(static_cast<std::size_t>(count), 0.0);
    w.pool->run(count, [&](int i) {
        double max_speed_squared = 0.0;
        const ParticleBlock<Dim>& pb = w.blocks[static_cast<std::size_t>(i)];
        std::array<Vec<Dim>, kLocalNodes<Dim>> local;
        detail::gather_local_velocities<Dim>(grid.data, pb.first_node, pb.slots, local);
        for (int k = pb.begin; k < pb.end; ++k) {
            const auto p = static_cast<std::size_t>(w.order[static_cast<std::size_t>(k)]);
            detail::gather_particle<Dim>(frame, pb.first_node, local, particles_.position[p],
                                         particles_.velocity[p], particles_.affine[p]);
            particles_.position[p] += dt * particles_.velocity[p];
            particles_.velocity[p] *= damping;
            max_speed_squared = std::max(max_speed_squared, particles_.velocity[p].squaredNorm());
        }
        w.task_max[static_cast<std::size_t>(i)] = max_speed_squared;
    });
    double max_speed_squared = 0.0;
    for (const double m : w.task_max) {
        max_speed_squared = std::max(max_speed_squared, m);
    }
    max_speed_ = std::sqrt(max_speed_squared);
}

template <int Dim>
void Solver<Dim>::update_stress(double dt) {
    const int n = static_cast<int>(particles_.size());
    Workspace& w = *work_;
    w.task_max.assign(static_cast<std::size_t>((n + kParticleGrain - 1) / kParticleGrain), 0.0);
    std::visit(
        [&](const auto& params) {
            using Params = std::decay_t<decltype(params)>;
            using Model = std::conditional_t<std::is_same_v<Params, LinearElastic>,
                                             LinearElasticModel, DruckerPragerModel>;
            const Model model(params);
            w.pool->parallel_for(n, kParticleGrain, [&](int begin, int end) {
                double max_density = 0.0;
                for (int i = begin; i < end; ++i) {
                    const auto p = static_cast<std::size_t>(i);
                    const Mat<Dim>& c = particles_.affine[p];
                    const Mat3 l = embed<Dim>(c);
                    const Mat3 strain_increment = (0.5 * dt) * (l + l.transpose());
                    // Jaumann rate: co-rotate with the spin before the constitutive update.
                    const Mat3 rotated = detail::corotate(particles_.stress[p], l, dt);
                    particles_.stress[p] =
                        model.update(rotated, strain_increment, particles_.plastic_shear_strain[p]);
                    const double jacobian = (Mat<Dim>::Identity() + dt * c).determinant();
                    particles_.volume[p] *= jacobian;
                    max_density = std::max(max_density, particles_.mass[p] / particles_.volume[p]);
                }
                w.task_max[static_cast<std::size_t>(begin / kParticleGrain)] = max_density;
            });
        },
        material_);
    max_density_ = 0.0;
    for (const double m : w.task_max) {
        max_density_ = std::max(max_density_, m);
    }
}

template class Solver<2>;
template class Solver<3>;

}  // namespace rockfall::mpm
