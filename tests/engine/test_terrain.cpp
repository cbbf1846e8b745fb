// Terrain meshes in the engine (issue 3): a sphere rolling down a finely triangulated plane
// against the same sphere on the analytic (box) plane, with and without the internal-edge
// correction, and rocks on the triangulated seed profile against the box slope.

#include "engine/simulation.hpp"
#include "shapes/slope.hpp"
#include "shapes/terrain.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using engine::Vec3;

namespace {

constexpr double kAngleDeg = 30.0;
constexpr double kRadius = 0.1;
// Distance rolled before the speeds are compared, m (issue 3: "after 5 m").
constexpr double kTravel = 5.0;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

Vec3 downslope() { return {std::cos(radians(kAngleDeg)), 0.0, -std::sin(radians(kAngleDeg))}; }

Vec3 upward_normal() { return {std::sin(radians(kAngleDeg)), 0.0, std::cos(radians(kAngleDeg))}; }

// A 12 m plane without bars or walls and a 0.2 m sphere released at rest 1 m below the crown.
engine::Scenario plane(double time_step) {
    engine::Scenario scenario;
    scenario.slope.segments = {{12.0, kAngleDeg}};
    scenario.slope.bars.enabled = false;
    scenario.slope.side_walls.enabled = false;
    scenario.slope.wall.enabled = false;
    scenario.rocks.front().rock.kind = shapes::RockKind::sphere;
    scenario.rocks.front().rock.size = 2.0 * kRadius;
    scenario.rocks.front().release.distance = 1.0;
    scenario.stations = {};
    scenario.numerics.time_step = time_step;
    scenario.numerics.max_time = 2.5;
    return scenario;
}

// The plane triangulated at `spacing` with every vertex inside the plane moved within it by up
// to 0.3 spacing, so that edges run in every direction.
std::shared_ptr<shapes::Terrain> triangulated_plane(const shapes::SlopeSpec& spec, double spacing) {
    shapes::TerrainGrid grid;
    grid.spacing = spacing;
    shapes::TriangleMesh mesh = shapes::profile_terrain(spec, grid);
    const double end_x = spec.segments.front().length * std::cos(radians(kAngleDeg));
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> jitter(-0.3 * spacing, 0.3 * spacing);
    for (Vec3& v : mesh.vertices) {
        // The crown and end rows also belong to the flat margins: they stay.
        if (v.x() > 1e-9 && v.x() < end_x - 1e-9) {
            v += jitter(random) * downslope() + jitter(random) * Vec3::UnitY();
        }
    }
    return std::make_shared<shapes::Terrain>("plane", std::move(mesh), shapes::TerrainPlacement{},
                                             "test plane");
}

struct Roll {
    // Speed after rolling kTravel metres, m/s.
    double speed = 0.0;
    // Highest gap between the sphere and the analytic plane before then, m.
    double hop = 0.0;
};

Roll roll(const engine::Scenario& scenario) {
    const Vec3 crown(0.0, 0.0, 12.0 * std::sin(radians(kAngleDeg)));
    Roll result;
    std::vector<engine::RockState> states;
    engine::RunOptions options;
    options.trajectory_interval = scenario.numerics.time_step;
    options.trajectory = [&](int, const engine::RockState& state) { states.push_back(state); };
    engine::simulate(scenario, 1, options);
    const Vec3 start = states.front().position;
    for (std::size_t i = 1; i < states.size(); ++i) {
        const double before = (states[i - 1].position - start).dot(downslope());
        const double after = (states[i].position - start).dot(downslope());
        result.hop =
            std::max(result.hop, (states[i].position - crown).dot(upward_normal()) - kRadius);
        if (after >= kTravel) {
            const double f = (kTravel - before) / (after - before);
            result.speed = states[i - 1].velocity.norm() +
                           f * (states[i].velocity.norm() - states[i - 1].velocity.norm());
            return result;
        }
    }
    FAIL("the sphere did not roll " << kTravel << " m");
    return result;
}

// v = sqrt(2 a s) with a = 5/7 g (sin - mu_r cos): a solid sphere rolling without slip against
// rolling resistance mu_r (the mean of rock and surface, both at the default 0.02).
double analytic_speed() {
    const double a =
        5.0 / 7.0 * 9.81 * (std::sin(radians(kAngleDeg)) - 0.02 * std::cos(radians(kAngleDeg)));
    return std::sqrt(2.0 * a * kTravel);
}

}  // namespace

TEST_CASE("a sphere rolls down a finely triangulated plane as down the analytic plane",
          "[verification][terrain]") {
    for (const double time_step : {1e-3, 1e-2}) {
        INFO("time step " << time_step << " s");
        engine::Scenario scenario = plane(time_step);
        const Roll box = roll(scenario);
        CHECK_THAT(box.speed, WithinRel(analytic_speed(), 0.01));
        CHECK(box.hop < 1e-3);

        scenario.slope.terrain = triangulated_plane(scenario.slope, 0.1);
        const Roll mesh = roll(scenario);
        INFO("box " << box.speed << " m/s, mesh " << mesh.speed << " m/s, hop " << mesh.hop
                    << " m");
        CHECK_THAT(mesh.speed, WithinRel(box.speed, 0.01));
        CHECK(mesh.hop < 1e-3);
    }
}

