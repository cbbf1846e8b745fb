#pragma once
/// Sweep specifications and samples: what a Monte Carlo or Latin hypercube sweep varies, and
/// sample i's inputs as a pure function of (run seed, i), independent of threads and order.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "risk/distribution.hpp"
#include "shapes/rocks.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
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
    /// Lateral position y, m. Each sample draws it conditioned on the band where its rock fits
    /// between the slope's edges, |y| <= width / 2 - bounding radius - lateral_margin
    /// (inverse_cdf_within): uniform across the whole width gives uniform across the band, as
    /// random_rock_scenario draws it. A fixed value, or a support outside the band, is clamped.
    Distribution lateral = fixed(0.0);
};

/// The most samples one sweep plans: 10^8. A sweep keeps a list of the samples to run (8 bytes
/// each, 0.8 GB here) and its database grows by about 0.6 kB a rock (60 GB here for one rock a
/// sample); 10^8 samples take about 23 days on one core at 50 samples/s.
inline constexpr std::int64_t max_samples = 100'000'000;

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
    /// Planned number of samples, in [1, max_samples]; Latin hypercube strata are 1 / samples
    /// wide.
    std::int64_t samples = 1000;
    /// Shape families and their weights (same length, weights >= 0, one positive among these,
    /// entry_weights and generated_weight). Kind custom stands for base.rocks[0]'s custom
    /// shape and needs one.
    std::vector<shapes::RockKind> kinds = {shapes::RockKind::sphere};
    std::vector<double> kind_weights = {1.0};
    /// Named shapes drawn besides the families (catalogue entries, hulls given inline), each
    /// of kind custom, and their weights (same length, >= 0). Names are unique, non-empty and
    /// none of reserved_shape_names; null entries are not allowed.
    std::vector<std::shared_ptr<const shapes::CustomShape>> entries;
    std::vector<double> entry_weights;
    /// Weight (>= 0) of generated rocks: shapes::rock_with_sphericity with the default options,
    /// a target Wadell sphericity drawn from `sphericity` and a seed derived from (seed, sample
    /// index), scaled to the drawn size. One choice covers every shape: kinds, then entries,
    /// then generated rocks, with weights kind_weights, entry_weights, generated_weight.
    double generated_weight = 0.0;
    /// Target sphericity of generated rocks; set exactly when generated_weight > 0, with a
    /// support inside [min_target_sphericity, max_target_sphericity].
    std::optional<Distribution> sphericity;
    /// Nominal size (volume-equivalent diameter), m; support inside the scenario's range of
    /// rocks.size ([0.01, 10]; app::validate_sweep checks supports against the scenario's rules).
    Distribution size = fixed(0.2);
    /// Density, kg/m3; support inside the scenario's range ([500, 10000]).
    Distribution density = fixed(2600.0);
    /// Rock contact coefficients; supports inside the scenario's ranges ([0, 2], [0, 1], [0, 1]).
    Distribution friction = fixed(0.6);
    Distribution restitution = fixed(0.3);
    Distribution rolling_resistance = fixed(0.02);
    /// Release zones (at least one).
    std::vector<ReleaseZone> zones = {ReleaseZone{}};
    /// Clearance kept between the rock's bounding sphere and each slope edge, m (>= 0).
    double lateral_margin = 0.05;
    /// Initial speed along the downslope surface tangent at the release point, m/s (>= 0).
    Distribution speed = fixed(0.0);
    /// Initial angular speed about the across-slope axis, rad/s; positive rolls downslope.
    Distribution spin = fixed(0.0);
    /// true: a uniformly random orientation per sample (Haar measure); false: the base rock's
    /// orientation_deg.
    bool random_orientation = true;
};

