#pragma once
/// The funnel (heap) test of seed 001 ("Angle of repose test"): a hollow cylinder standing on a
/// surface is filled with a cluster of rocks, the rocks settle, the cylinder is lifted at a
/// constant speed as a kinematic body until it clears them, and the heap settles. This file
/// runs the physics; risk/heap_test.hpp measures the angle of repose. SI units.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "shapes/grading.hpp"
#include "shapes/lining.hpp"
#include "shapes/rocks.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace rockfall::engine {

/// The funnel: a vertical hollow cylinder of thin boxes around a circle, lifted at a speed.
/// Defaults: seed 001's glass funnel, 174 mm across and 0.40 m high, lifted at 7.5 mm/s.
struct Funnel {
    /// Inside diameter, m, in [0.02, 2].
    double inner_diameter = 0.174;
    /// Height, m, in [0.05, 5]: the settled fill must not rise above it. The modelled tube is
    /// as tall as the initial packing needs (the rocks start above one another and fall in).
    double height = 0.40;
    /// Wall thickness, m, in [1e-3, 0.05].
    double wall_thickness = 0.003;
    /// Boxes around the circle, in [12, 256]; the inside is the polygon inscribing the circle's
    /// tangents (its flats touch the circle).
    int facets = 48;
    /// Lift speed, m/s, in [1e-4, 1].
    double lift_speed = 0.0075;
    /// Gap between the funnel's rim and the surface before the lift, m, in [0, 0.01].
    double rim_gap = 5e-4;
    /// The wall's contact coefficients (glass: low friction, no rolling resistance).
    Material material{0.3, 0.3, 0.0};
};

/// One heap test's set-up: the rocks, the funnel, the surface and the stepping.
struct HeapScenario {
    /// Rock family or custom hull (catalogue entry, mesh), density and contact material of every
    /// rock; sizes are drawn from `grading` (the size here is ignored). Rock-rock contacts use
    /// this material, rock-surface contacts the mean with `surface`, rock-funnel the mean with
    /// the funnel's.
    RockSpec rock;
    /// Grain sizes and their number. Default: cluster C2's grading (Cu 1.52, d_max / d_min 3.3)
    /// scaled to d50 = 25 mm, 300 rocks (seed 001 gives no grading for its heap tests; C2's
    /// 53 mm rocks would be 3 across the funnel).
    shapes::Grading grading = [] {
        shapes::Grading g;
        g.count = 300;
        g.d50 = 0.025;
        g.d_min = 0.014;
        g.d_max = 0.047;
        return g;
    }();
    /// When > 0, each rock is a random hull of this Wadell sphericity, in [0.5, 0.95] (as a
    /// cluster's `sphericity`).
    double sphericity = 0.0;
    /// The funnel.
    Funnel funnel;
    /// The surface: a horizontal slab of this material, `floor_size` square, its top at z = 0.
    Material surface;
    /// Side of the square surface, m, in [4 funnel diameters, 20]; a rock whose centre leaves
    /// it has rolled off and is taken out of the run.
    double floor_size = 2.0;
    /// A perforated sheet lying on the surface (seed 001's lining, with the surface's material),
    /// or none.
    std::optional<shapes::PerforatedSheet> sheet;
    /// Time step of the fill, s, in [1e-5, 1e-2].
    double time_step = 1e-3;
    /// Time step of the lift and the heap's settling, s, in [1e-5, 1e-2]; 0: `time_step`. The
    /// fill is a fall of 0.2-0.4 m into the funnel at up to 3 m/s, the lift a slow flow of
    /// rocks at centimetres per second, which a longer step resolves as well given enough
    /// solver iterations (`lift_solver_iterations`).
    double lift_time_step = 2e-3;
    /// The rocks are at rest when their root mean square speed (mass-weighted, of the rocks on
    /// the surface) stays below this, m/s (> 0) ...
    double rest_speed = 0.01;
    /// ... for this long, s (> 0); the fill before the lift and the heap after it.
    double rest_duration = 0.3;
    /// Longest simulated time of the fill before the lift, s (> 0): a fill still moving by then
    /// is lifted all the same.
    double max_fill_time = 3.0;
    /// Longest simulated time of the heap's settling after the lift, s (> 0).
    double max_settle_time = 10.0;
    /// Solver iterations per step of the fill, in [1, 100].
    int solver_iterations = 10;
    /// Solver iterations per step of the lift and the settling, in [0, 100]; 0:
    /// `solver_iterations`. A pile creeps by what the iterations leave unsolved of each step's
    /// load, so its creep per second grows with the step: a 2 ms lift with 40 gives the angle
    /// of a 0.25-0.5 ms lift with 10, a 1 ms lift with 10 stands 2-4 deg flatter
    /// (docs/calibration.md, *The mechanism: the solver's iterations per step*).
    int lift_solver_iterations = 40;
    /// Penetration left uncorrected, in units of g dt^2, in [0, 100] (Numerics::contact_slop).
    double contact_slop = Numerics{}.contact_slop;
    /// Gravitational acceleration, m/s2 (> 0).
    double gravity = 9.81;
    /// Threads for the collision detection of each step, in [1, 1024]: not physics, the
    /// outcome is bit-identical whatever the count.
    int collision_threads = 1;
};

