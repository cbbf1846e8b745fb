#include "db/results_db.hpp"

#include "create_file.hpp"
#include "file_checks.hpp"
#include "sample_io.hpp"
#include "schema.hpp"
#include "sqlite.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <functional>
#include <string>
#include <system_error>
#include <thread>
#include <utility>

namespace rockfall::db {
namespace {

namespace fs = std::filesystem;
using Kind = DatabaseError::Kind;

// A concurrent reader or writer holds its lock for one batch at most; wait that long.
constexpr int busy_timeout_ms = 10000;

// A connection closed on scope exit unless released into a ResultsDb.
struct Connection {
    sqlite3* db = nullptr;
    Connection() = default;
    Connection(const Connection&) = delete;
    Connection& operator=(const Connection&) = delete;
    ~Connection() { sqlite3_close_v2(db); }
    sqlite3* release() { return std::exchange(db, nullptr); }
};

void open_connection(Connection& connection, const fs::path& path, const std::string& name,
                     int flags) {
    // NOMUTEX: a connection is used by one thread at a time (results_db.hpp), so SQLite's
    // per-call mutex only costs time (measured 6 % of a one-million-row query).
    const int code =
        sqlite3_open_v2(name.c_str(), &connection.db, flags | SQLITE_OPEN_NOMUTEX, nullptr);
    if (code != SQLITE_OK) sql::fail(connection.db, code, path, "opening the database");
    sqlite3_busy_timeout(connection.db, busy_timeout_ms);
    sqlite3_extended_result_codes(connection.db, 1);
}

std::int64_t pragma_integer(sqlite3* db, const fs::path& path, const std::string& pragma) {
    sql::Statement statement(db, path, "PRAGMA " + pragma);
    if (!statement.step()) sql::fail(db, SQLITE_CORRUPT, path, "reading PRAGMA " + pragma);
    return statement.integer(0);
}

std::string pragma_text(sqlite3* db, const fs::path& path, const std::string& pragma) {
    sql::Statement statement(db, path, "PRAGMA " + pragma);
    return statement.step() ? statement.text(0) : std::string();
}

// Is this file ours, of a version this build reads, with every table and view?
void check_identity(sqlite3* db, const fs::path& path) {
    const std::int64_t id = pragma_integer(db, path, "application_id");
    if (id != application_id) {
        throw DatabaseError(path.string() +
                                " is an SQLite database but not a rockfall results database "
                                "(its application_id is " +
                                std::to_string(id) + ", not " + std::to_string(application_id) +
                                "): give a file written by `rockfall sweep`",
                            Kind::bad_file);
    }
    const std::int64_t version = pragma_integer(db, path, "user_version");
    if (version > schema_version) {
        throw DatabaseError(path.string() + " has schema version " + std::to_string(version) +
                                ", written by a newer rockfall; this build reads version " +
                                std::to_string(schema_version) + ": upgrade rockfall",
                            Kind::bad_file);
    }
    if (version < 1) {
        throw DatabaseError(path.string() + " has schema version " + std::to_string(version) +
                                ", which no rockfall writes: the file is damaged",
                            Kind::bad_file);
    }
    sql::Statement exists(db, path, "SELECT 1 FROM sqlite_schema WHERE name = ?");
    for (const std::string_view name : schema::objects) {
        if (version == 1 && name == "rocks") continue;
        exists.reset();
        exists.bind_text(1, name);
        if (!exists.step()) {
            throw DatabaseError(path.string() + " lacks its table or view '" + std::string(name) +
                                    "': the file is damaged; restore it from a copy",
                                Kind::bad_file);
        }
    }
}

// A calibration database's own tables (files written before they existed hold none).
void check_calibration_tables(sqlite3* db, const fs::path& path) {
    sql::Statement exists(db, path, "SELECT 1 FROM sqlite_schema WHERE name = ?");
    for (const std::string_view name : schema::calibration_objects) {
        exists.reset();
        exists.bind_text(1, name);
        if (!exists.step()) {
            throw DatabaseError(path.string() + " lacks its table '" + std::string(name) +
                                    "': the file is damaged; restore it from a copy",
                                Kind::bad_file);
        }
    }
}

std::int64_t stored_version(sqlite3* db, const fs::path& path) {
    return pragma_integer(db, path, "user_version");
}

// The views of this version as TEMP views, so that a version-1 file reads as version 2.
std::string temporary_views() {
    std::string views(schema::views);
    const std::string_view create = "CREATE VIEW";
    for (std::size_t at = views.find(create); at != std::string::npos;
         at = views.find(create, at)) {
        views.replace(at, create.size(), "CREATE TEMP VIEW");
    }
    return std::string(schema::version1_adapter) + views;
}

void set_writer_pragmas(sqlite3* db, const fs::path& path) {
    // WAL: readers (rockfall query) run while the sweep writes, and a crash or kill leaves the
    // last committed batch intact. synchronous=NORMAL in WAL mode keeps the file consistent
    // after a power loss at the price of the last batches, and syncs once per checkpoint
    // rather than per transaction (SQLite, "Write-Ahead Logging", sec. 2.3).
    const std::string mode = pragma_text(db, path, "journal_mode = WAL");
    if (mode != "wal") {
        throw DatabaseError(path.string() +
                                ": the file system does not support SQLite's WAL "
                                "journal (journal_mode is '" +
                                mode + "'); use a local disk",
                            Kind::bad_file);
    }
    sql::exec(db, path, "PRAGMA synchronous = NORMAL; PRAGMA foreign_keys = ON",
              "setting up the connection");
}

void check_integrity(sqlite3* db, const fs::path& path) {
    const std::string result = pragma_text(db, path, "quick_check(1)");
    if (result != "ok") {
        throw DatabaseError(path.string() + " is corrupt (SQLite quick_check: " + result +
                                "): restore it from a copy or run the sweep again",
                            Kind::bad_file);
    }
}

// The kind a file holds; a name this build does not know means a damaged or foreign file.
RunKind read_kind(sqlite3* db, const fs::path& path) {
    sql::Statement select(db, path, "SELECT kind FROM run WHERE id = 1");
    const std::string name = select.step() ? select.text(0) : std::string();
    for (const RunKind kind :
         {RunKind::rock_sweep, RunKind::soil_flow, RunKind::drop_test, RunKind::heap_test}) {
        if (name == to_string(kind)) return kind;
    }
    throw DatabaseError(path.string() + " holds no run of a kind this build knows (run.kind = '" +
                            name + "'): the file is damaged or was written by a newer rockfall",
                        Kind::bad_file);
}

// Copies every committed page from the -wal into the database file, so that the file alone
// holds the whole run. A FULL checkpoint waits (busy handler) while another connection reads an
// older snapshot, and is retried until `wait` has passed (SQLite, "Write-Ahead Logging", sec. 3
// and sqlite3_wal_checkpoint_v2). Then, without waiting, the -wal is truncated and the file
// leaves WAL mode: both need every other connection closed, and a file in WAL mode whose pages
// are all in it is as whole (its -wal is empty).
void make_whole(sqlite3* db, const fs::path& path, std::chrono::milliseconds wait) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point deadline = Clock::now() + wait;
    for (int attempt = 1;; ++attempt) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
        sqlite3_busy_timeout(db, static_cast<int>(std::max<std::int64_t>(1, left.count())));
        int frames = -1;
        int copied = -1;
        const int code =
            sqlite3_wal_checkpoint_v2(db, nullptr, SQLITE_CHECKPOINT_FULL, &frames, &copied);
        const bool busy = (code & 0xff) == SQLITE_BUSY || (code & 0xff) == SQLITE_LOCKED;
        if (code == SQLITE_OK && frames == copied) break;
        if (code != SQLITE_OK && !busy) {
            sql::fail(db, code, path, "copying the -wal into the database file");
        }
        if (Clock::now() >= deadline) {
            sqlite3_busy_timeout(db, busy_timeout_ms);
            const std::string file = path.string();
            throw DatabaseError(
                file + ": another program kept a read transaction open on it for " +
                    std::to_string(wait.count()) + " ms (" + std::to_string(attempt) +
                    " attempts), so the last samples are in " + file +
                    "-wal but not yet in the file itself; keep the two files together (they "
                    "hold every sample) until that program has closed the file, then make it "
                    "whole with: sqlite3 '" +
                    file + "' 'PRAGMA journal_mode = DELETE'",
                Kind::failure);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    sqlite3_busy_timeout(db, 0);
    sqlite3_wal_checkpoint_v2(db, nullptr, SQLITE_CHECKPOINT_TRUNCATE, nullptr, nullptr);
    sqlite3_exec(db, "PRAGMA journal_mode = DELETE", nullptr, nullptr, nullptr);
    sqlite3_busy_timeout(db, busy_timeout_ms);
}

void insert_run(sqlite3* db, const fs::path& path, const RunRecord& run, RunKind kind) {
    sql::Statement insert(db, path,
                          "INSERT INTO run (id, kind, tool_version, build, scenario_name, "
                          "scenario_text, scenario_hash, seed, method, samples_planned, "
                          "stop_rule, settings_json, started_at, finished_at, status) "
                          "VALUES (1, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    sql::Binder binder(insert);
    binder.text(to_string(kind))
        .text(run.tool_version)
        .text(run.build)
        .text(run.scenario_name)
        .text(run.scenario_text)
        .text(run.scenario_hash)
        .integer(sql::to_stored(run.seed))
        .text(run.method)
        .integer(run.samples_planned)
        .text(run.stop_rule)
        .text(run.settings_json)
        .text(run.started_at);
    if (run.finished_at.empty()) {
        binder.null();
    } else {
        binder.text(run.finished_at);
    }
    binder.text(run.status).run();

    sql::Statement zone(db, path, "INSERT INTO zones (zone, name) VALUES (?, ?)");
    for (std::size_t i = 0; i < run.zones.size(); ++i) {
        sql::Binder(zone).integer(static_cast<std::int64_t>(i)).text(run.zones[i]).run();
    }
}

}  // namespace

void build_database(const fs::path& temporary, const fs::path& path, const RunRecord& run,
                    RunKind kind, const std::function<void(sqlite3*)>& fill) {
    Connection connection;
    open_connection(connection, path, temporary.string(),
                    SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
    sqlite3* db = connection.db;
    sql::Transaction transaction(db, path);
    sql::exec(db, path,
              "PRAGMA application_id = " + std::to_string(application_id) +
                  "; PRAGMA user_version = " + std::to_string(schema_version),
              "creating the database");
    sql::exec(db, path, std::string(schema::definition), "creating the tables");
    sql::exec(db, path, std::string(schema::views), "creating the views");
    sql::exec(db, path, std::string(schema::soil_definition), "creating the soil tables");
    sql::exec(db, path, std::string(schema::calibration_definition),
              "creating the calibration tables");
    insert_run(db, path, run, kind);
    if (fill) fill(db);
    transaction.commit();
    const int code = sqlite3_close(connection.release());
    if (code != SQLITE_OK) sql::fail(nullptr, code, path, "closing the new database");
}

std::string_view to_string(RunKind kind) {
    switch (kind) {
        case RunKind::soil_flow:
            return "soil_flow";
        case RunKind::drop_test:
            return "drop_test";
        case RunKind::heap_test:
            return "heap_test";
        case RunKind::rock_sweep:
            break;
    }
    return "rock_sweep";
}

void create_database_file(const fs::path& path, const RunRecord& run, RunKind kind,
                          const std::function<void(sqlite3*)>& fill) {
    require_creatable(path);
    remove_stale_part_files(path);
    TemporaryFile temporary(path);
    build_database(temporary.path(), path, run, kind, fill);
    publish(temporary, path);
}

ResultsDb::ResultsDb(sqlite3* db, fs::path path, bool writable)
    : db_(db), path_(std::move(path)), writable_(writable) {}

ResultsDb::ResultsDb(ResultsDb&& other) noexcept
    : db_(std::exchange(other.db_, nullptr)),
      path_(std::move(other.path_)),
      writable_(other.writable_),
      writing_(other.writing_),
      statements_(std::move(other.statements_)) {}

ResultsDb& ResultsDb::operator=(ResultsDb&& other) noexcept {
    if (this != &other) {
        statements_.reset();
        sqlite3_close_v2(db_);
        db_ = std::exchange(other.db_, nullptr);
        path_ = std::move(other.path_);
        writable_ = other.writable_;
        writing_ = other.writing_;
        statements_ = std::move(other.statements_);
    }
    return *this;
}

ResultsDb::~ResultsDb() {
    // Statements first: a connection with unfinalized statements cannot close.
    statements_.reset();
    sqlite3_close_v2(db_);
}

ResultsDb ResultsDb::create(const fs::path& path, const RunRecord& run) {
    create_database_file(path, run, RunKind::rock_sweep, {});
    try {
        return open(path, true);
    } catch (...) {
        // The file is ours and was never handed out: leave nothing behind.
        std::error_code ignored;
        fs::remove(path, ignored);
        throw;
    }
}

ResultsDb ResultsDb::open(const fs::path& path, bool writable) {
    return open_checked(path, writable, false);
}

ResultsDb ResultsDb::open_any(const fs::path& path, bool writable) {
    return open_checked(path, writable, true);
}

ResultsDb ResultsDb::open_checked(const fs::path& path, bool writable, bool any_kind) {
    require_database_file(path, writable);
    Connection connection;
    const bool immutable = !writable && read_only_location(path);
    // Every check runs on a read-only connection, so that a refused file (and its -wal or
    // -journal) keeps every byte; the caller's own checks (--resume's seed and hash) read
    // through the writer's connection before its first write, which changes nothing either.
    open_connection(connection, path, immutable ? immutable_uri(path) : path.string(),
                    SQLITE_OPEN_READONLY | (immutable ? SQLITE_OPEN_URI : 0));
    check_identity(connection.db, path);
    const RunKind kind = read_kind(connection.db, path);
    if (kind == RunKind::drop_test || kind == RunKind::heap_test) {
        check_calibration_tables(connection.db, path);
    }
    if (!any_kind && kind != RunKind::rock_sweep) {
        throw DatabaseError(path.string() + " holds " + held_by(kind) +
                                ", not a rock sweep: `rockfall query " + path.string() +
                                " summary` reads it",
                            Kind::bad_file);
    }
    const bool version1 = stored_version(connection.db, path) == 1;
    if (version1 && writable) {
        throw DatabaseError(path.string() +
                                " has schema version 1 (one rock per sample, written by an older "
                                "rockfall): this build reads it (query, fit, envelope, simulate "
                                "--from) but does not add to it; continue it with the rockfall "
                                "that made it, or start a new sweep",
                            Kind::bad_file);
    }
    if (!writable) {
        if (version1) sql::exec(connection.db, path, temporary_views(), "reading schema version 1");
        // Queries scan whole tables: reading pages through a memory map rather than read()
        // calls saves the copies (measured a fifth of a one-million-row query). SQLite caps
        // the size at its compile-time limit.
        sql::exec(connection.db, path, "PRAGMA mmap_size = 2147483648", "setting up the reader");
        return ResultsDb(connection.release(), path, false);
    }
    // A sweep appends to this file for hours: check it once now rather than fail later.
    check_integrity(connection.db, path);
    const int code = sqlite3_close(connection.release());
    if (code != SQLITE_OK) sql::fail(nullptr, code, path, "closing the checking connection");
    Connection writer;
    open_connection(writer, path, path.string(), SQLITE_OPEN_READWRITE);
    // Until the first write the file stays as it is: closing this connection must not
    // checkpoint a -wal left by a crash (begin_writing turns it back on).
    sqlite3_db_config(writer.db, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr);
    return ResultsDb(writer.release(), path, true);
}

void ResultsDb::begin_writing() {
    require_writable(*this, "write");
    if (writing_) return;
    set_writer_pragmas(db_, path_);
    sqlite3_db_config(db_, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 0, nullptr);
    writing_ = true;
}

RunKind ResultsDb::kind() const { return read_kind(db_, path_); }

RunRecord ResultsDb::run() const {
    sql::Statement select(db_, path_,
                          "SELECT tool_version, build, scenario_name, scenario_text, "
                          "scenario_hash, seed, method, samples_planned, stop_rule, "
                          "settings_json, started_at, finished_at, status FROM run WHERE id = 1");
    if (!select.step()) {
        throw DatabaseError(path_.string() + " holds no run record: the file is damaged",
                            Kind::bad_file);
    }
    RunRecord run;
    run.tool_version = select.text(0);
    run.build = select.text(1);
    run.scenario_name = select.text(2);
    run.scenario_text = select.text(3);
    run.scenario_hash = select.text(4);
    run.seed = sql::from_stored(select.integer(5));
    run.method = select.text(6);
    run.samples_planned = select.integer(7);
    run.stop_rule = select.text(8);
    run.settings_json = select.text(9);
    run.started_at = select.text(10);
    run.finished_at = select.text(11);
    run.status = select.text(12);
    sql::Statement zones(db_, path_, "SELECT name FROM zones ORDER BY zone");
    while (zones.step()) run.zones.push_back(zones.text(0));
    return run;
}

void ResultsDb::write_batch(const std::vector<SampleRecord>& samples) {
    require_writable(*this, "write samples");
    begin_writing();
    if (!statements_) statements_ = std::make_unique<Statements>(db_, path_);
    sql::Transaction transaction(db_, path_);
    for (const SampleRecord& record : samples) statements_->write(record);
    transaction.commit();
}

std::vector<std::int64_t> ResultsDb::stored_samples() const {
    // A sample's inputs and its rocks' outcomes are written in the same transaction.
    sql::Statement select(db_, path_, "SELECT sample FROM samples ORDER BY sample");
    std::vector<std::int64_t> indices;
    while (select.step()) indices.push_back(select.integer(0));
    return indices;
}

void ResultsDb::delete_samples_from(std::int64_t first) {
    require_writable(*this, "delete samples");
    begin_writing();
    sql::Transaction transaction(db_, path_);
    // Children first: the foreign keys point at samples.
    for (const char* table :
         {"trajectories", "wall_impacts", "stations", "outcomes", "rocks", "samples"}) {
        sql::Statement erase(db_, path_,
                             std::string("DELETE FROM ") + table + " WHERE sample >= ?");
        erase.bind_int(1, first);
        erase.step();
    }
    transaction.commit();
}

void ResultsDb::finish(const std::string& status, const std::string& finished_at,
                       std::chrono::milliseconds reader_wait) {
    require_writable(*this, "record the end of the run");
    begin_writing();
    sql::Statement update(db_, path_, "UPDATE run SET status = ?, finished_at = ? WHERE id = 1");
    sql::Binder(update).text(status).text(finished_at).run();
    make_whole(db_, path_, reader_wait);
}

std::optional<SampleRecord> ResultsDb::sample(std::int64_t index) const {
    return read_sample(db_, path_, index);
}

}  // namespace rockfall::db