/// Smallest target sphericity a sweep may draw: rock_with_sphericity reaches about 0.04, but
/// below 0.3 its rocks (axes 1 : t : t^2, t < 0.16) are slivers thinner than 1/40 of their
/// length rather than rocks.
inline constexpr double min_target_sphericity = 0.3;
/// Largest target sphericity a sweep may draw: the unstretched point cloud of every seed
/// tried (5000) reaches at least 0.956; a seed that cannot reach the target is replaced by the
/// next of its chain (see draw_sample).
inline constexpr double max_target_sphericity = 0.95;

/// Shape names that an entry may not take: the families, "custom" (the base rock's shape) and
/// "generated" (a rock of target sphericity), as samples and results databases name shapes.
inline constexpr std::array<std::string_view, 5> reserved_shape_names = {
    "sphere", "massive", "planar", "custom", "generated"};
/// Whether `name` is one of reserved_shape_names.
bool is_reserved_shape_name(std::string_view name);

/// Lower-case name of a method ("monte_carlo", "latin_hypercube").
std::string to_string(SweepSpec::Method method);

/// The spec that varies nothing: every input fixed at base.rocks[0]'s value, one zone
/// "release" at its release point, kinds = {its kind}, random_orientation = its
/// random_orientation, speed = its velocity along the surface tangent there, spin = its spin's
/// y component. For a cluster scenario (base.cluster set) the default SweepSpec: its samples
/// are whole cluster releases and only method, samples and seed apply. Throws
/// std::invalid_argument when base has neither a rock nor a cluster.
SweepSpec sweep_defaults(const engine::Scenario& base);

/// A shape that a spec may draw, for checks that depend on the shape.
struct DrawableShape {
    /// "sphere", "massive", "planar", "custom" (the base rock's), an entry's name, or
    /// "generated rock of sphericity 0.7".
    std::string name;
    /// The family, or kind custom with its hull.
    shapes::RockKind kind = shapes::RockKind::sphere;
    std::shared_ptr<const shapes::CustomShape> shape;
    /// Bounding radius of the rock at a nominal size of 1 m, m (scales with the size).
    double radius_per_size = 0.5;
};

/// The shapes a valid spec draws with weight > 0 (kind custom only when base.rocks[0] has a
/// shape). Generated rocks are represented by the widest for its size of 16 reference rocks
/// (seeds 0-15) at the sphericity support's lower end, its radius raised by 10 % for the
/// spread between seeds (over 1000 seeds the widest was 4.3 % wider); they are left out when
/// the sphericity distribution or its support is invalid.
std::vector<DrawableShape> drawable_shapes(const SweepSpec& spec, const engine::Scenario& base);

/// One problem of a sweep spec.
struct SweepProblem {
    /// Key path in the scenario file: "sweep.rock.size", "sweep.release.zones[1].weight", or
    /// "rocks[0].release.velocity" for a base value the sweep cannot keep.
    std::string key;
    /// The value and the rule it breaks: "uniform [0.4, 0.2] m: min = 0.4, max = 0.2: must
    /// have min < max".
    std::string message;
};

/// Every problem of the spec against base: a base without rocks, samples outside
/// [1, max_samples], kinds, entries,
/// generated rocks and their weights, a sphericity without generated rocks or the reverse, a
/// sphericity support outside the targets' range, each distribution's parameters
/// (find_problems), speeds below 0, zone names, weights and count, lateral_margin < 0, a
/// largest rock that does not fit across the slope with its margin (for generated rocks,
/// estimated from reference rocks, see drawable_shapes), and a base rock's velocity off the
/// surface tangent or spin off the across-slope axis (a sweep sets both from speed and spin).
/// Not checked here: the scenario's own ranges of size, density, material and release
/// distance, which app::validate_sweep applies to the supports with the scenario file's rules,
/// where they are defined. For a cluster scenario only samples is checked (the rest does not
/// apply; scenario files refuse the keys).
std::vector<SweepProblem> find_problems(const SweepSpec& spec, const engine::Scenario& base);

