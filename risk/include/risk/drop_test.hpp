#pragma once
/// The virtual drop test of seed 001 ("Coefficient of restitution and drop tests"): a rock
/// dropped onto a horizontal surface in many random orientations, the three coefficients of
/// restitution of its first bounce (Eqs. 5-7) as distributions, and the surface restitution
/// that reproduces a measured mean kinematic coefficient (the paper's Fig. 11). SI units.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "risk/parameter_search.hpp"
#include "risk/sample_summary.hpp"
#include "risk/statistics.hpp"
#include "shapes/rocks.hpp"

#include <cstdint>
#include <vector>

namespace rockfall::risk {

/// One drop test: a rock, a surface, a height, and how many orientations.
struct DropTestSpec {
    /// The rock dropped (shape, size, density, its own material); a valid engine::RockSpec.
    engine::RockSpec rock;
    /// The surface's contact coefficients (defaults: the engine's slope material). The contact
    /// uses the mean of the rock's and the surface's values.
    engine::Material surface;
    /// Gap between the rock's lowest point and the surface at release, m (> 0).
    double height = 1.0;
    /// Number of drops, each in its own random orientation (>= 1).
    std::int64_t count = 40;
    /// Base seed: drop i runs with drop_seed(seed, i).
    std::uint64_t seed = 1;
    /// Time step, s, in [1e-5, 1e-2] (the engine's coarse step; the surface has no wall).
    double time_step = 1e-3;
    /// Gravitational acceleration, m/s2 (> 0).
    double gravity = 9.81;
};

/// Throws std::invalid_argument naming the field, its value, unit and allowed range when a
/// field of `spec` is out of range (the rock itself is checked by the scenario rules).
void check_drop_spec(const DropTestSpec& spec);

/// The engine seed of drop `index` (>= 0): splitmix64(splitmix64(seed) + index), a pure
/// function of the two, so results never depend on threads or order.
std::uint64_t drop_seed(std::uint64_t seed, std::int64_t index);

/// The scenario of one drop: a single horizontal segment (20 m long and wide, surface at z = 0,
/// no bars, side walls or wall, no stations) of the surface material, the rock released at its
/// middle `height` above it in a random orientation, and a time limit past the first apex.
engine::Scenario drop_scenario(const DropTestSpec& spec);

/// What one drop measured at its first bounce (the first touch up to the first apex of the
/// centre of mass in free flight; contacts in between belong to the bounce).
struct DropMeasurement {
    /// Drop index and its engine seed.
    std::int64_t index = 0;
    std::uint64_t seed = 0;
    /// Whether the rock left the surface upwards and reached an apex within the run; when
    /// false every coefficient is 0 (it stayed on the surface: toppled, slid or rested).
    bool rebounded = false;
    /// Mass, kg.
    double mass = 0.0;
    /// Fall H_i of the centre of mass from release to first touch, m (= the drop height).
    double drop_height = 0.0;
    /// Rise H_r of the centre of mass from its height at first touch to the apex, m (>= 0).
    double rebound_height = 0.0;
    /// Normal (vertical) speed of the centre of mass at first touch, m/s (> 0).
    double approach_speed = 0.0;
    /// Normal speed of the centre of mass after the last contact of the bounce, m/s (>= 0).
    double rebound_speed = 0.0;
    /// Normal impulse of the surface over the bounce, N s: the momentum change m (v_out + v_in)
    /// (the rigid contact is instantaneous; the weight's impulse while it is held is left out).
    double normal_impulse = 0.0;
    /// Normal impulse of the first contact alone (until the first step in free flight), N s,
    /// and its compression part (until the touching point's normal velocity is zero) and
    /// restitution part (sum: first_impulse); see docs/calibration.md.
    double first_impulse = 0.0;
    double compression_impulse = 0.0;
    double restitution_impulse = 0.0;
    /// Kinetic energy (translational + rotational) at first touch and after the bounce, J.
    double energy_before = 0.0;
    double energy_after = 0.0;
    /// Kinematic COR from heights, sqrt(H_r / H_i) (Eq. 5).
    double cor_height = 0.0;
    /// Kinematic COR from normal speeds, v_out / v_in (Eq. 5).
    double cor_speed = 0.0;
    /// Kinetic COR of the first contact, restitution over compression impulse (Poisson; Eq. 6,
    /// see the docs), >= 0.
    double cor_kinetic = 0.0;
    /// Energetic COR, sqrt(E_after / E_before) with rotation (Eq. 7, see the docs).
    double cor_energy = 0.0;
};

/// The first bounce in `states` (every step of one drop, the first the release state) of a
/// rock of `geometry` and `density` falling on the horizontal surface at height `surface_z`
/// (m) under `gravity` (m/s2). Throws std::runtime_error when the rock never touches it.
DropMeasurement measure_drop(const std::vector<engine::RockState>& states,
                             const shapes::RockGeometry& geometry, double density, double surface_z,
                             double gravity);

/// Runs drop `index` of `spec` (drop_scenario, engine::simulate with every step recorded) and
/// measures it. Throws std::runtime_error when the engine reports a numerical failure.
DropMeasurement run_drop(const DropTestSpec& spec, std::int64_t index);

/// Every drop of one test and the distributions of its outputs over the orientations.
struct DropTestResult {
    /// The drops, in index order.
    std::vector<DropMeasurement> drops;
    /// Drops without a rebound (all their coefficients 0).
    std::int64_t no_rebound = 0;
    /// Distributions of the four coefficients over every drop.
    SampleSummary cor_height;
    SampleSummary cor_speed;
    SampleSummary cor_kinetic;
    SampleSummary cor_energy;
    /// Distributions of approach and rebound speed (m/s), rebound height (m), normal impulse (N s).
    SampleSummary approach_speed;
    SampleSummary rebound_speed;
    SampleSummary rebound_height;
    SampleSummary normal_impulse;
};

/// Called on the calling thread with drops done and drops planned (the plan may grow).
using DropProgress = BatchProgress;

/// Runs the `spec.count` drops of a checked spec on `threads` (>= 1) worker threads; drop i's
/// result depends only on (spec, i), whatever the thread count.
DropTestResult run_drop_test(const DropTestSpec& spec, int threads,
                             const DropProgress& progress = {});

/// Which kinematic coefficient an identification matches.
enum class CorDefinition {
    height,  ///< sqrt(H_r / H_i), as measured in the laboratory (the paper's Fig. 9a)
    speed,   ///< v_out / v_in
};

/// One point of the curve mean COR against the surface restitution (the paper's Fig. 11).
struct CurvePoint {
    /// The surface's restitution, and the contact's (the mean with the rock's), in [0, 1].
    double surface_restitution = 0.0;
    double contact_restitution = 0.0;
    /// SampleSummary of the matched coefficient over the drops.
    SampleSummary cor;
};

/// Options of an identification.
struct RestitutionSearchOptions {
    /// Coefficient to match.
    CorDefinition definition = CorDefinition::height;
    /// Curve points, evenly spaced over surface restitution [0, 1] (>= 2).
    int curve_points = 11;
    /// The bracket is refined until narrower than this, in restitution (> 0).
    double tolerance = 1e-3;
    /// Most refinement steps after the curve.
    int max_iterations = 20;
    /// Worker threads (>= 1).
    int threads = 1;
};

/// The surface restitution that reproduces a target mean kinematic COR.
struct RestitutionIdentification {
    /// Target mean COR, in (0, 1).
    double target = 0.0;
    /// The identified surface restitution, and the contact restitution it gives with the rock.
    double surface_restitution = 0.0;
    double contact_restitution = 0.0;
    /// The matched coefficient's distribution at the identified restitution.
    SampleSummary achieved;
    /// Surface restitutions whose mean COR is consistent with the target: from where the
    /// upper bound of the 95 % interval of the mean first reaches the target to where its lower
    /// bound last does, interpolated linearly between the curve and refinement points.
    Interval consistent;
    /// The curve (evenly spaced), then every refinement point, each sorted by restitution.
    std::vector<CurvePoint> curve;
    std::vector<CurvePoint> refinements;
};

/// Finds the surface restitution in [0, 1] at which the mean `options.definition` COR of
/// `spec`'s drops (the same orientations at every value) equals `target`: the curve brackets
/// the first crossing, then the Illinois variant of regula falsi narrows it to the tolerance.
/// Throws std::invalid_argument when the target lies outside what the curve reaches (naming
/// the range), or is not in (0, 1).
RestitutionIdentification identify_surface_restitution(const DropTestSpec& spec, double target,
                                                       const RestitutionSearchOptions& options,
                                                       const DropProgress& progress = {});

}  // namespace rockfall::risk
