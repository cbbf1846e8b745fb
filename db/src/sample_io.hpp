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

/// Reads rock `rock` of sample `index` (outcome, stations, wall impacts, trajectory) into
/// `result`, whose inputs are read; false when its outcome is absent.
bool read_rock(sqlite3* db, const std::filesystem::path& path, std::int64_t index,
               std::int64_t rock, risk::RockResult& result);

/// Reads sample `index` with its rocks and their rows; empty when absent.
std::optional<SampleRecord> read_sample(sqlite3* db, const std::filesystem::path& path,
                                        std::int64_t index);

}  // namespace rockfall::db
