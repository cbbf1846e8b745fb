#pragma once
/// Wall impacts for `rockfall fit` and `rockfall envelope`: measured rows from a CSV file, or
/// every wall hit of a sweep from its results database.

#include "report/impact_data.hpp"

#include <filesystem>
#include <string>

namespace rockfall::app {

/// The impacts of a results database; throws db::DatabaseError for a bad file.
report::ImpactData database_impacts(const std::filesystem::path& path,
                                    report::HitVelocity velocity);

/// A results database's impacts, or a CSV file's rows (scenario/impact_csv.hpp).
report::ImpactData load_impacts(const std::filesystem::path& path, report::HitVelocity velocity);

}  // namespace rockfall::app
