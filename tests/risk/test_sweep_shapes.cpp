// Sweeps over named shapes (catalogue entries) and generated rocks of a target sphericity:
// frequencies, targets met, reproducibility, rebuilding a sample's shape, and bad specs.

#include "risk_test_support.hpp"
#include "scenario/scenario_file.hpp"

#include "risk/sampling.hpp"
#include "shapes/measures.hpp"
#include "shapes/platonic.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using Family = risk::Distribution::Family;
using Method = risk::SweepSpec::Method;
using shapes::RockKind;

namespace {

using test::problem_keys;
using test::problem_text;
using test::uniform;

std::shared_ptr<const shapes::CustomShape> named(const std::string& name,
                                                 shapes::ConvexPolyhedron hull) {
    return std::make_shared<const shapes::CustomShape>(shapes::CustomShape{name, std::move(hull)});
}

// Spheres, two named shapes (a cube and a slab) and generated rocks, weights 1 : 2 : 1 : 4.
risk::SweepSpec mixed(const engine::Scenario& base, Method method, std::int64_t samples) {
    risk::SweepSpec spec = risk::sweep_defaults(base);
    spec.method = method;
    spec.samples = samples;
    spec.seed = 77;
    spec.kinds = {RockKind::sphere};
    spec.kind_weights = {1.0};
    spec.entries = {named("cube", shapes::platonic_solid(shapes::PlatonicKind::cube, 1.0)),
                    named("slab", shapes::make_rock(RockKind::planar, 1.0).hull)};
    spec.entry_weights = {2.0, 1.0};
    spec.generated_weight = 4.0;
    spec.sphericity = uniform(0.6, 0.9);
    spec.size = uniform(0.2, 0.4);
    spec.zones.front().lateral = uniform(-2.5, 2.5);
    return spec;
}

std::string shape_of(const risk::SampleInputs& s) {
    return s.kind == RockKind::custom ? s.shape : std::string(shapes::to_string(s.kind));
}

}  // namespace

TEST_CASE("named shapes and generated rocks are drawn with their weights", "[risk][sampling]") {
    const engine::Scenario base;
    const std::map<std::string, double> share = {
        {"sphere", 1.0 / 8.0}, {"cube", 2.0 / 8.0}, {"slab", 1.0 / 8.0}, {"generated", 4.0 / 8.0}};
    SECTION("Latin hypercube: the shape coordinate is stratified, so counts are exact") {
        const risk::SweepSpec spec = mixed(base, Method::latin_hypercube, 400);
        REQUIRE(risk::find_problems(spec, base).empty());
        std::map<std::string, int> counts;
        for (std::int64_t i = 0; i < spec.samples; ++i)
            ++counts[shape_of(risk::draw_sample(spec, base, i))];
        // Each weight's interval of [0, 1) holds n w strata, give or take the one it shares.
        for (const auto& [name, p] : share) CHECK(std::abs(counts[name] - 400.0 * p) <= 1.0);
    }
    SECTION("Monte Carlo: counts within 4 standard errors of n p") {
        risk::SweepSpec spec = mixed(base, Method::monte_carlo, 800);
        spec.sphericity = uniform(0.9, 0.95);  // the nearly equant rocks generate fastest
        std::map<std::string, int> counts;
        for (std::int64_t i = 0; i < spec.samples; ++i)
            ++counts[shape_of(risk::draw_sample(spec, base, i))];
        for (const auto& [name, p] : share) {
            INFO(name << ": " << counts[name]);
            CHECK(std::abs(counts[name] - 800.0 * p) <= 4.0 * std::sqrt(800.0 * p * (1.0 - p)));
        }
    }
}

