#pragma once
/// Measured wall-load records (load-cell histories) read from CSV, for comparison with a
/// simulated soil flow (risk::compare_histories).
///
/// Measured CSV columns, named in the header in any order (other columns are ignored):
///   time_s                      time since the release, s (finite, >= 0, increasing)
///   load_kN | load_N            wall load normal to the wall, total over the wall (3D runs)
///   load_kN_per_m | load_N_per_m  the same per metre of width (2D plane-strain runs)
/// Exactly one load column; its unit is in its name.

#include "scenario/csv_table.hpp"

#include "risk/load_history.hpp"

#include <filesystem>

namespace rockfall::scenario {

/// The measured history of a CSV table, loads in N (or N/m). Throws CsvError naming the file,
/// line and column for a missing or doubled load column, text in a numeric field, a negative
/// or non-increasing time, and for fewer than two rows.
risk::LoadHistory measured_history(const CsvTable& table);

/// measured_history(CsvTable::read(path)).
risk::LoadHistory read_measured_history(const std::filesystem::path& path);

}  // namespace rockfall::scenario
