// Sweep benchmark (issue 4, "Benchmark"): samples per second of `rockfall sweep` on the
// shipped sample scenario with 1 and 2 threads, the 2-thread speed-up, and the cost of
// sampling and the database against the engine alone on the same samples.
//
// The sweep is timed as users run it: the real `rockfall sweep` program, as a child process,
// writing a real database. The engine alone is timed in this process on the same samples,
// drawn beforehand. CPU times come from getrusage, so that time lost to other work on a
// shared machine does not count as overhead.

#include "scenario/scenario_file.hpp"

#include "engine/simulation.hpp"
#include "risk/sampling.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using namespace rockfall;

double seconds(const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
}

double cpu_seconds(int who) {
    rusage usage{};
    getrusage(who, &usage);
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

struct Timing {
    double wall = 0.0;  // s
    double cpu = 0.0;   // s
};

// Runs `rockfall sweep` with the given thread count into a fresh database.
Timing run_program(const std::string& scenario, int samples, int threads) {
    const std::filesystem::path db =
        std::filesystem::temp_directory_path() /
        ("bench_sweep_" + std::to_string(getpid()) + "_" + std::to_string(threads) + ".db");
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db.string() + suffix);
    const std::string samples_text = std::to_string(samples);
    const std::string threads_text = std::to_string(threads);
    const double cpu_before = cpu_seconds(RUSAGE_CHILDREN);
    const auto start = std::chrono::steady_clock::now();
    std::fflush(stdout);  // or the child's copy of the buffer is printed twice
    const pid_t child = fork();
    if (child == 0) {
        std::freopen("/dev/null", "w", stdout);
        execl(ROCKFALL_PROGRAM, ROCKFALL_PROGRAM, "sweep", scenario.c_str(), "--db", db.c_str(),
              "--samples", samples_text.c_str(), "--threads", threads_text.c_str(), "--quiet",
              static_cast<char*>(nullptr));
        std::_Exit(127);
    }
    int status = 0;
    waitpid(child, &status, 0);
    Timing timing;
    timing.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    timing.cpu = cpu_seconds(RUSAGE_CHILDREN) - cpu_before;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "rockfall sweep failed (status %d)\n", status);
        std::exit(1);
    }
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db.string() + suffix);
    return timing;
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown";
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"Sweep benchmark: rockfall sweep on 1 and 2 threads against the engine alone"};
    std::string scenario = std::string(ROCKFALL_SAMPLES_DIR) + "/seed_sweep.toml";
    int samples = 2000;
    cli.add_option("--scenario", scenario, "Scenario with a [sweep] table")->capture_default_str();
    cli.add_option("--samples", samples, "Samples per run")->capture_default_str();
    CLI11_PARSE(cli, argc, argv);

    std::printf("machine: %s, %u hardware threads; build %s\n", cpu_model().c_str(),
                std::thread::hardware_concurrency(), ROCKFALL_BUILD_TYPE);
    std::printf("scenario: %s, %d samples\n\n", scenario.c_str(), samples);
    const scenario::ScenarioFile file = scenario::load_scenario(scenario);

    // Sampling alone: draw_sample and sample_scenario for every sample.
    double cpu = cpu_seconds(RUSAGE_SELF);
    std::vector<engine::Scenario> scenarios;
    std::vector<std::uint64_t> seeds;
    for (int i = 0; i < samples; ++i) {
        const risk::SampleInputs inputs = risk::draw_sample(file.sweep, file.scenario, i);
        scenarios.push_back(risk::sample_scenario(file.scenario, inputs));
        seeds.push_back(inputs.seed);
    }
    const double sampling_cpu = cpu_seconds(RUSAGE_SELF) - cpu;

    // The engine alone on the same samples, one thread.
    cpu = cpu_seconds(RUSAGE_SELF);
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < scenarios.size(); ++i) engine::simulate(scenarios[i], seeds[i]);
    const double engine_wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double engine_cpu = cpu_seconds(RUSAGE_SELF) - cpu;

    const Timing one = run_program(scenario, samples, 1);
    const Timing two = run_program(scenario, samples, 2);

    const double n = samples;
    std::printf("%-40s %10s %10s %14s\n", "", "wall s", "CPU s", "samples/s");
    std::printf("%-40s %10.2f %10.2f %14.1f\n", "engine alone (1 thread, in process)", engine_wall,
                engine_cpu, n / engine_wall);
    std::printf("%-40s %10s %10.3f %14s\n", "sampling alone (draw + scenario)", "", sampling_cpu,
                "");
    std::printf("%-40s %10.2f %10.2f %14.1f\n", "rockfall sweep --threads 1", one.wall, one.cpu,
                n / one.wall);
    std::printf("%-40s %10.2f %10.2f %14.1f\n\n", "rockfall sweep --threads 2", two.wall, two.cpu,
                n / two.wall);
    std::printf("2-thread speed-up (wall, 1 thread / 2 threads): %.2f (target >= 1.8)\n",
                one.wall / two.wall);
    std::printf("sweep overhead over the engine alone (CPU, 1 thread): %+.1f %% (target < 5 %%)\n",
                100.0 * (one.cpu - engine_cpu) / engine_cpu);
    std::printf("  of which sampling: %.1f %%\n", 100.0 * sampling_cpu / engine_cpu);
    return 0;
}
