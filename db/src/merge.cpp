#include "db/merge.hpp"

#include "create_file.hpp"
#include "file_checks.hpp"
#include "sqlite.hpp"

#include <array>
#include <string>
#include <string_view>
#include <utility>

namespace rockfall::db {
namespace {

namespace fs = std::filesystem;
using Kind = DatabaseError::Kind;

// The tables that hold samples, parents before children (the foreign keys point at samples).
constexpr std::array<std::string_view, 6> sample_tables = {
    "samples", "rocks", "outcomes", "stations", "wall_impacts", "trajectories"};

std::int64_t attached_integer(sqlite3* db, const fs::path& shard, const std::string& pragma) {
    sql::Statement statement(db, shard, "PRAGMA shard." + pragma);
    if (!statement.step()) sql::fail(db, SQLITE_CORRUPT, shard, "reading PRAGMA " + pragma);
    return statement.integer(0);
}

// The shard attached as `shard` is ours, of this build's schema version and not corrupt. A
// version-1 file is refused: its tables lack the rock column (it reads through TEMP views).
void check_attached(sqlite3* db, const fs::path& shard) {
    const std::int64_t id = attached_integer(db, shard, "application_id");
    if (id != application_id) {
        throw DatabaseError(shard.string() +
                                " is not a rockfall results database (application_id " +
                                std::to_string(id) + "): give shards written by `rockfall sweep`",
                            Kind::bad_file);
    }
    const std::int64_t version = attached_integer(db, shard, "user_version");
    if (version != schema_version) {
        throw DatabaseError(shard.string() + " has schema version " + std::to_string(version) +
                                "; merge copies rows of version " + std::to_string(schema_version) +
                                " only: run every shard with the same rockfall",
                            Kind::bad_file);
    }
    sql::Statement check(db, shard, "PRAGMA shard.quick_check(1)");
    const std::string result = check.step() ? check.text(0) : std::string();
    if (result != "ok") {
        throw DatabaseError(shard.string() + " is corrupt (SQLite quick_check: " + result +
                                "): run that shard again (rockfall sweep --shard K/N)",
                            Kind::bad_file);
    }
}

void copy_shard(sqlite3* db, const fs::path& out, const fs::path& shard) {
    sql::Statement attach(db, shard, "ATTACH DATABASE ? AS shard");
    attach.bind_text(1, read_only_uri(shard));
    attach.step();
    try {
        check_attached(db, shard);
        sql::Transaction transaction(db, out);
        for (const std::string_view table : sample_tables) {
            const std::string name(table);
            sql::exec(db, out, "INSERT INTO main." + name + " SELECT * FROM shard." + name,
                      "copying table " + name + " from " + shard.string());
        }
        transaction.commit();
    } catch (...) {
        sqlite3_exec(db, "DETACH DATABASE shard", nullptr, nullptr, nullptr);
        throw;
    }
    sql::exec(db, out, "DETACH DATABASE shard", "closing " + shard.string());
}

}  // namespace

void merge_runs(const fs::path& out, const RunRecord& run, const std::vector<fs::path>& shards) {
    require_creatable(out);
    remove_stale_part_files(out);
    TemporaryFile temporary(out);
    build_database(temporary.path(), out, run, RunKind::rock_sweep, {});
    sqlite3* db = nullptr;
    // URI filenames for ATTACH's mode=ro; a plain path (the temporary file) is read as before.
    const int code = sqlite3_open_v2(temporary.path().c_str(), &db,
                                     SQLITE_OPEN_READWRITE | SQLITE_OPEN_URI, nullptr);
    struct Closer {
        sqlite3* db;
        ~Closer() { sqlite3_close_v2(db); }
    } closer{db};
    if (code != SQLITE_OK) sql::fail(db, code, out, "opening the merged database");
    sqlite3_extended_result_codes(db, 1);
    sql::exec(db, out, "PRAGMA foreign_keys = ON", "setting up the merged database");
    for (const fs::path& shard : shards) copy_shard(db, out, shard);
    const int closed = sqlite3_close(std::exchange(closer.db, nullptr));
    if (closed != SQLITE_OK) sql::fail(nullptr, closed, out, "closing the merged database");
    publish(temporary, out);
}

}  // namespace rockfall::db
