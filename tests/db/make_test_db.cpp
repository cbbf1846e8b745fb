// make_test_db OUT N [options]: a results database of N synthetic samples written through
// ResultsDb::write_batch, for the CLI tests of `rockfall query`. Replaces OUT if it exists.
//   --uniform-reach        sample i reaches 10 i / N m, so that exceedances are known exactly
//   --application-id A     then stamps another application_id (a foreign SQLite file)
//   --user-version V       then stamps schema version V (e.g. a newer one)
//   --corrupt              then overwrites every page after the first with garbage

#include "synthetic.hpp"

#include <CLI/CLI.hpp>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace {

void stamp(const std::string& path, const std::string& pragma) {
    sqlite3* db = nullptr;
    if (sqlite3_open(path.c_str(), &db) != SQLITE_OK ||
        sqlite3_exec(db, ("PRAGMA " + pragma).c_str(), nullptr, nullptr, nullptr) != SQLITE_OK) {
        throw std::runtime_error("cannot set " + pragma + ": " + sqlite3_errmsg(db));
    }
    sqlite3_close(db);
}

void corrupt_pages(const std::string& path) {
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream buffer;
        buffer << in.rdbuf();
        bytes = buffer.str();
    }
    for (std::size_t i = 4096; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Writes a results database of synthetic samples"};
    std::string out;
    std::int64_t samples = 0;
    bool uniform_reach = false;
    bool corrupt = false;
    std::optional<std::int32_t> application_id;
    std::optional<int> user_version;
    rockfall::db::testing::SyntheticOptions options;
    app.add_option("out", out, "Database to write (replaced)")->required();
    app.add_option("samples", samples, "Number of samples")
        ->required()
        ->check(CLI::Range(0, 10000000));
    app.add_flag("--uniform-reach", uniform_reach, "Sample i reaches 10 i / N m");
    app.add_option("--seed", options.seed, "Seed of the synthetic set");
    app.add_option("--stations", options.stations, "Stations at 0, 3, 6, ... m past the toe");
    app.add_option("--application-id", application_id, "Stamp this application_id");
    app.add_option("--user-version", user_version, "Stamp this schema version");
    app.add_flag("--corrupt", corrupt, "Overwrite every page after the first");
    CLI11_PARSE(app, argc, argv);
    try {
        for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(out + suffix);
        {
            auto db = rockfall::db::ResultsDb::create(
                out, rockfall::db::testing::synthetic_run(options, samples));
            std::vector<rockfall::db::SampleRecord> batch;
            for (std::int64_t i = 0; i < samples; ++i) {
                batch.push_back(rockfall::db::testing::synthetic_record(options, i));
                if (uniform_reach) {
                    batch.back().rocks.at(0).outcome.reach =
                        10.0 * static_cast<double>(i) / static_cast<double>(samples);
                }
                if (batch.size() == 1000 || i + 1 == samples) {
                    db.write_batch(batch);
                    batch.clear();
                }
            }
            db.finish("complete", "2024-01-01T00:10:00Z");
        }
        if (application_id) stamp(out, "application_id = " + std::to_string(*application_id));
        if (user_version) stamp(out, "user_version = " + std::to_string(*user_version));
        if (corrupt) corrupt_pages(out);
    } catch (const std::exception& e) {
        std::cerr << "make_test_db: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
