// MPI sweep benchmark (issue 17, "Benchmark and plan"): samples per second of `rockfall sweep`
// on one process with one thread against `mpirun -np 2` ranks of one thread each (the
// efficiency of a second rank), and the owning rank's cost per sample: rank 1 sends rank 0
// synthetic samples (db/testing) as fast as it can, in the messages a rank sends, and rank 0
// receives, decodes and writes them in the sweep's batches. From these: how many busy cores one
// owner can feed. Run it without mpirun; it starts `mpirun -np 2` itself for the owner part.

#include "synthetic.hpp"

#include "db/results_db.hpp"
#include "db/sample_codec.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mpi.h>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <time.h>
#include <unistd.h>
#include <vector>

namespace {

using namespace rockfall;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown";
}

double thread_cpu() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double load_average() {
    double load = 0.0;
    std::ifstream("/proc/loadavg") >> load;
    return load;
}

double cpu_of_children() {
    rusage usage{};
    getrusage(RUSAGE_CHILDREN, &usage);
    const auto seconds = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
    };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

struct Timing {
    double wall = 0.0;  // s
    double cpu = 0.0;   // s, of the process and its children (mpirun's ranks)
};

// Runs the command (argv[0] a path), its stdout to /dev/null unless `show`.
Timing run(const std::vector<std::string>& command, bool show = false) {
    std::vector<char*> argv;
    for (const std::string& word : command) argv.push_back(const_cast<char*>(word.c_str()));
    argv.push_back(nullptr);
    const auto start = Clock::now();
    const double cpu = cpu_of_children();
    std::fflush(stdout);
    const pid_t child = fork();
    if (child == 0) {
        if (!show && std::freopen("/dev/null", "w", stdout) == nullptr) std::_Exit(126);
        execv(argv[0], argv.data());
        std::_Exit(127);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "%s failed (status %d)\n", command[0].c_str(), status);
        std::exit(1);
    }
    return {since(start), cpu_of_children() - cpu};
}

void remove_db(const fs::path& db) {
    for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(db.string() + suffix);
}

// 1 process against 2 ranks, one thread each, on the same samples.
// Returns one rank-thread's rate, samples/s.
double ranks_part(const std::string& scenario, int samples, int repeats, const fs::path& dir) {
    const fs::path db = dir / ("bench_mpi_" + std::to_string(getpid()) + ".db");
    const std::string n = std::to_string(samples);
    const std::vector<std::string> sweep = {
        ROCKFALL_PROGRAM, "sweep", scenario,    "--db", db.string(),
        "--samples",      n,       "--threads", "1",    "--quiet"};
    std::vector<std::string> ranks = {MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np",
                                      "2"};
    ranks.insert(ranks.end(), sweep.begin(), sweep.end());
    // The machine is shared: the runs alternate and the fastest of each counts.
    Timing one{1e30, 0.0};
    Timing two{1e30, 0.0};
    for (int round = 0; round < repeats; ++round) {
        std::printf("round %d: load average %.2f\n", round + 1, load_average());
        remove_db(db);
        const Timing a = run(sweep);
        remove_db(db);
        const Timing b = run(ranks);
        remove_db(db);
        if (a.wall < one.wall) one = a;
        if (b.wall < two.wall) two = b;
    }
    std::printf("%-46s %10s %10s %12s\n", "", "wall s", "CPU s", "samples/s");
    std::printf("%-46s %10.2f %10.2f %12.1f\n", "rockfall sweep --threads 1 (one process)",
                one.wall, one.cpu, samples / one.wall);
    std::printf("%-46s %10.2f %10.2f %12.1f\n", "mpirun -np 2 rockfall sweep --threads 1", two.wall,
                two.cpu, samples / two.wall);
    std::printf(
        "2 ranks / 1 rank: %.2f (target >= 1.8), efficiency %.0f %%; CPU per sample "
        "%+.1f %% (MPI start-up, messages, the second process)\n\n",
        one.wall / two.wall, 50.0 * one.wall / two.wall, 100.0 * (two.cpu - one.cpu) / one.cpu);
    return samples / one.wall;
}

