#pragma once
/// Text and JSON of a run's pressure-cell grid (engine/pressure_cells.hpp): per cell the peak
/// force and pressure (true, and as sampled), saturation; per rock the cells it loaded and its
/// sampled peak; the grid's summed force history. Units as in simulation_report.hpp.

#include "engine/outcome.hpp"
#include "engine/pressure_cells.hpp"
#include "engine/scenario.hpp"

#include <nlohmann/json.hpp>

#include <ostream>

namespace rockfall::report {

/// Writes the grid's summary: its layout, the peak cell, loaded and saturated cells, and one
/// line per rock that loaded it (named rocks first).
void print_pressure_cells(std::ostream& out, const engine::PressureMap& map,
                          const engine::Outcome& outcome);

/// The grid as JSON: spec, every loaded cell, per rock loads, and the sampled history of the
/// total wall force and of the grid's sum.
nlohmann::json pressure_cells_json(const engine::PressureMap& map, const engine::Outcome& outcome);

}  // namespace rockfall::report
