#pragma once
// Checks on the database file and its directory before SQLite touches them, so that every
// refusal names the file and the remedy, and a new database appears whole or not at all.

#include "db/results_db.hpp"

#include <filesystem>
#include <string>

namespace rockfall::db {

/// Throws DatabaseError (bad_file) unless a new database can be created at `path`: it does
/// not exist and its directory exists and is writable.
void require_creatable(const std::filesystem::path& path);

/// Throws DatabaseError (bad_file) unless `path` is an existing SQLite file (by its header),
/// and, when `writable`, the file and its directory are writable.
void require_database_file(const std::filesystem::path& path, bool writable);

/// What a database of `kind` holds and which command writes it ("a soil flow (written by
/// `rockfall soil --db`)"), for messages.
std::string held_by(RunKind kind);

/// Throws DatabaseError (failure) when `db` was opened read-only; `what` is the operation.
void require_writable(const ResultsDb& db, const std::string& what);

/// Whether a reader must open `path` as immutable because SQLite cannot create its -shm file
/// next to it (a read-only directory). Throws DatabaseError (bad_file) when the directory is
/// read-only and a -wal file holds samples not yet in the database file.
bool read_only_location(const std::filesystem::path& path);

/// The SQLite URI that opens `path` read-only and immutable (no locks, no -shm).
std::string immutable_uri(const std::filesystem::path& path);

/// The SQLite URI that opens `path` read-only (mode=ro), e.g. for ATTACH.
std::string read_only_uri(const std::filesystem::path& path);

/// Removes the part files of `target` (and their journals) that a killed rockfall left: those
/// no live process holds. A part file another rockfall is building stays.
void remove_stale_part_files(const std::filesystem::path& target);

/// A uniquely named file in the directory of a database being created (".NAME.<16 hex>.part"),
/// created empty and held under an exclusive flock() while this object lives, removed (with its
/// SQLite journal) on destruction; publish() links it to its target first.
class TemporaryFile {
  public:
    /// A name beside `target`, hidden, that no other process uses.
    explicit TemporaryFile(const std::filesystem::path& target);
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    ~TemporaryFile();
    /// The temporary file's path.
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
    int fd_ = -1;
};

/// Moves the finished temporary file to `target` without ever replacing an existing file;
/// throws DatabaseError when `target` appeared meanwhile or the move fails.
void publish(const TemporaryFile& temporary, const std::filesystem::path& target);

}  // namespace rockfall::db
