// Results database benchmark (issue 4, "Benchmark"): writes N synthetic outcomes (default one
// million, about 30 % with wall impacts) through ResultsDb::write_batch, then times the
// percentile and exceedance queries (target: under 1 s each), the worst-N and summary queries,
// opening the file, and the same queries through the `rockfall query` program. Prints the
// machine, the write rate and the file size. Not run by CTest or CI.

#include "synthetic.hpp"

#include "db/queries.hpp"
#include "db/results_db.hpp"

#include <CLI/CLI.hpp>
#include <sqlite3.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <thread>
#include <vector>

namespace {

using namespace rockfall;
namespace fs = std::filesystem;

#ifndef ROCKFALL_BUILD_TYPE
#define ROCKFALL_BUILD_TYPE "unknown"
#endif

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// CPU time of this process and of its finished children, s.
double cpu_seconds() {
    rusage self{};
    rusage children{};
    getrusage(RUSAGE_SELF, &self);
    getrusage(RUSAGE_CHILDREN, &children);
    const auto total = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
    };
    return total(self.ru_utime) + total(self.ru_stime) + total(children.ru_utime) +
           total(children.ru_stime);
}

struct Timing {
    double wall = 1e300;  // s
    double cpu = 1e300;   // s
};

// Best of `repeats` wall and CPU times: the machine is shared, so the wall time of the least
// disturbed run is the fairer figure, and the CPU time shows the work itself.
Timing best_time(int repeats, const std::function<void()>& work) {
    Timing best;
    for (int i = 0; i < repeats; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const double cpu_start = cpu_seconds();
        work();
        best.wall = std::min(best.wall, seconds_since(start));
        best.cpu = std::min(best.cpu, cpu_seconds() - cpu_start);
    }
    return best;
}

std::string number(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    }
    return "unknown";
}

void print_row(const std::string& what, Timing t, const std::string& note = "") {
    std::cout << "  " << std::left << std::setw(66) << what << std::right << std::fixed
              << std::setprecision(3) << std::setw(7) << t.wall << " s wall " << std::setw(7)
              << t.cpu << " s CPU" << (t.wall < 1.0 ? "" : "  (over 1 s)")
              << (note.empty() ? "" : "  " + note) << '\n';
}

struct Args {
    std::int64_t samples = 1000000;
    std::int64_t batch = 1000;
    std::string out;
    int repeats = 3;
    bool keep = false;
    bool reuse = false;
};

void write_database(const Args& args, const fs::path& path) {
    const db::testing::SyntheticOptions options;
    db::ResultsDb database =
        db::ResultsDb::create(path, db::testing::synthetic_run(options, args.samples));
    double generate = 0.0;
    double write = 0.0;
    double write_cpu = 0.0;
    std::int64_t impacts = 0;
    std::vector<db::SampleRecord> batch;
    for (std::int64_t first = 0; first < args.samples; first += args.batch) {
        auto start = std::chrono::steady_clock::now();
        batch.clear();
        for (std::int64_t i = first; i < std::min(first + args.batch, args.samples); ++i) {
            batch.push_back(db::testing::synthetic_record(options, i));
            impacts += static_cast<std::int64_t>(batch.back().rocks.at(0).outcome.wall_hits.size());
        }
        generate += seconds_since(start);
        start = std::chrono::steady_clock::now();
        const double cpu_start = cpu_seconds();
        database.write_batch(batch);
        write += seconds_since(start);
        write_cpu += cpu_seconds() - cpu_start;
    }
    const auto start = std::chrono::steady_clock::now();
    database.finish("complete", "2024-01-01T00:00:00Z");
    const double finish = seconds_since(start);
    const double n = static_cast<double>(args.samples);
    std::cout << "write: " << args.samples << " samples in batches of " << args.batch << ", "
              << impacts << " wall impacts, 2 stations each\n"
              << std::fixed << std::setprecision(2) << "  write_batch total " << write
              << " s: " << std::setprecision(0) << n / write << " samples/s ("
              << std::setprecision(1) << 1e6 * write / n << " us per sample; CPU "
              << std::setprecision(2) << write_cpu << " s, " << std::setprecision(0)
              << n / write_cpu << " samples per CPU second)\n"
              << std::setprecision(2) << "  generating the records " << generate
              << " s; finish (checkpoint, leave WAL) " << finish << " s\n"
              << "  file size " << static_cast<double>(fs::file_size(path)) / 1e6 << " MB ("
              << std::setprecision(0) << static_cast<double>(fs::file_size(path)) / n
              << " bytes per sample)\n";
}

