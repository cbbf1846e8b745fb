#pragma once
// Pieces of the SVG writer shared by the x-y plots (svg_plot.cpp) and the heat maps
// (heat_map.cpp): number and text formatting, the data-to-drawing frame, axes with grid lines,
// tick labels, axis labels and title. Private to the report library.

#include "report/svg_plot.hpp"

#include <optional>
#include <ostream>
#include <string>

namespace rockfall::report::svg_detail {

/// Font size of tick labels, px.
inline constexpr double font_size = 13.0;
/// Margins of the plot area, px: room for the y tick and axis labels on the left, the title
/// above, the x tick and axis labels below (write_axes draws them there).
inline constexpr double margin_left = 84.0;
inline constexpr double margin_top = 48.0;
inline constexpr double margin_bottom = 64.0;

/// A coordinate or length for an SVG attribute: two decimals.
std::string num(double value);

/// Text with &, <, > and " escaped for XML.
std::string escaped(const std::string& text);

/// The opening <svg> element of a drawing `width` x `height` px with its white background.
std::string svg_open(double width, double height);

/// Maps data coordinates to the drawing. An axis whose ticks have lower > upper runs backwards
/// (larger values on the left, or at the bottom).
struct Frame {
    PlotArea area;
    Ticks x;
    Ticks y;
    double px(double value) const {
        return area.left + (value - x.lower) / (x.upper - x.lower) * (area.right - area.left);
    }
    double py(double value) const {
        return area.bottom - (value - y.lower) / (y.upper - y.lower) * (area.bottom - area.top);
    }
};

/// Grid lines and labels at the ticks, the plot area's border, the axis labels and the title of
/// `plot` (its series are not drawn): the title 18 px above the area, the x label 46 px below
/// it, the y label 62 px left of it.
void write_axes(std::ostream& out, const Frame& frame, const Plot& plot);

/// Ticks over the data range [data_low, data_high] or the fixed ends `low`, `high`: a fixed
/// end stays where it was asked to be, even between two ticks.
Ticks axis_ticks(double data_low, double data_high, std::optional<double> low,
                 std::optional<double> high);

}  // namespace rockfall::report::svg_detail
