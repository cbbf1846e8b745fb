#pragma once
/// A soil flow in a results database (`rockfall soil --db`): the same file format as a sweep's
/// (application_id, schema version, the run table) with run.kind = 'soil_flow' and the soil
/// tables soil_run, soil_load, soil_load_steps, soil_motion and soil_deposit (docs/database.md);
/// one run per file. The record is plain values, so db depends on neither the solver nor the
/// program.
///
/// Units: SI; forces are those the soil exerts on the reaction wall, in the scene frame (x
/// normal to the wall, pushing it downslope; y across the slope; z up). A 2D run is a
/// plane-strain section: its forces, impulses, masses and energies are per metre of width (N/m,
/// N s/m, kg/m, J/m; the file keeps them in the columns named `..._per_m`), and its y
/// components and centre-of-mass y are NaN.

#include "db/results_db.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace rockfall::db {

/// A vector in the scene frame (x downslope, y across, z up).
using SceneVector = std::array<double, 3>;

/// The wall load over one sample interval.
struct SoilLoadSample {
    /// End of the interval, s.
    double time = 0.0;
    /// Mean force over the interval (impulse / interval), N (N/m in 2D).
    SceneVector force{};
    /// `force` smoothed by the run's centred moving average (filter_window), N (N/m in 2D).
    SceneVector force_filtered{};
};

/// The raw wall load of one step.
struct SoilStepLoad {
    /// End of the step, s.
    double time = 0.0;
    /// Step length, s (> 0).
    double dt = 0.0;
    /// Momentum the wall's grid nodes lost in the step divided by dt, N (N/m in 2D).
    SceneVector force{};
};

/// The soil's motion at one sample time.
struct SoilMotionSample {
    /// Time, s.
    double time = 0.0;
    /// Centre of mass, m.
    SceneVector centre_of_mass{};
    /// Front: largest x reached by the soil, m.
    double front_x = 0.0;
    /// Kinetic energy, J (J/m in 2D).
    double kinetic_energy = 0.0;
};

/// One bin of the final deposit's height profile (bins one cell wide along x).
struct SoilDepositBin {
    /// Bin centre, m.
    double x = 0.0;
    /// Largest soil height above the slope surface in the bin (over the width), m.
    double height = 0.0;
};

/// One soil flow: the run record, a summary and the histories.
struct SoilRunRecord {
    /// Tool, scenario (resolved TOML text and hash), times and settings (JSON); seed 0, method
    /// "mpm", samples_planned 1, zones empty. Stored with run.kind = 'soil_flow'.
    RunRecord run;
    /// 2 (plane strain) or 3.
    int dimension = 3;
    /// How the flow ended: "completed", "left_domain" or "non_finite"; `message` says why when
    /// not completed.
    std::string outcome = "completed";
    std::string message;
    /// Material points and solver steps (>= 0).
    std::int64_t particles = 0;
    std::int64_t steps = 0;
    /// Grid cell size, m.
    double cell_size = 0.0;
    /// Soil mass, kg (kg/m in 2D).
    double mass = 0.0;
    /// Simulated time and wall-clock runtime, s.
    double simulated_time = 0.0;
    double runtime = 0.0;
    /// Horizontal distance from the toe to the wall's front face, m; NaN without a wall.
    double wall_distance_from_toe = std::numeric_limits<double>::quiet_NaN();
    /// Interval of the sampled histories and width of the moving-average filter, s.
    double sample_interval = 0.0;
    double filter_window = 0.0;
    /// Peak of the sampled wall load normal to the wall (x) and the end of its interval: N
    /// (N/m in 2D), s.
    double peak_force = 0.0;
    double peak_time = 0.0;
    /// Peak of the filtered wall load (x), N (N/m in 2D).
    double peak_force_filtered = 0.0;
    /// Peak of the single-step wall load (x), N (N/m in 2D).
    double peak_force_step = 0.0;
    /// Total impulse on the wall (x), N s (N s/m in 2D).
    double impulse = 0.0;
    /// Furthest x reached by the deposit, and that distance past the toe, m.
    double runout_x = 0.0;
    double runout_past_toe = 0.0;
    /// Sampled wall load, raw steps, motion and deposit profile, in time (or x) order.
    std::vector<SoilLoadSample> load;
    std::vector<SoilStepLoad> step_load;
    std::vector<SoilMotionSample> motion;
    std::vector<SoilDepositBin> deposit;
};

/// Throws DatabaseError (bad_file) unless a new database can be created at `path` (it does not
/// exist; its directory exists and is writable): a check before a long run. write_soil_run
/// checks again.
void check_new_database(const std::filesystem::path& path);

/// Writes a new database at `path` holding `record`, in one transaction in a hidden temporary
/// file published under `path` at the end: the file appears whole or not at all, and an
/// existing file is never replaced. Throws DatabaseError (bad_file) when `path` exists or its
/// directory is missing or read-only, (failure) when writing fails (e.g. disk full).
void write_soil_run(const std::filesystem::path& path, const SoilRunRecord& record);

/// The soil flow `db` holds (open it with ResultsDb::open_any). Throws DatabaseError (bad_file)
/// when it holds a rock sweep, or when its soil tables are damaged.
SoilRunRecord read_soil_run(const ResultsDb& db);

}  // namespace rockfall::db
