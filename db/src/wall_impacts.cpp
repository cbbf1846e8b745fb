// Every wall hit of a sweep from the view impact_results (see wall_impacts.hpp).

#include "db/wall_impacts.hpp"

#include "sqlite.hpp"

namespace rockfall::db {

std::vector<WallImpact> read_wall_impacts(const ResultsDb& db) {
    sql::Statement rows(db.handle(), db.path(),
                        "SELECT sample, rock, hit, seed, kind, size_m, mass_kg, impact_speed_m_s, "
                        "normal_speed_m_s, peak_force_N, energy_before_J FROM impact_results "
                        "ORDER BY sample, rock, hit");
    std::vector<WallImpact> impacts;
    while (rows.step()) {
        WallImpact& w = impacts.emplace_back();
        w.sample = rows.integer(0);
        w.rock = rows.integer(1);
        w.hit = rows.integer(2);
        w.seed = sql::from_stored(rows.integer(3));
        w.kind = rows.text(4);
        w.size = rows.real(5);
        w.mass = rows.real(6);
        w.impact_speed = rows.real(7);
        w.normal_speed = rows.real(8);
        w.peak_force = rows.real(9);
        w.energy_before = rows.real(10);
    }
    return impacts;
}

}  // namespace rockfall::db