TEST_CASE("without the internal-edge correction the sphere hops at the triangles' edges",
          "[verification][terrain]") {
    // On the default 1 ms step the contact threshold of 0 and the split impulse keep the
    // sphere so shallow that it rarely touches a neighbouring triangle; the 10 ms step (the
    // coarsest the scenario allows) sinks it deep enough for the edges to kick it.
    engine::Scenario scenario = plane(1e-2);
    const Roll box = roll(scenario);
    const std::shared_ptr<shapes::Terrain> terrain = triangulated_plane(scenario.slope, 0.1);
    terrain->set_internal_edge_correction(false);
    scenario.slope.terrain = terrain;
    const Roll mesh = roll(scenario);
    INFO("box " << box.speed << " m/s, uncorrected mesh " << mesh.speed << " m/s, hop " << mesh.hop
                << " m");
    CHECK(mesh.hop > 5e-3);
    CHECK(std::abs(mesh.speed / box.speed - 1.0) > 0.005);
}

TEST_CASE("rocks on the triangulated seed profile run out as on the box slope",
          "[verification][terrain]") {
    engine::Scenario scenario;  // the seed slope, scenario A: a 0.2 m sphere, bars on
    shapes::TerrainGrid grid;
    grid.spacing = 0.25;
    const auto terrain = std::make_shared<const shapes::Terrain>(
        "seed", shapes::profile_terrain(scenario.slope, grid), shapes::TerrainPlacement{},
        "seed profile");

    for (const bool bars : {true, false}) {
        INFO("bars " << (bars ? "on" : "off"));
        scenario.slope.bars.enabled = bars;
        scenario.slope.terrain = nullptr;
        const engine::RockOutcome box = engine::simulate(scenario, 1).rocks.front();
        scenario.slope.terrain = terrain;
        const engine::RockOutcome mesh = engine::simulate(scenario, 1).rocks.front();
        CHECK_THAT(mesh.reach, WithinAbs(box.reach, 0.01));
        for (std::size_t i = 0; i < box.stations.size(); ++i) {
            REQUIRE(mesh.stations[i].reached);
            // With bars on, one trajectory bouncing off the bars is chaotic: the station speeds
            // of box and mesh differ by 2.9 against 5.5 m/s with rolling resistance off, so only
            // the bar-free roll is compared speed for speed.
            if (!bars) {
                CHECK_THAT(mesh.stations[i].speed, WithinRel(box.stations[i].speed, 0.02));
            }
        }
        CHECK(mesh.wall_hits.size() == box.wall_hits.size());
    }

    // Tumbling blocks and slabs are chaotic: compare the mean speed at the toe over seeds,
    // paired, against three standard errors of the mean difference. Planar slabs with bars off
    // are the case that showed the wedge gap below the box slope's concave kinks: before the
    // slabs met there, their mean toe speed was 0.29 m/s on the boxes against 1.78 m/s on the
    // mesh (60 seeds).
    struct Case {
        shapes::RockKind kind;
        bool bars;
    };
    for (const Case c :
         {Case{shapes::RockKind::massive, true}, Case{shapes::RockKind::planar, false}}) {
        scenario.slope.bars.enabled = c.bars;
        scenario.rocks.front().rock.kind = c.kind;
        scenario.rocks.front().release.random_orientation = true;
        constexpr int kSeeds = 40;
        double sum = 0.0;
        double squares = 0.0;
        double box_sum = 0.0;
        const auto toe_speed = [&](std::uint64_t seed) {
            // The outcome is kept: a reference into the temporary simulate() returns would
            // dangle past this statement (AddressSanitizer: heap-use-after-free).
            const engine::Outcome outcome = engine::simulate(scenario, seed);
            const engine::StationCrossing& toe = outcome.rocks.front().stations[0];
            return toe.reached ? toe.speed : 0.0;
        };
        for (int seed = 1; seed <= kSeeds; ++seed) {
            scenario.slope.terrain = nullptr;
            const double box = toe_speed(static_cast<std::uint64_t>(seed));
            scenario.slope.terrain = terrain;
            const double mesh = toe_speed(static_cast<std::uint64_t>(seed));
            sum += mesh - box;
            squares += (mesh - box) * (mesh - box);
            box_sum += box;
        }
        const double mean = sum / kSeeds;
        const double deviation = std::sqrt((squares - kSeeds * mean * mean) / (kSeeds - 1));
        INFO(shapes::to_string(c.kind)
             << ", bars " << (c.bars ? "on" : "off") << ": mean toe speed on the box slope "
             << box_sum / kSeeds << " m/s, mesh minus box " << mean << " m/s, standard error "
             << deviation / std::sqrt(kSeeds));
        CHECK(std::abs(mean) < 3.0 * deviation / std::sqrt(kSeeds));
    }
}
