#pragma once
/// What the rocks carried past each station of a sweep (table stations): for the per-station
/// statistics and the UNI 11211-4 design values of the HTML report (`rockfall report`).

#include "db/results_db.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace rockfall::db {

/// The rocks that crossed one station, and their values there.
struct StationValues {
    /// Station number (1-based, scenario order) and its horizontal distance from the toe, m.
    std::int64_t station = 0;
    double distance_from_toe = 0.0;
    /// Rocks with a row for the station (every rock of every sample) and those that crossed it.
    std::int64_t rocks = 0;
    std::int64_t reached = 0;
    /// Of the rocks that crossed it, ascending, NULLs skipped: speed (m/s), bounce height above
    /// the surface (m) and kinetic energy, translational + rotational (J).
    std::vector<double> speeds;
    std::vector<double> bounce_heights;
    std::vector<double> energies;
    /// Largest mass of a rock that crossed it, kg; NaN when none did.
    double max_mass = std::numeric_limits<double>::quiet_NaN();
};

/// Every station's values, by station number. Throws DatabaseError for a damaged file.
std::vector<StationValues> read_station_values(const ResultsDb& db);

}  // namespace rockfall::db
