#pragma once
/// The results database of a sweep: one SQLite file per run, written by the sweep and read by
/// `rockfall query`, `sqlite3` and pandas. The schema is documented in docs/database.md (summary in
/// docs/sweeps.md, "Results database"); every column name carries its unit.
///
/// Safety: WAL journal, one transaction per batch, so a crash or kill at any moment leaves a
/// valid file holding whole samples only. A file is ours when its SQLite application_id is
/// application_id below; its user_version is the schema version. Readers (`rockfall query`)
/// may run while the sweep writes.
///
/// Threads: a ResultsDb is used by one thread at a time (SQLite runs without its per-call
/// mutex); a sweep with worker threads hands finished batches to one writer or serializes the
/// calls itself.

#include "engine/outcome.hpp"
#include "risk/sampling.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

struct sqlite3;

namespace rockfall::db {

/// SQLite application_id of a rockfall results database ("RKFL").
inline constexpr std::int32_t application_id = 0x524b464c;
/// Schema version written by this build; files with a newer version are refused. Version 1
/// (one rock per sample) is read as version 2 with every row's rock = 0, but not written to.
inline constexpr int schema_version = 2;

/// A database problem; what() names the file and says what is wrong and what to do.
class DatabaseError : public std::runtime_error {
  public:
    /// Whose problem it is: the file given (the program exits 2) or the operation (exits 1).
    enum class Kind {
        bad_file,  ///< missing, exists already, foreign, corrupt, newer schema, read-only
        failure,   ///< disk full, I/O error, locked by another program, a broken invariant
    };
    /// An error with its message (file, problem, remedy) and kind.
    explicit DatabaseError(const std::string& message, Kind kind = Kind::failure)
        : std::runtime_error(message), kind_(kind) {}
    /// The kind given at construction.
    Kind kind() const { return kind_; }

  private:
    Kind kind_;
};

/// What a results database holds (run.kind).
enum class RunKind {
    rock_sweep,  ///< a Monte Carlo sweep of rocks (`rockfall sweep`): samples and their outcomes
    soil_flow,   ///< one soil flow (`rockfall soil --db`): the soil tables (db/soil_run.hpp)
    drop_test,  ///< `rockfall calibrate drop --db`: the calibration tables (db/calibration_run.hpp)
    heap_test,  ///< `rockfall calibrate heap --db`: the calibration tables
};

/// The name stored in run.kind: "rock_sweep", "soil_flow", "drop_test" or "heap_test".
std::string_view to_string(RunKind kind);

/// The run a database holds (one per file).
struct RunRecord {
    /// Tool version and build description (compiler, build type).
    std::string tool_version;
    std::string build;
    /// Scenario name, its complete TOML text (resolved) and a hash of that text (hex).
    std::string scenario_name;
    std::string scenario_text;
    std::string scenario_hash;
    /// Run seed and sampling method ("monte_carlo", "latin_hypercube").
    std::uint64_t seed = 0;
    std::string method;
    /// Planned samples (the sample budget; --samples or the [sweep] table).
    std::int64_t samples_planned = 0;
    /// Stop rule as written (e.g. "samples 2000", "until wall_probability +-0.01 at 95%").
    std::string stop_rule;
    /// Other settings as a JSON object (threads, trajectory interval, ...).
    std::string settings_json;
    /// UTC times, ISO 8601; finished_at empty while running.
    std::string started_at;
    std::string finished_at;
    /// "running", "complete" or "interrupted".
    std::string status = "running";
    /// Release zone names, in SweepSpec::zones order.
    std::vector<std::string> zones;
};

/// One finished sample: its inputs and each rock's inputs, outcome and trajectory
/// (risk::SampleResult).
using SampleRecord = risk::SampleResult;

/// True when the file starts with the SQLite 3 header ("SQLite format 3" and a zero byte): a
/// cheap test of which kind of input a command was given, before opening it.
bool is_sqlite_file(const std::filesystem::path& path);

/// An open results database.
class ResultsDb {
  public:
    /// Creates a new database at `path` holding `run` and opens it for writing. Throws
    /// DatabaseError (bad_file) when the file exists already (it is never replaced) or its
    /// directory is missing or read-only. The file is built beside the target under a hidden
    /// temporary name and appears whole or not at all: nothing is left behind on failure.
    static ResultsDb create(const std::filesystem::path& path, const RunRecord& run);

