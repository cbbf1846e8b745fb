#pragma once
/// What the rocks carried past each station of a sweep (table stations): for the per-station
/// statistics and the UNI 11211-4 design values of the HTML report (`rockfall report`), and
/// each rock's crossings for `rockfall query DB stations` (seed 000's Figures 5 and 6).

#include "db/results_db.hpp"

#include <cstdint>
#include <limits>
#include <string>
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

/// One rock of one sample with its crossings of every station.
struct RockStations {
    /// Sample index (0-based) and rock index within the sample (0-based).
    std::int64_t sample = 0;
    std::int64_t rock = 0;
    /// Shape family (sphere, massive, planar, custom) and shape (as samples.shape).
    std::string kind;
    std::string shape;
    /// Nominal (volume-equivalent) diameter, m; NaN when not stored.
    double size = std::numeric_limits<double>::quiet_NaN();
    /// The crossings in station order (1-based station i at index i - 1), reached or not.
    std::vector<engine::StationCrossing> stations;
};

/// Every rock with a station row, in (sample, rock) order. Throws DatabaseError for a damaged
/// file.
std::vector<RockStations> read_rock_stations(const ResultsDb& db);

}  // namespace rockfall::db
