#pragma once
/// Sweep specifications and samples: what a Monte Carlo or Latin hypercube sweep varies, and
/// sample i's inputs as a pure function of (run seed, i), independent of threads and order.

#include "engine/scenario.hpp"
#include "risk/distribution.hpp"
#include "shapes/rocks.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace rockfall::risk {

/// A part of the slope where rocks are released, with its share of the releases.
struct ReleaseZone {
    /// Name, for queries broken down by zone (unique within a sweep).
    std::string name = "release";
    /// Relative weight (> 0): zones are chosen with probability weight / sum of weights.
    double weight = 1.0;
    /// Distance along the surface from the crown, m (support inside [0, toe)).
    Distribution distance = fixed(0.5);
    /// Lateral position y, m; clamped per sample to the band where the rock fits between the
    /// slope's edges: |y| <= width / 2 - bounding radius - lateral_margin.
    Distribution lateral = fixed(0.0);
};

/// What a sweep varies. Every input that a scenario file's [sweep] table leaves out is fixed
/// at the base scenario's value for its first rock (see sweep_defaults).
struct SweepSpec {
    /// How the unit hypercube is sampled.
    enum class Method {
        monte_carlo,      ///< independent uniforms per sample
        latin_hypercube,  ///< one sample per stratum of each input (McKay et al. 1979)
    };
    Method method = Method::monte_carlo;
    /// Run seed (any 64-bit value).
    std::uint64_t seed = 1;
    /// Planned number of samples (>= 1); Latin hypercube strata are 1 / samples wide.
    std::int64_t samples = 1000;
    /// Shape families and their weights (same length, weights >= 0, one positive).
    std::vector<shapes::RockKind> kinds = {shapes::RockKind::sphere};
    std::vector<double> kind_weights = {1.0};
    /// Nominal size (volume-equivalent diameter), m; support inside [0.01, 10].
    Distribution size = fixed(0.2);
    /// Density, kg/m3; support inside [500, 10000].
    Distribution density = fixed(2600.0);
    /// Rock contact coefficients; supports inside the scenario's ranges ([0, 2], [0, 1], [0, 1]).
    Distribution friction = fixed(0.6);
    Distribution restitution = fixed(0.3);
    Distribution rolling_resistance = fixed(0.02);
    /// Release zones (at least one).
    std::vector<ReleaseZone> zones = {ReleaseZone{}};
    /// Clearance kept between the rock and each slope edge when clamping lateral, m (>= 0).
    double lateral_margin = 0.05;
    /// Initial speed along the downslope surface tangent at the release point, m/s (>= 0).
    Distribution speed = fixed(0.0);
    /// Initial angular speed about the across-slope axis, rad/s; positive rolls downslope.
    Distribution spin = fixed(0.0);
    /// true: a uniformly random orientation per sample (Haar measure); false: the base rock's
    /// orientation_deg.
    bool random_orientation = true;
};

/// Lower-case name of a method ("monte_carlo", "latin_hypercube").
std::string to_string(SweepSpec::Method method);

/// The spec that varies nothing: every input fixed at base.rocks[0]'s value, one zone at its
/// release point, kinds = {its kind}, random_orientation = its random_orientation.
SweepSpec sweep_defaults(const engine::Scenario& base);

/// Throws std::invalid_argument naming the key path ("sweep.rock.size", ...), the value and
/// the allowed range for any impossible parameter, including supports outside the ranges
/// above and release distances outside the slope above the toe.
void validate(const SweepSpec& spec, const engine::Scenario& base);

/// Sample i's inputs, after clamping (what the engine runs).
struct SampleInputs {
    /// Sample index, 0-based.
    std::int64_t index = 0;
    /// Seed passed to engine::simulate for this sample.
    std::uint64_t seed = 0;
    /// Index into SweepSpec::zones.
    std::size_t zone = 0;
    /// Shape family, nominal size (m) and density (kg/m3).
    shapes::RockKind kind = shapes::RockKind::sphere;
    double size = 0.2;
    double density = 2600.0;
    /// Rock contact coefficients.
    engine::Material material;
    /// Release distance along the surface from the crown (m) and lateral position (m).
    double release_distance = 0.5;
    double release_lateral = 0.0;
    /// Initial speed along the surface tangent (m/s) and spin about the across axis (rad/s).
    double speed = 0.0;
    double spin = 0.0;
    /// Orientation, x-y-z Euler angles in the surface frame, degrees.
    engine::Vec3 orientation_deg = engine::Vec3::Zero();
    /// Rock mass, kg (volume of the rock geometry times density).
    double mass = 0.0;
};

/// Sample `index` (0 <= index; < spec.samples for Latin hypercube) of a validated spec: a pure
/// function of (spec, base, index). The unit hypercube has one coordinate per input in a fixed
/// order (zone, kind, size, density, friction, restitution, rolling resistance, distance,
/// lateral, speed, spin, three for the orientation), all drawn even for fixed inputs so that
/// varying one input never changes another's draws.
SampleInputs draw_sample(const SweepSpec& spec, const engine::Scenario& base, std::int64_t index);

/// The one-rock scenario that sample runs: base with rocks = {base.rocks[0] with the inputs}.
engine::Scenario sample_scenario(const engine::Scenario& base, const SampleInputs& inputs);

}  // namespace rockfall::risk