/// Throws std::invalid_argument listing find_problems(spec, base), one per line as
/// "key = message", when there is any.
void validate(const SweepSpec& spec, const engine::Scenario& base);

/// Sample i's inputs, the lateral position inside its band (what the engine runs).
struct SampleInputs {
    /// Sample index, 0-based.
    std::int64_t index = 0;
    /// Seed passed to engine::simulate for this sample.
    std::uint64_t seed = 0;
    /// Index into SweepSpec::zones.
    std::size_t zone = 0;
    /// Shape family, nominal size (m) and density (kg/m3).
    shapes::RockKind kind = shapes::RockKind::sphere;
    /// Which custom shape a sample of kind custom has: "" for base.rocks[0]'s own shape, an
    /// entry's name (SweepSpec::entries), or "generated" for a rock of target sphericity;
    /// "" for the families.
    std::string shape;
    /// A generated rock's target Wadell sphericity and the seed of its
    /// shapes::rock_with_sphericity: with the default RandomRockOptions they fix its hull.
    /// NaN and 0 for every other shape.
    double target_sphericity = std::numeric_limits<double>::quiet_NaN();
    std::uint64_t shape_seed = 0;
    /// Wadell sphericity of the rock simulated, in (0, 1] (1 for a sphere).
    double sphericity = 1.0;
    /// The custom hull drawn (null for the families). Not stored in results databases:
    /// sample_shape rebuilds it from kind, shape, target_sphericity and shape_seed.
    std::shared_ptr<const shapes::CustomShape> custom_shape;
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

/// Number of coordinates of a sample's point in the unit hypercube: zone, shape, size, density,
/// friction, restitution, rolling resistance, distance, lateral, speed, spin, three for the
/// orientation and the target sphericity of a generated rock, in that order (the last was
/// added after the others, so the draws of the first 14 are those of sweeps without it).
inline constexpr std::size_t sample_dimensions = 15;

/// Sample `index`'s point in the open unit hypercube (0, 1)^sample_dimensions, a pure function
/// of (spec.seed, spec.method, spec.samples, index). Its own generator,
/// make_generator(hash of seed and index), draws one uniform_open01 v_d per coordinate.
/// Monte Carlo: u_d = v_d. Latin hypercube (McKay, Beckman and Conover 1979): u_d = (pi_d(index)
/// + v_d) / samples, with pi_d a keyed pseudo-random permutation of [0, samples) (a balanced
/// Feistel network over the next power of 4, cycle-walked into range: Black and Rogaway 2002),
/// so that each of the `samples` strata of every coordinate holds exactly one sample of
/// 0..samples-1, with O(1) memory and no dependence on the order samples are drawn in. Throws
/// std::invalid_argument for index < 0 or, for Latin hypercube, index >= samples.
std::array<double, sample_dimensions> unit_point(const SweepSpec& spec, std::int64_t index);

/// Sample `index` (0 <= index; < spec.samples for Latin hypercube) of a validated spec: a pure
/// function of (spec, base, index). Each input is inverse_cdf (choose for zone and shape) of
/// its coordinate of unit_point, every coordinate drawn even for fixed inputs so that varying
/// one input never changes another's draws. The shape is chosen among kinds, entries and
/// generated rocks; a generated rock is rock_with_sphericity(target, shape_seed) with the
/// default options, target from the sphericity coordinate and shape_seed a hash of
/// (spec.seed, index) on a stream of its own (a seed whose point cloud cannot reach the target
/// is replaced by the next of a SplitMix64 chain; none of 5000 seeds needed it). The engine
/// seed is a hash of (spec.seed, index) on another stream. Without random_orientation the
/// orientation is base.rocks[0]'s orientation_deg.
/// For a cluster scenario (base.cluster set) the sample is one whole release of base, drawn by
/// the engine from the seed alone: only index and seed are drawn (the same engine seed as a
/// rock sample's), zone 0; kind, density and material are the cluster's; size, mass, release
/// point, speed, spin, orientation and sphericity are NaN (each rock's are in RockInputs).
SampleInputs draw_sample(const SweepSpec& spec, const engine::Scenario& base, std::int64_t index);

/// The custom hull of a sample as draw_sample made it, from what a results database stores
/// (kind, shape, target_sphericity, shape_seed): null for the families, base.rocks[0]'s shape
/// for "", the entry of that name, or the generated rock. Throws std::invalid_argument for an
/// entry name the spec does not have or a generated rock without a valid target.
std::shared_ptr<const shapes::CustomShape> sample_shape(const SweepSpec& spec,
                                                        const engine::Scenario& base,
                                                        const SampleInputs& inputs);

/// The one-rock scenario that sample runs (for a cluster scenario: base itself): base with rocks =
/// {base.rocks[0] with the inputs}: kind, size, density, material, release distance and lateral;
/// velocity = speed times the downslope surface tangent at the release point; spin = spin about +y
/// (across the slope), which rolls a rock downslope when positive (omega y x r n = r omega t);
/// orientation_deg from the inputs with random_orientation false, so the scenario alone fixes the
/// rock. A custom rock takes inputs.custom_shape, or base.rocks[0]'s shape when that is null and
/// inputs.shape is "" (inputs read back from a database: use the overload with the spec).
engine::Scenario sample_scenario(const engine::Scenario& base, const SampleInputs& inputs);

/// One rock of a sample as simulated: the inputs the results database keeps per rock.
struct RockInputs {
    /// Where the rock comes from: true for a rock of the scenario's [cluster], false for one of
    /// its [[rocks]] (the swept rock of a one-rock sample).
    bool cluster = false;
    /// Shape family, and which custom shape as SampleInputs::shape ("" for the families and
    /// for a [[rocks]] entry's own shape).
    shapes::RockKind kind = shapes::RockKind::sphere;
    std::string shape;
    /// Nominal size (volume-equivalent diameter, m), density (kg/m3), mass (kg).
    double size = 0.0;
    double density = 0.0;
    double mass = 0.0;
    /// Contact coefficients.
    engine::Material material;
};

/// The inputs of a one-rock sample's rock, as the sample's.
RockInputs rock_inputs(const SampleInputs& inputs);

/// Every rock of `scenario` (sample_scenario's) in engine order ([[rocks]], then the cluster),
/// given the outcome of its run (the cluster rocks' drawn sizes): a one-rock sample's rock is
/// rock_inputs(inputs); a [[rocks]] entry or a cluster rock has its spec's kind, density and
/// material, its size and the mass density * pi / 6 * size^3 (the size is the
/// volume-equivalent diameter).
std::vector<RockInputs> rock_inputs(const engine::Scenario& scenario, const SampleInputs& inputs,
                                    const std::vector<engine::RockOutcome>& outcomes);

/// One rock of a finished sample.
struct RockResult {
    /// Its inputs (rock_inputs).
    RockInputs inputs;
    /// Its outcome.
    engine::RockOutcome outcome;
    /// Trajectory samples, empty unless RunnerOptions::trajectory_interval > 0.
    std::vector<engine::RockState> trajectory;
};

/// One finished sample.
struct SampleResult {
    /// Its inputs (draw_sample); for a cluster release, mass is the sum of its rocks' masses.
    SampleInputs inputs;
    /// Its rocks in engine::Outcome::rocks order (index = rock index): one for a rock sample,
    /// the scenario's [[rocks]] then the cluster's for a cluster release.
    std::vector<RockResult> rocks;
};

/// sample_scenario with the custom hull rebuilt by sample_shape when inputs.custom_shape is
/// null (a sample read back from a results database).
engine::Scenario sample_scenario(const SweepSpec& spec, const engine::Scenario& base,
                                 const SampleInputs& inputs);

}  // namespace rockfall::risk
