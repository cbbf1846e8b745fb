#include "risk/sampling.hpp"

#include "sample_shapes.hpp"

#include "engine/simulation.hpp"
#include "risk/number_text.hpp"
#include "risk/random_release.hpp"
#include "shapes/slope.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rockfall::risk {
namespace {

// Coordinates of a sample's point in the unit hypercube, in the order sampling.hpp documents.
enum Coordinate : std::size_t {
    zone_coordinate,
    kind_coordinate,
    size_coordinate,
    density_coordinate,
    friction_coordinate,
    restitution_coordinate,
    rolling_resistance_coordinate,
    distance_coordinate,
    lateral_coordinate,
    speed_coordinate,
    spin_coordinate,
    orientation_coordinate,  // and the two after it
    sphericity_coordinate = orientation_coordinate + 3,
};
static_assert(sphericity_coordinate + 1 == sample_dimensions);

// Independent streams of one run seed: the uniforms of the samples, the engine seeds, the
// Latin hypercube permutation keys and the seeds of generated rocks must not share hash inputs.
enum class Stream : std::uint64_t { draws = 1, engine = 2, permutation = 3, shape = 4 };

std::uint64_t hash(std::uint64_t seed, Stream stream, std::uint64_t index) {
    return splitmix64(splitmix64(splitmix64(seed) ^ static_cast<std::uint64_t>(stream)) + index);
}

// A balanced Feistel network on [0, 4^half_bits): a bijection whatever the round function, here
// SplitMix64 of (key, round, right half); six rounds make it a pseudo-random permutation
// (Luby and Rackoff 1988 need four with a pseudo-random round function).
std::uint64_t feistel(std::uint64_t x, int half_bits, std::uint64_t key) {
    constexpr std::uint64_t rounds = 6;
    const std::uint64_t mask = (std::uint64_t{1} << half_bits) - 1;
    std::uint64_t left = x >> half_bits;
    std::uint64_t right = x & mask;
    for (std::uint64_t round = 0; round < rounds; ++round) {
        // right < 2^32 and round < 2^8 occupy disjoint bits of the round function's input.
        const std::uint64_t next = left ^ (splitmix64(key ^ (round << 56) ^ right) & mask);
        left = right;
        right = next;
    }
    return (left << half_bits) | right;
}

// pi(index) for a keyed permutation pi of [0, n): the Feistel permutation of the smallest
// power-of-4 domain holding n, iterated until it lands below n (cycle walking, Black and
// Rogaway 2002). The walk stays on index's cycle, so it ends, after fewer than 4 steps on average.
std::uint64_t permute(std::uint64_t index, std::uint64_t n, std::uint64_t key) {
    assert(index < n);
    int half_bits = 1;
    while (half_bits < 32 && (std::uint64_t{1} << (2 * half_bits)) < n) ++half_bits;
    std::uint64_t x = index;
    do {
        x = feistel(x, half_bits, key);
    } while (x >= n);
    return x;
}

// Uniform in the open interval (0, 1), (top 52 bits + 1/2) 2^-52: inverse CDFs of unbounded
// distributions stay finite, and a Latin hypercube point stays inside its stratum.
double uniform_open01(std::mt19937_64& generator) {
    constexpr double two_to_minus_52 = 1.0 / 4503599627370496.0;
    return (static_cast<double>(generator() >> 12) + 0.5) * two_to_minus_52;
}

std::string vector_text(const engine::Vec3& v) {
    return "[" + number_text(v.x()) + ", " + number_text(v.y()) + ", " + number_text(v.z()) + "]";
}

// Checks one distribution; returns true when its parameters are valid.
bool check_distribution(std::vector<SweepProblem>& problems, const std::string& key,
                        const Distribution& d, const std::string& unit) {
    const std::vector<std::string> rules = find_problems(d);
    const std::string value = describe(d) + (unit.empty() ? "" : " " + unit);
    for (const std::string& rule : rules) problems.push_back({key, value + ": " + rule});
    return rules.empty();
}

void check_zones(std::vector<SweepProblem>& problems, const SweepSpec& spec) {
    if (spec.zones.empty()) {
        problems.push_back({"sweep.release.zones", "[]: must have at least one release zone"});
    }
    for (std::size_t i = 0; i < spec.zones.size(); ++i) {
        const ReleaseZone& zone = spec.zones[i];
        const std::string key = "sweep.release.zones[" + std::to_string(i) + "]";
        if (zone.name.empty()) {
            problems.push_back({key + ".name", "\"\": must not be empty"});
        } else {
            for (std::size_t j = 0; j < i; ++j) {
                if (spec.zones[j].name == zone.name) {
                    problems.push_back(
                        {key + ".name", "\"" + zone.name + "\": zone " + std::to_string(j) +
                                            " has this name too; names must differ"});
                    break;
                }
            }
        }
        if (!(zone.weight > 0.0 && std::isfinite(zone.weight))) {
            problems.push_back({key + ".weight", number_text(zone.weight) + ": must be > 0"});
        }
        check_distribution(problems, key + ".distance", zone.distance, "m");
        check_distribution(problems, key + ".lateral", zone.lateral, "m");
    }
}

// The largest rock of every shape that can be drawn must fit across the slope with its margin.
void check_lateral_room(std::vector<SweepProblem>& problems, const SweepSpec& spec,
                        const engine::Scenario& base) {
    const double largest = support(spec.size).upper;
    if (!std::isfinite(largest) || largest <= 0.0) return;
    // The bounding radius scales with the size; drawable_shapes measures it at 1 m, which keeps
    // make_rock in its range whatever size is asked for (the size's range is the scenario's).
    for (const DrawableShape& shape : drawable_shapes(spec, base)) {
        const double radius = largest * shape.radius_per_size;
        const double half_room = 0.5 * base.slope.width - radius - spec.lateral_margin;
        if (half_room < 0.0) {
            problems.push_back(
                {"sweep.rock.size", describe(spec.size) + " m: a " + shape.name + " of " +
                                        number_text(largest) + " m (bounding radius " +
                                        number_text(radius) + " m) with the lateral margin of " +
                                        number_text(spec.lateral_margin) +
                                        " m on each side does not fit across " + "the slope (" +
                                        number_text(base.slope.width) + " m wide)"});
        }
    }
}

// A sweep sets the release velocity from speed along the tangent and the spin about y; a base
// rock moving or spinning any other way could not be reproduced.
void check_base_motion(std::vector<SweepProblem>& problems, const engine::Scenario& base) {
    const engine::Release& release = base.rocks.front().release;
    const shapes::Slope slope(base.slope);
    const engine::Vec3 tangent =
        slope.surface_tangent(slope.point_at_distance(release.distance).x());
    const engine::Vec3 off_tangent = release.velocity - release.velocity.dot(tangent) * tangent;
    constexpr double tolerance = 1e-9;
    if (off_tangent.norm() > tolerance * std::max(1.0, release.velocity.norm())) {
        problems.push_back(
            {"rocks[0].release.velocity",
             vector_text(release.velocity) +
                 " m/s: a sweep starts each rock along the downslope surface tangent "
                 "(sweep.release.speed); give the base rock no velocity or one along " +
                 vector_text(tangent) + ", the tangent at its release point"});
    }
    const engine::Vec3 off_axis(release.spin.x(), 0.0, release.spin.z());
    if (off_axis.norm() > tolerance * std::max(1.0, release.spin.norm())) {
        problems.push_back({"rocks[0].release.spin",
                            vector_text(release.spin) +
                                " rad/s: a sweep spins each rock about the across-slope axis y "
                                "(sweep.release.spin); give the base rock no spin or a spin "
                                "[0, w, 0]"});
    }
}

}  // namespace

