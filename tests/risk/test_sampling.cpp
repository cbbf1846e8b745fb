#include "risk_test_support.hpp"
#include "scenario/scenario_file.hpp"

#include "risk/sampling.hpp"
#include "shapes/slope.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using shapes::RockKind;

namespace {

using test::normal;
using test::problem_keys;
using test::uniform;

constexpr double deg = 3.14159265358979323846 / 180.0;

// The population of the 200-rock runout check (risk::random_rock_scenario): the seed's three
// shapes equally often, 0.2-0.4 m, random orientation, anywhere across the width.
risk::SweepSpec seed_population(const engine::Scenario& base, risk::SweepSpec::Method method,
                                std::int64_t samples) {
    risk::SweepSpec spec = risk::sweep_defaults(base);
    spec.method = method;
    spec.samples = samples;
    spec.seed = 2024;
    spec.kinds = {RockKind::sphere, RockKind::massive, RockKind::planar};
    spec.kind_weights = {1.0, 1.0, 1.0};
    spec.size = uniform(0.2, 0.4);
    spec.random_orientation = true;
    spec.zones.front().lateral = uniform(-0.5 * base.slope.width, 0.5 * base.slope.width);
    return spec;
}

// Every input varied, two zones.
risk::SweepSpec everything_varied(const engine::Scenario& base, risk::SweepSpec::Method method) {
    risk::SweepSpec spec = seed_population(base, method, 300);
    spec.kind_weights = {1.0, 2.0, 1.0};
    spec.density = normal(2600.0, 100.0, 2400.0, 2800.0);
    spec.friction = uniform(0.4, 0.8);
    spec.restitution = uniform(0.2, 0.4);
    spec.rolling_resistance = uniform(0.0, 0.05);
    spec.speed = uniform(0.0, 2.0);
    spec.spin = normal(0.0, 3.0, -10.0, 10.0);
    risk::ReleaseZone crest;
    crest.name = "crest";
    crest.weight = 3.0;
    crest.distance = uniform(0.3, 1.0);
    crest.lateral = uniform(-2.5, 2.5);
    risk::ReleaseZone middle;
    middle.name = "middle";
    middle.distance = risk::fixed(6.0);
    middle.lateral = normal(0.0, 1.0, -2.0, 2.0);
    spec.zones = {crest, middle};
    return spec;
}

bool same(const risk::SampleInputs& a, const risk::SampleInputs& b) {
    return a.index == b.index && a.seed == b.seed && a.zone == b.zone && a.kind == b.kind &&
           a.size == b.size && a.density == b.density &&
           a.material.friction == b.material.friction &&
           a.material.restitution == b.material.restitution &&
           a.material.rolling_resistance == b.material.rolling_resistance &&
           a.release_distance == b.release_distance && a.release_lateral == b.release_lateral &&
           a.speed == b.speed && a.spin == b.spin && a.orientation_deg == b.orientation_deg &&
           a.mass == b.mass;
}

bool has(const std::vector<std::string>& keys, const std::string& key) {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

}  // namespace

TEST_CASE("a Latin hypercube puts one sample in every stratum of every coordinate",
          "[risk][sampling]") {
    const engine::Scenario base;
    for (const std::int64_t n : {std::int64_t{1}, std::int64_t{7}, std::int64_t{1000}}) {
        risk::SweepSpec spec = seed_population(base, risk::SweepSpec::Method::latin_hypercube, n);
        std::vector<std::vector<double>> coordinates(risk::sample_dimensions);
        for (std::int64_t i = 0; i < n; ++i) {
            const auto point = risk::unit_point(spec, i);
            for (std::size_t d = 0; d < point.size(); ++d) coordinates[d].push_back(point[d]);
        }
        for (std::size_t d = 0; d < coordinates.size(); ++d) {
            std::vector<double>& u = coordinates[d];
            std::sort(u.begin(), u.end());
            // The j-th smallest value lies in stratum j, [j / n, (j + 1) / n): each stratum once.
            for (std::size_t j = 0; j < u.size(); ++j) {
                INFO("n = " << n << ", coordinate " << d << ", stratum " << j);
                REQUIRE(u[j] > 0.0);
                REQUIRE(u[j] < 1.0);
                REQUIRE(u[j] >= static_cast<double>(j) / static_cast<double>(n));
                REQUIRE(u[j] < static_cast<double>(j + 1) / static_cast<double>(n));
            }
        }
    }
}

TEST_CASE("Latin hypercube coordinates are paired at random", "[risk][sampling]") {
    // Independent permutations make the strata of two coordinates uncorrelated: the rank
    // correlation of n = 1000 pairs has standard error 1 / sqrt(n - 1) = 0.032.
    const engine::Scenario base;
    const risk::SweepSpec spec =
        seed_population(base, risk::SweepSpec::Method::latin_hypercube, 1000);
    std::vector<std::array<double, risk::sample_dimensions>> points;
    for (std::int64_t i = 0; i < spec.samples; ++i) points.push_back(risk::unit_point(spec, i));
    for (std::size_t a = 0; a + 1 < risk::sample_dimensions; ++a) {
        double sum = 0.0;
        for (const auto& p : points) sum += (p[a] - 0.5) * (p[a + 1] - 0.5);
        // Uniforms: variance 1/12, so correlation = 12 * mean product.
        const double correlation = 12.0 * sum / static_cast<double>(points.size());
        INFO("coordinates " << a << " and " << a + 1);
        CHECK(std::abs(correlation) < 5.0 * 0.032);
    }
    // Nor does the stratum follow the sample index.
    double sum = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        sum += (static_cast<double>(i) / 999.0 - 0.5) * (points[i][2] - 0.5);
    }
    CHECK(std::abs(12.0 * sum / 1000.0) < 5.0 * 0.032);
}

