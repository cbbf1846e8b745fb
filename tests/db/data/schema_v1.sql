-- A results database of schema version 1 (one rock per sample), as rockfall wrote it before
-- per-rock rows: the version-1 schema and three hand-made samples. tests/db/test_schema_v1.cpp
-- builds a file from it and reads it with this build.
PRAGMA application_id = 1380664908; PRAGMA user_version = 1;

CREATE TABLE run (
    id INTEGER PRIMARY KEY CHECK (id = 1),  -- one run per file
    kind TEXT NOT NULL CHECK (kind IN ('rock_sweep', 'soil_flow')),
    tool_version TEXT NOT NULL,
    build TEXT NOT NULL,
    scenario_name TEXT NOT NULL,
    scenario_text TEXT NOT NULL,            -- the complete resolved scenario (TOML)
    scenario_hash TEXT NOT NULL,            -- hash of scenario_text, hex
    seed INTEGER NOT NULL,                  -- uint64 run seed stored as its int64 bit pattern
    method TEXT NOT NULL,                   -- monte_carlo or latin_hypercube; mpm (soil)
    samples_planned INTEGER NOT NULL CHECK (samples_planned >= 0),
    stop_rule TEXT NOT NULL,
    settings_json TEXT NOT NULL,
    started_at TEXT NOT NULL,               -- UTC, ISO 8601
    finished_at TEXT,                       -- NULL while running
    status TEXT NOT NULL CHECK (status IN ('running', 'complete', 'interrupted'))
);

CREATE TABLE zones (
    zone INTEGER PRIMARY KEY,               -- index into the sweep's release zones
    name TEXT NOT NULL UNIQUE
);

CREATE TABLE samples (
    sample INTEGER PRIMARY KEY CHECK (sample >= 0),  -- 0-based sample index
    seed INTEGER NOT NULL,                  -- engine seed (uint64 as int64 bit pattern)
    zone INTEGER NOT NULL REFERENCES zones,
    kind TEXT NOT NULL,                     -- sphere, massive, planar, custom
    size_m REAL,                            -- nominal (volume-equivalent) diameter
    density_kg_m3 REAL,
    mass_kg REAL,
    friction REAL,
    restitution REAL,
    rolling_resistance REAL,
    release_distance_m REAL,                -- along the surface from the crown
    release_lateral_m REAL,
    speed_m_s REAL,                         -- initial speed along the surface
    spin_rad_s REAL,                        -- initial spin about the across-slope axis
    orientation_x_deg REAL,
    orientation_y_deg REAL,
    orientation_z_deg REAL,
    shape TEXT NOT NULL,                    -- the kind, or for custom: custom (the base rock's
                                            -- own shape), a named shape (catalogue entry) or
                                            -- generated (a rock of target sphericity)
    sphericity REAL,                        -- Wadell sphericity of the rock simulated
    target_sphericity REAL,                 -- generated rocks: the target drawn, else NULL
    shape_seed INTEGER                      -- generated rocks: generator seed (uint64 as int64
                                            -- bit pattern), else NULL
);

CREATE TABLE outcomes (
    sample INTEGER PRIMARY KEY REFERENCES samples,
    stop_reason TEXT NOT NULL,              -- at_rest, left_domain, time_limit, numerical_failure
    stop_time_s REAL,
    reach_m REAL,                           -- furthest horizontal distance past the toe
    final_x_m REAL,
    final_y_m REAL,
    final_z_m REAL,
    final_vx_m_s REAL,
    final_vy_m_s REAL,
    final_vz_m_s REAL,
    final_speed_m_s REAL,
    max_speed_m_s REAL,
    max_kinetic_energy_J REAL,
    max_bounce_height_m REAL,
    velocity_change REAL,                   -- V' between the first two stations
    wall_hits INTEGER NOT NULL CHECK (wall_hits >= 0)
);

CREATE TABLE stations (
    sample INTEGER NOT NULL REFERENCES samples,
    station INTEGER NOT NULL CHECK (station >= 1),  -- 1-based, scenario order
    distance_from_toe_m REAL,
    reached INTEGER NOT NULL CHECK (reached IN (0, 1)),
    time_s REAL,                            -- this and below: NULL when not reached
    speed_m_s REAL,
    parallel_speed_m_s REAL,
    angular_speed_rad_s REAL,
    bounce_height_m REAL,
    rolling_coefficient REAL,
    translational_energy_J REAL,
    rotational_energy_J REAL,
    PRIMARY KEY (sample, station)
) WITHOUT ROWID;

CREATE TABLE wall_impacts (
    sample INTEGER NOT NULL REFERENCES samples,
    hit INTEGER NOT NULL CHECK (hit >= 1),  -- 1-based, time order
    start_time_s REAL,
    end_time_s REAL,
    x_m REAL,                               -- force-weighted mean contact point
    y_m REAL,
    z_m REAL,
    impact_speed_m_s REAL,                  -- |velocity before|
    normal_speed_m_s REAL,
    normal_impulse_N_s REAL,
    tangential_impulse_N_s REAL,            -- magnitude
    tangential_impulse_x_N_s REAL,
    tangential_impulse_y_N_s REAL,
    tangential_impulse_z_N_s REAL,
    vx_before_m_s REAL,
    vy_before_m_s REAL,
    vz_before_m_s REAL,
    vx_after_m_s REAL,
    vy_after_m_s REAL,
    vz_after_m_s REAL,
    wx_before_rad_s REAL,
    wy_before_rad_s REAL,
    wz_before_rad_s REAL,
    wx_after_rad_s REAL,
    wy_after_rad_s REAL,
    wz_after_rad_s REAL,
    energy_before_J REAL,
    energy_after_J REAL,
    peak_force_N REAL,
    peak_time_s REAL,
    PRIMARY KEY (sample, hit)
) WITHOUT ROWID;

