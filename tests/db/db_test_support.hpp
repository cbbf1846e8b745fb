#pragma once
// Helpers for the results database tests: a scratch directory, hand-made records and a
// field-by-field comparison of records.

#include "synthetic.hpp"

#include "db/results_db.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace rockfall::db::test {

/// A fresh directory under the system temporary directory, removed with its contents (made
/// writable first) on destruction.
class ScratchDir {
  public:
    ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    ~ScratchDir();
    /// The directory.
    const std::filesystem::path& path() const { return path_; }
    /// A path inside it.
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
    /// The names of the files in it, sorted.
    std::vector<std::string> files() const;

  private:
    std::filesystem::path path_;
};

/// Runs `sql` on the SQLite file at `path` (created when missing), CHECKing that it succeeds.
void run_sql(const std::filesystem::path& path, const std::string& sql);

/// The file's bytes.
std::string read_bytes(const std::filesystem::path& path);
/// Writes the bytes to the file (replacing it).
void write_bytes(const std::filesystem::path& path, const std::string& bytes);

/// A minimal record: sample `index` with the given reach (m) and one wall hit per entry of
/// `peak_forces` (N), every other field plausible and fixed.
SampleRecord hand_record(std::int64_t index, double reach,
                         const std::vector<double>& peak_forces = {});

/// CHECKs that every stored field of the two records is equal (NaN equals NaN).
void check_same(const SampleRecord& expected, const SampleRecord& actual);

/// CHECKs that every stored field of the two rocks is equal (NaN equals NaN).
void check_same_rock(const risk::RockResult& expected, const risk::RockResult& actual);

/// Creates a database at `path` with the synthetic run record and writes `records`.
ResultsDb make_database(const std::filesystem::path& path, const std::vector<SampleRecord>& records,
                        std::size_t zones = 2);

/// True when both are NaN or they are equal.
inline bool same_value(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

}  // namespace rockfall::db::test
