#pragma once
/// The MPM solver's verification cases with analytic or experimental answers, shared by the
/// tests (tests/mpm/) and `rockfall validate`'s report: an elastic bar's first axial mode, a
/// soil column at rest (K0), a granular column collapse and a block sliding on an incline, all
/// 2D plane strain, one thread (results do not depend on the thread count). SI units.

#include "mpm/boundary.hpp"
#include "mpm/math.hpp"
#include "shapes/slope.hpp"

#include <vector>

namespace rockfall::mpm::verification {

/// Axis-aligned box between two corners (scene frame), m.
shapes::OrientedBox axis_box(const Vec3& lo, const Vec3& hi);

/// Box whose local x axis points down an incline of `angle_deg` (rotation about scene y), with
/// the given centre and half extents along (downslope, across, normal), m.
shapes::OrientedBox inclined_box(double angle_deg, const Vec3& center, const Vec3& half);

/// A static boundary of `box` with friction coefficient `mu` in boundary group `group`.
StaticBoundary solid(const shapes::OrientedBox& box, BoundaryKind kind, double mu, int group);

/// The bar's first axial mode: fixed at x = 0, free at x = L = 1 m, E = 10 MPa, 1000 kg/m3,
/// nu = 0, started with v(x) = v0 sin(pi x / 2L), v0 = 0.1 m/s, run for three periods
/// (analytic: omega = pi c / 2L, c = sqrt(E / rho); Sulsky et al. 1994).
struct ElasticBar {
    /// Cell size, m.
    double cell_size = 0.0;
    /// Period from the zero crossings of the mean velocity, and the analytic one, s.
    double period = 0.0;
    double expected_period = 0.0;
    /// Largest tip displacement in the first period and the analytic one, m.
    double tip_amplitude = 0.0;
    double expected_tip_amplitude = 0.0;
    /// Largest mean velocity in the third period and the analytic 2 v0 / pi, m/s.
    double late_velocity_amplitude = 0.0;
    double expected_velocity_amplitude = 0.0;
    /// Mean velocity of the bar against time, every step (s, m/s).
    std::vector<double> time;
    std::vector<double> mean_velocity;
};

/// Runs the elastic bar at cell size `cell_size` (m, <= 0.1). Throws std::runtime_error when
/// the mean velocity crosses zero fewer than 5 times.
ElasticBar elastic_bar(double cell_size = 0.05);

/// An elastic column (E = 10 MPa, 2000 kg/m3, 2 m high) at rest in a box with frictionless
/// walls, settled under gravity with damping; forces averaged over the last 0.2 s of 1 s.
struct ColumnForces {
    /// Weight of the column and the at-rest thrust K0 gamma H^2 / 2, K0 = nu / (1 - nu), N/m.
    double weight = 0.0;
    double thrust = 0.0;
    /// Force on the base and on the left and right walls, N/m.
    double base = 0.0;
    double left = 0.0;
    double right = 0.0;
};

/// The column `width` (m) wide with walls at x = 0 and x = width, base at z = 0, Poisson ratio
/// `nu`, cell `cell` (m); the grid's first node `offset` m below and left of the column's
/// corner (a multiple of the cell puts nodes on the walls); SolverSettings::boundary_reach
/// `reach` and volumetric_averaging `averaging`.
ColumnForces column_at_rest(double nu, double cell, double width, double offset, double reach = 0.0,
                            bool averaging = true);

/// Runout (L_inf - L0) / L0 of a granular column of aspect a = H0 / L0 by the fits of Lube et
/// al. 2005 (1.2 a below 1.8, 1.9 a^(2/3) above 2.8, the larger between) and of Lajeunesse et
/// al. 2005 (1.8 a below 3, 2.3 a^(2/3) from 3), as Lagree et al. 2011 tabulate them.
double lube_runout(double aspect);
double lajeunesse_runout(double aspect);

/// The collapse's column length L0, m.
inline constexpr double collapse_length = 0.2;

/// A planar column collapse: L0 = 0.2 m against a back wall, H0 = a L0, Drucker-Prager
/// (phi 30 deg plane-strain match, no cohesion, E 1 MPa, nu 0.3, 1600 kg/m3), geostatic K0
/// start, basal and wall friction 30 deg, 4 particles per cell, run until at rest (or 20
/// sqrt(H0 / g)).
struct ColumnCollapse {
    /// Aspect ratio a and cells per L0.
    double aspect = 0.0;
    int cells_per_length = 0;
    /// (front + h/4 - L0) / L0, the front being the farthest particle centre.
    double runout = 0.0;
    /// Simulated time, s, and steps in which particles were pulled back into the domain.
    double time = 0.0;
    int clamped_steps = 0;
    /// Final particle positions (x, z), m, and masses per metre of width, kg/m.
    std::vector<Vec<2>> deposit;
    std::vector<double> deposit_mass;
    /// Centre of mass of the deposit (x, z), m, and the kinetic energy at t = sqrt(H0 / g), J/m.
    Vec<2> centre_of_mass = Vec<2>::Zero();
    double early_kinetic_energy = 0.0;
};

/// Runout (x_f - L0) / L0 to the front x_f of the part of the deposit thicker than `thickness`
/// (m): per h-wide column of the grid the deposit's mass over (1600 kg/m3 h), the thickness at
/// the column's initial density (a particle's own volume also counts the dilation of soil that
/// separated), x_f the far edge of the farthest column above `thickness`. Unlike
/// ColumnCollapse::runout (the farthest particle) it ignores a tail thinner than `thickness`,
/// which a finer grid resolves further.
double deposit_front(const ColumnCollapse& collapse, double thickness);

/// Runout (x_t - L0) / L0 to the toe x_t of the deposit's surface: a least-squares line through
/// the thickness (as in deposit_front) of the h-wide grid columns past the thickest one whose
/// thickness lies in [lower, upper] (m), at the columns' centres, extended to zero thickness.
/// It reads the body of the deposit, not its tail, and so converges under refinement where the
/// farthest particle does not (docs/column_collapse.md). NaN with fewer than two such columns
/// or a line that does not fall.
double surface_toe(const ColumnCollapse& collapse, double lower, double upper);

/// The collapse's settings: the transfer (SolverSettings::cfl and flip), the solver's threads
/// (results do not depend on them) and the soil's friction angle (deg; the cone matched in
/// plane strain; the floor and back wall keep 30 deg).
struct CollapseNumerics {
    double cfl = 0.3;
    double flip = 0.0;
    int threads = 1;
    double friction_angle_deg = 30.0;
};

/// Runs the collapse of aspect `aspect` (> 0) at `cells_per_length` cells per L0 (>= 4).
ColumnCollapse column_collapse(double aspect, int cells_per_length = 16,
                               const CollapseNumerics& numerics = {});

/// A 0.4 m x 0.2 m elastic block (E = 5 MPa, nu 0.3, 2000 kg/m3, cell 0.05 m) released with zero
/// stress on an incline whose boundary is an oriented box not aligned with the grid.
struct BlockSlide {
    /// Acceleration along the incline from a least-squares fit s = s0 + v0 t + a t^2 / 2 of the
    /// centre of mass, m/s2, and the final displacement along it, m.
    double fitted_acceleration = 0.0;
    double displacement = 0.0;
    /// The analytic g (sin theta - tan phi_b cos theta), m/s2 (0 when the block holds).
    double expected_acceleration = 0.0;
    /// Displacement along the incline against time, every step (s, m).
    std::vector<double> time;
    std::vector<double> along;
};

/// Slides the block on an incline of `angle_deg` with basal friction angle
/// `friction_angle_deg` for `duration` s, with particle damping `damping` (1/s).
BlockSlide sliding_block(double angle_deg, double friction_angle_deg, double duration,
                         double damping = 0.0);

/// A Drucker-Prager soil layer (phi 30 deg, no cohesion, E 1 MPa, nu 0.3, 1600 kg/m3, geostatic
/// K0 start) 1 m long and `thickness` m thick, sliding at 1 m/s on a horizontal floor of basal
/// friction angle `friction_angle_deg`, at cells of `cell_size` m and 4 particles per cell.
struct LayerSlide {
    /// Deceleration from a least-squares line through the mean velocity until it halves, m/s2.
    double fitted_deceleration = 0.0;
    /// The analytic tan(phi_b) g, m/s2.
    double expected_deceleration = 0.0;
};

/// Slides the layer until its mean velocity halves (at most 1 s).
LayerSlide sliding_layer(double cell_size, double thickness, double friction_angle_deg);

}  // namespace rockfall::mpm::verification
