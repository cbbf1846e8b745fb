// Marked rocks tracked one by one (issue 14): the camera's speeds (displacement between frames
// over the interval) and the engine samples' speeds against distance travelled, checked on
// analytic motions; forces and cells per named rock.

#include "report/marked_rocks.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using namespace rockfall::report;

namespace {

// Samples every `dt` s from t = 0 to `end` of a rock on a straight line along `direction`
// (unit) at distance s(t) from `start`, speed v(t), recorded through SeriesRecorder as the
// engine's samples are.
template <class Distance, class Speed>
RockSeries line_motion(double dt, double end, const engine::Vec3& start,
                       const engine::Vec3& direction, Distance s, Speed v) {
    SeriesRecorder recorder;
    const int n = static_cast<int>(std::lround(end / dt));
    for (int k = 0; k <= n; ++k) {
        engine::RockState state;
        state.time = k * dt;
        state.position = start + s(state.time) * direction;
        state.velocity = v(state.time) * direction;
        recorder.add(0, state);
    }
    return recorder.series().front();
}

engine::RockOutcome named(std::string name) {
    engine::RockOutcome rock;
    rock.name = std::move(name);
    return rock;
}

}  // namespace

TEST_CASE("a rock at constant speed gives that speed to the camera and to the samples",
          "[report][marked_rocks]") {
    const double speed = 2.7;  // m/s
    const engine::Vec3 direction = engine::Vec3(1.0, 0.2, -1.0).normalized();
    const RockSeries fine = line_motion(
        0.01, 1.0, engine::Vec3(0.1, 0.0, 2.0), direction, [&](double t) { return speed * t; },
        [&](double) { return speed; });
    const RockSeries camera = camera_series(fine, 0.04);
    // Frames at 0, 0.04, ..., 1.0: 25 steps, each at its middle in time and distance.
    REQUIRE(camera.points.size() == 25);
    for (std::size_t j = 0; j < camera.points.size(); ++j) {
        const SeriesPoint& p = camera.points[j];
        CHECK_THAT(p.speed, WithinRel(speed, 1e-9));
        CHECK_THAT(p.time, WithinAbs(0.04 * (double(j) + 0.5), 1e-12));
        CHECK_THAT(p.distance, WithinAbs(speed * 0.04 * (double(j) + 0.5), 1e-9));
    }
    CHECK_THAT(speed_at_distance(fine, 1.1), WithinRel(speed, 1e-9));
    CHECK_THAT(speed_at_distance(camera, 1.1), WithinRel(speed, 1e-9));
    // 2.7 m travelled in all: 1.4 m is reached, 3 m is not.
    CHECK_THAT(speed_at_distance(camera, 1.4), WithinRel(speed, 1e-9));
    CHECK(std::isnan(speed_at_distance(fine, 3.0)));
    CHECK(std::isnan(speed_at_distance(RockSeries{}, 0.5)));
}

TEST_CASE("uniform acceleration: speeds at 1.1 m of travel match v = sqrt(2 a s)",
          "[report][marked_rocks][verification]") {
    // From rest at a = 4 m/s2: s = a t^2 / 2, v = a t; 1.1 m is reached at t = 0.742 s.
    const double a = 4.0;
    const RockSeries fine = line_motion(
        0.01, 1.2, engine::Vec3::Zero(), engine::Vec3::UnitX(),
        [&](double t) { return 0.5 * a * t * t; }, [&](double t) { return a * t; });
    const double exact = std::sqrt(2.0 * a * 1.1);  // 2.966 m/s
    // The samples' distance is the trapezoidal integral of v, exact for v linear in t; speed is
    // then interpolated linearly in distance between samples 0.01 s apart.
    CHECK_THAT(speed_at_distance(fine, 1.1), WithinAbs(exact, 2e-3));
    // The camera's step from t to t + T covers a T (t + T / 2): its speed is the exact speed at
    // the step's middle time. Its distance (the chords' sum to the middle) runs a T^2 / 8 =
    // 0.8 mm ahead of the true one, and the camera points are 0.04 s (about 0.12 m) apart.
    const RockSeries camera = camera_series(fine, 0.04);
    REQUIRE(camera.points.size() == 30);
    for (const SeriesPoint& p : camera.points) CHECK_THAT(p.speed, WithinAbs(a * p.time, 1e-9));
    CHECK_THAT(speed_at_distance(camera, 1.1), WithinAbs(exact, 5e-3));
    // Far from the point: a camera that saw every 0.2 s differs by more than these bounds.
    CHECK(std::abs(speed_at_distance(camera_series(fine, 0.2), 1.1) - exact) > 5e-3);
}