/// The time step of the lift and the settling, s: `lift_time_step`, or `time_step` when 0.
double effective_lift_step(const HeapScenario& heap);
/// The solver iterations of the lift and the settling: `lift_solver_iterations`, or
/// `solver_iterations` when 0.
int effective_lift_iterations(const HeapScenario& heap);

/// Whether a `lift_time_step` (s) is allowed: 0, or within `time_step`'s range [1e-5, 1e-2].
bool lift_step_allowed(double lift_time_step);

/// How a heap test ended.
enum class HeapStatus {
    at_rest,            ///< the heap came to rest after the lift
    time_limit,         ///< the heap still moved max_settle_time after the lift
    overflow,           ///< the settled fill rose above the funnel's height (no lift was run)
    numerical_failure,  ///< a rock's state became non-finite
};

/// Lower-case name of a status ("at_rest", "time_limit", "overflow", "numerical_failure").
const char* to_string(HeapStatus status);

/// What a heap test left: every rock's geometry and final state, and the run's times.
struct HeapOutcome {
    HeapStatus status = HeapStatus::at_rest;
    /// Every rock's geometry in its body frame (centroid at the origin) and its final state,
    /// in the same order; a rock that rolled off keeps its state when it left.
    std::vector<shapes::RockGeometry> rocks;
    std::vector<RockState> final_states;
    /// Whether each rock is still on the surface (false: it rolled off).
    std::vector<bool> on_floor;
    /// Height of the surface the heap stands on (the sheet's top with a sheet), m.
    double surface_z = 0.0;
    /// Funnel axis (x, y), m.
    double axis_x = 0.0;
    double axis_y = 0.0;
    /// Top of the settled fill above the surface before the lift, m.
    double fill_height = 0.0;
    /// Whether the fill met the rest criterion before max_fill_time (false: it was lifted
    /// still moving).
    bool fill_at_rest = true;
    /// Simulated times of the fill, the lift (until the rim cleared every rock) and the
    /// heap's settling after it, s.
    double fill_time = 0.0;
    double lift_time = 0.0;
    double settle_time = 0.0;
    /// Steps taken and rock-steps (rocks in the world times steps).
    std::int64_t steps = 0;
    std::int64_t body_steps = 0;
    /// Rocks that rolled off the surface.
    int rolled_off = 0;
};

/// Called after every step with the simulated time, s; returning false is not supported (the
/// run always completes). May be empty.
using HeapStepSink = std::function<void(double time)>;

/// The highest point of a rock of `geometry` at `state` above z = 0, m (its centre's height
/// plus the highest hull vertex, or the radius of a sphere).
double rock_top(const shapes::RockGeometry& geometry, const RockState& state);

/// Runs one heap test: the rocks drawn and packed (engine cluster code: sizes from the grading,
/// random orientations, sequential deposition of bounding spheres in the square inscribed in
/// the funnel) from `seed`, the fill settled inside the funnel, the lift, the heap settled.
/// The same scenario, seed and binary give bit-identical outcomes. The scenario must be valid
/// (risk::check_heap_spec); throws shapes::PackingError when the packing fails.
HeapOutcome simulate_heap(const HeapScenario& scenario, std::uint64_t seed,
                          const HeapStepSink& step = {});

}  // namespace rockfall::engine
