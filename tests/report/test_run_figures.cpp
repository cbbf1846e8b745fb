// The figures of a run (issue 14): heat maps of the pressure cells with a colour bar in kPa and
// saturated cells flagged, the wall force history, the marked rocks' speed profiles; each
// written only when the run has its data; every SVG well-formed.

#include "report/heat_map.hpp"
#include "report/run_figures.hpp"
#include "scenario/scenario_file.hpp"
#include "svg_check.hpp"

#include "shapes/slope.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <regex>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using namespace rockfall::report;
using rockfall::test::occurrences;
using rockfall::test::xml_problem;

namespace {

// Seed 001's flume at 45 deg: the wall with its 16 x 16 cells over 0.6 x 0.3 m (each 37.5 x
// 18.75 mm), capacity 345 kPa, sampled every 1 ms.
const engine::Scenario& flume() {
    static const engine::Scenario scenario =
        scenario::load_scenario(ROCKFALL_SAMPLES_DIR "/flume_45.toml").scenario;
    return scenario;
}

// A wall force of `force` N at (y, up) on the face from `start` for `duration` s.
engine::WallHit hit(double y, double up, double force, double start, double duration) {
    const shapes::Slope slope(flume().slope);
    engine::ForceSample f;
    f.time = start;
    f.duration = duration;
    f.normal = force;
    f.point = engine::Vec3(slope.wall_x(), y, slope.surface_height(slope.wall_x()) + up);
    engine::WallHit h;
    h.start_time = start;
    h.end_time = start + duration;
    h.point = f.point;
    h.peak_normal_force = force;
    h.peak_time = start;
    h.history = {f};
    return h;
}

// Rock 1 (unnamed) loads column 0, row 0 with 5 kN for 1 ms (7.1 MPa: saturated); rock 2,
// "red", loads the cell at y = 0.1 m, 0.15 m up with 50 N for 2 ms (71 kPa).
engine::Outcome two_hits() {
    engine::Outcome outcome;
    outcome.rocks.resize(2);
    outcome.rocks[0].wall_hits = {hit(-0.29, 0.005, 5000.0, 1.0, 1e-3)};
    outcome.rocks[1].name = "red";
    outcome.rocks[1].wall_hits = {hit(0.1, 0.15, 50.0, 1.2, 2e-3)};
    return outcome;
}

// "red" moving at 2 m/s along x for 1 s, sampled every 0.01 s.
RunSeries red_series() {
    SeriesRecorder recorder;
    for (int k = 0; k <= 100; ++k) {
        engine::RockState state;
        state.time = 0.01 * k;
        state.position = engine::Vec3(2.0 * state.time, 0.0, 0.0);
        state.velocity = engine::Vec3(2.0, 0.0, 0.0);
        recorder.add(1, state);
    }
    RunSeries series;
    series.rocks = recorder.series();
    return series;
}

std::vector<std::string> files(const std::vector<Figure>& figures) {
    std::vector<std::string> names;
    for (const Figure& f : figures) names.push_back(f.file);
    return names;
}

double attribute(const std::string& element, const std::string& name) {
    std::smatch m;
    const std::regex pattern(" " + name + "=\"([-0-9.]+)\"");
    REQUIRE(std::regex_search(element, m, pattern));
    return std::stod(m[1]);
}

}  // namespace

TEST_CASE("the well-formedness check finds broken documents", "[report][figures]") {
    CHECK(xml_problem("<svg><g><rect x=\"1\"/></g></svg>").empty());
    CHECK(!xml_problem("<svg><g></svg>").empty());
    CHECK(!xml_problem("<svg><rect x=\"1/></svg>").empty());
    CHECK(!xml_problem("<svg>a & b</svg>").empty());
    CHECK(!xml_problem("<svg></svg><svg></svg>").empty());
}

