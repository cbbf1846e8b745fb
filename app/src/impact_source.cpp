// Wall impacts from a CSV file or a results database (see impact_source.hpp).

#include "impact_source.hpp"

#include "scenario/impact_csv.hpp"

#include "db/results_db.hpp"
#include "db/wall_impacts.hpp"

namespace rockfall::app {

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
