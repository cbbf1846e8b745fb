// Wall impacts from a CSV file or a results database (see impact_source.hpp).

#include "impact_source.hpp"

#include "scenario/impact_csv.hpp"

#include "db/results_db.hpp"

#include <cmath>
#include <optional>

namespace rockfall::app {
namespace {

bool positive(double x) { return std::isfinite(x) && x > 0.0; }

}  // namespace

report::ImpactData database_impacts(const std::filesystem::path& path,
                                    report::HitVelocity velocity) {
    const db::ResultsDb database = db::ResultsDb::open(path, false);
    report::ImpactData data;
    data.from_database = true;
    for (db::WallImpact& hit : db::read_wall_impacts(database)) {
        risk::ImpactRow row;
        row.velocity =
            velocity == report::HitVelocity::normal ? hit.normal_speed : hit.impact_speed;
        row.peak_force = hit.peak_force;
        row.mass = hit.mass;
        const std::optional<risk::ImpactShape> shape = risk::find_impact_shape(hit.kind);
        if (!shape || !positive(row.velocity) || !positive(row.peak_force) || !positive(row.mass)) {
            ++data.skipped;
            continue;
        }
        row.shape = *shape;
        data.rows.push_back(row);
        data.hits.push_back(std::move(hit));
    }
    return data;
}

report::ImpactData load_impacts(const std::filesystem::path& path, report::HitVelocity velocity) {
    if (db::is_sqlite_file(path)) return database_impacts(path, velocity);
    report::ImpactData data;
    data.rows = scenario::read_impact_csv(path);
    return data;
}

}  // namespace rockfall::app