    /// Opens an existing database; throws DatabaseError (bad_file) for a missing, empty,
    /// non-SQLite, foreign (application_id), damaged (missing tables) or newer-schema file, and
    /// when writable for a read-only file or directory (no write bit counts as read-only even for
    /// root) or a file failing SQLite's quick_check (a full read: about 1.5 s CPU for one
    /// million samples). The checks read through a read-only connection, and a writable
    /// database changes nothing in the file, its -wal or -journal until the first write
    /// (write_batch, delete_samples_from, finish), which switches it to WAL: a file refused
    /// here or by the caller's own checks keeps every byte. Read-only opens of a file in a
    /// read-only directory use SQLite's immutable mode, refused when a -wal file holds unmerged
    /// samples. A database holding a soil flow rather than a rock sweep is refused too
    /// (bad_file). A missing file beside a hidden part file left by a killed `rockfall sweep`
    /// (`.NAME.<hex>.part`) is refused with a message saying so.
    static ResultsDb open(const std::filesystem::path& path, bool writable);

    /// Opens a database of either kind with the checks of open(); kind() says which it is.
    static ResultsDb open_any(const std::filesystem::path& path, bool writable);

    ResultsDb(ResultsDb&&) noexcept;
    ResultsDb& operator=(ResultsDb&&) noexcept;
    ~ResultsDb();

    /// The file's path.
    const std::filesystem::path& path() const { return path_; }

    /// The run record.
    RunRecord run() const;

    /// What the database holds.
    RunKind kind() const;

    /// Writes the samples, their outcomes, wall impacts, stations and trajectories in one
    /// transaction: all of them or none. Throws DatabaseError (e.g. disk full) after rolling
    /// back.
    void write_batch(const std::vector<SampleRecord>& samples);

    /// Indices of the samples stored, ascending.
    std::vector<std::int64_t> stored_samples() const;

    /// Deletes every sample with index >= first (and its rows), in one transaction.
    void delete_samples_from(std::int64_t first);

    /// Records the end of the run: status ("running", "complete" or "interrupted") and
    /// finished_at, then makes the file whole: every sample is copied from the -wal into the
    /// file itself, waiting up to `reader_wait` for other programs reading it (an sqlite3 shell,
    /// pandas, `rockfall query`) to finish their read transactions. The file then leaves WAL
    /// mode for a rollback journal, so that no -wal or -shm remain, unless another connection is
    /// still open: the file stays in WAL mode then, with everything in it and an empty -wal.
    /// Throws DatabaseError (failure), saying what to do, when a reader held its transaction
    /// for all of `reader_wait` (the -wal then still holds samples the file lacks).
    void finish(const std::string& status, const std::string& finished_at,
                std::chrono::milliseconds reader_wait = std::chrono::seconds(10));

    /// The stored sample with its outcome (trajectory included); empty when absent. Not
    /// stored, so left at their defaults: the final state's orientation, angular velocity and
    /// energies (final_state.time is the stop time), the wall hits' force histories, and the
    /// crossing values of stations not reached.
    std::optional<SampleRecord> sample(std::int64_t index) const;

    /// Whether the database was opened (or created) for writing.
    bool writable() const { return writable_; }

    /// The underlying connection, for queries.
    sqlite3* handle() const { return db_; }

  private:
    struct Statements;
    ResultsDb(sqlite3* db, std::filesystem::path path, bool writable);
    // open() and open_any(): with `any_kind` false, a soil flow is refused.
    static ResultsDb open_checked(const std::filesystem::path& path, bool writable, bool any_kind);
    // The writer's pragmas (WAL) before the first write; see open().
    void begin_writing();
    sqlite3* db_ = nullptr;
    std::filesystem::path path_;
    bool writable_ = false;
    bool writing_ = false;
    // The insert statements, prepared on the first write_batch and reused by later ones.
    std::unique_ptr<Statements> statements_;
};

}  // namespace rockfall::db
