#include "schema.hpp"

namespace rockfall::db::schema {

// The calibration tables, in every file written since they were added (files of the same
// version written before lack them and are never calibration runs); a database of a drop test
// (run.kind = 'drop_test') or a heap test ('heap_test') fills them and leaves the sweep and
// soil tables empty. SQL comments stay in the file for its readers.
const std::string_view calibration_definition = R"sql(
-- A calibration experiment (`rockfall calibrate drop|heap --db`): one row per shape tested, in
-- command-line order. The contact between rock and surface uses the mean of the two materials.
CREATE TABLE calibration_shapes (
    shape INTEGER PRIMARY KEY CHECK (shape >= 0),
    label TEXT NOT NULL,                    -- what the rock is (a kind, a catalogue entry, ...)
    kind TEXT NOT NULL,                     -- sphere, massive, planar, custom
    size_m REAL,                            -- drop test: nominal (volume-equivalent) diameter;
                                            -- heap test: NULL (sizes from the grading)
    density_kg_m3 REAL,
    sphericity REAL,                        -- Wadell sphericity of the rock's hull
    rock_friction REAL,                     -- the rock's material as configured
    rock_restitution REAL,
    rock_rolling_resistance REAL,
    surface_friction REAL,                  -- the surface's material as configured
    surface_restitution REAL,
    surface_rolling_resistance REAL
);

-- The identification of a shape (with --target-cor or --target-angle): the parameter found,
-- the measured value it reproduces and what the experiment gave there.
CREATE TABLE calibration_identified (
    shape INTEGER PRIMARY KEY REFERENCES calibration_shapes,
    parameter TEXT NOT NULL CHECK (parameter IN ('surface_restitution', 'rock_friction')),
    measure TEXT NOT NULL CHECK (measure IN ('cor_height', 'cor_speed', 'angle_deg')),
    target REAL NOT NULL,                   -- the measured value matched, in measure's unit
    value REAL NOT NULL,                    -- the parameter identified
    contact_value REAL,                     -- drop test: the contact restitution there (mean
                                            -- with the rock's); heap test: NULL
    achieved_count INTEGER NOT NULL,        -- drops or heaps at the identified value
    achieved_mean REAL,
    achieved_sd REAL,
    achieved_mean_lower REAL,               -- 95 % Student t interval of the mean
    achieved_mean_upper REAL,
    consistent_lower REAL,                  -- parameter values whose interval holds the target
    consistent_upper REAL
);

-- The curve measure against parameter (Fig. 11: mean COR against surface restitution; Fig. 8:
-- mean angle of repose against rock friction), with the search's refinement points.
CREATE TABLE calibration_curve (
    shape INTEGER NOT NULL REFERENCES calibration_shapes,
    parameter_value REAL NOT NULL,
    refinement INTEGER NOT NULL CHECK (refinement IN (0, 1)),  -- 0: on the even grid
    contact_value REAL,                     -- drop test: contact restitution; heap test: NULL
    count INTEGER NOT NULL,                 -- drops or heaps
    mean REAL,
    sd REAL,
    p5 REAL,
    p50 REAL,
    p95 REAL,
    mean_lower REAL,                        -- 95 % Student t interval of the mean
    mean_upper REAL,
    PRIMARY KEY (shape, parameter_value)
) WITHOUT ROWID;

-- Every drop at the configured surface restitution: the first bounce (docs/calibration.md).
CREATE TABLE drop_tests (
    shape INTEGER NOT NULL REFERENCES calibration_shapes,
    drop_index INTEGER NOT NULL CHECK (drop_index >= 0),
    seed INTEGER NOT NULL,                  -- engine seed (uint64 as int64 bit pattern)
    rebounded INTEGER NOT NULL CHECK (rebounded IN (0, 1)),  -- 0: every COR is 0
    mass_kg REAL,
    drop_height_m REAL,                     -- fall of the centre of mass to first touch
    rebound_height_m REAL,                  -- rise of the centre of mass to the apex
    approach_speed_m_s REAL,                -- normal speed at first touch
    rebound_speed_m_s REAL,
    normal_impulse_N_s REAL,                -- over the bounce
    first_impulse_N_s REAL,                 -- first contact alone
    compression_impulse_N_s REAL,
    restitution_impulse_N_s REAL,
    energy_before_J REAL,                   -- kinetic, translational + rotational
    energy_after_J REAL,
    cor_height REAL,                        -- sqrt(H_r / H_i), Eq. 5
    cor_speed REAL,                         -- v_out / v_in, Eq. 5
    cor_kinetic REAL,                       -- restitution / compression impulse, Eq. 6
    cor_energy REAL,                        -- sqrt(E_after / E_before), Eq. 7
    PRIMARY KEY (shape, drop_index)
) WITHOUT ROWID;

-- Every heap, at the configured rock friction and at every friction of the curve.
CREATE TABLE heap_tests (
    shape INTEGER NOT NULL REFERENCES calibration_shapes,
    rock_friction REAL NOT NULL,
    heap INTEGER NOT NULL CHECK (heap >= 0),
    seed INTEGER NOT NULL,                  -- engine seed (uint64 as int64 bit pattern)
    status TEXT NOT NULL CHECK (status IN ('at_rest', 'time_limit', 'overflow',
                                           'numerical_failure')),
    rocks INTEGER NOT NULL,
    rolled_off INTEGER NOT NULL,            -- rocks that left the surface
    fill_height_m REAL,                     -- settled fill in the funnel before the lift
    fill_time_s REAL,                       -- simulated times of the three phases
    lift_time_s REAL,
    settle_time_s REAL,
    heap_height_m REAL,
    foot_radius_m REAL,
    angle_deg REAL,                         -- mean over the valid planes
    angle_sd_deg REAL,                      -- scatter over the valid planes
    valid_planes INTEGER NOT NULL,
    PRIMARY KEY (shape, rock_friction, heap)
) WITHOUT ROWID;

-- The outline fit of every heap in each vertical half-plane through the funnel's axis.
CREATE TABLE heap_planes (
    shape INTEGER NOT NULL,
    rock_friction REAL NOT NULL,
    heap INTEGER NOT NULL,
    plane INTEGER NOT NULL CHECK (plane >= 0),
    azimuth_deg REAL,
    valid INTEGER NOT NULL CHECK (valid IN (0, 1)),  -- enough outline points for a fit
    angle_deg REAL,
    fitted_points INTEGER NOT NULL,
    heap_height_m REAL,
    foot_radius_m REAL,
    PRIMARY KEY (shape, rock_friction, heap, plane),
    FOREIGN KEY (shape, rock_friction, heap) REFERENCES heap_tests
) WITHOUT ROWID;
)sql";

}  // namespace rockfall::db::schema