std::string to_string(SweepSpec::Method method) {
    switch (method) {
        case SweepSpec::Method::monte_carlo:
            return "monte_carlo";
        case SweepSpec::Method::latin_hypercube:
            return "latin_hypercube";
    }
    assert(false && "unknown sampling method");
    return "unknown";
}

namespace {

void check_sample_count(std::vector<SweepProblem>& problems, const SweepSpec& spec) {
    if (spec.samples < 1) {
        problems.push_back({"sweep.samples", std::to_string(spec.samples) + ": must be >= 1"});
    } else if (spec.samples > max_samples) {
        problems.push_back({"sweep.samples", std::to_string(spec.samples) + ": must be in [1, " +
                                                 std::to_string(max_samples) +
                                                 "], the most one sweep plans"});
    }
}

// A cluster release: the engine draws its rocks from the seed (engine/cluster_release.cpp), so
// only the seed is drawn here, on the stream a rock sample's engine seed comes from.
SampleInputs cluster_sample(const SweepSpec& spec, const engine::Cluster& cluster,
                            std::int64_t index) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    SampleInputs s;
    s.index = index;
    s.seed = hash(spec.seed, Stream::engine, static_cast<std::uint64_t>(index));
    s.zone = 0;
    s.kind = cluster.rock.kind;
    s.sphericity = nan;
    s.size = nan;
    s.density = cluster.rock.density;
    s.material = cluster.rock.material;
    s.release_distance = nan;
    s.release_lateral = nan;
    s.speed = nan;
    s.spin = nan;
    s.orientation_deg = engine::Vec3::Constant(nan);
    s.mass = nan;
    return s;
}

}  // namespace

