#include "schema.hpp"

namespace rockfall::db::schema {

// The soil-flow tables, in every file; a soil database (run.kind = 'soil_flow') fills them and
// leaves the sweep tables empty, a sweep database the reverse. SQL comments stay in the file
// for its readers.
const std::string_view soil_definition = R"sql(
-- A soil flow (`rockfall soil --db`): one row. Forces are those the soil exerts on the
-- reaction wall, scene frame: x normal to the wall (pushing it downslope), y across, z up. A 2D
-- run is a plane-strain section: its forces, impulses, masses and energies are per metre of
-- width and fill the *_per_m columns, whose plain twins stay NULL (the reverse in 3D); its y
-- columns are NULL.
CREATE TABLE soil_run (
    id INTEGER PRIMARY KEY CHECK (id = 1) REFERENCES run,
    dimension INTEGER NOT NULL CHECK (dimension IN (2, 3)),
    outcome TEXT NOT NULL CHECK (outcome IN ('completed', 'left_domain', 'non_finite')),
    message TEXT NOT NULL,                  -- why, when the outcome is not completed
    particles INTEGER NOT NULL CHECK (particles >= 0),
    steps INTEGER NOT NULL CHECK (steps >= 0),
    cell_size_m REAL,
    mass_kg REAL,
    mass_kg_per_m REAL,
    simulated_time_s REAL,
    runtime_s REAL,                         -- wall-clock time of the run
    wall_distance_from_toe_m REAL,          -- to the wall's front face; NULL without a wall
    sample_interval_s REAL,
    filter_window_s REAL,                   -- width of the filtered load's moving average
    peak_force_x_N REAL,                    -- largest mean over any sample_interval window
    peak_force_x_N_per_m REAL,
    peak_time_s REAL,                       -- centre of that window
    peak_force_x_filtered_N REAL,
    peak_force_x_filtered_N_per_m REAL,
    peak_force_x_step_N REAL,               -- largest load of a single step
    peak_force_x_step_N_per_m REAL,
    impulse_x_N_s REAL,                     -- total impulse on the wall
    impulse_x_N_s_per_m REAL,
    runout_x_m REAL,                        -- furthest x of the deposit
    runout_past_toe_m REAL
);

-- The wall load per sample interval: the mean (impulse / interval) and the filtered mean.
CREATE TABLE soil_load (
    time_s REAL PRIMARY KEY,                -- end of the interval
    force_x_N REAL,
    force_y_N REAL,
    force_z_N REAL,
    force_x_filtered_N REAL,
    force_y_filtered_N REAL,
    force_z_filtered_N REAL,
    force_x_N_per_m REAL,
    force_z_N_per_m REAL,
    force_x_filtered_N_per_m REAL,
    force_z_filtered_N_per_m REAL
) WITHOUT ROWID;

-- The raw wall load of every step: momentum the wall's grid nodes lost / dt.
CREATE TABLE soil_load_steps (
    step INTEGER PRIMARY KEY CHECK (step >= 1),
    time_s REAL NOT NULL,                   -- end of the step
    dt_s REAL NOT NULL,
    force_x_N REAL,
    force_y_N REAL,
    force_z_N REAL,
    force_x_N_per_m REAL,
    force_z_N_per_m REAL
);

-- The soil's motion per sample interval.
CREATE TABLE soil_motion (
    time_s REAL PRIMARY KEY,
    centre_x_m REAL,                        -- centre of mass
    centre_y_m REAL,
    centre_z_m REAL,
    front_x_m REAL,                         -- largest x reached by the soil
    kinetic_energy_J REAL,
    kinetic_energy_J_per_m REAL
) WITHOUT ROWID;

-- The final deposit's height profile, bins one cell wide along x.
CREATE TABLE soil_deposit (
    x_m REAL PRIMARY KEY,                   -- bin centre
    height_m REAL                           -- largest height above the slope surface in the bin
) WITHOUT ROWID;
)sql";

}  // namespace rockfall::db::schema
