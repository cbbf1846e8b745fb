#pragma once
/// Wall impacts for `rockfall fit` and `rockfall envelope`: measured rows from a CSV file, or
/// every wall hit of a sweep from its results database.

#include "report/impact_data.hpp"

#include <filesystem>
#include <string>

namespace CLI {
class App;
}

namespace rockfall::app {

/// Which impacts a fit or envelope report keeps (--min-velocity, --first-hits).
struct ImpactFilter {
    double min_velocity = 0.0;
    bool first_hits = false;
};

/// Registers --min-velocity and --first-hits on `cmd`, writing into `filter`.
void add_impact_filter_options(CLI::App& cmd, ImpactFilter& filter);

/// Applies `filter` to `data` (report::drop_slow, report::keep_first_hits) and records it in
/// `selection`; throws std::invalid_argument for a bad minimum or --first-hits on a CSV file.
void apply_impact_filter(report::ImpactData& data, const ImpactFilter& filter,
                         report::ImpactSelection& selection);

/// The impacts of a results database; throws db::DatabaseError for a bad file.
report::ImpactData database_impacts(const std::filesystem::path& path,
                                    report::HitVelocity velocity);

/// A results database's impacts, or a CSV file's rows (scenario/impact_csv.hpp).
report::ImpactData load_impacts(const std::filesystem::path& path, report::HitVelocity velocity);

}  // namespace rockfall::app
