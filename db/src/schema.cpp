#include "schema.hpp"

namespace rockfall::db::schema {

// SQL comments stay in the file (sqlite3's .schema shows them), so they are written for
// readers of the database. NaN is stored as NULL everywhere.
const std::string_view definition = R"sql(
CREATE TABLE run (
    id INTEGER PRIMARY KEY CHECK (id = 1),  -- one run per file
    kind TEXT NOT NULL CHECK (kind IN ('rock_sweep', 'soil_flow', 'drop_test', 'heap_test')),
    tool_version TEXT NOT NULL,
    build TEXT NOT NULL,
    scenario_name TEXT NOT NULL,
    scenario_text TEXT NOT NULL,            -- the complete resolved scenario (TOML)
    scenario_hash TEXT NOT NULL,            -- hash of scenario_text, hex
    seed INTEGER NOT NULL,                  -- uint64 run seed stored as its int64 bit pattern
    method TEXT NOT NULL,                   -- monte_carlo or latin_hypercube; mpm (soil);
                                            -- drop_test, heap_test (calibration)
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
    shape_seed INTEGER,                     -- generated rocks: generator seed (uint64 as int64
                                            -- bit pattern), else NULL
    rocks INTEGER NOT NULL DEFAULT 1 CHECK (rocks >= 1)  -- rocks simulated in the sample
);
-- A cluster release (a scenario with [cluster]): kind, density and material are the cluster's,
-- mass_kg the sum over its rocks, and size, release point, speed, spin, orientation and
-- sphericity are NULL; each rock's are in rocks.

CREATE TABLE rocks (
    sample INTEGER NOT NULL REFERENCES samples,
    rock INTEGER NOT NULL CHECK (rock >= 0),  -- 0-based, scenario order: [[rocks]], then cluster
    origin TEXT NOT NULL CHECK (origin IN ('rocks', 'cluster')),
    kind TEXT NOT NULL,                     -- sphere, massive, planar, custom
    shape TEXT NOT NULL,                    -- as samples.shape
    size_m REAL,                            -- nominal (volume-equivalent) diameter
    density_kg_m3 REAL,
    mass_kg REAL,
    friction REAL,
    restitution REAL,
    rolling_resistance REAL,
    PRIMARY KEY (sample, rock)
) WITHOUT ROWID;

CREATE TABLE outcomes (
    sample INTEGER NOT NULL REFERENCES samples,
    rock INTEGER NOT NULL CHECK (rock >= 0),  -- rocks.rock
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
    wall_hits INTEGER NOT NULL CHECK (wall_hits >= 0),
    PRIMARY KEY (sample, rock)
) WITHOUT ROWID;

CREATE TABLE stations (
    sample INTEGER NOT NULL REFERENCES samples,
    rock INTEGER NOT NULL CHECK (rock >= 0),
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
    PRIMARY KEY (sample, rock, station)
) WITHOUT ROWID;

CREATE TABLE wall_impacts (
    sample INTEGER NOT NULL REFERENCES samples,
    rock INTEGER NOT NULL CHECK (rock >= 0),
    hit INTEGER NOT NULL CHECK (hit >= 1),  -- 1-based, time order, per rock
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
    PRIMARY KEY (sample, rock, hit)
) WITHOUT ROWID;

CREATE TABLE trajectories (
    sample INTEGER NOT NULL REFERENCES samples,
    rock INTEGER NOT NULL CHECK (rock >= 0),
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
    PRIMARY KEY (sample, rock, time_s)
) WITHOUT ROWID;

)sql";

// The views, created after the tables; a version-1 file gets them as TEMP views over
// version1_adapter (compatible_views).
const std::string_view views = R"sql(
-- One row per rock: its sample's inputs, its own (rocks) and its outcome.
CREATE VIEW sample_results AS
SELECT s.sample, o.rock, s.seed, s.zone, r.kind, r.size_m, r.density_kg_m3, r.mass_kg,
       r.friction, r.restitution, r.rolling_resistance, s.release_distance_m,
       s.release_lateral_m, s.speed_m_s, s.spin_rad_s, s.orientation_x_deg, s.orientation_y_deg,
       s.orientation_z_deg, r.shape, s.sphericity, s.target_sphericity, s.shape_seed, s.rocks,
       r.origin, z.name AS zone_name, o.stop_reason, o.stop_time_s, o.reach_m, o.final_x_m,
       o.final_y_m, o.final_z_m, o.final_vx_m_s, o.final_vy_m_s, o.final_vz_m_s,
       o.final_speed_m_s, o.max_speed_m_s, o.max_kinetic_energy_J, o.max_bounce_height_m,
       o.velocity_change, o.wall_hits
FROM outcomes o JOIN samples s ON s.sample = o.sample
JOIN rocks r ON r.sample = o.sample AND r.rock = o.rock LEFT JOIN zones z ON z.zone = s.zone;

-- One row per wall hit, with its rock's kind, size and mass.
CREATE VIEW impact_results AS
SELECT w.*, s.seed, r.kind, r.size_m, r.mass_kg, s.zone, z.name AS zone_name, r.shape,
       s.sphericity, r.origin
FROM wall_impacts w JOIN samples s ON s.sample = w.sample
JOIN rocks r ON r.sample = w.sample AND r.rock = w.rock LEFT JOIN zones z ON z.zone = s.zone;

-- One row per rock that hit the wall: each wall quantity's largest value over its hits.
CREATE VIEW sample_impacts AS
SELECT m.sample, m.rock, s.seed, r.kind, r.size_m, r.mass_kg, s.zone, z.name AS zone_name,
       m.hits, m.peak_force_N, m.normal_impulse_N_s, m.energy_before_J, m.impact_speed_m_s,
       m.normal_speed_m_s, r.shape, s.sphericity
FROM (SELECT sample, rock, COUNT(*) AS hits, MAX(peak_force_N) AS peak_force_N,
             MAX(normal_impulse_N_s) AS normal_impulse_N_s,
             MAX(energy_before_J) AS energy_before_J, MAX(impact_speed_m_s) AS impact_speed_m_s,
             MAX(normal_speed_m_s) AS normal_speed_m_s
      FROM wall_impacts GROUP BY sample, rock) m
JOIN samples s ON s.sample = m.sample JOIN rocks r ON r.sample = m.sample AND r.rock = m.rock
LEFT JOIN zones z ON z.zone = s.zone;
)sql";

// Version 1 (one rock per sample, no rock column, no rocks table) read as version 2: TEMP
// views, which a read-only connection may create and which shadow the file's tables of the same
// name, add rock = 0 and a rocks table made of each sample's one rock.
const std::string_view version1_adapter = R"sql(
CREATE TEMP VIEW samples AS SELECT *, 1 AS rocks FROM main.samples;
CREATE TEMP VIEW rocks AS
SELECT sample, 0 AS rock, 'rocks' AS origin, kind, shape, size_m, density_kg_m3, mass_kg,
       friction, restitution, rolling_resistance FROM main.samples;
CREATE TEMP VIEW outcomes AS SELECT 0 AS rock, * FROM main.outcomes;
CREATE TEMP VIEW stations AS SELECT 0 AS rock, * FROM main.stations;
CREATE TEMP VIEW wall_impacts AS SELECT 0 AS rock, * FROM main.wall_impacts;
CREATE TEMP VIEW trajectories AS SELECT 0 AS rock, * FROM main.trajectories;
)sql";

}  // namespace rockfall::db::schema