TEST_CASE("viridis runs from dark purple to yellow through matplotlib's table",
          "[report][figures]") {
    CHECK(viridis_hex(0.0) == "#440154");
    CHECK(viridis_hex(1.0) == "#fde725");
    CHECK(viridis_hex(-1.0) == "#440154");
    // matplotlib's entries 127 and 128: (0.128729, 0.563265, 0.551229), (0.127568, 0.566949,
    // 0.550556).
    const auto mid = viridis(0.5);
    CHECK_THAT(mid[0], WithinAbs(0.1281, 2.0 / 255));
    CHECK_THAT(mid[1], WithinAbs(0.5651, 2.0 / 255));
    CHECK_THAT(mid[2], WithinAbs(0.5509, 2.0 / 255));
    // Lightness grows monotonically (a perceptual map): green channel here.
    for (int k = 1; k <= 100; ++k) CHECK(viridis(k / 100.0)[1] > viridis((k - 1) / 100.0)[1]);
}

TEST_CASE("the peak pressure map: kPa, colour bar, saturated cells, orientation",
          "[report][figures]") {
    const engine::Outcome outcome = two_hits();
    const shapes::Slope slope(flume().slope);
    const engine::PressureMap map = engine::pressure_map(*flume().wall_cells, slope, outcome);
    const HeatMap heat = pressure_peak_map(map);
    REQUIRE(heat.values.size() == 256);
    // Cell (column 0, row 0): 5 kN over 37.5 x 18.75 mm.
    CHECK_THAT(heat.values[0], WithinRel(5000.0 / (0.0375 * 0.01875) / 1e3, 1e-9));
    CHECK(heat.flagged[0]);
    const int red = map.cell_at(outcome.rocks[1].wall_hits[0].point);
    CHECK_THAT(heat.values[static_cast<std::size_t>(red)],
               WithinRel(50.0 / (0.0375 * 0.01875) / 1e3, 1e-9));
    CHECK(!heat.flagged[static_cast<std::size_t>(red)]);
    CHECK(std::count_if(heat.values.begin(), heat.values.end(),
                        [](double v) { return std::isnan(v); }) == 254);
    CHECK(heat.mirror_x);

    const std::string svg = render_heat_map_svg(heat);
    INFO(svg.substr(0, 2000));
    CHECK(xml_problem(svg).empty());
    CHECK_THAT(svg, Contains(">peak sampled pressure (kPa)</text>"));
    CHECK_THAT(svg, Contains("saturated (sampled pressure &gt; 345 kPa): 1 cell"));
    CHECK_THAT(svg, Contains("capacity 345 kPa"));
    CHECK_THAT(svg, Contains("column 1 (y = -0.30 m) on the right"));
    CHECK(occurrences(svg, "class=\"flagged\"") == 1);
    // The colour bar's ticks cover 0 to the largest pressure (7111 kPa), rounded up to a tick.
    const Ticks scale = heat_map_scale(heat);
    CHECK(scale.lower == 0.0);
    CHECK(scale.upper >= heat.values[0]);
    CHECK(occurrences(svg, "class=\"colour-bar-tick\"") == scale.values.size());
    CHECK_THAT(svg, Contains("class=\"colour-bar-tick\">0</text>"));
    // The largest cell has the top colour only when the scale ends at it; the grey cells are
    // all the empty colour.
    CHECK(occurrences(svg, "fill=\"#e6e6e6\"/>") == 254);
    // Seen from the slope, column 0 (y = -0.3 m) is drawn on the right half of the map.
    const std::size_t cells_start = svg.find("<g stroke=\"white\"");
    REQUIRE(cells_start != std::string::npos);
    const std::size_t first = svg.find("<rect", cells_start);
    const std::string cell0 = svg.substr(first, svg.find("/>", first) - first);
    CHECK(attribute(cell0, "x") > 84.0 + 320.0);
    CHECK(attribute(cell0, "y") > 48.0 + 160.0);  // row 0 at the bottom
}

