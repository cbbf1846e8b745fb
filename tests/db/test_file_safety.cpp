// The database file around the run: whole at the end even while another program reads it,
// byte for byte unchanged when opened and refused, and the hidden part file of a creator that
// was killed recognised and cleaned up.

#include "db_test_support.hpp"
#include "synthetic.hpp"

#include "db/results_db.hpp"

#include <catch2/catch.hpp>
#include <sqlite3.h>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <string>
#include <sys/file.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

using namespace rockfall::db;
using rockfall::db::test::read_bytes;
using rockfall::db::test::ScratchDir;
using rockfall::db::test::write_bytes;
namespace fs = std::filesystem;

namespace {

std::vector<SampleRecord> records(std::int64_t first, std::int64_t count) {
    std::vector<SampleRecord> batch;
    for (std::int64_t i = first; i < first + count; ++i) {
        batch.push_back(testing::synthetic_record({}, i));
    }
    return batch;
}

// Another program's connection (an sqlite3 shell, pandas): read-write, as those open files.
struct Reader {
    sqlite3* db = nullptr;
    explicit Reader(const fs::path& path) {
        REQUIRE(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK);
    }
    Reader(const Reader&) = delete;
    Reader& operator=(const Reader&) = delete;
    ~Reader() { sqlite3_close(db); }
    std::int64_t count(const std::string& sql) const {
        sqlite3_stmt* statement = nullptr;
        REQUIRE(sqlite3_prepare_v2(db, sql.c_str(), -1, &statement, nullptr) == SQLITE_OK);
        REQUIRE(sqlite3_step(statement) == SQLITE_ROW);
        const std::int64_t value = sqlite3_column_int64(statement, 0);
        sqlite3_finalize(statement);
        return value;
    }
    void exec(const std::string& sql) const {
        REQUIRE(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK);
    }
};

// The .db alone, copied without its -wal or -shm as a user keeps or sends it.
ResultsDb open_alone(const fs::path& path, const ScratchDir& elsewhere) {
    const fs::path copy = elsewhere / path.filename().string();
    fs::copy_file(path, copy);
    return ResultsDb::open(copy, false);
}

// Every byte of the file and of its -wal and -journal (absent ones as "<absent>").
std::vector<std::string> file_bytes(const fs::path& path) {
    std::vector<std::string> bytes;
    for (const std::string suffix : {"", "-wal", "-journal"}) {
        const fs::path file = path.string() + suffix;
        bytes.push_back(fs::exists(file) ? read_bytes(file) : std::string("<absent>"));
    }
    return bytes;
}

}  // namespace

TEST_CASE("finish makes the file whole while another program has it open", "[db]") {
    ScratchDir dir;
    ScratchDir elsewhere;
    const fs::path path = dir / "read.db";
    ResultsDb db = rockfall::db::test::make_database(path, records(0, 150));
    // An idle reader that has read (a pandas connection left open), and one that ends its read
    // transaction during the wait, as a query does.
    const Reader idle(path);
    CHECK(idle.count("SELECT COUNT(*) FROM samples") == 150);
    db.write_batch(records(150, 50));
    const Reader busy(path);
    busy.exec("BEGIN");
    CHECK(busy.count("SELECT COUNT(*) FROM samples") == 200);
    db.write_batch(records(200, 10));
    std::thread finisher([&] { db.finish("complete", "2024-01-01T01:00:00Z"); });
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    busy.exec("COMMIT");
    finisher.join();

    const ResultsDb alone = open_alone(path, elsewhere);
    CHECK(alone.stored_samples().size() == 210);
    CHECK(alone.run().status == "complete");
    // The -wal, if the readers kept it, is empty.
    CHECK((!fs::exists(path.string() + "-wal") || fs::file_size(path.string() + "-wal") == 0));
    CHECK(idle.count("SELECT COUNT(*) FROM samples") == 210);
}

TEST_CASE("finish says so when a reader keeps the file from being made whole", "[db]") {
    ScratchDir dir;
    const fs::path path = dir / "held.db";
    ResultsDb db = rockfall::db::test::make_database(path, records(0, 20));
    const Reader held(path);
    held.exec("BEGIN");
    CHECK(held.count("SELECT COUNT(*) FROM samples") == 20);
    db.write_batch(records(20, 20));
    try {
        db.finish("complete", "2024-01-01T01:00:00Z", std::chrono::milliseconds(200));
        FAIL("finish returned while a reader held an older snapshot");
    } catch (const DatabaseError& e) {
        CHECK(e.kind() == DatabaseError::Kind::failure);
        CHECK_THAT(e.what(), Catch::Contains("held.db-wal") &&
                                 Catch::Contains("kept a read transaction open") &&
                                 Catch::Contains("PRAGMA journal_mode = DELETE"));
    }
    // Nothing is lost: the file with its -wal holds every sample.
    held.exec("COMMIT");
    CHECK(held.count("SELECT COUNT(*) FROM samples") == 40);
}

