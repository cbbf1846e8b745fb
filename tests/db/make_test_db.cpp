// make_test_db OUT N [--uniform-reach] [--seed S]: a results database of N synthetic samples
// written through ResultsDb::write_batch, for the CLI tests. Replaces OUT if it exists.
// --uniform-reach sets sample i's reach to 10 i / N m so that exceedances are known exactly.

#include "synthetic.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"Writes a results database of synthetic samples"};
    std::string out;
    std::int64_t samples = 0;
    bool uniform_reach = false;
    rockfall::db::testing::SyntheticOptions options;
    app.add_option("out", out, "Database to write (replaced)")->required();
    app.add_option("samples", samples, "Number of samples")
        ->required()
        ->check(CLI::Range(0, 10000000));
    app.add_flag("--uniform-reach", uniform_reach, "Sample i reaches 10 i / N m");
    app.add_option("--seed", options.seed, "Seed of the synthetic set");
    CLI11_PARSE(app, argc, argv);
    try {
        for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(out + suffix);
        auto db = rockfall::db::ResultsDb::create(
            out, rockfall::db::testing::synthetic_run(options, samples));
        std::vector<rockfall::db::SampleRecord> batch;
        for (std::int64_t i = 0; i < samples; ++i) {
            batch.push_back(rockfall::db::testing::synthetic_record(options, i));
            if (uniform_reach)
                batch.back().outcome.reach =
                    10.0 * static_cast<double>(i) / static_cast<double>(samples);
            if (batch.size() == 1000 || i + 1 == samples) {
                db.write_batch(batch);
                batch.clear();
            }
        }
        db.finish("complete", "2024-01-01T00:10:00Z");
    } catch (const std::exception& e) {
        std::cerr << "make_test_db: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