TEST_CASE("the map at the grid's peak sample has its time and load in the title",
          "[report][figures]") {
    const engine::Outcome outcome = two_hits();
    const engine::PressureMap map =
        engine::pressure_map(*flume().wall_cells, shapes::Slope(flume().slope), outcome);
    const HeatMap heat = pressure_sample_map(map, map.peak_sample);
    CHECK_THAT(heat.title, Contains("t = 1.000 s"));
    CHECK_THAT(heat.title, Contains("5000.0 N on the grid"));
    CHECK(heat.flagged[0]);
    const std::string svg = render_heat_map_svg(heat);
    CHECK(xml_problem(svg).empty());
    CHECK_THAT(svg, Contains(">sampled pressure (kPa)</text>"));
}

TEST_CASE("the wall force history: the whole wall and the grid, in N", "[report][figures]") {
    const engine::Outcome outcome = two_hits();
    const engine::PressureMap map =
        engine::pressure_map(*flume().wall_cells, shapes::Slope(flume().slope), outcome);
    const Plot plot = wall_force_plot(map, true);
    REQUIRE(plot.series.size() == 2);
    CHECK(plot.y_label == "normal force on the wall (N)");
    CHECK_THAT(*std::max_element(plot.series[0].y.begin(), plot.series[0].y.end()),
               WithinRel(5000.0, 1e-9));
    CHECK(plot.series[1].y == plot.series[0].y);  // both hits inside the grid
    // Zero stretches are thinned: far fewer points than the 1000-odd samples.
    CHECK(plot.series[0].x.size() < 20);
    CHECK(xml_problem(render_svg(plot)).empty());
    CHECK(wall_force_plot(map, false).series.size() == 1);
}

TEST_CASE("rock colours follow colour names", "[report][figures]") {
    CHECK(rock_colour("red", 3) == "#d62728");
    CHECK(rock_colour("Blue", 0) == "#1f77b4");
    CHECK(rock_colour("yellow", 0) != "#ffff00");  // darkened to read on white
    CHECK(rock_colour("granite", 1) == "#ff7f0e");
    CHECK(rock_colour("granite", 11) == "#ff7f0e");
}

TEST_CASE("a run's figures exist only for the data it has", "[report][figures]") {
    engine::Scenario scenario = flume();
    engine::Outcome quiet;
    quiet.rocks.resize(2);
    CHECK(run_figures(scenario, quiet, {}).empty());

    const engine::Outcome outcome = two_hits();
    CHECK(files(run_figures(scenario, outcome, {})) ==
          std::vector<std::string>{"pressure_peak.svg", "pressure_at_peak.svg", "wall_force.svg"});
    const std::vector<Figure> all = run_figures(scenario, outcome, red_series());
    REQUIRE(files(all) == std::vector<std::string>{"pressure_peak.svg", "pressure_at_peak.svg",
                                                   "wall_force.svg", "marked_speeds.svg"});
    for (const Figure& f : all) {
        INFO(f.file);
        CHECK(xml_problem(f.svg).empty());
        CHECK(!f.description.empty());
    }
    const std::string& speeds = all.back().svg;
    CHECK_THAT(speeds, Contains(">red (engine samples)</text>"));
    CHECK_THAT(speeds, Contains(">red (camera, every 0.04 s)</text>"));
    CHECK_THAT(speeds, Contains("stroke=\"#d62728\""));
    CHECK_THAT(speeds, Contains(">speed of the centre of mass (m/s)</text>"));

    scenario.wall_cells.reset();
    CHECK(files(run_figures(scenario, outcome, red_series())) ==
          std::vector<std::string>{"wall_force.svg", "marked_speeds.svg"});
    engine::Outcome named_only = quiet;
    named_only.rocks[1].name = "red";
    CHECK(files(run_figures(scenario, named_only, red_series())) ==
          std::vector<std::string>{"marked_speeds.svg"});
}