TEST_CASE("samples are a pure function of seed and index, whatever the order of drawing",
          "[risk][sampling]") {
    const engine::Scenario base;
    for (const auto method :
         {risk::SweepSpec::Method::monte_carlo, risk::SweepSpec::Method::latin_hypercube}) {
        const risk::SweepSpec spec = everything_varied(base, method);
        std::vector<risk::SampleInputs> forward;
        for (std::int64_t i = 0; i < spec.samples; ++i) {
            forward.push_back(risk::draw_sample(spec, base, i));
        }
        std::vector<std::int64_t> order(static_cast<std::size_t>(spec.samples));
        std::iota(order.begin(), order.end(), 0);
        std::reverse(order.begin(), order.end());
        for (const std::int64_t i : order) {
            REQUIRE(same(risk::draw_sample(spec, base, i), forward[static_cast<std::size_t>(i)]));
        }
        std::shuffle(order.begin(), order.end(), std::mt19937_64(5));
        for (const std::int64_t i : order) {
            REQUIRE(same(risk::draw_sample(spec, base, i), forward[static_cast<std::size_t>(i)]));
        }
        // Another run seed gives other samples, and engine seeds differ between samples.
        risk::SweepSpec other = spec;
        other.seed = spec.seed + 1;
        CHECK(risk::draw_sample(other, base, 0).size != forward[0].size);
        CHECK(forward[0].seed != forward[1].seed);
    }
}

TEST_CASE("every sample is a valid scenario with the drawn inputs", "[risk][sampling]") {
    const engine::Scenario base;
    const shapes::Slope slope(base.slope);
    for (const auto method :
         {risk::SweepSpec::Method::monte_carlo, risk::SweepSpec::Method::latin_hypercube}) {
        const risk::SweepSpec spec = everything_varied(base, method);
        REQUIRE(risk::find_problems(spec, base).empty());
        for (std::int64_t i = 0; i < spec.samples; ++i) {
            const risk::SampleInputs s = risk::draw_sample(spec, base, i);
            const engine::Scenario scenario = risk::sample_scenario(base, s);
            REQUIRE_NOTHROW(scenario::validate_scenario(scenario));
            REQUIRE(scenario.rocks.size() == 1);
            const engine::RockRelease& rock = scenario.rocks.front();
            CHECK(rock.rock.kind == s.kind);
            CHECK(rock.rock.size == s.size);
            CHECK(rock.release.lateral == s.release_lateral);
            CHECK_FALSE(rock.release.random_orientation);
            CHECK(rock.release.orientation_deg == s.orientation_deg);
            // The lateral position keeps the rock and its margin inside the side walls.
            const shapes::RockGeometry geometry = shapes::make_rock(s.kind, s.size);
            CHECK(std::abs(s.release_lateral) <=
                  0.5 * base.slope.width - geometry.bounding_radius - spec.lateral_margin);
            CHECK_THAT(s.mass,
                       WithinRel(s.density * std::numbers::pi * std::pow(s.size, 3) / 6.0, 1e-9));
            // Velocity along the downslope tangent; a positive spin about y rolls downslope:
            // the centre of a rock rolling on the surface moves at omega x (r n).
            const double x = slope.point_at_distance(s.release_distance).x();
            CHECK_THAT((rock.release.velocity - s.speed * slope.surface_tangent(x)).norm(),
                       WithinAbs(0.0, 1e-12));
            const engine::Vec3 rolling_velocity = rock.release.spin.cross(slope.surface_normal(x));
            CHECK_THAT(rolling_velocity.dot(slope.surface_tangent(x)), WithinAbs(s.spin, 1e-12));
        }
    }
}