// Rank 1: every sample encoded beforehand, sent `per_message` at a time. Rank 0: receives,
// decodes, and writes batches of 256 (the sweep's) into a fresh database.
void owner_part(int samples, int per_message, const fs::path& dir, double thread_rate) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    db::testing::SyntheticOptions options;
    if (rank == 1) {
        std::vector<std::string> messages;
        for (int first = 0; first < samples; first += per_message) {
            std::string bytes;
            for (int i = first; i < std::min(samples, first + per_message); ++i)
                db::encode_sample(db::testing::synthetic_record(options, i), bytes);
            messages.push_back(std::move(bytes));
        }
        MPI_Barrier(MPI_COMM_WORLD);
        for (const std::string& bytes : messages)
            MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, 0, 1, MPI_COMM_WORLD);
        MPI_Send(nullptr, 0, MPI_BYTE, 0, 2, MPI_COMM_WORLD);
        return;
    }
    const fs::path path = dir / ("bench_mpi_owner_" + std::to_string(getpid()) + ".db");
    remove_db(path);
    db::ResultsDb results =
        db::ResultsDb::create(path, db::testing::synthetic_run(options, samples));
    std::vector<db::SampleRecord> batch;
    double receive = 0.0;
    double decode = 0.0;
    double write = 0.0;
    std::size_t bytes_received = 0;
    MPI_Barrier(MPI_COMM_WORLD);
    const auto start = Clock::now();
    const double cpu_start = thread_cpu();
    for (;;) {
        auto t = Clock::now();
        MPI_Status status;
        MPI_Probe(1, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
        int size = 0;
        MPI_Get_count(&status, MPI_BYTE, &size);
        std::string bytes(static_cast<std::size_t>(size), '\0');
        MPI_Recv(bytes.data(), size, MPI_BYTE, 1, status.MPI_TAG, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        receive += since(t);
        if (status.MPI_TAG == 2) break;
        bytes_received += bytes.size();
        t = Clock::now();
        for (db::SampleRecord& record : db::decode_samples(bytes))
            batch.push_back(std::move(record));
        decode += since(t);
        if (batch.size() >= 256) {
            t = Clock::now();
            results.write_batch(batch);
            write += since(t);
            batch.clear();
        }
    }
    auto t = Clock::now();
    if (!batch.empty()) results.write_batch(batch);
    results.finish("complete", "2026-01-01T00:00:00Z");
    write += since(t);
    const double total = since(start);
    const double cpu = thread_cpu() - cpu_start;
    const auto size = fs::file_size(path);
    remove_db(path);
    const double n = samples;
    std::printf(
        "owner: %d synthetic samples (%zu stations, one rock; %.0f bytes each as sent), "
        "%d per message\n",
        samples, options.stations, static_cast<double>(bytes_received) / n, per_message);
    std::printf("  receive %.3f s, decode %.3f s, write %.3f s (database %.0f bytes/sample)\n",
                receive, decode, write, static_cast<double>(size) / n);
    std::printf("  owner rate: %.0f samples/s (target >= 20000), %.1f us per sample\n", n / total,
                1e6 * total / n);
    // The CPU time of rank 0's thread: what the owner costs whatever else the machine runs.
    std::printf("  owner CPU: %.1f us per sample, %.0f samples/s per owner core\n", 1e6 * cpu / n,
                n / cpu);
    if (thread_rate > 0.0)
        std::printf(
            "one owner feeds %.0f busy cores (wall rate) to %.0f (CPU rate) at the %.1f "
            "samples/s of one rank-thread here\n",
            n / total / thread_rate, n / cpu / thread_rate, thread_rate);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"MPI sweep benchmark: 1 against 2 ranks, and the owner's cost per sample"};
    std::string scenario = std::string(ROCKFALL_SAMPLES_DIR) + "/seed_sweep.toml";
    int samples = 2000;  // 400 (5 s of sweep) measures start-up as much as the sweep
    int repeats = 3;
    int owner_samples = 200000;
    int per_message = 8;
    std::string dir = fs::current_path().string();
    bool owner = false;
    double thread_rate = 0.0;
    cli.add_option("--scenario", scenario, "Scenario with a [sweep] table")->capture_default_str();
    cli.add_option("--samples", samples, "Samples of the rank runs")->capture_default_str();
    cli.add_option("--repeats", repeats, "Rounds of the rank runs (the fastest counts)")
        ->capture_default_str();
    cli.add_option("--owner-samples", owner_samples, "Synthetic samples fed to the owner")
        ->capture_default_str();
    cli.add_option("--per-message", per_message, "Samples per message to the owner")
        ->capture_default_str();
    cli.add_option("--dir", dir, "Directory of the databases (a local disk)")
        ->capture_default_str();
    cli.add_flag("--owner", owner, "The owner part alone (run under mpirun -np 2)");
    cli.add_option("--thread-rate", thread_rate,
                   "With --owner: one rank-thread's samples/s, for the cores one owner feeds");
    CLI11_PARSE(cli, argc, argv);

    if (owner) {
        MPI_Init(&argc, &argv);
        owner_part(owner_samples, per_message, dir, thread_rate);
        MPI_Finalize();
        return 0;
    }
    std::printf("machine: %s, %u hardware threads; build %s\n", cpu_model().c_str(),
                std::thread::hardware_concurrency(), ROCKFALL_BUILD_TYPE);
    std::printf("scenario: %s, %d samples; databases in %s\n\n", scenario.c_str(), samples,
                dir.c_str());
    const double rate = ranks_part(scenario, samples, repeats, dir);
    std::printf("\n");
    (void)run({MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", "2",
               fs::read_symlink("/proc/self/exe").string(), "--owner", "--owner-samples",
               std::to_string(owner_samples), "--per-message", std::to_string(per_message), "--dir",
               dir, "--thread-rate", std::to_string(rate)},
              true);
    return 0;
}
