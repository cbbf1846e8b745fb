#pragma once
// Thin RAII wrappers over the SQLite C API, private to the db library so that sqlite3.h stays
// out of the public headers (the SQLiteCpp model: objects valid from construction to
// destruction, errors as exceptions, a transaction that rolls back unless committed).

#include "db/results_db.hpp"

#include <sqlite3.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rockfall::db::sql {

/// Throws the DatabaseError for SQLite result `code` on connection `db` (may be null): names
/// `path`, says what was being done (`doing`, e.g. "writing a batch"), what went wrong in
/// words a user understands and what to do.
[[noreturn]] void fail(sqlite3* db, int code, const std::filesystem::path& path,
                       std::string_view doing);

/// Runs SQL text that returns no rows (one or more statements).
void exec(sqlite3* db, const std::filesystem::path& path, const std::string& sql,
          std::string_view doing);

/// One prepared statement; bind, step, read columns, reset to reuse.
class Statement {
  public:
    /// Prepares `sql` on `db`; the statement is persistent when it will be reused many times.
    Statement(sqlite3* db, const std::filesystem::path& path, std::string_view sql,
              bool persistent = false);
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;
    ~Statement();

    /// Resets the statement to be run again (bindings are kept until replaced).
    void reset();

    /// Binds parameter `index` (1-based); NaN binds NULL.
    void bind_real(int index, double value);
    void bind_int(int index, std::int64_t value);
    void bind_text(int index, std::string_view value);
    void bind_null(int index);

    /// Steps: true when a row is ready, false when done; throws DatabaseError on an error.
    bool step();

    /// Column `column` (0-based) of the current row. real(): NULL reads as NaN.
    double real(int column) const;
    std::int64_t integer(int column) const;
    std::string text(int column) const;
    /// Text valid until the next step or reset (no copy, for scans of many rows).
    std::string_view text_view(int column) const;
    bool is_null(int column) const;

  private:
    sqlite3* db_;
    std::filesystem::path path_;
    sqlite3_stmt* statement_ = nullptr;
};

/// Binds a statement's parameters in order, so an INSERT's binds read in its column order.
class Binder {
  public:
    /// Resets `statement` and starts at parameter 1.
    explicit Binder(Statement& statement) : statement_(statement) { statement_.reset(); }
    /// Binds the next parameter; NaN binds NULL.
    Binder& real(double value);
    Binder& integer(std::int64_t value);
    Binder& text(std::string_view value);
    Binder& null();
    /// Binds NULL when `present` is false, else the value.
    Binder& real_if(bool present, double value);
    /// Steps the statement to completion (an INSERT, UPDATE or DELETE).
    void run();

  private:
    Statement& statement_;
    int next_ = 1;
};

/// A transaction: BEGIN IMMEDIATE on construction, ROLLBACK on destruction unless committed.
class Transaction {
  public:
    Transaction(sqlite3* db, const std::filesystem::path& path);
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;
    /// Rolls back unless committed; never throws.
    ~Transaction();
    /// Commits; throws DatabaseError (and the destructor then rolls back).
    void commit();

  private:
    sqlite3* db_;
    const std::filesystem::path& path_;
    bool committed_ = false;
};

/// The uint64 seed as the int64 SQLite stores (its bit pattern) and back.
std::int64_t to_stored(std::uint64_t value);
std::uint64_t from_stored(std::int64_t value);

}  // namespace rockfall::db::sql
