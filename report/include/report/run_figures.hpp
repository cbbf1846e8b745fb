#pragma once
/// The figures of one run (`rockfall simulate --figures DIR`): seed 001's pressure maps of the
/// wall (peak per cell, and the map at the grid's peak sample), the wall force history, and the
/// marked rocks' speed profiles. Each figure exists only when the run has its data.

#include "report/heat_map.hpp"
#include "report/marked_rocks.hpp"
#include "report/simulation_report.hpp"
#include "report/svg_plot.hpp"

#include "engine/outcome.hpp"
#include "engine/pressure_cells.hpp"
#include "engine/scenario.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace rockfall::report {

/// One figure, ready to write.
struct Figure {
    /// File name in the figures directory, e.g. "pressure_peak.svg".
    std::string file;
    /// What it shows, one line.
    std::string description;
    /// The SVG document.
    std::string svg;
};

/// The heat map of every cell's sampled peak pressure (kPa) over the grid, seen from the slope
/// (column 0, at y = -width / 2, on the right; row 0 at the wall's foot), axes in m; cells never
/// loaded are grey, saturated cells hatched, the capacity marked on the colour bar.
HeatMap pressure_peak_map(const engine::PressureMap& map);

/// The same for the cells' sampled pressure at sample `sample` (< map.samples); saturated:
/// above the capacity in that sample.
HeatMap pressure_sample_map(const engine::PressureMap& map, std::size_t sample);

/// The sampled normal force on the whole wall against time, and with `grid` the part on the
/// grid's cells; in N, or kN when the force passes 10 kN.
Plot wall_force_plot(const engine::PressureMap& map, bool grid);

/// The marked rocks' speed (m/s) against distance travelled (m): the engine's samples as
/// lines, the camera's points as circles, one colour per rock (rock_colour), and dashed lines at
/// the distances of the speed readings. Needs a rock with at least two samples.
Plot marked_speeds_plot(const MarkedRocks& marked);

/// A rock's colour: the name's own when it names a common colour (red, blue, green, yellow,
/// orange, purple, brown, pink, grey or gray, black, cyan, magenta; case-insensitive; yellow
/// darkened to stay readable on white), otherwise the `index`-th of a ten-colour palette.
std::string rock_colour(const std::string& name, std::size_t index);

/// The figures the run has data for, in this order: pressure_peak.svg and pressure_at_peak.svg
/// (with [wall_cells] and a loaded cell), wall_force.svg (with a wall hit), marked_speeds.svg
/// (with a named rock sampled at least twice; camera interval from `series`).
std::vector<Figure> run_figures(const engine::Scenario& scenario, const engine::Outcome& outcome,
                                const RunSeries& series);

}  // namespace rockfall::report
