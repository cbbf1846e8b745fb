// Wall impacts from a CSV file or a results database (see impact_source.hpp).

#include "impact_source.hpp"

#include "scenario/impact_csv.hpp"

#include "db/results_db.hpp"
#include "db/wall_impacts.hpp"

#include <CLI/CLI.hpp>

namespace rockfall::app {

void add_impact_filter_options(CLI::App& cmd, ImpactFilter& filter) {
    cmd.add_option("--min-velocity", filter.min_velocity,
                   "Leave out impacts slower than this (m/s): resting or pushing contacts")
        ->capture_default_str();
    cmd.add_flag("--first-hits", filter.first_hits,
                 "Database: only each rock's first hit, its arrival at the wall (seed 000 "
                 "measured the velocity just before it), not rebounds or re-contacts");
}

void apply_impact_filter(report::ImpactData& data, const ImpactFilter& filter,
                         report::ImpactSelection& selection) {
    report::drop_slow(data, filter.min_velocity);
    if (filter.first_hits) report::keep_first_hits(data);
    selection.min_velocity = filter.min_velocity;
    selection.first_hits = filter.first_hits;
}

report::ImpactData database_impacts(const std::filesystem::path& path,
                                    report::HitVelocity velocity) {
    const db::ResultsDb database = db::ResultsDb::open(path, false);
    return report::database_rows(db::read_wall_impacts(database), velocity);
}

report::ImpactData load_impacts(const std::filesystem::path& path, report::HitVelocity velocity) {
    if (db::is_sqlite_file(path)) return database_impacts(path, velocity);
    report::ImpactData data;
    data.rows = scenario::read_impact_csv(path);
    return data;
}

}  // namespace rockfall::app