SweepSpec sweep_defaults(const engine::Scenario& base) {
    if (base.cluster) return SweepSpec{};
    if (base.rocks.empty()) {
        throw std::invalid_argument("sweep_defaults: the base scenario has no rock to vary");
    }
    const engine::RockRelease& rock = base.rocks.front();
    const shapes::Slope slope(base.slope);
    const engine::Vec3 tangent =
        slope.surface_tangent(slope.point_at_distance(rock.release.distance).x());

    SweepSpec spec;
    spec.kinds = {rock.rock.kind};
    spec.kind_weights = {1.0};
    spec.size = fixed(rock.rock.size);
    spec.density = fixed(rock.rock.density);
    spec.friction = fixed(rock.rock.material.friction);
    spec.restitution = fixed(rock.rock.material.restitution);
    spec.rolling_resistance = fixed(rock.rock.material.rolling_resistance);
    ReleaseZone zone;
    zone.distance = fixed(rock.release.distance);
    zone.lateral = fixed(rock.release.lateral);
    spec.zones = {zone};
    spec.speed = fixed(rock.release.velocity.dot(tangent));
    spec.spin = fixed(rock.release.spin.y());
    spec.random_orientation = rock.release.random_orientation;
    return spec;
}

std::vector<SweepProblem> find_problems(const SweepSpec& spec, const engine::Scenario& base) {
    std::vector<SweepProblem> problems;
    if (base.cluster) {
        check_sample_count(problems, spec);
        return problems;
    }
    if (base.rocks.empty()) {
        problems.push_back({"rocks", "[]: a sweep varies the scenario's first rock; add one"});
        return problems;
    }
    check_sample_count(problems, spec);
    const bool shapes_ok = detail::check_shapes(problems, spec, base);
    if (spec.sphericity) {
        check_distribution(problems, "sweep.rock.sphericity", *spec.sphericity, "");
    }
    const bool size_ok = check_distribution(problems, "sweep.rock.size", spec.size, "m");
    check_distribution(problems, "sweep.rock.density", spec.density, "kg/m3");
    check_distribution(problems, "sweep.rock.material.friction", spec.friction, "");
    check_distribution(problems, "sweep.rock.material.restitution", spec.restitution, "");
    check_distribution(problems, "sweep.rock.material.rolling_resistance", spec.rolling_resistance,
                       "");
    if (check_distribution(problems, "sweep.release.speed", spec.speed, "m/s") &&
        support(spec.speed).lower < 0.0) {
        problems.push_back({"sweep.release.speed",
                            describe(spec.speed) + " m/s: every value must be >= 0 (a speed " +
                                "along the downslope tangent); truncate it with min = 0"});
    }
    check_distribution(problems, "sweep.release.spin", spec.spin, "rad/s");
    check_zones(problems, spec);
    const bool margin_ok = spec.lateral_margin >= 0.0 && std::isfinite(spec.lateral_margin);
    if (!margin_ok) {
        problems.push_back(
            {"sweep.lateral_margin", number_text(spec.lateral_margin) + " m: must be >= 0"});
    }
    if (size_ok && margin_ok && shapes_ok) check_lateral_room(problems, spec, base);
    check_base_motion(problems, base);
    return problems;
}