TEST_CASE("the defaults reproduce the base rock", "[risk][sampling]") {
    engine::Scenario base;
    base.rocks.front().rock.kind = RockKind::massive;
    base.rocks.front().rock.size = 0.3;
    base.rocks.front().release.distance = 2.0;
    base.rocks.front().release.lateral = -0.7;
    base.rocks.front().release.orientation_deg = {10.0, 20.0, 30.0};
    base.rocks.front().release.spin = {0.0, 4.0, 0.0};
    const risk::SweepSpec spec = risk::sweep_defaults(base);
    CHECK(risk::find_problems(spec, base).empty());
    CHECK_FALSE(spec.random_orientation);
    const engine::Scenario sample = risk::sample_scenario(base, risk::draw_sample(spec, base, 17));
    const engine::RockRelease& rock = sample.rocks.front();
    const engine::RockRelease& expected = base.rocks.front();
    CHECK(rock.rock.kind == expected.rock.kind);
    CHECK(rock.rock.size == expected.rock.size);
    CHECK(rock.rock.density == expected.rock.density);
    CHECK(rock.release.distance == expected.release.distance);
    CHECK(rock.release.lateral == expected.release.lateral);
    CHECK(rock.release.orientation_deg == expected.release.orientation_deg);
    CHECK(rock.release.spin == expected.release.spin);
    CHECK(rock.release.velocity.norm() == 0.0);
}

TEST_CASE("varying one input leaves the draws of the others unchanged", "[risk][sampling]") {
    const engine::Scenario base;
    for (const auto method :
         {risk::SweepSpec::Method::monte_carlo, risk::SweepSpec::Method::latin_hypercube}) {
        const risk::SweepSpec fixed_density = everything_varied(base, method);
        risk::SweepSpec varied_density = fixed_density;
        varied_density.density = risk::fixed(3000.0);
        risk::SweepSpec fixed_size = fixed_density;
        fixed_size.size = risk::fixed(0.3);
        for (std::int64_t i = 0; i < 100; ++i) {
            const risk::SampleInputs a = risk::draw_sample(fixed_density, base, i);
            const risk::SampleInputs b = risk::draw_sample(varied_density, base, i);
            CHECK(b.density == 3000.0);
            CHECK(a.size == b.size);
            CHECK(a.release_lateral == b.release_lateral);
            CHECK(a.orientation_deg == b.orientation_deg);
            CHECK(a.material.friction == b.material.friction);
            const risk::SampleInputs c = risk::draw_sample(fixed_size, base, i);
            // The lateral band depends on the size; nothing else does.
            CHECK(c.size == 0.3);
            CHECK(a.kind == c.kind);
            CHECK(a.zone == c.zone);
            CHECK(a.density == c.density);
            CHECK(a.release_distance == c.release_distance);
            CHECK(a.speed == c.speed);
            CHECK(a.spin == c.spin);
            CHECK(a.orientation_deg == c.orientation_deg);
        }
    }
}

