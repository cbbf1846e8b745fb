#pragma once
/// Explicit MLS-MPM solver (Hu et al. 2018, A moving least squares material point method,
/// ACM Trans. Graph. 37(4)) with APIC transfers (Jiang et al. 2015, The affine particle-in-cell
/// method, ACM Trans. Graph. 34(4)) and quadratic B-spline shape functions, in 2D plane strain
/// or 3D.
///
/// One step is five phases (update-stress-last):
///   1. clear grid: zero the grid blocks the particles touch;
///   2. particles to grid: mass and APIC momentum, plus the internal force of the particle
///      stress, f_i = -sum_p V_p sigma_p D^-1 (x_i - x_p) w_ip with D^-1 = 4/h^2 I (Hu et al.
///      2018, eq. 18);
///   3. grid update: v_i = p_i / m_i + dt g, then the boundaries in group order,
///      recording the momentum each group removes;
///   4. grid to particles: v_p = sum w v_i, C_p = D^-1 sum w v_i (x_i - x_p)^T, x_p += dt v_p
///      (optional damping of v_p);
///   5. stress update: sigma co-rotated with the spin W = skew(C_p) (Jaumann rate), then the
///      constitutive model with the strain increment sym(C_p) dt; V_p *= det(I + dt C_p).
/// They run as three parallel passes: each particle block scatters into its own buffer (2);
/// each grid block is cleared, sums the buffers overlapping it and is updated (1, 2, 3); each
/// particle block gathers, moves and updates its stresses (4, 5).
///
/// Parallel and deterministic: particles are sorted by particle block (2 cells per axis); every
/// block scatters into a private 4^Dim node buffer, and each grid node sums the buffers that
/// write it in the order of their colour (2^Dim colours by block parity; blocks of one colour
/// never share a node), so every node sums its contributions in the same order whatever the
/// thread count. Reductions run in a fixed order. Results are bitwise identical for any thread
/// count.