TEST_CASE("every sample's rock is its shape at its size, with its sphericity", "[risk][sampling]") {
    const engine::Scenario base;
    const risk::SweepSpec spec = mixed(base, Method::latin_hypercube, 60);
    std::vector<double> targets;
    for (std::int64_t i = 0; i < spec.samples; ++i) {
        const risk::SampleInputs s = risk::draw_sample(spec, base, i);
        const engine::Scenario scenario = risk::sample_scenario(base, s);
        REQUIRE_NOTHROW(scenario::validate_scenario(scenario));
        const engine::RockSpec& rock = scenario.rocks.front().rock;
        const shapes::RockGeometry geometry = rock.geometry();
        CHECK(rock.kind == s.kind);
        CHECK((rock.shape != nullptr) == (s.kind == RockKind::custom));
        CHECK_THAT(s.mass, WithinRel(s.density * geometry.properties.volume, 1e-12));
        CHECK_THAT(geometry.properties.volume,
                   WithinRel(std::numbers::pi * std::pow(s.size, 3) / 6.0, 1e-9));
        // The recorded sphericity is the simulated rock's, measured independently.
        CHECK_THAT(s.sphericity,
                   WithinAbs(shapes::shape_measures(geometry).wadell_sphericity, 1e-12));
        CHECK(std::abs(s.release_lateral) <=
              0.5 * base.slope.width - geometry.bounding_radius - spec.lateral_margin);
        if (s.shape == "generated") {
            CHECK(std::isfinite(s.target_sphericity));
            // rock_with_sphericity meets targets within 1e-4; the brief asks for 0.02.
            CHECK_THAT(s.sphericity, WithinAbs(s.target_sphericity, 1e-4));
            CHECK(s.target_sphericity >= 0.6);
            CHECK(s.target_sphericity <= 0.9);
            targets.push_back(s.target_sphericity);
        } else {
            CHECK(std::isnan(s.target_sphericity));
            CHECK(s.shape_seed == 0);
        }
        if (s.shape == "cube") CHECK_THAT(s.sphericity, WithinAbs(0.806, 5e-4));
        if (s.kind == RockKind::sphere) CHECK(s.sphericity == 1.0);
    }
    // Half of the 60 strata of the shape coordinate are generated rocks; their targets come
    // from a coordinate of their own, uniform in [0.6, 0.9]: mean 0.75, sd 0.087.
    REQUIRE(targets.size() == 30);
    const double mean = std::accumulate(targets.begin(), targets.end(), 0.0) / 30.0;
    CHECK(std::abs(mean - 0.75) < 4.0 * 0.087 / std::sqrt(30.0));
}

TEST_CASE("shape draws are a pure function of seed and index, and rebuild from what is stored",
          "[risk][sampling]") {
    const engine::Scenario base;
    const risk::SweepSpec spec = mixed(base, Method::monte_carlo, 40);
    std::vector<risk::SampleInputs> forward;
    for (std::int64_t i = 0; i < spec.samples; ++i)
        forward.push_back(risk::draw_sample(spec, base, i));
    std::vector<std::int64_t> order(static_cast<std::size_t>(spec.samples));
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937_64(3));
    std::set<std::uint64_t> shape_seeds;
    for (const std::int64_t i : order) {
        const risk::SampleInputs& a = forward[static_cast<std::size_t>(i)];
        const risk::SampleInputs b = risk::draw_sample(spec, base, i);
        REQUIRE(b.kind == a.kind);
        REQUIRE(b.shape == a.shape);
        REQUIRE(b.shape_seed == a.shape_seed);
        REQUIRE((b.target_sphericity == a.target_sphericity ||
                 (std::isnan(a.target_sphericity) && std::isnan(b.target_sphericity))));
        REQUIRE(b.sphericity == a.sphericity);
        REQUIRE(b.mass == a.mass);
        REQUIRE(b.release_lateral == a.release_lateral);
        if (a.kind != RockKind::custom) continue;
        REQUIRE(b.custom_shape->hull.vertices == a.custom_shape->hull.vertices);
        // What a results database keeps (no hull) rebuilds the very same hull.
        risk::SampleInputs stored = a;
        stored.custom_shape = nullptr;
        const auto rebuilt = risk::sample_shape(spec, base, stored);
        REQUIRE(rebuilt->hull.vertices == a.custom_shape->hull.vertices);
        REQUIRE(rebuilt->hull.triangles == a.custom_shape->hull.triangles);
        const engine::Scenario replay = risk::sample_scenario(spec, base, stored);
        CHECK(replay.rocks.front().rock.geometry().properties.volume ==
              risk::sample_scenario(base, a).rocks.front().rock.geometry().properties.volume);
        if (a.shape == "generated") shape_seeds.insert(a.shape_seed);
    }
    CHECK(shape_seeds.size() > 5);  // every generated rock has a seed of its own
    // Another run seed draws other rocks.
    risk::SweepSpec other = spec;
    other.seed = spec.seed + 1;
    bool differs = false;
    for (std::int64_t i = 0; i < 10; ++i) {
        differs |= risk::draw_sample(other, base, i).shape_seed !=
                   forward[static_cast<std::size_t>(i)].shape_seed;
    }
    CHECK(differs);
}