void validate(const SweepSpec& spec, const engine::Scenario& base) {
    const std::vector<SweepProblem> problems = find_problems(spec, base);
    if (problems.empty()) return;
    std::string message;
    for (const SweepProblem& problem : problems) {
        message += (message.empty() ? "" : "\n") + problem.key + " = " + problem.message;
    }
    throw std::invalid_argument(message);
}

std::array<double, sample_dimensions> unit_point(const SweepSpec& spec, std::int64_t index) {
    const bool latin = spec.method == SweepSpec::Method::latin_hypercube;
    if (index < 0 || (latin && index >= spec.samples)) {
        throw std::invalid_argument(
            "sample index " + std::to_string(index) + ": must be in [0, " +
            (latin ? std::to_string(spec.samples) + ") for a Latin hypercube of that many samples"
                   : std::string("inf)")));
    }
    const auto sample = static_cast<std::uint64_t>(index);
    std::mt19937_64 generator = make_generator(hash(spec.seed, Stream::draws, sample));
    std::array<double, sample_dimensions> point{};
    for (std::size_t d = 0; d < sample_dimensions; ++d) {
        const double v = uniform_open01(generator);
        if (!latin) {
            point[d] = v;
            continue;
        }
        const auto n = static_cast<std::uint64_t>(spec.samples);
        const std::uint64_t stratum = permute(sample, n, hash(spec.seed, Stream::permutation, d));
        const double strata = static_cast<double>(n);
        // (k + v) / n can round up to the next stratum's lower end: keep it below.
        const double upper = static_cast<double>(stratum + 1) / strata;
        const double u = (static_cast<double>(stratum) + v) / strata;
        point[d] = u < upper ? u : std::nextafter(upper, 0.0);
    }
    return point;
}

SampleInputs draw_sample(const SweepSpec& spec, const engine::Scenario& base, std::int64_t index) {
    if (base.cluster) return cluster_sample(spec, *base.cluster, index);
    assert(!base.rocks.empty() && !spec.zones.empty());
    const std::array<double, sample_dimensions> u = unit_point(spec, index);

    SampleInputs s;
    s.index = index;
    s.seed = hash(spec.seed, Stream::engine, static_cast<std::uint64_t>(index));
    std::vector<double> zone_weights;
    zone_weights.reserve(spec.zones.size());
    for (const ReleaseZone& zone : spec.zones) zone_weights.push_back(zone.weight);
    s.zone = choose(zone_weights, u[zone_coordinate]);
    detail::draw_shape(spec, base, u[kind_coordinate], u[sphericity_coordinate],
                       hash(spec.seed, Stream::shape, static_cast<std::uint64_t>(index)), s);
    s.size = inverse_cdf(spec.size, u[size_coordinate]);
    s.density = inverse_cdf(spec.density, u[density_coordinate]);
    s.material.friction = inverse_cdf(spec.friction, u[friction_coordinate]);
    s.material.restitution = inverse_cdf(spec.restitution, u[restitution_coordinate]);
    s.material.rolling_resistance =
        inverse_cdf(spec.rolling_resistance, u[rolling_resistance_coordinate]);

    const ReleaseZone& zone = spec.zones[s.zone];
    s.release_distance = inverse_cdf(zone.distance, u[distance_coordinate]);
    engine::RockSpec drawn;
    drawn.kind = s.kind;
    drawn.size = s.size;
    drawn.shape = s.custom_shape;
    const shapes::RockGeometry rock = drawn.geometry();
    s.sphericity = rock.sphericity;
    // validate() checked the largest rock against the band; rounding may leave -1e-17 here,
    // and a generated rock wider than the check's reference rocks a little more.
    const double half_band =
        std::max(0.0, 0.5 * base.slope.width - rock.bounding_radius - spec.lateral_margin);
    s.release_lateral =
        inverse_cdf_within(zone.lateral, -half_band, half_band, u[lateral_coordinate]);
    s.speed = inverse_cdf(spec.speed, u[speed_coordinate]);
    s.spin = inverse_cdf(spec.spin, u[spin_coordinate]);
    s.orientation_deg = spec.random_orientation
                            ? orientation_deg_from_uniforms(u[orientation_coordinate],
                                                            u[orientation_coordinate + 1],
                                                            u[orientation_coordinate + 2])
                            : base.rocks.front().release.orientation_deg;
    s.mass = rock.properties.volume * s.density;
    return s;
}

