#pragma once
/// A small SVG heat-map writer: a grid of cells coloured by value on a perceptual colour map
/// (viridis), axes in data units with nice ticks (shared with svg_plot.hpp), a colour bar with
/// ticks and its label, and flagged cells (e.g. saturated sensors) hatched and outlined.

#include "report/svg_plot.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace rockfall::report {

/// Viridis (van der Walt, Smith and Firing for matplotlib, 2015; CC0) at `f` in [0, 1]
/// (clamped): red, green and blue in [0, 1].
std::array<double, 3> viridis(double f);

/// viridis(f) as an SVG colour "#rrggbb".
std::string viridis_hex(double f);

/// A grid of values over a rectangle in data coordinates.
struct HeatMap {
    /// Title above the map; axis labels (with units) below and left of it.
    std::string title;
    std::string x_label;
    std::string y_label;
    /// Label of the colour bar, with its unit (e.g. "peak pressure (kPa)").
    std::string value_label;
    /// Cells across and up (>= 1 each).
    int columns = 1;
    int rows = 1;
    /// Extent in data units: column 0 starts at x_min, row 0 at y_min (the bottom); x_min <
    /// x_max, y_min < y_max.
    double x_min = 0.0;
    double x_max = 1.0;
    double y_min = 0.0;
    double y_max = 1.0;
    /// Draw x backwards: x_max on the left, column 0 on the right.
    bool mirror_x = false;
    /// Values row-major (values[row * columns + column], columns * rows of them); NaN for a
    /// cell without a value, drawn light grey.
    std::vector<double> values;
    /// Empty, or one per cell: the cell is hatched and outlined in red.
    std::vector<bool> flagged;
    /// Legend text for flagged cells and for cells without a value (an empty text leaves its
    /// legend entry out).
    std::string flagged_label;
    std::string empty_label;
    /// Top of the colour scale; unset: the largest value rounded up to a nice tick. The bottom
    /// is 0 (values below it take the colour of 0).
    std::optional<double> value_max;
    /// A value marked across the colour bar with a red line and `mark_label` (e.g. a sensor's
    /// capacity), when inside the scale.
    std::optional<double> mark;
    std::string mark_label;
    /// Width of the map itself, px (>= 100); its height follows the data's aspect (equal scales
    /// across and up), at most 1.2 times the width.
    double map_width = 640.0;
};

/// The colour scale's ticks: 0 to value_max or the largest finite value (any non-negative
/// values; all NaN gives 0 to 1).
Ticks heat_map_scale(const HeatMap& map);

/// The map as a standalone SVG document: cells, axes with grid ticks, the colour bar with its
/// ticks, label and mark, the legend for flagged and empty cells. Text is XML-escaped. Throws
/// std::invalid_argument when the sizes do not match, the extent is empty or a value is
/// infinite.
std::string render_heat_map_svg(const HeatMap& map);

}  // namespace rockfall::report
