#include "schema.hpp"

namespace rockfall::db::schema {

// SQL comments stay in the file (sqlite3's .schema shows them), so they are written for
// readers of the database. NaN is stored as NULL everywhere.
const std::string_view definition = R"sql(
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
)sql";

}  // namespace rockfall::db::schema
