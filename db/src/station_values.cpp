// The rocks' values at each station (see station_values.hpp).

#include "db/station_values.hpp"

#include "sample_io.hpp"
#include "sqlite.hpp"

#include <algorithm>
#include <cmath>

namespace rockfall::db {

std::vector<StationValues> read_station_values(const ResultsDb& db) {
    // Storage order (sample, rock, station): the primary key's, no sort.
    sql::Statement rows(db.handle(), db.path(),
                        "SELECT t.station, t.distance_from_toe_m, t.reached, t.speed_m_s, "
                        "t.bounce_height_m, t.translational_energy_J + t.rotational_energy_J, "
                        "r.mass_kg FROM stations t "
                        "JOIN rocks r ON r.sample = t.sample AND r.rock = t.rock");
    std::vector<StationValues> stations;
    while (rows.step()) {
        const std::int64_t station = rows.integer(0);
        if (station < 1) continue;
        const auto index = static_cast<std::size_t>(station - 1);
        if (index >= stations.size()) stations.resize(index + 1);
        StationValues& s = stations[index];
        s.station = station;
        s.distance_from_toe = rows.real(1);
        ++s.rocks;
        if (rows.integer(2) == 0) continue;
        ++s.reached;
        if (!rows.is_null(3)) s.speeds.push_back(rows.real(3));
        if (!rows.is_null(4)) s.bounce_heights.push_back(rows.real(4));
        if (!rows.is_null(5)) s.energies.push_back(rows.real(5));
        const double mass = rows.real(6);
        if (!std::isnan(mass) && !(mass <= s.max_mass)) s.max_mass = mass;
    }
    // Stations numbered with gaps (none in files this tool writes) leave empty entries out.
    stations.erase(std::remove_if(stations.begin(), stations.end(),
                                  [](const StationValues& s) { return s.station == 0; }),
                   stations.end());
    for (StationValues& s : stations) {
        for (std::vector<double>* values : {&s.speeds, &s.bounce_heights, &s.energies}) {
            std::sort(values->begin(), values->end());
        }
    }
    return stations;
}

std::vector<RockStations> read_rock_stations(const ResultsDb& db) {
    // The primary key's order (sample, rock, station): one pass groups each rock's rows.
    sql::Statement rows(db.handle(), db.path(),
                        std::string("SELECT t.sample, t.rock, r.kind, r.shape, r.size_m, ") +
                            station_columns +
                            " FROM stations t JOIN rocks r ON r.sample = t.sample AND "
                            "r.rock = t.rock ORDER BY t.sample, t.rock, t.station");
    std::vector<RockStations> rocks;
    while (rows.step()) {
        const std::int64_t sample = rows.integer(0);
        const std::int64_t rock = rows.integer(1);
        if (rocks.empty() || rocks.back().sample != sample || rocks.back().rock != rock) {
            RockStations& r = rocks.emplace_back();
            r.sample = sample;
            r.rock = rock;
            r.kind = rows.text(2);
            r.shape = rows.text(3);
            r.size = rows.real(4);
        }
        rocks.back().stations.push_back(station_from(rows, 5));
    }
    return rocks;
}

}  // namespace rockfall::db
