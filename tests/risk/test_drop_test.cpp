// The virtual drop test (risk/drop_test.hpp): the coefficients of restitution of spheres
// against the configured contact restitution on every surface material of the samples, the
// identification of a known restitution from its own mean COR, determinism, bad inputs.

#include "scenario/scenario_file.hpp"

#include "risk/drop_test.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

using namespace rockfall;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

const std::filesystem::path samples = ROCKFALL_SAMPLES_DIR;

risk::DropTestSpec sphere_drops(std::int64_t count) {
    risk::DropTestSpec spec;
    spec.rock.kind = shapes::RockKind::sphere;
    spec.rock.size = 0.2;
    spec.count = count;
    return spec;
}

// A sphere's states every dt (continuous kinematics): a free fall from `height` (gap above the
// surface at z = 0), a rebound at e times the touch speed (e = 0: it stays on the surface).
std::vector<engine::RockState> synthetic_bounce(const shapes::RockGeometry& sphere, double height,
                                                double e, double dt) {
    constexpr double g = 9.81;
    const double radius = sphere.radius;
    const double touch = std::sqrt(2.0 * height / g);
    const double rebound = e * g * touch;
    std::vector<engine::RockState> states;
    for (int k = 0; k * dt < 2.2 * touch; ++k) {
        engine::RockState s;
        s.time = k * dt;
        const double after = s.time - touch;
        if (after < 0.0) {
            s.position.z() = radius + height - 0.5 * g * s.time * s.time;
            s.velocity.z() = -g * s.time;
        } else if (e > 0.0) {
            s.position.z() = radius + rebound * after - 0.5 * g * after * after;
            s.velocity.z() = rebound - g * after;
        } else {
            s.position.z() = radius;
        }
        s.translational_energy = 0.5 * 2600.0 * sphere.properties.volume * s.velocity.squaredNorm();
        states.push_back(s);
    }
    return states;
}

}  // namespace

TEST_CASE("the first bounce of a known trajectory gives its coefficients", "[unit]") {
    const shapes::RockGeometry sphere = shapes::make_rock(shapes::RockKind::sphere, 0.2);
    const double mass = 2600.0 * sphere.properties.volume;
    const double v_in = std::sqrt(2.0 * 9.81 * 1.0);
    const risk::DropMeasurement m =
        risk::measure_drop(synthetic_bounce(sphere, 1.0, 0.4, 1e-5), sphere, 2600.0, 0.0, 9.81);
    CHECK(m.rebounded);
    CHECK_THAT(m.drop_height, WithinRel(1.0, 1e-6));
    CHECK_THAT(m.approach_speed, WithinRel(v_in, 1e-6));
    CHECK_THAT(m.rebound_speed, WithinRel(0.4 * v_in, 1e-3));
    CHECK_THAT(m.rebound_height, WithinRel(0.16, 1e-3));
    CHECK_THAT(m.cor_height, WithinRel(0.4, 1e-3));
    CHECK_THAT(m.cor_speed, WithinRel(0.4, 1e-3));
    CHECK_THAT(m.cor_kinetic, WithinRel(0.4, 1e-3));
    CHECK_THAT(m.cor_energy, WithinRel(0.4, 1e-3));
    CHECK_THAT(m.normal_impulse, WithinRel(mass * 1.4 * v_in, 1e-3));
    CHECK_THAT(m.compression_impulse, WithinRel(mass * v_in, 1e-3));
    CHECK_THAT(m.compression_impulse + m.restitution_impulse, WithinRel(m.first_impulse, 1e-12));

    // Stopped dead on the surface: no rebound, every coefficient 0.
    const risk::DropMeasurement dead =
        risk::measure_drop(synthetic_bounce(sphere, 1.0, 0.0, 1e-4), sphere, 2600.0, 0.0, 9.81);
    CHECK_FALSE(dead.rebounded);
    CHECK(dead.cor_height == 0.0);
    CHECK(dead.cor_speed == 0.0);
    CHECK(dead.cor_kinetic == 0.0);
    CHECK(dead.cor_energy == 0.0);
    CHECK_THAT(dead.normal_impulse, WithinRel(mass * v_in, 1e-3));

    // A rock that never touches is an error, not a zero.
    std::vector<engine::RockState> falling = synthetic_bounce(sphere, 1.0, 0.4, 1e-4);
    falling.resize(100);
    CHECK_THROWS_AS(risk::measure_drop(falling, sphere, 2600.0, 0.0, 9.81), std::runtime_error);
}

