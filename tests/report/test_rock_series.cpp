// Speed against distance travelled and the cluster front (report/rock_series.hpp), and the
// simulate report's rock table and JSON keys built on them.

#include "../engine/plane_scenario.hpp"
#include "report/rock_series.hpp"
#include "report/simulation_report.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using engine::RockState;
using engine::Vec3;

namespace {

RockState state_at(double t, const Vec3& position, const Vec3& velocity) {
    RockState s;
    s.time = t;
    s.position = position;
    s.velocity = velocity;
    return s;
}

// A block sliding from rest down a 30 deg plane with friction `mu`, sampled every 10 ms.
struct SlidingRun {
    engine::Scenario scenario;
    engine::Outcome outcome;
    report::SeriesRecorder series;
};

SlidingRun sliding_block(double mu, int rocks) {
    SlidingRun run;
    run.scenario =
        engine::test::plane_scenario(30.0, shapes::RockKind::massive, {mu, 0.0, 0.0}, 1e-3);
    run.scenario.numerics.max_time = 2.0;
    run.scenario.slope.width = 10.0;
    for (int i = 1; i < rocks; ++i) {
        engine::RockRelease second = run.scenario.rocks.front();
        second.release.distance = 5.0 + 1.0 * i;
        second.release.lateral = 0.5 * i;
        run.scenario.rocks.push_back(second);
    }
    engine::RunOptions options;
    options.trajectory_interval = 0.01;
    options.trajectory = [&run](int rock, const RockState& s) { run.series.add(rock, s); };
    run.outcome = engine::simulate(run.scenario, 1, options);
    return run;
}

}  // namespace

TEST_CASE("distance travelled is the trapezoidal integral of the speed", "[report]") {
    report::SeriesRecorder recorder;
    // Speed 0, 1, 3 m/s at t = 0, 1, 2 s: s = 0, 0.5, 2.5 m.
    recorder.add(0, state_at(0.0, Vec3::Zero(), Vec3::Zero()));
    recorder.add(0, state_at(1.0, Vec3(0.5, 0, 0), Vec3(1, 0, 0)));
    recorder.add(0, state_at(2.0, Vec3(2.5, 0, 0), Vec3(0, 3, 0)));
    const report::RockSeries& s = recorder.series().at(0);
    REQUIRE(s.points.size() == 3);
    CHECK_THAT(s.points[1].distance, WithinAbs(0.5, 1e-12));
    CHECK_THAT(s.distance(), WithinAbs(2.5, 1e-12));
    // Halfway between the last two samples in distance (1.5 m): 2 m/s at 1.5 s.
    const report::SeriesPoint p = report::point_at_distance(s, 1.5);
    CHECK_THAT(p.speed, WithinAbs(2.0, 1e-12));
    CHECK_THAT(p.time, WithinAbs(1.5, 1e-12));
    const std::vector<report::SeriesPoint> table = report::sampled_by_distance(s, 6);
    REQUIRE(table.size() == 6);
    CHECK(table.front().distance == 0.0);
    CHECK_THAT(table.back().distance, WithinAbs(2.5, 1e-12));
    CHECK_THAT(table.back().speed, WithinAbs(3.0, 1e-12));
}

TEST_CASE("a block sliding down a plane has v = sqrt(2 a s) against distance travelled",
          "[report][verification]") {
    const double mu = GENERATE(0.0, 0.3);
    const SlidingRun run = sliding_block(mu, 1);
    const double angle = engine::test::radians(30.0);
    const double a = engine::test::kGravity * (std::sin(angle) - mu * std::cos(angle));
    const report::RockSeries& series = run.series.series().at(0);
    REQUIRE(series.distance() > 3.0);
    INFO("mu = " << mu);
    // Tolerance: 2 % of the speed plus 0.02 m/s (the block's first steps onto the plane).
    int checked = 0;
    for (const report::SeriesPoint& p : series.points) {
        if (p.distance < 0.1) continue;
        const double expected = std::sqrt(2.0 * a * p.distance);
        CHECK_THAT(p.speed, WithinAbs(expected, 0.02 * expected + 0.02));
        ++checked;
    }
    CHECK(checked > 100);
}

