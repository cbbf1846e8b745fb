// Every kind of file that is not a usable results database gives a DatabaseError naming the
// file and the problem, and leaves the file as it was.

#include "db_test_support.hpp"
#include "synthetic.hpp"

#include "db/results_db.hpp"

#include <catch2/catch.hpp>
#include <sqlite3.h>

#include <filesystem>
#include <string>
#include <sys/stat.h>

using namespace rockfall::db;
using rockfall::db::test::read_bytes;
using rockfall::db::test::run_sql;
using rockfall::db::test::ScratchDir;
using rockfall::db::test::write_bytes;
namespace fs = std::filesystem;

namespace {

// Opening `path` (read-only unless `writable_only`, and for writing) throws a bad_file
// DatabaseError whose message names the file and contains `problem`; the file's bytes do not
// change.
void check_refused(const fs::path& path, const std::string& problem, bool writable_only = false) {
    const std::string before = read_bytes(path);
    for (const bool writable : {false, true}) {
        if (!writable && writable_only) continue;
        INFO((writable ? "open for writing" : "open read-only"));
        try {
            ResultsDb db = ResultsDb::open(path, writable);
            db.stored_samples();
            FAIL("opened " << path);
        } catch (const DatabaseError& e) {
            CHECK_THAT(e.what(), Catch::Contains(path.string()) && Catch::Contains(problem));
            CHECK(e.kind() == DatabaseError::Kind::bad_file);
        }
    }
    CHECK(read_bytes(path) == before);
}

std::vector<SampleRecord> some_records(std::int64_t count) {
    std::vector<SampleRecord> records;
    for (std::int64_t i = 0; i < count; ++i) records.push_back(testing::synthetic_record({}, i));
    return records;
}

}  // namespace

TEST_CASE("a missing file or a directory is refused", "[db]") {
    ScratchDir dir;
    CHECK_THROWS_WITH(ResultsDb::open(dir / "nope.db", false),
                      Catch::Contains("nope.db: no such file"));
    CHECK_THROWS_WITH(ResultsDb::open(dir.path(), false), Catch::Contains("is not a regular file"));
    CHECK(dir.files().empty());
}

TEST_CASE("a text file or an empty file is refused", "[db]") {
    ScratchDir dir;
    write_bytes(dir / "notes.txt", "reach 3.2 m\nreach 4.1 m\n");
    check_refused(dir / "notes.txt", "is not an SQLite database");
    write_bytes(dir / "empty.db", "");
    check_refused(dir / "empty.db", "is empty");
}

TEST_CASE("an SQLite file that is not ours is refused", "[db]") {
    ScratchDir dir;
    run_sql(dir / "other.db", "CREATE TABLE t (x); INSERT INTO t VALUES (1)");
    check_refused(dir / "other.db", "not a rockfall results database");
}

TEST_CASE("a newer schema version is refused", "[db]") {
    ScratchDir dir;
    rockfall::db::test::make_database(dir / "new.db", some_records(3));
    run_sql(dir / "new.db", "PRAGMA user_version = " + std::to_string(schema_version + 1));
    check_refused(dir / "new.db", "written by a newer rockfall");
}

TEST_CASE("a database missing a table is refused", "[db]") {
    ScratchDir dir;
    rockfall::db::test::make_database(dir / "damaged.db", some_records(3));
    run_sql(dir / "damaged.db", "DROP VIEW sample_impacts");
    check_refused(dir / "damaged.db", "lacks its table or view 'sample_impacts'");
}

TEST_CASE("corrupt bytes are refused", "[db]") {
    ScratchDir dir;
    const fs::path path = dir / "corrupt.db";
    rockfall::db::test::make_database(path, some_records(300));
    std::string bytes = read_bytes(path);
    REQUIRE(bytes.size() > 4 * 4096);

    SECTION("in the header") {
        // The magic string stays, the page size and the rest of the header are garbage.
        for (std::size_t i = 16; i < 100; ++i) bytes[i] = '\x5a';
        write_bytes(path, bytes);
        check_refused(path, "not a rockfall results database");
    }
    SECTION("in the pages") {
        // Page 1 (header, schema root) intact; every later page garbage.
        for (std::size_t i = 4096; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7);
        write_bytes(path, bytes);
        check_refused(path, "corrupt");
    }
}