TEST_CASE("Student t quantiles match the tables", "[unit]") {
    CHECK_THAT(risk::student_t_quantile(0.975, 1.0), WithinRel(12.706204736, 1e-8));
    CHECK_THAT(risk::student_t_quantile(0.975, 10.0), WithinRel(2.228138852, 1e-8));
    CHECK_THAT(risk::student_t_quantile(0.95, 30.0), WithinRel(1.697260887, 1e-8));
    CHECK_THAT(risk::student_t_quantile(0.025, 10.0), WithinRel(-2.228138852, 1e-8));
    CHECK_THAT(risk::student_t_quantile(0.975, 1e6), WithinRel(1.959966, 1e-5));
    CHECK_THROWS_AS(risk::student_t_quantile(1.0, 3.0), std::invalid_argument);
}

TEST_CASE("a sample summary has its mean, percentiles and t interval", "[unit]") {
    const risk::SampleSummary s = risk::sample_summary({1.0, 2.0, 3.0, 4.0, 5.0});
    CHECK(s.count == 5);
    CHECK_THAT(s.mean, WithinAbs(3.0, 1e-15));
    CHECK_THAT(s.standard_deviation, WithinRel(std::sqrt(2.5), 1e-15));
    CHECK_THAT(s.p5, WithinAbs(1.2, 1e-12));
    CHECK_THAT(s.p50, WithinAbs(3.0, 1e-12));
    CHECK_THAT(s.p95, WithinAbs(4.8, 1e-12));
    const double half = 2.776445105 * std::sqrt(2.5) / std::sqrt(5.0);
    CHECK_THAT(s.mean_interval.lower, WithinRel(3.0 - half, 1e-8));
    CHECK_THAT(s.mean_interval.upper, WithinRel(3.0 + half, 1e-8));
    const risk::SampleSummary one = risk::sample_summary({0.7});
    CHECK(one.mean_interval.lower == 0.7);
    CHECK(one.mean_interval.upper == 0.7);
}

TEST_CASE("a sphere's COR is the configured restitution on every surface of the samples",
          "[verification]") {
    // Every surface material (the wall is a compliant contact, not a Bullet one) of the seed
    // slope and the flume; the contact restitution is the mean with the rock's.
    std::vector<engine::Material> surfaces;
    for (const char* file : {"seed_slope.toml", "flume_45.toml"}) {
        const engine::Scenario s = scenario::load_scenario(samples / file).scenario;
        surfaces.push_back(s.materials.slope);
        surfaces.push_back(s.materials.bars);
        surfaces.push_back(s.materials.side_walls);
    }
    for (const double rock_restitution : {0.3, 0.8}) {
        for (const engine::Material& surface : surfaces) {
            risk::DropTestSpec spec = sphere_drops(2);
            spec.rock.material.restitution = rock_restitution;
            spec.surface = surface;
            const double e = 0.5 * (rock_restitution + surface.restitution);
            const risk::DropTestResult r = risk::run_drop_test(spec, 1);
            INFO("surface friction " << surface.friction << ", restitution " << surface.restitution
                                     << ", contact e " << e);
            CHECK(r.no_rebound == 0);
            CHECK_THAT(r.cor_speed.mean, WithinRel(e, 0.05));
            CHECK_THAT(r.cor_kinetic.mean, WithinRel(e, 0.05));
            CHECK_THAT(r.cor_energy.mean, WithinRel(e, 0.05));
            // Heights and speeds agree (a sphere does not turn): within 1 %.
            CHECK_THAT(r.cor_height.mean, WithinRel(r.cor_speed.mean, 0.01));
            // sqrt(2 g h) less g dt / 2, the engine's semi-implicit Euler fall (0.11 %).
            CHECK_THAT(r.approach_speed.mean,
                       WithinRel(std::sqrt(2.0 * 9.81 * 1.0) - 0.5 * 9.81 * 1e-3, 1e-4));
            CHECK_THAT(r.drops.front().drop_height, WithinRel(1.0, 1e-3));
        }
    }
}