void time_queries(const Args& args, const fs::path& path) {
    const int r = args.repeats;
    std::cout << "open (best of " << r << "):\n";
    print_row("open read-only", best_time(r, [&] { db::ResultsDb::open(path, false); }));
    print_row("open for writing (WAL, quick_check)",
              best_time(1, [&] { db::ResultsDb::open(path, true); }));
    const db::ResultsDb database = db::ResultsDb::open(path, false);

    std::cout << "percentiles 50, 90, 95, 99 with confidence intervals (best of " << r << "):\n";
    const std::vector<double> ps = {0.5, 0.9, 0.95, 0.99};
    struct Case {
        db::Quantity quantity;
        db::GroupBy by;
    };
    for (const Case c : {Case{db::Quantity::reach, db::GroupBy::none},
                         Case{db::Quantity::reach, db::GroupBy::kind},
                         Case{db::Quantity::reach, db::GroupBy::size},
                         Case{db::Quantity::max_speed, db::GroupBy::zone},
                         Case{db::Quantity::peak_force, db::GroupBy::none},
                         Case{db::Quantity::impact_energy, db::GroupBy::kind},
                         Case{db::Quantity::impulse, db::GroupBy::size}}) {
        const db::Grouping grouping{c.by, {}};
        std::int64_t n = 0;
        const Timing t = best_time(r, [&] {
            const auto table = db::percentiles(database, c.quantity, ps, grouping);
            n = 0;
            for (const auto& g : table.groups) n += g.n;
        });
        print_row(
            std::string(db::to_string(c.quantity)) + " by " + std::string(db::to_string(c.by)), t,
            std::to_string(n) + " values");
    }

    std::cout << "exceedance with its interval (best of " << r << "):\n";
    for (const Case c : {Case{db::Quantity::reach, db::GroupBy::none},
                         Case{db::Quantity::reach, db::GroupBy::zone},
                         Case{db::Quantity::reach, db::GroupBy::size},
                         Case{db::Quantity::peak_force, db::GroupBy::kind}}) {
        const double threshold = c.quantity == db::Quantity::reach ? 3.0 : 2.0e5;
        for (const auto method :
             {db::IntervalMethod::wilson, db::IntervalMethod::clopper_pearson}) {
            double probability = 0.0;
            const Timing t = best_time(r, [&] {
                const auto table =
                    db::exceedance(database, c.quantity, threshold, {c.by, {}}, method);
                probability = table.groups.front().probability;
            });
            print_row(std::string(db::to_string(c.quantity)) + " >= " + number(threshold) + " by " +
                          std::string(db::to_string(c.by)) + ", " +
                          std::string(db::to_string(method)),
                      t);
            static_cast<void>(probability);
        }
    }

    std::cout << "other queries (best of " << r << "):\n";
    print_row("worst 10 by reach",
              best_time(r, [&] { db::worst_samples(database, db::Quantity::reach, 10); }));
    print_row("worst 10 by peak_force",
              best_time(r, [&] { db::worst_samples(database, db::Quantity::peak_force, 10); }));
    print_row("summary", best_time(r, [&] { db::summarize(database); }));
}

// The same questions as a user asks them: the program, its start-up, opening and output.
void time_program(const Args& args, const fs::path& path) {
#ifdef ROCKFALL_PROGRAM
    std::cout << "through the program, output to /dev/null (best of " << args.repeats << "):\n";
    const std::string program = ROCKFALL_PROGRAM;
    for (const std::string query :
         {"percentiles", "percentiles --of peak_force --by size", "exceed --distance 3",
          "exceed --distance 3 --by kind --interval clopper-pearson --csv", "worst --n 10",
          "summary --json"}) {
        const std::string command =
            "'" + program + "' query '" + path.string() + "' " + query + " > /dev/null";
        int status = 0;
        const Timing t = best_time(args.repeats, [&] { status = std::system(command.c_str()); });
        print_row("rockfall query DB " + query, t, status == 0 ? "" : "FAILED");
    }
#else
    static_cast<void>(args);
    static_cast<void>(path);
#endif
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Results database benchmark: write rate and query times on synthetic outcomes"};
    Args args;
    app.add_option("--samples", args.samples, "Synthetic samples to write")->capture_default_str();
    app.add_option("--batch", args.batch, "Samples per write_batch")->capture_default_str();
    app.add_option("--out", args.out, "Database file (default: in the temporary directory)");
    app.add_option("--repeats", args.repeats, "Repeats per query (best is shown)")
        ->capture_default_str();
    app.add_flag("--keep", args.keep, "Keep the database afterwards");
    app.add_flag("--reuse", args.reuse, "Query the --out database as it is, without writing");
    CLI11_PARSE(app, argc, argv);

    const fs::path path = args.out.empty() ? fs::temp_directory_path() / "rockfall_bench_db.sqlite"
                                           : fs::path(args.out);
    if (!args.reuse) {
        for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(path.string() + suffix);
    }
    std::cout << "machine: " << cpu_model() << ", " << std::thread::hardware_concurrency()
              << " hardware threads; build " << ROCKFALL_BUILD_TYPE << "; SQLite "
              << sqlite3_libversion() << "\nfile: " << path << "\n";
    try {
        if (!args.reuse) write_database(args, path);
        time_queries(args, path);
        time_program(args, path);
    } catch (const std::exception& e) {
        std::cerr << "bench_db: " << e.what() << '\n';
        return 1;
    }
    if (!args.keep && !args.reuse) fs::remove(path);
    return 0;
}