#include "mpm/boundary.hpp"
#include "mpm/material.hpp"
#include "mpm/math.hpp"
#include "mpm/particles.hpp"

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace rockfall::mpm {

/// Numerical settings of a solver.
struct SolverSettings {
    /// Grid cell size h, m (> 0).
    double cell_size = 0.2;
    /// Lower corner of the grid domain (scene frame; 2D ignores y), m; it is a grid node, so the
    /// node planes lie at domain_min + k cell_size: this places the grid.
    Vec3 domain_min = Vec3::Zero();
    /// Upper corner of the grid domain (scene frame; 2D ignores y), m; at least 4 cells
    /// beyond domain_min on every axis.
    Vec3 domain_max = Vec3::Ones();
    /// Gravity (scene frame; 2D uses x and z), m/s2.
    Vec3 gravity = Vec3(0.0, 0.0, -9.81);
    /// How far outside a solid a grid node may lie and still be constrained by it, as a fraction
    /// of cell_size, [0, 0.5]. 0 (default): only nodes on or inside the solid, so a surface
    /// between node planes acts up to one cell behind its true place and the soil in front of
    /// it is compliant (place node planes on walls through domain_min, which is a node). 0.5:
    /// the node layer nearest the surface, within h/2 of its true place on either side (the
    /// at-rest thrust against a wall between node planes: 45 % of K0 gamma H^2 / 2 with 0,
    /// 89 % with 0.5, tests/mpm/test_column_at_rest.cpp). Both agree when a node plane lies on
    /// the surface.
    double boundary_reach = 0.0;
    /// Courant number of stable_time_step(), (0, 1].
    double cfl = 0.3;
    /// Upper bound of stable_time_step(), s (> 0).
    double max_time_step = 1e-2;
    /// Viscous damping of the particle velocities after each transfer, 1/s (>= 0; 0 = none):
    /// v_p <- v_p / (1 + damping dt) after the position update. For quasi-static set-ups only; it
    /// does not alter the boundary reactions of a body at rest.
    double damping = 0.0;
    /// Worker threads including the caller (>= 0; 0 = the hardware's thread count).
    int threads = 0;
    /// Steps between physical reorderings of the particle arrays by grid block (>= 1).
    int reorder_interval = 16;
    /// true (default): F-bar volumetric averaging. Each particle's volume ratio over the step,
    /// det(I + dt C_p), is replaced by the volume-weighted mean over its dual cell (the h-wide
    /// box centred on a grid node, holding the particles whose stencil starts one node below
    /// it): the increment I + dt C_p is scaled by (mean / own)^(1/Dim) before the stress and
    /// volume update, so the deviatoric part and the spin stay the particle's own and every
    /// volume stays positive. This is the cell-averaged F-bar of Coombs et al. (2018) applied
    /// to the step's increment. false: each particle's own rate (the solver before
    /// 2026-12-04; a plastic flow at zero dilatancy then locks, and the seed flow's static wall
    /// load rose about 10 % per halving of the cell, docs/soil.md).
    bool volumetric_averaging = true;
    /// FLIP fraction of the particle velocity update, [0, 1]. 0 (default): APIC, v_p = sum w v_i
    /// (the grid velocity after the step). alpha > 0: v_p = sum w v_i + alpha (v_p_old -
    /// sum w v_i_old), v_i_old the grid velocity before the step's forces (PIC/FLIP blend,
    /// Zhu & Bridson 2005; with APIC's affine velocity as Fei et al. 2021). Each APIC transfer
    /// smooths the velocity field's non-affine part, a loss per step, so with alpha = 0 a flow's
    /// dissipation grows as the time step shrinks (docs/soil.md); alpha keeps 1 - alpha of it.
    double flip = 0.0;
    /// Lower bound of a particle's density as a fraction of the largest initial density, [0, 1)
    /// (0 = none): a particle's volume never grows past mass / (ratio rho_0).
    double min_density_ratio = 0.0;
};

/// One zero vector per boundary group (Eigen vectors are not zeroed by default).
inline std::array<Vec3, kBoundaryGroups> zero_impulses() {
    std::array<Vec3, kBoundaryGroups> zero;
    zero.fill(Vec3::Zero());
    return zero;
}

/// What one step did.
struct StepReport {
    /// Time step, s.
    double dt = 0.0;
    /// Momentum each boundary group removed from the grid this step (scene frame), N s;
    /// divided by dt it is the force the soil exerts on that group.
    std::array<Vec3, kBoundaryGroups> impulse = zero_impulses();
    /// Impulse the spring and dashpot of the SpringSupport (if any) passed to the fixed support
    /// this step, along its direction, N s: divided by dt it is the load-cell force.
    double spring_impulse = 0.0;
    /// Particles pulled back inside the grid domain this step (0 unless the domain is too small).
    int clamped_particles = 0;
    /// Largest particle speed after the step, m/s.
    double max_speed = 0.0;
};

/// The MPM solver over a fixed set of particles, one material and rigid boundaries.
template <int Dim>
class Solver {
  public:
    static_assert(Dim == 2 || Dim == 3, "the solver is 2D (plane strain) or 3D");

    /// Builds the grid and classifies boundary nodes lazily as the particles reach them; with
    /// `spring`, the static solids of its group are a spring-backed facing. Throws
    /// std::invalid_argument for invalid settings, material, boundaries or spring, or for
    /// particles outside the domain.
    Solver(const SolverSettings& settings, const Material& material, Particles<Dim> particles,
           std::vector<StaticBoundary> statics, std::vector<HingedBoundary> hinged = {},
           std::optional<SpringSupport> spring = std::nullopt);
    ~Solver();
    Solver(const Solver&) = delete;
    Solver& operator=(const Solver&) = delete;

    /// Largest stable step, s: cfl h / (c + v_max), c = sqrt((lambda + 2 mu) / rho) with the
    /// highest current particle density, v_max the largest particle speed; capped by
    /// max_time_step.
    double stable_time_step() const;

    /// Advances by dt seconds (> 0) through the five phases; no allocation once the grid has
    /// seen the region.
    const StepReport& step(double dt);

    /// Simulated time, s.
    double time() const { return time_; }
    /// Steps taken.
    long step_count() const { return step_count_; }
    /// The particles (their order changes as they are sorted by grid block).
    const Particles<Dim>& particles() const { return particles_; }
    /// Mutable particles, for setting initial stress or velocity between steps.
    Particles<Dim>& particles() { return particles_; }
    /// The settings.
    const SolverSettings& settings() const { return settings_; }
    /// Threads used: settings.threads (or the hardware's count), but at most one per 512
    /// particles.
    int threads() const { return threads_; }
    /// Grid nodes allocated so far (block-sparse grid), for memory reports.
    long allocated_nodes() const;
    /// Displacement of the spring-backed facing along its direction, m (0 without one).
    double spring_displacement() const { return spring_u_; }
    /// Velocity of the spring-backed facing along its direction, m/s (0 without one).
    double spring_velocity() const { return spring_w_; }

  private:
    struct Grid;
    struct Workspace;

    void bin_particles();
    void particles_to_grid(double dt);
    void update_grid(double dt);
    void update_spring(double dt);
    void grid_to_particles(double dt);
    std::array<double, 1 << Dim> dual_cell_means(int begin, int end) const;
    void reorder_particles();

    SolverSettings settings_;
    Material material_;
    Particles<Dim> particles_;
    std::vector<StaticBoundary> statics_;
    std::vector<HingedBoundary> hinged_;
    std::optional<SpringSupport> spring_;
    double spring_u_ = 0.0;
    double spring_w_ = 0.0;
    std::unique_ptr<Grid> grid_;
    std::unique_ptr<Workspace> work_;
    StepReport report_;
    double time_ = 0.0;
    long step_count_ = 0;
    int threads_ = 1;
    double max_speed_ = 0.0;
    double max_density_ = 0.0;
    // Largest particle density at construction, kg/m3 (SolverSettings::min_density_ratio).
    double initial_density_ = 0.0;
};

extern template class Solver<2>;
extern template class Solver<3>;

}  // namespace rockfall::mpm
