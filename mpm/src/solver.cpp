#include "mpm/solver.hpp"

#include "solver_workspace.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>

namespace rockfall::mpm {

using detail::Contribution;
using detail::kBlockEdge;
using detail::kBlockNodes;
using detail::kParticleBlockEdge;
using detail::Node;
using detail::ParticleBlock;
using detail::PlacedBody;

namespace {

void require(bool ok, const char* field, double value, const char* unit, const char* range) {
    if (!ok) {
        std::ostringstream message;
        message << "solver." << field << " = " << value << (unit[0] != '\0' ? " " : "") << unit
                << ": must be " << range;
        throw std::invalid_argument(message.str());
    }
}

}  // namespace

template <int Dim>
Solver<Dim>::Solver(const SolverSettings& settings, const Material& material,
                    Particles<Dim> particles, std::vector<StaticBoundary> statics,
                    std::vector<HingedBoundary> hinged, std::optional<SpringSupport> spring)
    : settings_(settings),
      material_(material),
      particles_(std::move(particles)),
      statics_(std::move(statics)),
      hinged_(std::move(hinged)),
      spring_(spring),
      work_(std::make_unique<Workspace>()) {
    const SolverSettings& s = settings_;
    require(std::isfinite(s.cell_size) && s.cell_size > 0.0, "cell_size", s.cell_size, "m", "> 0");
    require(s.boundary_reach >= 0.0 && s.boundary_reach <= 0.5, "boundary_reach", s.boundary_reach,
            "", "in [0, 0.5]");
    require(s.cfl > 0.0 && s.cfl <= 1.0, "cfl", s.cfl, "", "in (0, 1]");
    require(s.max_time_step > 0.0, "max_time_step", s.max_time_step, "s", "> 0");
    require(s.damping >= 0.0, "damping", s.damping, "1/s", ">= 0");
    require(s.flip >= 0.0 && s.flip <= 1.0, "flip", s.flip, "", "in [0, 1]");
    require(s.min_density_ratio >= 0.0 && s.min_density_ratio < 1.0, "min_density_ratio",
            s.min_density_ratio, "", "in [0, 1)");
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
    // A node on a surface up to round-off (1e-6 h) counts as on it: node positions lo + k h and
    // a wall at the same place computed another way differ in the last bits.
    grid_ = std::make_unique<Grid>(lo, s.cell_size, nodes,
                                   std::max(s.boundary_reach, 1e-6) * s.cell_size);
    grid_->keep_old_velocity = s.flip > 0.0;
    int particle_block_count = 1;
    for (int d = 0; d < Dim; ++d) {
        work_->particle_blocks[d] = (nodes[d] + kParticleBlockEdge - 1) / kParticleBlockEdge;
        particle_block_count *= work_->particle_blocks[d];
    }
    work_->block_cursor.assign(static_cast<std::size_t>(particle_block_count), 0);

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
    if (spring_) {
        const SpringSupport& k = *spring_;
        require(k.group >= 0 && k.group < kBoundaryGroups, "spring.group", k.group, "",
                "in [0, kBoundaryGroups)");
        require(std::abs(k.direction.norm() - 1.0) < 1e-9, "spring.direction length",
                k.direction.norm(), "", "1");
        require(std::isfinite(k.mass) && k.mass > 0.0, "spring.mass", k.mass,
                Dim == 2 ? "kg/m" : "kg", "> 0");
        require(std::isfinite(k.stiffness) && k.stiffness > 0.0, "spring.stiffness", k.stiffness,
                Dim == 2 ? "N/m per m" : "N/m", "> 0");
        require(std::isfinite(k.damping) && k.damping >= 0.0, "spring.damping", k.damping,
                Dim == 2 ? "N s/m per m" : "N s/m", ">= 0");
        for (const HingedBoundary& b : hinged_) {
            require(b.group != k.group, "hinged[].group", b.group, "",
                    "other than the spring-backed group");
        }
    }

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
    initial_density_ = max_density_;
    threads_ = s.threads > 0 ? s.threads
                             : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    // Below about 512 particles per thread the fork-join overhead of a phase outweighs its
    // work; fewer threads give the same (thread-count independent) results sooner.
    threads_ = std::clamp(static_cast<int>(particles_.size()) / 512, 1, threads_);
    work_->pool = std::make_unique<shapes::ThreadPool>(threads_);
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
    particles_to_grid(dt);
    update_grid(dt);
    if (spring_) {
        update_spring(dt);
    }
    grid_to_particles(dt);
    time_ += dt;
    ++step_count_;
    report_.max_speed = max_speed_;
    return report_;
}

// Phase 2, first half: every particle block scatters its particles into its own buffer, all
// blocks at once (Hu et al. 2018, eq. 29: MLS-MPM P2G with APIC momentum and the stress force
// folded into the affine term). update_grid sums the buffers into the grid.
template <int Dim>
void Solver<Dim>::particles_to_grid(double dt) {
    Grid& grid = *grid_;
    Workspace& w = *work_;
    const detail::KernelFrame<Dim> frame{grid.origin, grid.h};
    const bool flip = settings_.flip > 0.0;
    w.buffers.resize(w.blocks.size());
    if (flip) w.force_buffers.resize(w.blocks.size());
    w.pool->run(w.block_split, [&](int i) {
        const ParticleBlock<Dim>& pb = w.blocks[static_cast<std::size_t>(i)];
        detail::LocalNodes<Dim>& local = w.buffers[static_cast<std::size_t>(i)];
        for (auto& node : local) {
            node.setZero();
        }
        detail::LocalNodes<Dim>* forces =
            flip ? &w.force_buffers[static_cast<std::size_t>(i)] : nullptr;
        if (forces) {
            for (auto& node : *forces) {
                node.setZero();
            }
        }
        for (int k = pb.begin; k < pb.end; ++k) {
            const auto p = static_cast<std::size_t>(w.order[static_cast<std::size_t>(k)]);
            if (forces) {
                detail::scatter_particle<Dim, true>(
                    frame, pb.first_node, dt, particles_.position[p], particles_.velocity[p],
                    particles_.affine[p], particles_.stress[p], particles_.mass[p],
                    particles_.volume[p], local, forces);
            } else {
                detail::scatter_particle<Dim>(frame, pb.first_node, dt, particles_.position[p],
                                              particles_.velocity[p], particles_.affine[p],
                                              particles_.stress[p], particles_.mass[p],
                                              particles_.volume[p], local);
            }
        }
    });
}

// Phases 1, 2 (second half) and 3 per active node block: clear it, sum the particle blocks'
// buffers that overlap it in colour order, then v_i = p_i / m_i + dt g and the boundaries.
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
    const int spring_group = spring_ ? spring_->group : -1;
    if (spring_ && w.slot_spring_nodes.size() < active.size()) {
        w.slot_spring_nodes.resize(active.size());
    }
    const Vec<Dim> gravity = from_scene<Dim>(settings_.gravity);
    const bool flip = settings_.flip > 0.0;
    w.pool->run(w.slot_split, [&](int i) {
        const auto slot = static_cast<std::size_t>(active[static_cast<std::size_t>(i)]);
        Node<Dim>* nodes = grid.data.data() + slot * kBlockNodes<Dim>;
        for (int j = 0; j < kBlockNodes<Dim>; ++j) {
            nodes[j].setZero();
        }
        Node<Dim>* old_nodes = flip ? grid.old_velocity.data() + slot * kBlockNodes<Dim> : nullptr;
        if (flip) {
            for (int j = 0; j < kBlockNodes<Dim>; ++j) {
                old_nodes[j].setZero();
            }
        }
        for (std::int32_t c = w.contribution_start[static_cast<std::size_t>(i)];
             c < w.contribution_start[static_cast<std::size_t>(i) + 1]; ++c) {
            const Contribution& from = w.contributions[static_cast<std::size_t>(c)];
            const auto b = static_cast<std::size_t>(from.block);
            detail::add_buffer_part<Dim>(w.buffers[b], w.blocks[b].first_node, from.offset_bits,
                                         nodes);
            if (flip) {
                detail::add_buffer_part<Dim>(w.force_buffers[b], w.blocks[b].first_node,
                                             from.offset_bits, old_nodes);
            }
        }

        auto& impulse = w.slot_impulse[static_cast<std::size_t>(i)];
        for (auto& g : impulse) {
            g.setZero();
        }
        if (spring_) {
            w.slot_spring_nodes[static_cast<std::size_t>(i)].clear();
        }
        const IVec<Dim> first_node = kBlockEdge * grid.block_of_slot[slot];
        for (int j = 0; j < kBlockNodes<Dim>; ++j) {
            Node<Dim>& node = nodes[j];
            const double m = node[Dim];
            if (m <= 0.0) {
                continue;
            }
            const IVec<Dim> index = first_node + detail::block_local_coords<Dim>(j);
            if (flip) {
                // The momentum less the stress impulse: the velocity before the step's forces.
                Node<Dim>& old = old_nodes[j];
                old.template head<Dim>() =
                    (node.template head<Dim>() - old.template head<Dim>()) / m;
            }
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
                    if (solid.group == spring_group) {
                        // The facing's velocity is solved with all its nodes (update_spring).
                        w.slot_spring_nodes[static_cast<std::size_t>(i)].push_back(
                            {slot * kBlockNodes<Dim> + static_cast<std::size_t>(j),
                             constraint.normal, constraint.boundary});
                        continue;
                    }
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
                                                  grid.boundary_reach, x, v)) {
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

// Phase 3, the spring-backed facing: its velocity w' at the end of the step and the velocities
// of the nodes it constrains, solved together. The facing's momentum over the step,
//   m_f (w' - w) = P(w') - dt (k (u + u') / 2 + c (w + w') / 2),  u' = u + dt (w + w') / 2,
// (trapezoidal rule) with P(w') the momentum along d the nodes lose when constrained by a
// solid moving at w' d, is A w' - B - P(w') = 0 with A = m_f + dt^2 k / 4 + dt c / 2 and
// B = m_f w - dt k u - (dt^2 k / 4 + dt c / 2) w. P never increases with w', so the left side
// increases strictly: bracketed, then bisected (fixed order over the nodes: deterministic).
template <int Dim>
void Solver<Dim>::update_spring(double dt) {
    const SpringSupport& k = *spring_;
    Grid& grid = *grid_;
    Workspace& w = *work_;
    const Vec<Dim> d = from_scene<Dim>(k.direction);
    const std::size_t count = w.active_slots.size();
    auto constrained = [&](const typename Workspace::SpringNode& n, double facing) {
        Vec<Dim> v = grid.data[n.node].template head<Dim>();
        const StaticBoundary& solid = statics_[static_cast<std::size_t>(n.boundary)];
        detail::apply_boundary<Dim>(v, n.normal, facing * d, solid.kind,
                                    solid.friction_coefficient);
        return v;
    };
    auto lost_momentum = [&](double facing) {
        double lost = 0.0;
        for (std::size_t i = 0; i < count; ++i) {
            for (const auto& n : w.slot_spring_nodes[i]) {
                const Node<Dim>& node = grid.data[n.node];
                lost += node[Dim] * (node.template head<Dim>() - constrained(n, facing)).dot(d);
            }
        }
        return lost;
    };
    const double coupling = 0.25 * dt * dt * k.stiffness + 0.5 * dt * k.damping;
    const double a = k.mass + coupling;
    const double b = k.mass * spring_w_ - dt * k.stiffness * spring_u_ - coupling * spring_w_;
    auto residual = [&](double facing) { return a * facing - b - lost_momentum(facing); };
    double lo = spring_w_;
    double hi = spring_w_;
    double step = std::max(1e-6, std::abs(residual(spring_w_)) / a);
    while (residual(lo) > 0.0) {
        lo -= step;
        step *= 2.0;
    }
    while (residual(hi) < 0.0) {
        hi += step;
        step *= 2.0;
    }
    for (int iteration = 0; iteration < 200 && hi - lo > 1e-14 * std::max(1.0, std::abs(hi));
         ++iteration) {
        const double mid = 0.5 * (lo + hi);
        (residual(mid) > 0.0 ? hi : lo) = mid;
    }
    const double facing = 0.5 * (lo + hi);
    Vec3& impulse = report_.impulse[static_cast<std::size_t>(k.group)];
    for (std::size_t i = 0; i < count; ++i) {
        for (const auto& n : w.slot_spring_nodes[i]) {
            Node<Dim>& node = grid.data[n.node];
            const Vec<Dim> v = constrained(n, facing);
            impulse += to_scene<Dim>(node[Dim] * (node.template head<Dim>() - v));
            node.template head<Dim>() = v;
        }
    }
    const double u_next = spring_u_ + 0.5 * dt * (spring_w_ + facing);
    report_.spring_impulse =
        dt * (0.5 * k.stiffness * (spring_u_ + u_next) + 0.5 * k.damping * (spring_w_ + facing));
    spring_u_ = u_next;
    spring_w_ = facing;
}

namespace {

// Phase 5 for particle p (update-stress-last): sigma co-rotated with the spin W = skew(L)
// (Jaumann rate), then the constitutive model with the strain increment sym(L) dt and
// V_p *= det(I + dt L). L is C_p, or with `own_and_mean` (the particle's det(I + dt C_p) and
// its dual cell's mean of it, volumetric averaging) the rate of the F-bar increment
// (mean / own)^(1/Dim) (I + dt C_p), whose determinant is the mean. Returns the
// particle's new density, kg/m3.
template <int Dim, typename Model>
double update_stress(Particles<Dim>& particles, std::size_t p, const Model& model, double dt,
                     double max_specific_volume,
                     std::optional<std::pair<double, double>> own_and_mean = std::nullopt) {
    Mat<Dim> c = particles.affine[p];
    double volume_ratio = 0.0;
    if (own_and_mean && own_and_mean->first > 0.0 && own_and_mean->second > 0.0) {
        const double ratio = own_and_mean->second / own_and_mean->first;
        const double s = Dim == 2 ? std::sqrt(ratio) : std::cbrt(ratio);
        c = s * c;
        c.diagonal().array() += (s - 1.0) / dt;
        // det(s (I + dt C)) = s^Dim det(I + dt C): the mean, without a second determinant.
        volume_ratio = own_and_mean->second;
    } else {
        volume_ratio = (Mat<Dim>::Identity() + dt * c).determinant();
    }
    const Mat3 l = embed<Dim>(c);
    const Mat3 strain_increment = (0.5 * dt) * (l + l.transpose());
    const Mat3 rotated = detail::corotate(particles.stress[p], l, dt);
    particles.stress[p] =
        model.update(rotated, strain_increment, particles.plastic_shear_strain[p]);
    particles.volume[p] =
        std::min(particles.volume[p] * volume_ratio, particles.mass[p] * max_specific_volume);
    return particles.mass[p] / particles.volume[p];
}

}  // namespace

// Phases 4 and 5 per particle block: each particle takes its velocity and affine velocity from
// the grid and moves, then updates its stress, while its data are in cache. Without volumetric
// averaging a task is a chunk of a block; with it a task is a whole block, whose dual-cell means
// need all its particles' volume ratios before any of its stresses.
template <int Dim>
void Solver<Dim>::grid_to_particles(double dt) {
    Grid& grid = *grid_;
    Workspace& w = *work_;
    const detail::KernelFrame<Dim> frame{grid.origin, grid.h};
    const bool averaging = settings_.volumetric_averaging;
    const double flip = settings_.flip;
    const double max_specific_volume = settings_.min_density_ratio > 0.0
                                           ? 1.0 / (settings_.min_density_ratio * initial_density_)
                                           : std::numeric_limits<double>::infinity();
    const int count = static_cast<int>(averaging ? w.blocks.size() : w.chunks.size());
    // Damping acts on the particles after the transfer, so the boundary impulses of a body at
    // rest are its full reactions.
    const double damping = 1.0 / (1.0 + settings_.damping * dt);
    w.task_max.assign(static_cast<std::size_t>(count), 0.0);
    w.task_density.assign(static_cast<std::size_t>(count), 0.0);
    if (averaging) {
        w.particle_jacobian.resize(particles_.size());
        w.particle_cell.resize(particles_.size());
    }
    std::visit(
        [&](const auto& params) {
            using Params = std::decay_t<decltype(params)>;
            using Model = std::conditional_t<std::is_same_v<Params, LinearElastic>,
                                             LinearElasticModel, DruckerPragerModel>;
            const Model model(params);
            // Sorted particles [begin, end) of block pb: gather, move and (without averaging)
            // update the stress. Returns the largest squared speed and density.
            const auto gather = [&](const ParticleBlock<Dim>& pb, int begin, int end) {
                double max_speed_squared = 0.0;
                double max_density = 0.0;
                detail::LocalNodes<Dim> local;
                detail::gather_local_nodes<Dim>(grid.data, pb.first_node, pb.slots, local);
                detail::LocalNodes<Dim> old;
                if (flip > 0.0) {
                    detail::gather_local_nodes<Dim>(grid.old_velocity, pb.first_node, pb.slots,
                                                    old);
                }
                for (int k = begin; k < end; ++k) {
                    const auto p = static_cast<std::size_t>(w.order[static_cast<std::size_t>(k)]);
                    if (averaging) {
                        w.particle_cell[p] = static_cast<std::int8_t>(
                            detail::dual_cell<Dim>(frame, pb.first_node, particles_.position[p]));
                    }
                    // FLIP part: the particle's own velocity less the grid's before the step.
                    if (flip > 0.0) {
                        const Vec<Dim> own = particles_.velocity[p];
                        Vec<Dim> old_grid;
                        detail::gather_particle<Dim, true>(
                            frame, pb.first_node, local, particles_.position[p],
                            particles_.velocity[p], particles_.affine[p], &old, &old_grid);
                        particles_.position[p] += dt * particles_.velocity[p];
                        particles_.velocity[p] += flip * (own - old_grid);
                    } else {
                        detail::gather_particle<Dim>(frame, pb.first_node, local,
                                                     particles_.position[p], particles_.velocity[p],
                                                     particles_.affine[p]);
                        particles_.position[p] += dt * particles_.velocity[p];
                    }
                    particles_.velocity[p] *= damping;
                    max_speed_squared =
                        std::max(max_speed_squared, particles_.velocity[p].squaredNorm());
                    if (averaging) {
                        w.particle_jacobian[p] =
                            (Mat<Dim>::Identity() + dt * particles_.affine[p]).determinant();
                    } else {
                        max_density = std::max(max_density, update_stress(particles_, p, model, dt,
                                                                          max_specific_volume));
                    }
                }
                return std::pair(max_speed_squared, max_density);
            };
            if (!averaging) {
                w.pool->run(w.chunk_split, [&](int i) {
                    const detail::ParticleChunk& chunk = w.chunks[static_cast<std::size_t>(i)];
                    const auto [speed, density] = gather(
                        w.blocks[static_cast<std::size_t>(chunk.block)], chunk.begin, chunk.end);
                    w.task_max[static_cast<std::size_t>(i)] = speed;
                    w.task_density[static_cast<std::size_t>(i)] = density;
                });
                return;
            }
            // Per particle block: gather, its dual cells' mean volume ratios, its stresses.
            w.pool->run(w.block_split, [&](int i) {
                const ParticleBlock<Dim>& pb = w.blocks[static_cast<std::size_t>(i)];
                const double speed = gather(pb, pb.begin, pb.end).first;
                const auto means = dual_cell_means(pb.begin, pb.end);
                double max_density = 0.0;
                for (int k = pb.begin; k < pb.end; ++k) {
                    const auto p = static_cast<std::size_t>(w.order[static_cast<std::size_t>(k)]);
                    const double mean = means[static_cast<std::size_t>(w.particle_cell[p])];
                    max_density = std::max(
                        max_density, update_stress(particles_, p, model, dt, max_specific_volume,
                                                   std::pair(w.particle_jacobian[p], mean)));
                }
                w.task_max[static_cast<std::size_t>(i)] = speed;
                w.task_density[static_cast<std::size_t>(i)] = max_density;
            });
        },
        material_);
    double max_speed_squared = 0.0;
    for (const double m : w.task_max) {
        max_speed_squared = std::max(max_speed_squared, m);
    }
    max_speed_ = std::sqrt(max_speed_squared);
    max_density_ = 0.0;
    for (const double m : w.task_density) {
        max_density_ = std::max(max_density_, m);
    }
}

// Volumetric averaging: the volume-weighted mean volume ratio det(I + dt C) over each of the
// 2^Dim dual cells of the particle block holding the sorted particles [begin, end) (they are
// summed in that order, so the result is thread-count independent).
template <int Dim>
std::array<double, 1 << Dim> Solver<Dim>::dual_cell_means(int begin, int end) const {
    const Workspace& w = *work_;
    std::array<double, 1 << Dim> sum{};
    std::array<double, 1 << Dim> weight{};
    for (int k = begin; k < end; ++k) {
        const auto p = static_cast<std::size_t>(w.order[static_cast<std::size_t>(k)]);
        const auto cell = static_cast<std::size_t>(w.particle_cell[p]);
        sum[cell] += particles_.volume[p] * w.particle_jacobian[p];
        weight[cell] += particles_.volume[p];
    }
    for (std::size_t c = 0; c < sum.size(); ++c) {
        if (weight[c] > 0.0) sum[c] /= weight[c];
    }
    return sum;
}

template class Solver<2>;
template class Solver<3>;

}  // namespace rockfall::mpm
