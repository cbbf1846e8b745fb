#include "sqlite.hpp"

#include <bit>
#include <cmath>
#include <string>

namespace rockfall::db::sql {

void fail(sqlite3* db, int code, const std::filesystem::path& path, std::string_view doing) {
    using Kind = DatabaseError::Kind;
    const std::string file = path.string();
    const std::string detail = db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(code);
    const std::string context = std::string(doing) + " (SQLite: " + detail + ")";
    switch (code & 0xff) {
        case SQLITE_FULL:
            throw DatabaseError(file + ": disk full while " + context +
                                    "; nothing of this step was written: free space and retry",
                                Kind::failure);
        case SQLITE_READONLY:
        case SQLITE_PERM:
        case SQLITE_AUTH:
            throw DatabaseError(file + " is read-only: " + context +
                                    "; make the file and its directory writable or use a copy",
                                Kind::bad_file);
        case SQLITE_NOTADB:
            throw DatabaseError(file + " is not a rockfall results database (" + detail +
                                    "): give a file written by `rockfall sweep`",
                                Kind::bad_file);
        case SQLITE_CORRUPT:
            throw DatabaseError(file + " is corrupt: " + context +
                                    "; restore it from a copy or run the sweep again",
                                Kind::bad_file);
        case SQLITE_CANTOPEN:
            throw DatabaseError("cannot open " + file + ": " + context +
                                    "; check the path and the directory's permissions",
                                Kind::bad_file);
        case SQLITE_BUSY:
        case SQLITE_LOCKED:
            throw DatabaseError(file + " is locked by another program (another sweep?) while " +
                                    context + "; wait for it to finish",
                                Kind::failure);
        default:
            throw DatabaseError(file + ": " + context, Kind::failure);
    }
}

void exec(sqlite3* db, const std::filesystem::path& path, const std::string& sql,
          std::string_view doing) {
    const int code = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr);
    if (code != SQLITE_OK) fail(db, code, path, doing);
}

Statement::Statement(sqlite3* db, const std::filesystem::path& path, std::string_view sql,
                     bool persistent)
    : db_(db), path_(path) {
    const int code =
        sqlite3_prepare_v3(db, sql.data(), static_cast<int>(sql.size()),
                           persistent ? SQLITE_PREPARE_PERSISTENT : 0u, &statement_, nullptr);
    if (code != SQLITE_OK) fail(db, code, path, "preparing a statement");
}

Statement::~Statement() { sqlite3_finalize(statement_); }

void Statement::reset() { sqlite3_reset(statement_); }

void Statement::bind_real(int index, double value) {
    if (std::isnan(value)) {
        bind_null(index);
        return;
    }
    const int code = sqlite3_bind_double(statement_, index, value);
    if (code != SQLITE_OK) fail(db_, code, path_, "binding a value");
}

void Statement::bind_int(int index, std::int64_t value) {
    const int code = sqlite3_bind_int64(statement_, index, value);
    if (code != SQLITE_OK) fail(db_, code, path_, "binding a value");
}

void Statement::bind_text(int index, std::string_view value) {
    const int code = sqlite3_bind_text64(statement_, index, value.data(), value.size(),
                                         SQLITE_TRANSIENT, SQLITE_UTF8);
    if (code != SQLITE_OK) fail(db_, code, path_, "binding a value");
}

void Statement::bind_null(int index) {
    const int code = sqlite3_bind_null(statement_, index);
    if (code != SQLITE_OK) fail(db_, code, path_, "binding a value");
}

bool Statement::step() {
    const int code = sqlite3_step(statement_);
    if (code == SQLITE_ROW) return true;
    if (code == SQLITE_DONE) return false;
    // sqlite3_step's own code is the extended one; the connection's message explains it.
    fail(db_, code, path_, std::string("running ") + sqlite3_sql(statement_));
}

double Statement::real(int column) const {
    if (is_null(column)) return std::nan("");
    return sqlite3_column_double(statement_, column);
}

std::int64_t Statement::integer(int column) const {
    return sqlite3_column_int64(statement_, column);
}

std::string Statement::text(int column) const { return std::string(text_view(column)); }

std::string_view Statement::text_view(int column) const {
    const auto* bytes = sqlite3_column_text(statement_, column);
    if (bytes == nullptr) return {};
    return {reinterpret_cast<const char*>(bytes),
            static_cast<std::size_t>(sqlite3_column_bytes(statement_, column))};
}

bool Statement::is_null(int column) const {
    return sqlite3_column_type(statement_, column) == SQLITE_NULL;
}

Binder& Binder::real(double value) {
    statement_.bind_real(next_++, value);
    return *this;
}

Binder& Binder::integer(std::int64_t value) {
    statement_.bind_int(next_++, value);
    return *this;
}

Binder& Binder::text(std::string_view value) {
    statement_.bind_text(next_++, value);
    return *this;
}

Binder& Binder::null() {
    statement_.bind_null(next_++);
    return *this;
}

Binder& Binder::real_if(bool present, double value) { return present ? real(value) : null(); }

void Binder::run() {
    while (statement_.step()) {
    }
}

Transaction::Transaction(sqlite3* db, const std::filesystem::path& path) : db_(db), path_(path) {
    // IMMEDIATE takes the write lock now, so a concurrent writer fails here and not halfway.
    exec(db_, path_, "BEGIN IMMEDIATE", "starting a transaction");
}

Transaction::~Transaction() {
    // SQLite may have rolled back already (e.g. after SQLITE_FULL); only an open transaction
    // needs the ROLLBACK, and its failure cannot be reported from a destructor.
    if (!committed_ && sqlite3_get_autocommit(db_) == 0) {
        sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    }
}

void Transaction::commit() {
    exec(db_, path_, "COMMIT", "committing a transaction");
    committed_ = true;
}

std::int64_t to_stored(std::uint64_t value) { return std::bit_cast<std::int64_t>(value); }

std::uint64_t from_stored(std::int64_t value) { return std::bit_cast<std::uint64_t>(value); }

}  // namespace rockfall::db::sql
