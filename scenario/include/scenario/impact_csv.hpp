#pragma once
/// Measured or simulated wall impacts read from a CSV file, for `rockfall fit`, and the
/// trajectory sample of `rockfall formula uni`.
///
/// Impacts:
/// Columns, named in the header in any order (other columns are ignored):
///   velocity_m_s                  impact velocity just before the hit, m/s (> 0)
///   peak_force_kN | peak_force_N  peak load, in kN or N as the name says (exactly one; > 0)
///   mass_kg                       rock mass, kg (> 0)
///   shape                         sphere, massive or planar (seed 000's shape classes)
/// A design sample:
///   velocity_m_s                  the rock's speed, m/s (>= 0)
///   bounce_height_m               its bounce (passing) height, m (>= 0)

#include "scenario/csv_table.hpp"

#include "risk/design_values.hpp"
#include "risk/impact_fit.hpp"

#include <filesystem>
#include <vector>

namespace rockfall::scenario {

/// The impact rows of a table in SI units (peak force in N). Throws CsvError naming the file,
/// line and column for a missing column, text in a numeric field, a value out of range or an
/// unknown shape, and when the table has no data row.
std::vector<risk::ImpactRow> impact_rows(const CsvTable& table);

/// impact_rows(CsvTable::read(path)).
std::vector<risk::ImpactRow> read_impact_csv(const std::filesystem::path& path);

/// The speeds and heights of a design sample; throws CsvError naming the file, line and
/// column for a missing column, text or a negative value, and when there is no data row.
risk::DesignSample read_design_sample(const std::filesystem::path& path);

}  // namespace rockfall::scenario