TEST_CASE("drawing the shape leaves every other input's draw unchanged", "[risk][sampling]") {
    const engine::Scenario base;
    for (const Method method : {Method::monte_carlo, Method::latin_hypercube}) {
        const risk::SweepSpec with_shapes = mixed(base, method, 50);
        risk::SweepSpec families = with_shapes;
        families.kinds = {RockKind::sphere, RockKind::massive};
        families.kind_weights = {1.0, 1.0};
        families.entries.clear();
        families.entry_weights.clear();
        families.generated_weight = 0.0;
        families.sphericity.reset();
        for (std::int64_t i = 0; i < 50; ++i) {
            const risk::SampleInputs a = risk::draw_sample(with_shapes, base, i);
            const risk::SampleInputs b = risk::draw_sample(families, base, i);
            CHECK(a.seed == b.seed);
            CHECK(a.zone == b.zone);
            CHECK(a.size == b.size);
            CHECK(a.density == b.density);
            CHECK(a.release_distance == b.release_distance);
            CHECK(a.speed == b.speed);
            CHECK(a.orientation_deg == b.orientation_deg);
        }
    }
}

TEST_CASE("bad shape specs are rejected naming the key", "[risk][sampling]") {
    const engine::Scenario base;
    const risk::SweepSpec good = mixed(base, Method::monte_carlo, 100);
    REQUIRE(problem_keys(good, base).empty());

    risk::SweepSpec low = good;
    low.sphericity = uniform(0.2, 0.9);
    CHECK(problem_keys(low, base) == std::vector<std::string>{"sweep.rock.sphericity"});
    CHECK_THAT(problem_text(low, base),
               Contains("sweep.rock.sphericity = uniform [0.2, 0.9]: every target must lie in "
                        "[0.3, 0.95]"));
    risk::SweepSpec unbounded = good;
    unbounded.sphericity = risk::Distribution{};
    unbounded.sphericity->family = Family::normal;
    unbounded.sphericity->mean = 0.8;
    unbounded.sphericity->sd = 0.05;
    CHECK_THAT(problem_text(unbounded, base), Contains("truncate the distribution"));

    risk::SweepSpec without = good;
    without.sphericity.reset();
    CHECK(problem_keys(without, base) == std::vector<std::string>{"sweep.rock.kind"});
    risk::SweepSpec unused = good;
    unused.generated_weight = 0.0;
    CHECK(problem_keys(unused, base) == std::vector<std::string>{"sweep.rock.sphericity"});

    risk::SweepSpec names = good;
    names.entries = {named("sphere", names.entries[0]->hull), named("slab", names.entries[1]->hull),
                     named("slab", names.entries[1]->hull)};
    names.entry_weights = {1.0, 1.0, -1.0};
    CHECK_THAT(problem_text(names, base), Contains("entry \"sphere\""));
    CHECK_THAT(problem_text(names, base), Contains("\"slab\" is listed twice"));
    CHECK_THAT(problem_text(names, base), Contains("weight -1 of \"slab\""));

    risk::SweepSpec mismatch = good;
    mismatch.entry_weights = {1.0};
    CHECK(problem_keys(mismatch, base) == std::vector<std::string>{"sweep.rock.kind"});

    // Generated rocks of sphericity 0.3 are needles about 3.5 times as long as their size.
    risk::SweepSpec wide = good;
    wide.sphericity = uniform(0.3, 0.9);
    wide.size = uniform(0.2, 1.0);
    CHECK(problem_keys(wide, base) == std::vector<std::string>{"sweep.rock.size"});
    CHECK_THAT(problem_text(wide, base), Contains("generated rock of sphericity 0.3"));

    // A stored sample naming a shape the spec does not have cannot be rebuilt.
    risk::SampleInputs stray;
    stray.kind = RockKind::custom;
    stray.shape = "boulder";
    CHECK_THROWS_WITH(risk::sample_shape(good, base, stray), Contains("\"boulder\""));
    stray.shape = "generated";
    stray.target_sphericity = 0.1;
    CHECK_THROWS_AS(risk::sample_shape(good, base, stray), std::invalid_argument);
}
