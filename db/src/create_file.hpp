#pragma once
// Creating a new database file of either kind (private to the db library).

#include "db/results_db.hpp"

#include <filesystem>
#include <functional>

struct sqlite3;

namespace rockfall::db {

/// Creates a database at `path` holding `run` as a run of `kind`, with `fill` (may be empty)
/// writing further rows in the same transaction. The file is built under a hidden temporary
/// name beside `path` and published at the end: it appears whole or not at all, and an
/// existing file is never replaced. Throws DatabaseError (bad_file) when `path` exists or its
/// directory is missing or read-only, (failure) when writing fails.
/// Writes a new database holding `run` into the empty file `temporary` (rollback journal, so
/// that closing it leaves one file), `fill` (may be empty) writing further rows in the same
/// transaction; `path` is the target, named in errors.
void build_database(const std::filesystem::path& temporary, const std::filesystem::path& path,
                    const RunRecord& run, RunKind kind, const std::function<void(sqlite3*)>& fill);

void create_database_file(const std::filesystem::path& path, const RunRecord& run, RunKind kind,
                          const std::function<void(sqlite3*)>& fill);

}  // namespace rockfall::db
