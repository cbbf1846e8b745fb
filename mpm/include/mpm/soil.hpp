#pragma once
/// Scenario C (seed 000): a soil mass released from a tilted bed at the crown flows down the
/// slope into the reaction wall. Plain structs with defaults (the seed's Table 1 and SPEC.md),
/// a validation, and a run that returns the wall load history, the motion and the deposit.

#include "mpm/material.hpp"
#include "mpm/math.hpp"
#include "shapes/slope.hpp"

#include <functional>
#include <string>
#include <vector>

namespace rockfall::mpm {

/// The seed slope for the soil flow: SPEC scenario A without angle bars (50 mm bars are far
/// below the 0.2 m grid and cannot be resolved).
shapes::SlopeSpec seed_soil_slope();

/// The soil block and the tilting bed that releases it. The bed is hinged at its lower edge on
/// a horizontal axis across the slope (scene y), at the crown plus an offset; the block lies on
/// the bed between the hinge and `length` upslope of it. The bed rotates from
/// initial_bed_angle_deg to bed_angle_deg over tilt_duration (linearly), then stays.
struct SoilRelease {
    /// Block length along the bed (downslope once tilted), m (> 0); seed 2.3.
    double length = 2.3;
    /// Block width across the slope, m (> 0); seed 1.9 (ignored in 2D).
    double width = 1.9;
    /// Block thickness normal to the bed, m (> 0); seed 0.20.
    double thickness = 0.20;
    /// Final bed angle above the horizontal, degrees, (0, 90); seed 66.
    double bed_angle_deg = 66.0;
    /// Bed angle at t = 0, degrees, [0, bed_angle_deg]; equal to bed_angle_deg (default) puts
    /// the block on the already tilted bed and releases it at t = 0.
    double initial_bed_angle_deg = 66.0;
    /// Time to tilt from the initial to the final angle, s (>= 0).
    double tilt_duration = 0.0;
    /// Hinge position relative to the crown, horizontal, m.
    double hinge_offset_x = 0.0;
    /// Hinge position relative to the crown, vertical, m.
    double hinge_offset_z = 0.0;
    /// Height of the bed's side boards above the bed, m (>= 0; 0 = none; ignored in 2D).
    double side_board_height = 0.3;
};

/// How the reaction wall is held.
enum class WallSupport {
    /// Rigid: the wall does not move (the paper's MPM model, and the default).
    rigid,
    /// A facing of areal mass wall_facing_mass on a spring of areal stiffness wall_stiffness and
    /// a dashpot in parallel (SpringSupport): a panel in front of a load cell. The wall load is
    /// then the spring and dashpot force, what the load cell measures.
    spring,
};

/// Boundary friction: the slope surface is frictional; the reaction wall is fixed (seed).
struct SoilBoundaries {
    /// Basal friction angle of the slope surface and side walls, degrees, [0, 89]; seed 30.
    double basal_friction_angle_deg = 30.0;
    /// Friction angle between soil and bed, degrees, [0, 89].
    double bed_friction_angle_deg = 30.0;
    /// Reaction wall as a fixed (no-slip, seed) boundary; false = frictional at the basal angle.
    bool wall_fixed = true;
    /// Rigid (default) or spring-backed reaction wall; the facing is the whole front face
    /// (wall height times the slope width, times 1 m in 2D) and moves normal to it.
    WallSupport wall_support = WallSupport::rigid;
    /// Facing mass per area of the face, kg/m2 (> 0); default 24, a 10 mm concrete panel
    /// (2400 kg/m3), seed 000's facing in front of its load cell.
    double wall_facing_mass = 24.0;
    /// Spring stiffness per area of the face, Pa/m (N/m per m2, > 0); default 1e7: 1 mm under
    /// 10 kPa, the order of the seed flow's pressures (the paper gives no value).
    double wall_stiffness = 1.0e7;
    /// Damping ratio of the facing on its spring, c / (2 sqrt(k m_f)), [0, 10]; default 0.05.
    double wall_damping_ratio = 0.05;
};

/// Discretisation and threads.
struct SoilNumerics {
    /// 3 (default) or 2 (plane-strain section along the slope's centre line, loads per metre).
    int dimension = 3;
    /// Grid cell size, m (> 0); seed 0.20.
    double cell_size = 0.20;
    /// Particles per cell edge, [1, 8]; 3 gives 27 per cell in 3D (about 3,000 particles for
    /// the seed block at 0.2 m; the paper used 3,922).
    int particles_per_cell = 3;
    /// Courant number, (0, 1].
    double cfl = 0.3;
    /// Grid placement. true (default): node planes lie on the reaction wall's front face
    /// (x = wall_x) and on the run-out surface (z of the toe), whatever the cell size, so those
    /// two boundaries act exactly at their surface; without a wall, on the toe's x. false: the
    /// grid's first node is 3 cells below and behind the bed and slope (the placement before
    /// this field), and a boundary between node planes acts where boundary_reach puts it.
    bool align_grid = true;
    /// How far outside a solid a grid node may lie and still be constrained by it, as a
    /// fraction of cell_size, [0, 0.5] (SolverSettings::boundary_reach). 0 (default): nodes on or
    /// inside the solid only, so a surface between node planes (the inclined slope segments,
    /// and with align_grid false the wall) acts up to one cell behind its true place; 0.5: the
    /// node layer nearest the surface, within h/2 of it.
    double boundary_reach = 0.0;
    /// Volumetric strain rate averaged over each dual cell before the stress update, against
    /// volumetric locking (SolverSettings::volumetric_averaging). true (default); false: the
    /// solver before 2026-12-04.
    bool volumetric_averaging = true;
    /// FLIP fraction of the particle velocity update, [0, 1] (SolverSettings::flip). 0
    /// (default): APIC, whose per-step smoothing makes a flow's dissipation depend on the time
    /// step; 0.99 keeps 1 % of it.
    double flip = 0.0;
    /// Density floor of a particle as a fraction of the soil's density, [0, 1)
    /// (SolverSettings::min_density_ratio). 0 (default): none.
    double min_density_ratio = 0.0;
    /// Worker threads (>= 0; 0 = all available).
    int threads = 0;
};

/// What is recorded and how.
struct SoilOutput {
    /// Simulated time, s (> 0); the seed flow takes about 6 s.
    double duration = 8.0;
    /// Interval of the sampled histories, s (> 0); also the window of the peak wall load.
    double sample_interval = 0.01;
    /// Width of the centred moving average of the wall load (the filtered history and peak),
    /// s (>= 0; 0 = no filtering).
    double filter_window = 0.05;
    /// Interval between particle frames passed to the frame callback, s (> 0).
    double frame_interval = 0.1;
};

/// A whole soil-flow scenario. Defaults: the seed experiment with the paper's MPM parameters.
struct SoilScenario {
    /// Slope geometry (shared with the rigid-body engine).
    shapes::SlopeSpec slope = seed_soil_slope();
    /// Soil strength and stiffness; default Table 1 (perfectly plastic Drucker-Prager).
    DruckerPrager material;
    /// Soil density, kg/m3 (> 0); seed Table 1: 1640 (the experiment's 18.5 kN/m3 is moister).
    double density = 1640.0;
    /// Block and bed.
    SoilRelease release;
    /// Boundary friction.
    SoilBoundaries boundaries;
    /// Discretisation.
    SoilNumerics numerics;
    /// Recording.
    SoilOutput output;
};

/// Checks every field; throws std::invalid_argument listing each problem as
/// `field = value unit: must be range`, one per line.
void validate(const SoilScenario& scenario);

/// How a run ended.
enum class SoilStatus {
    /// Ran to the requested duration.
    completed,
    /// Some particles reached the grid's edge and were held there (the domain was too small).
    left_domain,
    /// A non-finite particle state appeared; the run stopped.
    non_finite,
};

/// The status as stored and printed: "completed", "left_domain" or "non_finite".
const char* status_name(SoilStatus status);

/// The deposit at the end of the run.
struct SoilDeposit {
    /// Largest x reached by the soil (particle centres plus half a particle spacing), m.
    double runout_x = 0.0;
    /// runout_x minus the toe's x, m.
    double runout_past_toe = 0.0;
    /// Bin centres of the height profile along x, m (bins one cell wide).
    std::vector<double> profile_x;
    /// Largest soil height above the slope surface in each bin (over the width), m.
    std::vector<double> profile_height;
};

/// The results of one run. Forces are on the reaction wall, normal to it (scene +x, pushing
/// the wall downslope), in N (N per metre of width in 2D).
struct SoilOutcome {
    /// How the run ended; `message` says why when not completed.
    SoilStatus status = SoilStatus::completed;
    /// Explanation of a status other than completed.
    std::string message;
    /// Dimension the run used (2 or 3).
    int dimension = 3;
    /// Number of particles.
    long particles = 0;
    /// Soil mass, kg (kg/m in 2D).
    double mass = 0.0;
    /// Steps taken.
    long steps = 0;
    /// End time of every step, s.
    std::vector<double> step_time;
    /// Raw wall load of every step: momentum the wall's nodes lost divided by the step, N.
    std::vector<double> step_wall_force;
    /// Sample times (end of each sample interval), s.
    std::vector<double> sample_time;
    /// Wall load averaged over each sample interval (wall impulse / interval), N.
    std::vector<double> wall_force;
    /// Wall load averaged over exactly output.filter_window centred on the middle of each sample
    /// interval (from the step history, shorter at the ends of the run), N.
    std::vector<double> wall_force_filtered;
    /// The wall load as a vector (scene frame: x normal to the wall as wall_force, y across, z
    /// up; y is 0 in 2D), N: of every step, averaged over each sample interval, and filtered.
    /// The x components equal step_wall_force, wall_force and wall_force_filtered.
    std::vector<Vec3> step_wall_load;
    std::vector<Vec3> wall_load;
    std::vector<Vec3> wall_load_filtered;
    /// Centre of mass at each sample time (scene frame), m.
    std::vector<Vec3> centre_of_mass;
    /// Front: largest particle x at each sample time, m.
    std::vector<double> front_x;
    /// Kinetic energy at each sample time, J (J/m in 2D).
    std::vector<double> kinetic_energy;
    /// Peak wall load: the largest mean over any window of output.sample_interval within the
    /// run, every position tried (exact for the step history; mpm/load_window.hpp), N. At least
    /// the largest of wall_force, which only tries the sample grid's positions.
    double peak_wall_force = 0.0;
    /// Centre of the window of peak_wall_force, s.
    double peak_wall_force_time = 0.0;
    /// Filtered peak: the largest mean over any window of output.filter_window within the run,
    /// N (peak_wall_force if filter_window is 0).
    double peak_wall_force_filtered = 0.0;
    /// Total impulse on the wall, N s.
    double wall_impulse = 0.0;
    /// Spring-backed wall: largest displacement of the facing (along +x, away from the soil)
    /// and its displacement at the end, m; 0 for a rigid wall.
    double max_wall_displacement = 0.0;
    double final_wall_displacement = 0.0;
    /// Final deposit.
    SoilDeposit deposit;
};

/// Particle state handed to a frame callback and the VTK writer (scene frame, 3D vectors).
struct ParticleFrame {
    /// Simulated time, s.
    double time = 0.0;
    /// Positions, m.
    std::vector<Vec3> position;
    /// Velocities, m/s.
    std::vector<Vec3> velocity;
    /// Masses, kg (kg/m in 2D).
    std::vector<double> mass;
    /// Mean stress p = tr(sigma)/3, Pa (negative in compression).
    std::vector<double> mean_stress;
    /// Deviatoric stress q = sqrt(J2), Pa.
    std::vector<double> deviatoric_stress;
    /// Accumulated plastic shear strain.
    std::vector<double> plastic_shear_strain;
};

/// Called at t = 0 and every output.frame_interval with the particles; must not throw.
using FrameCallback = std::function<void(const ParticleFrame&)>;

/// Validates the scenario and runs it. Numerical trouble is reported in the outcome's status;
/// invalid input throws std::invalid_argument.
SoilOutcome run_soil(const SoilScenario& scenario, const FrameCallback& on_frame = {});

}  // namespace rockfall::mpm