TEST_CASE("a file opened for writing and closed unwritten keeps every byte", "[db]") {
    ScratchDir dir;
    const fs::path path = dir / "kept.db";
    SECTION("a finished file (rollback journal)") {
        ResultsDb db = rockfall::db::test::make_database(path, records(0, 30));
        db.finish("complete", "2024-01-01T01:00:00Z");
    }
    SECTION("a file left in WAL mode by a crash, samples still in its -wal") {
        ResultsDb db = rockfall::db::test::make_database(path, records(0, 30));
        const fs::path wal = path.string() + "-wal";
        REQUIRE(fs::file_size(wal) > 0);
        // What a crash leaves: the file and its -wal as they are now, copied aside.
        fs::copy_file(path, dir / "crashed.db");
        fs::copy_file(wal, dir / "crashed.db-wal");
    }
    const fs::path file = fs::exists(dir / "crashed.db") ? dir / "crashed.db" : path;
    const std::vector<std::string> before = file_bytes(file);
    {
        // What a refused --resume does: open for writing, read the run record, give up.
        const ResultsDb db = ResultsDb::open(file, true);
        CHECK(db.run().seed == testing::synthetic_run({}, 30).seed);
        CHECK(db.stored_samples().size() == 30);
    }
    CHECK(file_bytes(file) == before);
}

TEST_CASE("the part file of a killed creator is named on open and removed by the next create",
          "[db]") {
    ScratchDir dir;
    const fs::path path = dir / "new.db";
    const RunRecord run = testing::synthetic_run({}, 10);
    // The part file of a `rockfall sweep` that was killed while creating new.db: a child builds
    // a database with a 64 MB scenario text (long enough to be caught in the act) and is
    // killed once its part file and journal exist.
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        RunRecord big = run;
        big.scenario_text.assign(std::size_t{64} << 20, 'x');
        try {
            ResultsDb::create(path, big);
        } catch (...) {
        }
        _exit(0);
    }
    const auto part_files = [&] {
        std::vector<std::string> names;
        for (const std::string& name : dir.files()) {
            if (name.rfind(".new.db.", 0) == 0) names.push_back(name);
        }
        return names;
    };
    for (int i = 0; i < 2000 && part_files().size() < 2; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    REQUIRE(kill(child, SIGKILL) == 0);
    int status = 0;
    waitpid(child, &status, 0);
    REQUIRE(WIFSIGNALED(status));
    REQUIRE_FALSE(fs::exists(path));
    const std::vector<std::string> left = part_files();
    REQUIRE(left.size() == 2);  // .new.db.<hex>.part and its -journal
    CHECK_THAT(left[0], Catch::Matches(R"(\.new\.db\.[0-9a-f]{16}\.part)"));
    CHECK(left[1] == left[0] + "-journal");

    try {
        ResultsDb::open(path, true);
        FAIL("opened a missing file");
    } catch (const DatabaseError& e) {
        CHECK(e.kind() == DatabaseError::Kind::bad_file);
        CHECK_THAT(e.what(), Catch::Contains("new.db: no such file") &&
                                 Catch::Contains("was stopped before it stored anything") &&
                                 Catch::Contains(left[0]) && Catch::Contains("without --resume"));
    }
    CHECK(part_files() == left);  // a refusal changes nothing

    { ResultsDb::create(path, run); }
    CHECK(dir.files() == std::vector<std::string>{"new.db"});
}

TEST_CASE("the part file of a live creator is left alone", "[db]") {
    ScratchDir dir;
    // Another process building other.db holds its part file locked (as TemporaryFile does).
    const fs::path part = dir / ".other.db.00000000deadbeef.part";
    write_bytes(part, "");
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        const int fd = ::open(part.c_str(), O_RDWR);
        if (fd < 0 || ::flock(fd, LOCK_EX) != 0) _exit(1);
        pause();
        _exit(0);
    }
    // Stale files of other names, or that merely look alike, are not ours to remove either.
    write_bytes(dir / ".other.db.notahexnumber00.part", "");
    write_bytes(dir / ".another.db.00000000deadbeef.part", "");
    for (int i = 0; i < 1000; ++i) {
        const int fd = ::open(part.c_str(), O_RDONLY);
        const bool locked = ::flock(fd, LOCK_EX | LOCK_NB) != 0;
        ::close(fd);
        if (locked) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    CHECK_THROWS_WITH(ResultsDb::open(dir / "other.db", false),
                      Catch::Contains("another rockfall is creating it"));
    { ResultsDb::create(dir / "other.db", testing::synthetic_run({}, 10)); }
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    CHECK(dir.files() == std::vector<std::string>{".another.db.00000000deadbeef.part",
                                                  ".other.db.00000000deadbeef.part",
                                                  ".other.db.notahexnumber00.part", "other.db"});
}
