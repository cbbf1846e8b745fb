#pragma once
/// A small SVG writer for x-y plots (points and lines, axes with nice ticks, a legend), enough
/// for the figures engineers put in a report, without a plotting dependency.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rockfall::report {

/// Evenly spaced tick values covering a range.
struct Ticks {
    /// The range rounded out to whole steps (lower < upper).
    double lower = 0.0;
    double upper = 1.0;
    /// Step between ticks (> 0): 1, 2 or 5 times a power of ten.
    double step = 1.0;
    /// Tick values from lower to upper, inclusive.
    std::vector<double> values;
    /// Decimals that print every tick value without rounding (>= 0).
    int decimals = 0;
};

/// Ticks for the range [lower, upper] (finite, lower <= upper; an empty range is widened)
/// with about `target` ticks (>= 2), by Heckbert's nice numbers ("Nice numbers for graph
/// labels", Graphics Gems, 1990): the step is the nice number nearest range / (target - 1)
/// (without Heckbert's first rounding of the range, which can double the step), and the range
/// is rounded out to whole steps. Throws std::invalid_argument on a non-finite or reversed
/// range.
Ticks nice_ticks(double lower, double upper, int target = 6);

/// The symbol drawn at each point of a series.
enum class Marker { none, circle, square, triangle };

/// One data series.
struct Series {
    /// Legend text; an empty label keeps the series out of the legend.
    std::string label;
    /// Stroke and fill colour (any SVG colour, e.g. "#1f77b4").
    std::string color = "#1f77b4";
    /// Data coordinates (same size, finite).
    std::vector<double> x;
    std::vector<double> y;
    /// Whether a line joins the points in order.
    bool line = true;
    /// Line width, px (> 0).
    double line_width = 1.5;
    /// SVG stroke-dasharray of the line ("" for solid, e.g. "6 4" dashed).
    std::string dash;
    /// Marker drawn at each point.
    Marker marker = Marker::none;
    /// Marker radius (circle) or half side (square, triangle), px (> 0).
    double marker_size = 4.0;
    /// Opacity of lines and markers, in (0, 1].
    double opacity = 1.0;
};

/// An x-y plot.
struct Plot {
    /// Title above the plot area; axis labels (with units) below and left of it.
    std::string title;
    std::string x_label;
    std::string y_label;
    /// Series, drawn in order (later ones on top).
    std::vector<Series> series;
    /// Axis ranges; unset ends follow the data, rounded out to nice ticks.
    std::optional<double> x_min;
    std::optional<double> x_max;
    std::optional<double> y_min;
    std::optional<double> y_max;
    /// Size of the drawing, px (>= 200 each).
    double width = 960.0;
    double height = 600.0;
    /// Prefix of the ids inside the drawing (its clip path): ids are global in an HTML page, so
    /// each of several drawings inlined in one page needs its own ("fig2-"). Empty by default.
    std::string id_prefix;
};

/// The rectangle of the plot area inside the drawing, px from the top-left corner.
struct PlotArea {
    double left = 0.0;
    double top = 0.0;
    double right = 0.0;
    double bottom = 0.0;
};

/// Where render_svg puts the plot area: fixed margins for the title and axis labels, and the
/// legend (when a series has a label) to the right of it, as wide as its longest label.
PlotArea plot_area(const Plot& plot);

/// The x and y ticks render_svg uses: the data range (or the fixed ends) rounded out.
/// Throws std::invalid_argument when no series has a point.
std::pair<Ticks, Ticks> plot_ticks(const Plot& plot);

/// The plot as a standalone SVG document: a white background, grid lines and labels at the
/// ticks, the series clipped to the plot area, the title, axis labels and legend. Text is
/// XML-escaped. Throws std::invalid_argument for a series with x and y of different sizes or
/// a non-finite value, or when no series has a point.
std::string render_svg(const Plot& plot);

}  // namespace rockfall::report