TEST_CASE("the seed population matches the 200-rock runout check's", "[risk][sampling]") {
    // Shapes equally often, sizes uniform in [0.2, 0.4], lateral uniform across the band where
    // the rock fits, orientations uniform on rotations (a rotated axis has components of mean
    // 0 and mean square 1/3). 3000 Latin hypercube samples; 5 standard errors.
    const engine::Scenario base;
    const risk::SweepSpec spec =
        seed_population(base, risk::SweepSpec::Method::latin_hypercube, 3000);
    const double n = static_cast<double>(spec.samples);
    std::array<double, 3> kinds{};
    double band_fraction_sum = 0.0;
    double band_fraction_square = 0.0;
    Eigen::Vector3d axis_sum = Eigen::Vector3d::Zero();
    Eigen::Vector3d axis_square = Eigen::Vector3d::Zero();
    for (std::int64_t i = 0; i < spec.samples; ++i) {
        const risk::SampleInputs s = risk::draw_sample(spec, base, i);
        kinds[static_cast<std::size_t>(s.kind)] += 1.0;
        REQUIRE(s.size >= 0.2);
        REQUIRE(s.size <= 0.4);
        const double half_band = 0.5 * base.slope.width -
                                 shapes::make_rock(s.kind, s.size).bounding_radius -
                                 spec.lateral_margin;
        const double fraction = s.release_lateral / half_band;
        REQUIRE(std::abs(fraction) <= 1.0);
        band_fraction_sum += fraction;
        band_fraction_square += fraction * fraction;
        const Eigen::Vector3d a = s.orientation_deg * deg;
        const Eigen::Matrix3d r = (Eigen::AngleAxisd(a.z(), Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(a.y(), Eigen::Vector3d::UnitY()) *
                                   Eigen::AngleAxisd(a.x(), Eigen::Vector3d::UnitX()))
                                      .toRotationMatrix();
        const Eigen::Vector3d z = r.col(2);
        axis_sum += z;
        axis_square += z.cwiseProduct(z);
    }
    // A stratified kind coordinate gives each third of [0, 1) exactly n / 3 samples.
    for (const double count : kinds) CHECK(std::abs(count - n / 3.0) <= 1.0);
    // Uniform on [-1, 1]: mean 0 (sd 1/sqrt(3)), mean square 1/3 (sd 0.298).
    CHECK(std::abs(band_fraction_sum / n) < 5.0 * 0.577 / std::sqrt(n));
    CHECK(std::abs(band_fraction_square / n - 1.0 / 3.0) < 5.0 * 0.298 / std::sqrt(n));
    for (int k = 0; k < 3; ++k) {
        CHECK(std::abs(axis_sum[k] / n) < 5.0 * 0.577 / std::sqrt(n));
        CHECK(std::abs(axis_square[k] / n - 1.0 / 3.0) < 5.0 * 0.298 / std::sqrt(n));
    }
}

TEST_CASE("impossible sweep specs are rejected naming the key", "[risk][sampling]") {
    const engine::Scenario base;
    const risk::SweepSpec good = everything_varied(base, risk::SweepSpec::Method::monte_carlo);
    REQUIRE(problem_keys(good, base).empty());

    risk::SweepSpec bad = good;
    bad.samples = 0;
    bad.kind_weights = {1.0, -1.0, 1.0};
    bad.density.sd = -5.0;
    bad.speed = uniform(-1.0, 1.0);
    bad.lateral_margin = -0.1;
    bad.zones[1].name = "crest";
    bad.zones[0].weight = 0.0;
    bad.zones[1].distance = uniform(3.0, 2.0);
    const std::vector<std::string> keys = problem_keys(bad, base);
    CHECK(has(keys, "sweep.samples"));
    CHECK(has(keys, "sweep.rock.kind"));
    CHECK(has(keys, "sweep.rock.density"));
    CHECK(has(keys, "sweep.release.speed"));
    CHECK(has(keys, "sweep.lateral_margin"));
    CHECK(has(keys, "sweep.release.zones[1].name"));
    CHECK(has(keys, "sweep.release.zones[0].weight"));
    CHECK(has(keys, "sweep.release.zones[1].distance"));
    CHECK(keys.size() == 8);
    try {
        risk::validate(bad, base);
        FAIL("validate accepted a bad spec");
    } catch (const std::invalid_argument& error) {
        CHECK_THAT(error.what(), Contains("sweep.rock.density = normal (mean 2600, sd -5) on "
                                          "[2400, 2800] kg/m3: sd = -5: must be > 0"));
        CHECK_THAT(error.what(), Contains("sweep.samples = 0: must be >= 1"));
    }

    // --samples 1099511627776 once ran out of memory building the list of samples to run.
    risk::SweepSpec huge = good;
    huge.samples = std::int64_t{1} << 40;
    REQUIRE(problem_keys(huge, base) == std::vector<std::string>{"sweep.samples"});
    CHECK(risk::find_problems(huge, base).front().message ==
          "1099511627776: must be in [1, 100000000], the most one sweep plans");
    huge.samples = risk::max_samples;
    CHECK(problem_keys(huge, base).empty());

    risk::SweepSpec mismatch = good;
    mismatch.kind_weights = {1.0};
    CHECK(problem_keys(mismatch, base) == std::vector<std::string>{"sweep.rock.kind"});
    risk::SweepSpec zero = good;
    zero.kind_weights = {0.0, 0.0, 0.0};
    CHECK(problem_keys(zero, base) == std::vector<std::string>{"sweep.rock.kind"});

    // 4 m massive and planar rocks (bounding radii near 3 m) do not fit across the 5 m slope;
    // a 4 m sphere (radius 2 m) does, with its 5 cm margins. One problem per shape.
    risk::SweepSpec wide = good;
    wide.size = uniform(0.2, 4.0);
    CHECK(problem_keys(wide, base) ==
          std::vector<std::string>{"sweep.rock.size", "sweep.rock.size"});

    // A base rock thrown sideways cannot be kept: speeds are along the surface tangent.
    engine::Scenario sideways = base;
    sideways.rocks.front().release.velocity = {0.0, 1.0, 0.0};
    sideways.rocks.front().release.spin = {1.0, 0.0, 0.0};
    const std::vector<std::string> motion = problem_keys(risk::sweep_defaults(sideways), sideways);
    CHECK(motion == std::vector<std::string>{"rocks[0].release.velocity", "rocks[0].release.spin"});

    // Latin hypercube indices stop at the planned number of samples.
    risk::SweepSpec latin = good;
    latin.method = risk::SweepSpec::Method::latin_hypercube;
    CHECK_THROWS_AS(risk::unit_point(latin, latin.samples), std::invalid_argument);
    CHECK_THROWS_AS(risk::unit_point(good, -1), std::invalid_argument);
    CHECK_NOTHROW(risk::unit_point(good, good.samples + 5));
}

TEST_CASE("kind custom samples the base rock's own shape", "[risk][sampling]") {
    engine::Scenario base;
    engine::RockSpec& rock = base.rocks.front().rock;
    rock.kind = RockKind::custom;
    rock.shape = std::make_shared<const shapes::CustomShape>(
        shapes::CustomShape{"slab", shapes::make_rock(RockKind::planar, 1.0).hull});
    risk::SweepSpec spec = risk::sweep_defaults(base);
    REQUIRE(spec.kinds == std::vector<RockKind>{RockKind::custom});
    spec.kinds = {RockKind::sphere, RockKind::custom};
    spec.kind_weights = {1.0, 1.0};
    spec.size = uniform(0.2, 0.4);
    REQUIRE(risk::find_problems(spec, base).empty());
    int custom = 0;
    for (std::int64_t i = 0; i < 40; ++i) {
        const risk::SampleInputs s = risk::draw_sample(spec, base, i);
        const engine::Scenario scenario = risk::sample_scenario(base, s);
        REQUIRE_NOTHROW(scenario::validate_scenario(scenario));
        const engine::RockSpec& drawn = scenario.rocks.front().rock;
        CHECK((drawn.shape != nullptr) == (s.kind == RockKind::custom));
        CHECK_THAT(s.mass, WithinRel(drawn.density * drawn.geometry().properties.volume, 1e-12));
        custom += s.kind == RockKind::custom ? 1 : 0;
    }
    CHECK(custom > 0);
    CHECK(custom < 40);
    // Without a custom base rock, kind custom has no shape to stand for.
    CHECK(problem_keys(spec, engine::Scenario{}) == std::vector<std::string>{"sweep.rock.kind"});
}
