#include "file_checks.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <random>
#include <sys/file.h>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace rockfall::db {
namespace {

namespace fs = std::filesystem;
using Kind = DatabaseError::Kind;

[[noreturn]] void refuse(const fs::path& path, const std::string& problem) {
    throw DatabaseError(path.string() + problem, Kind::bad_file);
}

fs::path directory_of(const fs::path& path) {
    const fs::path parent = path.parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

// access() lets root write anything, so a file or directory protected with `chmod a-w` is
// also treated as read-only when no write bit is set: a results file kept read-only stays
// unchanged whoever runs the program.
bool writable_location(const fs::path& path) {
    std::error_code error;
    const fs::perms perms = fs::status(path, error).permissions();
    if (error) return false;
    constexpr fs::perms any_write =
        fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
    return (perms & any_write) != fs::perms::none && ::access(path.c_str(), W_OK) == 0;
}

std::string percent_encoded(const std::string& text) {
    // RFC 3986 unreserved characters and '/' pass; SQLite decodes %HH in URI paths.
    std::string out;
    for (const unsigned char c : text) {
        if (std::isalnum(c) != 0 || std::strchr("-._~/", c) != nullptr) {
            out += static_cast<char>(c);
        } else {
            std::array<char, 4> hex{};
            std::snprintf(hex.data(), hex.size(), "%%%02X", c);
            out += hex.data();
        }
    }
    return out;
}

constexpr std::string_view part_suffix = ".part";
constexpr std::string_view journal_suffix = "-journal";

// Whether `name` is a part file of `target` (".NAME.<16 hex digits>.part"), as TemporaryFile
// names them; `journal` for its SQLite rollback journal (the same name + "-journal").
bool is_part_name(const std::string& name, const fs::path& target, bool journal) {
    const std::string prefix = "." + target.filename().string() + ".";
    const std::size_t suffix = part_suffix.size() + (journal ? journal_suffix.size() : 0);
    if (name.size() != prefix.size() + 16 + suffix || name.rfind(prefix, 0) != 0) return false;
    const std::string_view rest = std::string_view(name).substr(prefix.size());
    for (std::size_t i = 0; i < 16; ++i) {
        if (std::isxdigit(static_cast<unsigned char>(rest[i])) == 0) return false;
    }
    return rest.substr(16, part_suffix.size()) == part_suffix &&
           (!journal || rest.substr(16 + part_suffix.size()) == journal_suffix);
}

// A live creator holds an exclusive flock() on its part file (TemporaryFile); the kernel drops
// it when the process ends, however it ends. flock() locks are separate from the fcntl() locks
// SQLite takes, so neither disturbs the other.
bool held_by_live_process(const fs::path& part) {
    const int fd = ::open(part.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool held = ::flock(fd, LOCK_EX | LOCK_NB) != 0;
    ::close(fd);
    return held;
}

struct PartFiles {
    std::vector<fs::path> stale;  // part files and journals no live process holds
    std::vector<fs::path> live;   // part files a running rockfall is building
};

PartFiles part_files(const fs::path& target) {
    PartFiles found;
    std::error_code error;
    const fs::path directory = directory_of(target);
    for (fs::directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (is_part_name(name, target, false)) {
            (held_by_live_process(it->path()) ? found.live : found.stale).push_back(it->path());
        } else if (is_part_name(name, target, true)) {
            const fs::path part = directory / name.substr(0, name.size() - journal_suffix.size());
            if (!fs::exists(part, error) || !held_by_live_process(part)) {
                found.stale.push_back(it->path());
            }
        }
    }
    // The part file itself first, its journal after, so that messages name the part file.
    std::sort(found.stale.begin(), found.stale.end());
    return found;
}

}  // namespace

void require_creatable(const fs::path& path) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (fs::exists(status) && !fs::is_regular_file(status)) {
        refuse(path,
               " is not a regular file (a directory, device, FIFO or socket): a results "
               "database is a regular file that rockfall creates; give a new file name");
    }
    if (fs::exists(fs::symlink_status(path, error))) {
        refuse(path,
               " exists already; rockfall never overwrites results: choose another file "
               "name, or delete the file first");
    }
    const fs::path directory = directory_of(path);
    if (!fs::is_directory(directory, error)) {
        refuse(path, ": cannot create it, its directory " + directory.string() + " does not exist");
    }
    if (!writable_location(directory)) {
        refuse(path, ": cannot create it, its directory " + directory.string() +
                         " is read-only; choose a writable directory");
    }
}

bool is_sqlite_file(const std::filesystem::path& path) {
    // Every SQLite 3 database starts with these 16 bytes (sqlite.org/fileformat.html, 1.3.1).
    static constexpr char magic[] = "SQLite format 3";
    std::array<char, sizeof magic> head{};
    std::ifstream in(path, std::ios::binary);
    in.read(head.data(), head.size());
    return in.gcount() == static_cast<std::streamsize>(head.size()) &&
           std::memcmp(head.data(), magic, sizeof magic) == 0;
}

void require_database_file(const fs::path& path, bool writable) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (!fs::exists(status)) {
        const PartFiles parts = part_files(path);
        if (!parts.live.empty()) {
            refuse(path, ": no such file yet; another rockfall is creating it (" +
                             parts.live.front().filename().string() + "): wait for it to finish");
        }
        if (!parts.stale.empty()) {
            refuse(path,
                   ": no such file; the rockfall that was creating it was stopped before "
                   "it stored anything, and left its unfinished hidden file " +
                       parts.stale.front().filename().string() +
                       " beside it: run the same command without --resume, which removes "
                       "it and starts again");
        }
        refuse(path, ": no such file; give a results database written by `rockfall sweep`");
    }
    if (!fs::is_regular_file(status)) {
        refuse(path,
               " is not a regular file (a directory, device, FIFO or socket); give a "
               "results database written by `rockfall sweep`");
    }
    // SQLite treats an empty or unreadable file in its own terms ("file is not a database",
    // or an empty database it would happily write to); the header says it plainly first.
    std::ifstream in(path, std::ios::binary);
    if (!in) refuse(path, ": cannot read it; check its permissions");
    if (in.peek() == std::ifstream::traits_type::eof()) {
        refuse(path,
               " is empty, not a rockfall results database; give a file written by "
               "`rockfall sweep`");
    }
    if (!is_sqlite_file(path)) {
        refuse(path,
               " is not an SQLite database, so not a rockfall results database; give a "
               "file written by `rockfall sweep`");
    }
    if (!writable) return;
    if (!writable_location(path)) {
        refuse(path, " is read-only; make it writable (chmod u+w) or work on a copy");
    }
    const fs::path directory = directory_of(path);
    if (!writable_location(directory)) {
        refuse(path, ": its directory " + directory.string() +
                         " is read-only, and SQLite needs to create its journal files there; "
                         "move the file to a writable directory");
    }
}