engine::Scenario sample_scenario(const engine::Scenario& base, const SampleInputs& inputs) {
    if (base.cluster) return base;
    assert(!base.rocks.empty());
    engine::RockRelease rock = base.rocks.front();
    rock.rock.kind = inputs.kind;
    rock.rock.size = inputs.size;
    rock.rock.shape = nullptr;
    if (inputs.kind == shapes::RockKind::custom) {
        assert((inputs.custom_shape != nullptr || inputs.shape.empty()) &&
               "a sample read back from a database needs sample_shape");
        rock.rock.shape = inputs.custom_shape ? inputs.custom_shape : base.rocks.front().rock.shape;
    }
    rock.rock.density = inputs.density;
    rock.rock.material = inputs.material;
    rock.release.distance = inputs.release_distance;
    rock.release.lateral = inputs.release_lateral;
    // The engine places the rock in the surface frame at the point below this x (release.cpp).
    const shapes::Slope slope(base.slope);
    const double x = slope.point_at_distance(inputs.release_distance).x();
    rock.release.velocity = inputs.speed * slope.surface_tangent(x);
    rock.release.spin = inputs.spin * engine::Vec3::UnitY();
    rock.release.orientation_deg = inputs.orientation_deg;
    rock.release.random_orientation = false;

    engine::Scenario scenario = base;
    scenario.rocks = {rock};
    return scenario;
}

engine::Scenario sample_scenario(const SweepSpec& spec, const engine::Scenario& base,
                                 const SampleInputs& inputs) {
    if (base.cluster) return base;
    if (inputs.custom_shape != nullptr || inputs.kind != shapes::RockKind::custom) {
        return sample_scenario(base, inputs);
    }
    SampleInputs resolved = inputs;
    resolved.custom_shape = sample_shape(spec, base, inputs);
    return sample_scenario(base, resolved);
}

RockInputs rock_inputs(const SampleInputs& inputs) {
    return {false,          inputs.kind, inputs.shape,   inputs.size,
            inputs.density, inputs.mass, inputs.material};
}

std::vector<RockInputs> rock_inputs(const engine::Scenario& scenario, const SampleInputs& inputs,
                                    const std::vector<engine::RockOutcome>& outcomes) {
    if (!scenario.cluster) {
        assert(outcomes.size() == 1 && scenario.rocks.size() == 1);
        return {rock_inputs(inputs)};
    }
    assert(outcomes.size() >= scenario.rocks.size());
    std::vector<RockInputs> rocks;
    rocks.reserve(outcomes.size());
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
        const bool in_cluster = i >= scenario.rocks.size();
        const engine::RockSpec spec =
            engine::simulated_rock(scenario, i, outcomes.size(), outcomes[i].size);
        const double size = outcomes[i].size;
        const double volume = std::acos(-1.0) / 6.0 * size * size * size;
        // A [[rocks]] entry's own shape is its spec's (""); a cluster rock's is named.
        const std::string shape = in_cluster && spec.shape ? spec.shape->name : "";
        rocks.push_back({in_cluster, spec.kind, shape, size, spec.density, spec.density * volume,
                         spec.material});
    }
    return rocks;
}

}  // namespace rockfall::risk
