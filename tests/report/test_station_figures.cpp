// The stations query and seed 000's Figures 5 and 6 on rocks made up for the purpose.

#include "report/station_figures.hpp"
#include "svg_check.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sstream>

namespace rockfall::report {
namespace {

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

engine::StationCrossing crossing(double distance, double speed, double omega, double cr) {
    return {.distance_from_toe = distance,
            .reached = true,
            .speed = speed,
            .parallel_speed = speed,
            .angular_speed = omega,
            .rolling_coefficient = cr};
}

engine::StationCrossing not_reached(double distance) { return {.distance_from_toe = distance}; }

// A rock crossing the toe at speed a with spin 5 a + 2 rad/s, then 4 m at speed b with Cr.
db::RockStations rock(std::int64_t sample, const std::string& shape, double a, double b,
                      double cr) {
    db::RockStations r;
    r.sample = sample;
    r.kind = shape;
    r.shape = shape;
    r.size = 0.2;
    r.stations = {crossing(0.0, a, 5.0 * a + 2.0, 1.0), crossing(4.0, b, 10.0, cr)};
    return r;
}

StationSet made_up_set() {
    StationSet set{"made_up", "made_up.db", "made-up scenario", {}};
    // Spheres roll (Cr 1, V' -0.1); slabs slide (Cr 0.2, V' -0.5); blocks in between.
    for (int i = 0; i < 6; ++i) {
        const double a = 4.0 + i;
        set.rocks.push_back(rock(3 * i, "sphere", a, 0.9 * a, 1.0));
        set.rocks.push_back(rock(3 * i + 1, "planar", a, 0.5 * a, 0.2));
        set.rocks.push_back(rock(3 * i + 2, "massive", a, 0.7 * a, 0.6));
    }
    // A rock that stopped before the toe counts at no station.
    db::RockStations stopped = rock(99, "planar", 1.0, 1.0, 1.0);
    stopped.stations = {not_reached(0.0), not_reached(4.0)};
    set.rocks.push_back(stopped);
    return set;
}

// The plot as SVG, checked to be well-formed.
std::string checked_svg(const Plot& plot) {
    const std::string svg = render_svg(plot);
    CHECK(test::xml_problem(svg).empty());
    return svg;
}

// How many legend entries (text elements) read exactly `label`.
std::size_t legend_entries(const std::string& svg, const std::string& label) {
    return test::occurrences(svg, ">" + label + "</text>");
}

}  // namespace

TEST_CASE("V' against Cr: points by shape and the lowest and highest third of Cr",
          "[report][stations]") {
    const MotionTrend trend = velocity_change_trend(made_up_set());
    REQUIRE(trend.shapes.size() == 3);
    CHECK(trend.shapes[0].shape == "sphere");
    CHECK(trend.shapes[1].shape == "massive");
    CHECK(trend.shapes[2].shape == "planar");
    REQUIRE(trend.all.x.size() == 18);
    for (const double v : trend.shapes[2].y) CHECK_THAT(v, WithinAbs(-0.5, 1e-12));
    CHECK(trend.lower.rocks == 6);
    CHECK_THAT(trend.lower.cr_max, WithinAbs(0.2, 1e-12));
    CHECK_THAT(trend.lower.mean_velocity_change, WithinAbs(-0.5, 1e-12));
    CHECK(trend.lower.negative == 6);
    CHECK_THAT(trend.upper.cr_min, WithinAbs(1.0, 1e-12));
    CHECK_THAT(trend.upper.mean_velocity_change, WithinAbs(-0.1, 1e-12));
    REQUIRE(trend.all.fit);
    CHECK(trend.all.fit->correlation() > 0.99);
}

TEST_CASE("angular speed against speed: the least-squares line per shape and over all",
          "[report][stations]") {
    const MotionTrend trend = spin_speed_trend(made_up_set());
    REQUIRE(trend.shapes.size() == 3);
    for (const ShapePoints& p : trend.shapes) {
        REQUIRE(p.fit);
        CHECK_THAT(p.fit->slope, WithinRel(5.0, 1e-12));
        CHECK_THAT(p.fit->intercept, WithinAbs(2.0, 1e-9));
    }
    CHECK(trend.all.x.size() == 18);
}

TEST_CASE("the stations must include the toe and 4 m: errors name the stations there are",
          "[report][stations]") {
    StationSet set = made_up_set();
    for (db::RockStations& r : set.rocks) r.stations[1].distance_from_toe = 3.0;
    CHECK_THROWS_WITH(velocity_change_trend(set),
                      Contains("made_up.db: V' between the toe and 4 m needs a station 4 m past "
                               "the toe; the scenario's stations are at 0, 3 m past the toe"));
    CHECK_NOTHROW(spin_speed_trend(set));
    // The text says what is not shown rather than failing.
    std::ostringstream text;
    write_stations(text, QueryFormat::text, {set});
    CHECK_THAT(text.str(), Contains("not shown: made_up.db: V' between the toe and 4 m"));

    StationSet empty{"empty", "empty.db", "no stations", {}};
    CHECK_THROWS_WITH(station_distances(empty), Contains("empty.db: no station rows"));
    CHECK_THROWS_WITH(spin_speed_trend(empty), Contains("empty.db: no station rows"));
}

TEST_CASE("Figure 5 as SVG: well-formed, one marker series per shape in the legend",
          "[report][stations][svg]") {
    const std::string svg =
        checked_svg(velocity_change_figure({velocity_change_trend(made_up_set())}, "Fig. 5"));
    for (const char* shape : {"sphere", "massive", "planar"}) {
        CHECK(legend_entries(svg, std::string(shape) + " (n = 6)") == 1);
    }
    CHECK_THAT(svg, Contains("rolling coefficient Cr"));
    CHECK_THAT(svg, Contains("rate of velocity change V' = (b - a) / a, toe to 4 m (-)"));
}

TEST_CASE("a shape none of whose rocks crossed the stations keeps its legend entry, n = 0",
          "[report][stations][svg]") {
    StationSet set = made_up_set();
    // The slabs stop between the toe and 4 m.
    for (db::RockStations& r : set.rocks) {
        if (r.shape == "planar") r.stations[1] = not_reached(4.0);
    }
    const MotionTrend trend = velocity_change_trend(set);
    REQUIRE(trend.shapes.size() == 3);
    CHECK(trend.shapes[2].shape == "planar");
    CHECK(trend.shapes[2].x.empty());
    CHECK_FALSE(trend.shapes[2].fit);
    CHECK(trend.all.x.size() == 12);
    const std::string svg = checked_svg(velocity_change_figure({trend}, "Fig. 5"));
    CHECK(legend_entries(svg, "planar (n = 0)") == 1);
    CHECK(legend_entries(svg, "sphere (n = 6)") == 1);
}

TEST_CASE("Figure 6 as SVG: with two databases, series per database and shape, a line each",
          "[report][stations][svg]") {
    StationSet other = made_up_set();
    other.label = "other";
    for (db::RockStations& r : other.rocks) r.stations[0].angular_speed *= 2.0;
    const std::vector<MotionTrend> trends = {spin_speed_trend(made_up_set()),
                                             spin_speed_trend(other)};
    const Plot plot = spin_speed_figure(trends, "Fig. 6");
    // 3 shapes x 2 sets of points, one least-squares line per set.
    CHECK(plot.series.size() == 8);
    const std::string svg = checked_svg(plot);
    CHECK(legend_entries(svg, "made_up: sphere (n = 6)") == 1);
    CHECK(legend_entries(svg, "other: planar (n = 6)") == 1);
    CHECK(legend_entries(svg, "made_up: least squares, slope 5 rad/m") == 1);
    CHECK(legend_entries(svg, "other: least squares, slope 10 rad/m") == 1);
    CHECK_THAT(svg, Contains("speed at the toe v (m/s)"));
    CHECK_THAT(svg, Contains("(rad/s)"));
}

TEST_CASE("the stations query as JSON: station means, thirds of Cr and slopes with units",
          "[report][stations]") {
    std::ostringstream out;
    write_stations(out, QueryFormat::json, {made_up_set()});
    const nlohmann::json doc = nlohmann::json::parse(out.str());
    CHECK(doc["query"] == "stations");
    REQUIRE(doc["stations"].size() == 6);  // 3 shapes x 2 stations
    const nlohmann::json& planar_toe = doc["stations"][4];
    CHECK(planar_toe["shape"] == "planar");
    CHECK(planar_toe["rocks"] == 7);
    CHECK(planar_toe["reached"] == 6);
    CHECK_THAT(planar_toe["mean_speed_m_s"].get<double>(), WithinRel(6.5, 1e-12));
    const nlohmann::json& change = doc["velocity_change_vs_cr"][0];
    CHECK(change["rocks"] == 18);
    CHECK_THAT(change["lower_cr_third"]["negative_share"].get<double>(), WithinAbs(1.0, 0.0));
    const nlohmann::json& all = doc["angular_speed_vs_speed"][3];
    CHECK(all["shape"] == "all");
    CHECK_THAT(all["slope_rad_m"].get<double>(), WithinRel(5.0, 1e-12));
    CHECK(doc["notes"].empty());
}

}  // namespace rockfall::report