void require_writable(const ResultsDb& db, const std::string& what) {
    if (!db.writable()) {
        throw DatabaseError(db.path().string() + " was opened read-only: cannot " + what,
                            Kind::failure);
    }
}

bool read_only_location(const fs::path& path) {
    if (writable_location(directory_of(path))) return false;
    std::error_code error;
    const fs::path wal = path.string() + "-wal";
    const auto wal_size = fs::file_size(wal, error);
    if (!error && wal_size > 0) {
        refuse(path, ": its latest samples are still in " + wal.string() +
                         " and the directory is read-only, so SQLite cannot read them; copy "
                         "both files to a writable directory");
    }
    return true;
}

std::string immutable_uri(const fs::path& path) {
    return "file:" + percent_encoded(fs::absolute(path).string()) + "?immutable=1";
}

std::string read_only_uri(const fs::path& path) {
    return "file:" + percent_encoded(fs::absolute(path).string()) + "?mode=ro";
}

void remove_stale_part_files(const fs::path& target) {
    std::error_code ignored;
    for (const fs::path& stale : part_files(target).stale) fs::remove(stale, ignored);
}

TemporaryFile::TemporaryFile(const fs::path& target) {
    std::random_device device;
    const auto tag = (static_cast<unsigned long long>(device()) << 32U) ^ device() ^
                     static_cast<unsigned long long>(::getpid());
    std::array<char, 17> hex{};
    std::snprintf(hex.data(), hex.size(), "%016llx", tag);
    path_ = directory_of(target) / ("." + target.filename().string() + "." + hex.data() + ".part");
    // Created here (SQLite takes an empty file as an empty database) and locked for this
    // object's lifetime, so that the next run tells a killed creator's file from a live one.
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd_ < 0 || ::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const std::string reason = std::strerror(errno);
        if (fd_ >= 0) ::close(fd_);
        std::error_code ignored;
        if (fd_ >= 0) fs::remove(path_, ignored);
        throw DatabaseError("cannot create " + target.string() + ": creating its temporary file " +
                                path_.string() + " failed: " + reason,
                            Kind::bad_file);
    }
}

TemporaryFile::~TemporaryFile() {
    std::error_code ignored;
    fs::remove(path_, ignored);
    fs::remove(path_.string() + "-journal", ignored);
    ::close(fd_);
}

void publish(const TemporaryFile& temporary, const fs::path& target) {
    // A hard link fails when the target exists, so a file that appeared since
    // require_creatable is never replaced; rename() would replace it silently.
    std::error_code error;
    fs::create_hard_link(temporary.path(), target, error);
    if (!error) return;
    if (error == std::errc::file_exists) {
        refuse(target, " appeared while the database was being created; nothing was written");
    }
    // File systems without hard links (FAT, some network shares): check, then rename.
    if (fs::exists(fs::symlink_status(target, error))) {
        refuse(target, " appeared while the database was being created; nothing was written");
    }
    fs::rename(temporary.path(), target, error);
    if (error) {
        throw DatabaseError("cannot create " + target.string() + ": " + error.message(),
                            Kind::failure);
    }
}

std::string held_by(RunKind kind) {
    switch (kind) {
        case RunKind::soil_flow:
            return "a soil flow (written by `rockfall soil --db`)";
        case RunKind::drop_test:
            return "a drop test (written by `rockfall calibrate drop --db`)";
        case RunKind::heap_test:
            return "a heap test (written by `rockfall calibrate heap --db`)";
        case RunKind::rock_sweep:
            break;
    }
    return "a rock sweep (written by `rockfall sweep`)";
}

}  // namespace rockfall::db