TEST_CASE("camera frames fall at whole multiples of the interval within the samples",
          "[report][marked_rocks]") {
    // Samples from 0.013 s to 0.1 s: frames at 0.04 and 0.08 only, one step.
    SeriesRecorder recorder;
    for (int k = 0; k <= 87; ++k) {
        engine::RockState state;
        state.time = 0.013 + 0.001 * k;
        state.position = engine::Vec3(state.time * state.time, 0.0, 0.0);
        state.velocity = engine::Vec3(2.0 * state.time, 0.0, 0.0);
        recorder.add(0, state);
    }
    const RockSeries& fine = recorder.series().front();
    CHECK_THAT(position_at_time(fine, 0.0505).x(), WithinAbs(0.0505 * 0.0505, 1e-6));
    CHECK(position_at_time(fine, 0.0).x() == fine.points.front().position.x());
    CHECK(position_at_time(fine, 1.0).x() == fine.points.back().position.x());
    const RockSeries camera = camera_series(fine, 0.04);
    REQUIRE(camera.points.size() == 1);
    CHECK_THAT(camera.points[0].speed, WithinAbs((0.08 * 0.08 - 0.04 * 0.04) / 0.04, 1e-6));
    CHECK(camera_series(fine, 0.5).points.empty());
}

TEST_CASE("marked rocks: named rocks only, with their wall force and cells",
          "[report][marked_rocks]") {
    engine::Outcome outcome;
    outcome.rocks = {engine::RockOutcome{}, named("red"), named("blue")};
    engine::WallHit first;
    first.peak_normal_force = 150.0;
    first.peak_time = 1.2;
    engine::WallHit second = first;
    second.peak_normal_force = 410.0;
    second.peak_time = 1.5;
    outcome.rocks[1].wall_hits = {first, second};
    std::vector<RockSeries> series(3);
    series[1] = line_motion(
        0.01, 1.0, engine::Vec3::Zero(), engine::Vec3::UnitX(), [](double t) { return 2.0 * t; },
        [](double) { return 2.0; });

    engine::PressureMap cells;
    cells.spec.columns = 16;
    engine::RockCellLoad load;
    load.rock = 1;
    load.cells = {3, 19};
    load.sampled_peak_force = 380.0;
    load.sampled_peak_time = 1.5;
    cells.rocks = {load};

    const MarkedRocks marked = marked_rocks(outcome, series, &cells, 0.04);
    REQUIRE(marked.rocks.size() == 2);
    const MarkedRock& red = marked.rocks[0];
    CHECK(red.rock == 1);
    CHECK(red.name == "red");
    CHECK(red.wall_hits == 2);
    CHECK(red.peak_force == 410.0);
    CHECK(red.peak_time == 1.5);
    CHECK(red.sampled_peak_force == 380.0);
    CHECK(red.cells == std::vector<int>{3, 19});
    REQUIRE(red.fine_speed.size() == 2);
    CHECK_THAT(red.fine_speed[0], WithinRel(2.0, 1e-9));
    CHECK_THAT(red.camera_speed[1], WithinRel(2.0, 1e-9));
    const MarkedRock& blue = marked.rocks[1];
    CHECK(blue.peak_force == 0.0);
    CHECK(std::isnan(blue.peak_time));
    CHECK(!blue.sampled_peak_force);
    CHECK(std::isnan(blue.fine_speed[0]));

    const nlohmann::json json = marked_rocks_json(marked);
    CHECK(json["camera_interval_s"] == 0.04);
    CHECK(json["distances_m"] == nlohmann::json({1.1, 1.4}));
    const nlohmann::json& r = json["rocks"][0];
    CHECK(r["rock"] == 2);
    CHECK(r["peak_wall_force_N"] == 410.0);
    CHECK(r["sampled_peak_wall_force_N"] == 380.0);
    CHECK(r["cells_loaded"] ==
          nlohmann::json::parse(R"([{"column": 3, "row": 0}, {"column": 3, "row": 1}])"));
    CHECK(r["speed_at_distance"][0]["camera_speed_m_s"].get<double>() == Approx(2.0));
    CHECK(r["camera"]["columns"] == nlohmann::json({"time_s", "distance_m", "speed_m_s"}));
    CHECK(json["rocks"][1]["speed_at_distance"][1]["fine_speed_m_s"].is_null());
    CHECK(json["rocks"][1]["sampled_peak_wall_force_N"].is_null());

    std::ostringstream text;
    print_marked_rocks(text, marked);
    CHECK_THAT(text.str(), Catch::Matchers::Contains("displacement between frames 0.04 s apart"));
    CHECK_THAT(text.str(), Catch::Matchers::Contains("2.00 / 2.00"));
    CHECK_THAT(text.str(), Catch::Matchers::Contains("410.0      380.0      2"));
    // Without a grid: no sampled peaks, no cells.
    const MarkedRocks bare = marked_rocks(outcome, series, nullptr, 0.04);
    CHECK(!bare.has_cells);
    CHECK(marked_rocks_json(bare)["rocks"][0]["cells_loaded"].is_null());
}