TEST_CASE("a read-only file or directory is refused for writing only", "[db]") {
    ScratchDir dir;
    const fs::path path = dir / "kept.db";
    rockfall::db::test::make_database(path, some_records(5));

    SECTION("read-only file") {
        fs::permissions(path, fs::perms::owner_read | fs::perms::group_read);
        check_refused(path, "kept.db is read-only", true);
        CHECK(ResultsDb::open(path, false).stored_samples().size() == 5);
    }
    SECTION("read-only directory") {
        fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
        CHECK_THROWS_WITH(ResultsDb::open(path, true),
                          Catch::Contains("directory") && Catch::Contains("is read-only"));
        // Readers need no journal files: the database opens immutable.
        const ResultsDb db = ResultsDb::open(path, false);
        CHECK(db.stored_samples().size() == 5);
        CHECK(db.sample(4).has_value());
        CHECK(dir.files() == std::vector<std::string>{"kept.db"});
    }
}

TEST_CASE("samples still in the -wal file of a read-only directory are not silently lost", "[db]") {
    ScratchDir dir;
    ScratchDir copy;
    // Copy a database and its -wal file while the writer has them open, as a backup of a
    // running sweep would, into a directory that is then made read-only.
    ResultsDb writer = rockfall::db::test::make_database(dir / "live.db", some_records(20));
    fs::copy_file(dir / "live.db", copy / "live.db");
    fs::copy_file(dir / "live.db-wal", copy / "live.db-wal");
    REQUIRE(fs::file_size(copy / "live.db-wal") > 0);
    fs::permissions(copy.path(), fs::perms::owner_read | fs::perms::owner_exec);
    CHECK_THROWS_WITH(ResultsDb::open(copy / "live.db", false),
                      Catch::Contains("live.db-wal") && Catch::Contains("copy both files"));
}

TEST_CASE("create refuses an existing file and leaves it unchanged", "[db]") {
    ScratchDir dir;
    write_bytes(dir / "precious.db", "results of last year");
    const RunRecord run = testing::synthetic_run({}, 10);
    try {
        ResultsDb::create(dir / "precious.db", run);
        FAIL("created over an existing file");
    } catch (const DatabaseError& e) {
        CHECK_THAT(e.what(), Catch::Contains("precious.db exists already"));
        CHECK(e.kind() == DatabaseError::Kind::bad_file);
    }
    CHECK(read_bytes(dir / "precious.db") == "results of last year");
    CHECK(dir.files() == std::vector<std::string>{"precious.db"});
}

TEST_CASE("create and open refuse what is not a regular file, and leave it as it was", "[db]") {
    ScratchDir dir;
    fs::create_directory(dir / "folder.db");
    REQUIRE(mkfifo((dir / "pipe.db").c_str(), 0600) == 0);
    const RunRecord run = testing::synthetic_run({}, 10);
    for (const std::string name : {"folder.db", "pipe.db"}) {
        CHECK_THROWS_WITH(ResultsDb::create(dir / name, run),
                          Catch::Contains(name + " is not a regular file") &&
                              Catch::Contains("a results database is a regular file"));
        CHECK_THROWS_WITH(ResultsDb::open(dir / name, true),
                          Catch::Contains(name + " is not a regular file"));
    }
    CHECK(fs::is_directory(dir / "folder.db"));
    CHECK(fs::is_empty(dir / "folder.db"));
    CHECK(fs::is_fifo(dir / "pipe.db"));
    CHECK(dir.files() == std::vector<std::string>{"folder.db", "pipe.db"});
}

TEST_CASE("a failed create leaves nothing behind", "[db]") {
    ScratchDir dir;
    RunRecord run = testing::synthetic_run({}, 10);

    SECTION("a missing directory") {
        CHECK_THROWS_WITH(ResultsDb::create(dir / "no" / "r.db", run),
                          Catch::Contains("does not exist"));
    }
    SECTION("a read-only directory") {
        fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
        CHECK_THROWS_WITH(ResultsDb::create(dir / "r.db", run), Catch::Contains("read-only"));
    }
    SECTION("a run record the schema rejects") {
        run.zones = {"upper", "upper"};
        CHECK_THROWS_WITH(ResultsDb::create(dir / "r.db", run), Catch::Contains("UNIQUE"));
    }
    CHECK(dir.files().empty());
}
