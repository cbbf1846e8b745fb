// The database record of a soil flow (see soil_record.hpp).

#include "soil_record.hpp"

#include "report/text_format.hpp"
#include "sweep_record.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rockfall::app {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A scene vector of a run: its y is NaN in 2D, where a plane-strain section has none.
db::SceneVector scene(const mpm::Vec3& v, int dimension) {
    return {v.x(), dimension == 2 ? nan : v.y(), v.z()};
}

}  // namespace

db::SoilRunRecord make_soil_record(const scenario::SoilFile& file, const mpm::SoilOutcome& o,
                                   const SoilRunTimes& times) {
    const mpm::SoilScenario& s = file.scenario;
    db::SoilRunRecord r;
    r.run.tool_version = ROCKFALL_VERSION;
    r.run.build = ROCKFALL_BUILD;
    r.run.scenario_name = file.name;
    r.run.scenario_text = file.text;
    r.run.scenario_hash = identity_hash({file.text, nlohmann::json::object(), ""});
    r.run.seed = 0;  // the flow is deterministic
    r.run.method = "mpm";
    r.run.samples_planned = 1;
    r.run.stop_rule = "duration " + report::fmt("%g s", s.output.duration);
    r.run.settings_json = nlohmann::json{
        {"dimension", s.numerics.dimension},
        {"cell_size_m", s.numerics.cell_size},
        {"particles_per_cell", s.numerics.particles_per_cell},
        {"cfl", s.numerics.cfl},
        {"align_grid", s.numerics.align_grid},
        {"boundary_reach", s.numerics.boundary_reach},
        {"volumetric_averaging", s.numerics.volumetric_averaging},
        {"flip", s.numerics.flip},
        {"min_density_ratio", s.numerics.min_density_ratio},
        {"wall_support",
         s.boundaries.wall_support == mpm::WallSupport::spring ? "spring" : "rigid"},
        {"wall_facing_mass_kg_m2", s.boundaries.wall_facing_mass},
        {"wall_stiffness_Pa_m", s.boundaries.wall_stiffness},
        {"wall_damping_ratio", s.boundaries.wall_damping_ratio},
        {"threads",
         s.numerics.threads}}.dump();
    r.run.started_at = times.started_at;
    r.run.finished_at = times.finished_at;
    r.run.status = "complete";

    r.dimension = o.dimension;
    r.outcome = mpm::status_name(o.status);
    r.message = o.message;
    r.particles = o.particles;
    r.steps = o.steps;
    r.cell_size = s.numerics.cell_size;
    r.mass = o.mass;
    r.simulated_time = o.step_time.empty() ? 0.0 : o.step_time.back();
    r.runtime = times.runtime;
    r.wall_distance_from_toe = s.slope.wall.enabled ? s.slope.wall.distance_from_toe : nan;
    r.sample_interval = s.output.sample_interval;
    r.filter_window = s.output.filter_window;
    r.peak_force = o.peak_wall_force;
    r.peak_time = o.peak_wall_force_time;
    r.peak_force_filtered = o.peak_wall_force_filtered;
    r.peak_force_step = 0.0;
    for (const double f : o.step_wall_force) r.peak_force_step = std::max(r.peak_force_step, f);
    r.impulse = o.wall_impulse;
    r.runout_x = o.deposit.runout_x;
    r.runout_past_toe = o.deposit.runout_past_toe;

    for (std::size_t k = 0; k < o.sample_time.size(); ++k) {
        r.load.push_back({o.sample_time[k], scene(o.wall_load[k], o.dimension),
                          scene(o.wall_load_filtered[k], o.dimension)});
        r.motion.push_back({o.sample_time[k], scene(o.centre_of_mass[k], o.dimension), o.front_x[k],
                            o.kinetic_energy[k]});
    }
    double previous = 0.0;
    for (std::size_t k = 0; k < o.step_time.size(); ++k) {
        r.step_load.push_back(
            {o.step_time[k], o.step_time[k] - previous, scene(o.step_wall_load[k], o.dimension)});
        previous = o.step_time[k];
    }
    for (std::size_t b = 0; b < o.deposit.profile_x.size(); ++b) {
        r.deposit.push_back({o.deposit.profile_x[b], o.deposit.profile_height[b]});
    }
    return r;
}

}  // namespace rockfall::app