CREATE TABLE trajectories (
    sample INTEGER NOT NULL REFERENCES samples,
    time_s REAL NOT NULL,
    x_m REAL,
    y_m REAL,
    z_m REAL,
    vx_m_s REAL,
    vy_m_s REAL,
    vz_m_s REAL,
    wx_rad_s REAL,
    wy_rad_s REAL,
    wz_rad_s REAL,
    orientation_w REAL,                     -- unit quaternion, body to world
    orientation_x REAL,
    orientation_y REAL,
    orientation_z REAL,
    translational_energy_J REAL,
    rotational_energy_J REAL,
    kinetic_energy_J REAL,                  -- translational + rotational
    PRIMARY KEY (sample, time_s)
) WITHOUT ROWID;

CREATE VIEW sample_results AS
SELECT s.*, z.name AS zone_name, o.stop_reason, o.stop_time_s, o.reach_m, o.final_x_m,
       o.final_y_m, o.final_z_m, o.final_vx_m_s, o.final_vy_m_s, o.final_vz_m_s,
       o.final_speed_m_s, o.max_speed_m_s, o.max_kinetic_energy_J, o.max_bounce_height_m,
       o.velocity_change, o.wall_hits
FROM samples s JOIN outcomes o ON o.sample = s.sample LEFT JOIN zones z ON z.zone = s.zone;

CREATE VIEW impact_results AS
SELECT w.*, s.seed, s.kind, s.size_m, s.mass_kg, s.zone, z.name AS zone_name, s.shape,
       s.sphericity
FROM wall_impacts w JOIN samples s ON s.sample = w.sample LEFT JOIN zones z ON z.zone = s.zone;

CREATE VIEW sample_impacts AS
SELECT m.sample, s.seed, s.kind, s.size_m, s.mass_kg, s.zone, z.name AS zone_name, m.hits,
       m.peak_force_N, m.normal_impulse_N_s, m.energy_before_J, m.impact_speed_m_s,
       m.normal_speed_m_s, s.shape, s.sphericity
FROM (SELECT sample, COUNT(*) AS hits, MAX(peak_force_N) AS peak_force_N,
             MAX(normal_impulse_N_s) AS normal_impulse_N_s,
             MAX(energy_before_J) AS energy_before_J, MAX(impact_speed_m_s) AS impact_speed_m_s,
             MAX(normal_speed_m_s) AS normal_speed_m_s
      FROM wall_impacts GROUP BY sample) m
JOIN samples s ON s.sample = m.sample LEFT JOIN zones z ON z.zone = s.zone;


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
    filter_window_s REAL,                   -- centred moving average of the sampled load
    peak_force_x_N REAL,                    -- largest mean load over a sample interval
    peak_force_x_N_per_m REAL,
    peak_time_s REAL,                       -- end of that interval
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

INSERT INTO run VALUES (1, 'rock_sweep', '0.9.0', 'schema-1 fixture', 'v1 fixture',
  'name = "v1 fixture"', '0', 7, 'monte_carlo', 3, '3 samples', '{}',
  '2026-01-01T00:00:00Z', '2026-01-01T00:01:00Z', 'complete');
INSERT INTO zones VALUES (0, 'release');
INSERT INTO samples (sample, seed, zone, kind, size_m, density_kg_m3, mass_kg, friction, restitution, rolling_resistance, release_distance_m, release_lateral_m, speed_m_s, spin_rad_s, orientation_x_deg, orientation_y_deg, orientation_z_deg, shape, sphericity, target_sphericity, shape_seed) VALUES
  (0, 101, 0, 'sphere', 0.3, 2600, 36.8, 0.6, 0.3, 0.02, 0.5, 0, 0, 0, 0, 0, 0, 'sphere', 1, NULL, NULL),
  (1, 102, 0, 'massive', 0.2, 2600, 10.9, 0.6, 0.3, 0.02, 0.5, 0, 0, 0, 0, 0, 0, 'massive', 0.85, NULL, NULL),
  (2, 103, 0, 'sphere', 0.4, 2600, 87.1, 0.6, 0.3, 0.02, 0.5, 0, 0, 0, 0, 0, 0, 'sphere', 1, NULL, NULL);
INSERT INTO outcomes (sample, stop_reason, stop_time_s, reach_m, max_speed_m_s, max_kinetic_energy_J, max_bounce_height_m, wall_hits) VALUES
  (0, 'at_rest', 5.0, 1.5, 8.0, 1000, 0.2, 2),
  (1, 'at_rest', 4.0, 0.5, 6.0, 200, 0.1, 0),
  (2, 'left_domain', 6.0, 2.5, 9.0, 3000, 0.3, 1);
INSERT INTO stations (sample, station, distance_from_toe_m, reached) VALUES
  (0, 1, 0, 1), (1, 1, 0, 1), (2, 1, 0, 1);
INSERT INTO wall_impacts (sample, hit, impact_speed_m_s, normal_speed_m_s, normal_impulse_N_s, energy_before_J, peak_force_N) VALUES
  (0, 1, 5.0, 4.0, 300, 500, 1000),
  (0, 2, 2.0, 1.5, 100, 80, 3000),
  (2, 1, 6.0, 5.0, 600, 1500, 2000);
