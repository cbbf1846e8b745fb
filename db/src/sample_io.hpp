#pragma once
// Writing and reading whole samples (inputs, outcome, stations, wall impacts, trajectory):
// the column order of every INSERT and SELECT lives here only.

#include "sqlite.hpp"

#include "db/results_db.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace rockfall::db {

/// The insert statements of write_batch, prepared once per connection and reused.
struct ResultsDb::Statements {
    Statements(sqlite3* db, const std::filesystem::path& path);
    /// Inserts one record's rows (inside the caller's transaction).
    void write(const SampleRecord& record);
    /// Inserts one rock's rows (inputs, outcome, stations, wall impacts, trajectory).
    void write_rock(std::int64_t index, std::int64_t rock_index, const risk::RockResult& result);

    sql::Statement sample;
    sql::Statement rock;
    sql::Statement outcome;
    sql::Statement station;
    sql::Statement impact;
    sql::Statement trajectory;
};

/// The columns a station crossing is read from, in the order station_from() expects them.
inline constexpr const char* station_columns =
    "distance_from_toe_m, reached, time_s, speed_m_s, parallel_speed_m_s, angular_speed_rad_s, "
    "bounce_height_m, rolling_coefficient, translational_energy_J, rotational_energy_J";

/// A crossing from station_columns starting at column `first` of the current row; a station not
/// reached keeps its defaults past `reached`.
engine::StationCrossing station_from(const sql::Statement& row, int first);

/// Reads rock `rock` of sample `index` (outcome, stations, wall impacts, trajectory) into
/// `result`, whose inputs are read; false when its outcome is absent.
bool read_rock(sqlite3* db, const std::filesystem::path& path, std::int64_t index,
               std::int64_t rock, risk::RockResult& result);

/// Reads sample `index` with its rocks and their rows; empty when absent.
std::optional<SampleRecord> read_sample(sqlite3* db, const std::filesystem::path& path,
                                        std::int64_t index);

}  // namespace rockfall::db