TEST_CASE("the front is the rock furthest downslope among those still in the run", "[report]") {
    engine::Scenario scenario;  // seed slope: toe at the end of the second segment
    const shapes::Slope slope(scenario.slope);
    engine::Outcome outcome;
    outcome.rocks.resize(2);
    outcome.rocks[0].stop = engine::StopReason::left_domain;
    outcome.rocks[0].stop_time = 1.0;
    outcome.rocks[1].stop = engine::StopReason::at_rest;
    outcome.rocks[1].stop_time = 1.5;
    report::SeriesRecorder recorder;
    for (int k = 0; k <= 4; ++k) {
        const double t = 0.5 * k;
        // Rock 0 leads until it leaves at 1 s; rock 1 rests at x = 3 m from 1.5 s.
        if (t <= 1.0) recorder.add(0, state_at(t, Vec3(2.0 + 2.0 * t, 0, 0), Vec3(2, 0, 0)));
        recorder.add(1, state_at(t, Vec3(1.0 + 2.0 * std::min(t, 1.0), 0, 0), Vec3::Zero()));
    }
    const std::vector<report::FrontPoint> front =
        report::cluster_front(scenario, recorder.series(), outcome);
    REQUIRE(front.size() == 5);
    CHECK(front[0].rock == 0);
    CHECK(front[2].rock == 0);
    CHECK_THAT(front[2].past_toe, WithinAbs(4.0 - slope.toe_x(), 1e-12));
    CHECK(front[3].rock == 1);
    CHECK_THAT(front[3].past_toe, WithinAbs(3.0 - slope.toe_x(), 1e-12));
    CHECK(front[0].travel == 0.0);
    CHECK_THAT(
        front[2].travel,
        WithinAbs(slope.distance_along_surface(4.0) - slope.distance_along_surface(2.0), 1e-12));
}

TEST_CASE("the simulate report gives every rock's series, hits and the front", "[report]") {
    const SlidingRun run = sliding_block(0.3, 3);
    REQUIRE(run.outcome.rocks.size() == 3);
    report::RunSeries series{run.series.series(), {}};
    series.front = report::cluster_front(run.scenario, series.rocks, run.outcome);
    REQUIRE_FALSE(series.front.empty());
    const report::RunInfo info{"plane.toml", 1, 0.1};

    const nlohmann::json json = report::outcome_json(run.scenario, run.outcome, info, series);
    REQUIRE(json["rocks"].size() == 3);
    for (const auto& rock : json["rocks"]) {
        CHECK(rock["distance_travelled_m"].get<double>() > 1.0);
        CHECK(rock["wall_hit_count"] == 0);
        CHECK(rock.contains("max_peak_normal_force_N"));
        CHECK(rock.contains("total_normal_impulse_N_s"));
        CHECK(rock["speed_by_distance"]["columns"][1] == "distance_m");
        CHECK(rock["speed_by_distance"]["rows"].size() > 100);
    }
    CHECK(json["front"]["columns"][1] == "past_toe_m");
    CHECK(json["front"]["rows"].size() == series.front.size());
    // The furthest-released rock leads throughout.
    CHECK(json["front"]["rows"].back()[4] == 3);

    // Rocks 2 and 3 are the scenario's own: always in full, so all three have a block.
    std::ostringstream text;
    report::print_summary(text, run.scenario, run.outcome, info, series, {});
    const std::string out = text.str();
    CHECK(out.find("rocks (s: distance travelled") != std::string::npos);
    CHECK(out.find("rock 3: massive") != std::string::npos);
    CHECK(out.find("speed against distance travelled") != std::string::npos);
    CHECK(out.find("front at 0.00 m past the toe") != std::string::npos);

    // As a cluster of three with no [[rocks]]: rows for all, in full only the one asked for.
    engine::Scenario cluster = run.scenario;
    cluster.rocks.clear();
    cluster.cluster.emplace();
    cluster.cluster->rock.kind = shapes::RockKind::massive;
    std::ostringstream brief;
    report::print_summary(brief, cluster, run.outcome, info, series, {false, {1}});
    const std::string table = brief.str();
    CHECK(table.find("rock 2: massive") != std::string::npos);
    CHECK(table.find("rock 1: massive") == std::string::npos);
    CHECK(table.find("rock 3: massive") == std::string::npos);
    CHECK(table.find("2 of 3 rocks in the table only") != std::string::npos);
}
