#include "report/svg_plot.hpp"

#include <catch2/catch.hpp>

#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;
using Catch::Matchers::StartsWith;
using Catch::Matchers::WithinAbs;
using namespace rockfall::report;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

Series series(std::string label, std::string color, std::vector<double> x, std::vector<double> y) {
    Series s;
    s.label = std::move(label);
    s.color = std::move(color);
    s.x = std::move(x);
    s.y = std::move(y);
    return s;
}

Plot two_series() {
    Plot plot;
    plot.title = "Peak load & velocity";
    plot.x_label = "impact velocity (m/s)";
    plot.y_label = "peak load (kN)";
    plot.x_min = 0.0;
    plot.y_min = 0.0;
    plot.series = {series("measured <sphere>", "#1f77b4", {2.0, 4.0, 6.0}, {30.0, 80.0, 120.0}),
                   series("mean", "#d62728", {0.0, 10.0}, {0.0, 200.0}),
                   series("", "#2ca02c", {1.0, 9.0}, {10.0, 10.0})};
    plot.series[0].line = false;
    plot.series[0].marker = Marker::circle;
    plot.series[1].dash = "6 4";
    return plot;
}

}  // namespace

TEST_CASE("nice ticks use steps of 1, 2 or 5 and cover the range", "[report][svg]") {
    Ticks t = nice_ticks(0.0, 10.0);
    CHECK(t.step == 2.0);
    CHECK(t.values == std::vector<double>{0, 2, 4, 6, 8, 10});
    CHECK(t.decimals == 0);

    t = nice_ticks(3.2, 9.7);  // 6.5 / 5 = 1.3, nearest nice 1: ticks 3..10
    CHECK(t.step == 1.0);
    CHECK(t.lower == 3.0);
    CHECK(t.upper == 10.0);

    t = nice_ticks(0.0, 1014.0);  // 202.8 -> 200: 0..1200, not Heckbert's 0..1500
    CHECK(t.step == 200.0);
    CHECK(t.upper == 1200.0);

    t = nice_ticks(0.013, 0.087);  // 0.0148 -> 0.01
    CHECK_THAT(t.step, WithinAbs(0.01, 1e-15));
    CHECK(t.decimals == 2);
    CHECK_THAT(t.lower, WithinAbs(0.01, 1e-15));
    CHECK_THAT(t.upper, WithinAbs(0.09, 1e-15));
    CHECK(t.values.size() == 9);

    t = nice_ticks(-1.0, 1.0, 5);  // range 2 -> 2, / 4 = 0.5
    CHECK(t.step == 0.5);
    CHECK(t.values.size() == 5);
    CHECK(t.values[2] == 0.0);

    t = nice_ticks(5.0, 5.0);  // an empty range is widened to 4.5 .. 5.5
    CHECK(t.lower <= 4.5);
    CHECK(t.upper >= 5.5);
    CHECK_THROWS_AS(nice_ticks(2.0, 1.0), std::invalid_argument);
}

TEST_CASE("SVG document has the plot's structure", "[report][svg]") {
    const Plot plot = two_series();
    const std::string svg = render_svg(plot);
    CHECK_THAT(svg, StartsWith("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"960.00\""));
    CHECK_THAT(svg, EndsWith("</svg>\n"));
    CHECK_THAT(svg, Contains("viewBox=\"0 0 960.00 600.00\""));
    CHECK_THAT(svg, Contains("<clipPath id=\"plot-area\">"));
    // Three data circles plus the one in the legend; two data lines plus one legend line
    // (the unlabelled series has no legend entry).
    CHECK(count(svg, "<circle") == 4);
    CHECK(count(svg, "<polyline") == 3);
    CHECK(count(svg, "stroke-dasharray=\"6 4\"") == 2);
    // Text is escaped; the labels and ticks are there.
    CHECK_THAT(svg, Contains("Peak load &amp; velocity"));
    CHECK_THAT(svg, Contains("measured &lt;sphere&gt;"));
    CHECK_THAT(svg, Contains(">impact velocity (m/s)</text>"));
    CHECK_THAT(svg, Contains(">peak load (kN)</text>"));
    CHECK_THAT(svg, Contains(">200</text>"));
    CHECK_THAT(svg, Contains(">10</text>"));
    CHECK(svg.find("<sphere>") == std::string::npos);
}

TEST_CASE("SVG points land where the axes say", "[report][svg]") {
    Plot plot = two_series();
    plot.series.resize(1);
    plot.x_max = 10.0;
    plot.y_max = 200.0;
    const PlotArea a = plot_area(plot);
    const auto [x, y] = plot_ticks(plot);
    CHECK(x.lower == 0.0);
    CHECK(x.upper == 10.0);
    CHECK(y.upper == 200.0);
    // The point (4, 80): 40 % across, 40 % up.
    const double px = a.left + 0.4 * (a.right - a.left);
    const double py = a.bottom - 0.4 * (a.bottom - a.top);
    char expected[64];
    std::snprintf(expected, sizeof expected, "<circle cx=\"%.2f\" cy=\"%.2f\"", px, py);
    CHECK_THAT(render_svg(plot), Contains(expected));
    // The legend takes room on the right; without labels the plot area is wider.
    Plot bare = plot;
    bare.series[0].label.clear();
    CHECK(plot_area(bare).right > a.right);
    CHECK(count(render_svg(bare), "<circle") == 3);
}

TEST_CASE("SVG writer rejects bad series", "[report][svg]") {
    Plot plot = two_series();
    plot.series[1].y.pop_back();
    CHECK_THROWS_WITH(render_svg(plot), Contains("2 x values but 1 y values"));
    plot = two_series();
    plot.series[0].y[1] = std::nan("");
    CHECK_THROWS_WITH(render_svg(plot), Contains("point 1 is not finite"));
    plot.series.clear();
    CHECK_THROWS_WITH(render_svg(plot), Contains("no data"));
}