TEST_CASE("a block's kinematic COR lies below its contact restitution, its kinetic COR near it",
          "[verification]") {
    risk::DropTestSpec spec;
    spec.rock.kind = shapes::RockKind::massive;
    spec.count = 12;
    const risk::DropTestResult r = risk::run_drop_test(spec, 2);
    // Corner impacts turn the block: the centre of mass keeps less than e of its speed, and
    // the touching point's own Poisson coefficient stays near e (friction takes some).
    CHECK(r.cor_height.mean < 0.9 * 0.3);
    CHECK(r.cor_speed.mean < 0.9 * 0.3);
    CHECK_THAT(r.cor_kinetic.p50, WithinRel(0.3, 0.1));
    CHECK(r.cor_height.standard_deviation > 0.01);
    CHECK(r.cor_height.mean_interval.lower < r.cor_height.mean);
    CHECK(r.cor_height.mean_interval.upper > r.cor_height.mean);
}

TEST_CASE("identification recovers a known surface restitution from its own mean COR",
          "[verification]") {
    // A sphere: its curve rises steadily (a block's mean over few orientations is noisy and may
    // cross the target more than once; see docs/calibration.md).
    risk::DropTestSpec spec = sphere_drops(2);
    spec.rock.material.restitution = 0.45;
    spec.surface.restitution = 0.45;
    const double target = risk::run_drop_test(spec, 2).cor_height.mean;
    risk::RestitutionSearchOptions options;
    options.threads = 2;
    options.tolerance = 1e-4;
    spec.surface.restitution = 0.3;  // where the test would start: not the answer
    const risk::RestitutionIdentification id =
        risk::identify_surface_restitution(spec, target, options);
    CHECK_THAT(id.surface_restitution, WithinRel(0.45, 0.02));
    CHECK_THAT(id.contact_restitution, WithinRel(0.45, 0.02));
    CHECK_THAT(id.achieved.mean, WithinAbs(target, 0.01));
    CHECK(id.consistent.lower <= id.surface_restitution + 1e-6);
    CHECK(id.consistent.upper >= id.surface_restitution - 1e-6);
    REQUIRE(id.curve.size() == 11);
    CHECK(id.curve.front().surface_restitution == 0.0);
    CHECK(id.curve.back().surface_restitution == 1.0);
    CHECK(id.curve.back().cor.mean > id.curve.front().cor.mean);

    // A target the curve cannot reach names the reachable range.
    CHECK_THROWS_WITH(risk::identify_surface_restitution(spec, 0.99, options),
                      Catch::Contains("target_cor = 0.99: must be in ["));
}

TEST_CASE("drop tests are reproducible and independent of the thread count", "[unit]") {
    risk::DropTestSpec spec;
    spec.rock.kind = shapes::RockKind::planar;
    spec.count = 5;
    spec.seed = 42;
    const risk::DropTestResult a = risk::run_drop_test(spec, 1);
    const risk::DropTestResult b = risk::run_drop_test(spec, 2);
    REQUIRE(a.drops.size() == 5);
    for (std::size_t i = 0; i < a.drops.size(); ++i) {
        CHECK(a.drops[i].seed == risk::drop_seed(42, static_cast<std::int64_t>(i)));
        CHECK(a.drops[i].seed == b.drops[i].seed);
        CHECK(a.drops[i].cor_height == b.drops[i].cor_height);
        CHECK(a.drops[i].cor_kinetic == b.drops[i].cor_kinetic);
        CHECK(a.drops[i].energy_after == b.drops[i].energy_after);
    }
    // Different orientations give different bounces.
    CHECK(a.drops[0].cor_height != a.drops[1].cor_height);
    spec.seed = 43;
    CHECK(risk::run_drop_test(spec, 2).drops[0].cor_height != a.drops[0].cor_height);
}

TEST_CASE("bad drop test inputs are refused with field, value and range", "[unit]") {
    risk::DropTestSpec spec = sphere_drops(3);
    spec.height = 0.0;
    CHECK_THROWS_WITH(risk::run_drop_test(spec, 1),
                      Catch::Contains("height = 0 m: must be finite and > 0"));
    spec = sphere_drops(0);
    CHECK_THROWS_WITH(risk::run_drop_test(spec, 1),
                      Catch::Contains("count = 0 drops: must be >= 1"));
    spec = sphere_drops(3);
    spec.surface.restitution = 1.5;
    CHECK_THROWS_WITH(risk::run_drop_test(spec, 1),
                      Catch::Contains("surface.restitution = 1.5: must be in [0, 1]"));
    spec = sphere_drops(3);
    spec.surface.friction = -0.1;
    CHECK_THROWS_AS(risk::run_drop_test(spec, 1), std::invalid_argument);
    spec = sphere_drops(3);
    CHECK_THROWS_WITH(risk::identify_surface_restitution(spec, 1.0, {}),
                      Catch::Contains("target_cor = 1: must be in (0, 1)"));
}
