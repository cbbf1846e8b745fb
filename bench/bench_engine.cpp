// Engine benchmark (issue 2, "Benchmark"): trajectories per second on the seed slope with
// random rocks for (a) the engine at its default settings, (b) a bare Bullet loop with
// Bullet's default world at the coarse step and (c) the same loop at the engine's fine
// near-wall step everywhere. Prints the machine, the rates and the ratios a/b and a/c.

#include "bare_bullet.hpp"

#include "app/scenario_file.hpp"
#include "engine/simulation.hpp"
#include "risk/random_release.hpp"

#include <CLI/CLI.hpp>
#include <LinearMath/btScalar.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <thread>
#include <time.h>
#include <vector>

namespace {

using namespace rockfall;

#ifndef ROCKFALL_BUILD_TYPE
#define ROCKFALL_BUILD_TYPE "unknown"
#endif

// Wall-clock (steady_clock) and CPU time of this thread: the machine is shared, so the CPU
// time shows how much of the wall time went to others.
struct Stopwatch {
    std::chrono::steady_clock::time_point wall_start = std::chrono::steady_clock::now();
    double cpu_start = thread_cpu_seconds();

    static double thread_cpu_seconds() {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }
    double wall() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    }
    double cpu() const { return thread_cpu_seconds() - cpu_start; }
};

// One method's totals over the rocks it ran.
struct Tally {
    int trajectories = 0;
    double wall = 0.0;       // s
    double cpu = 0.0;        // s
    double simulated = 0.0;  // s
    std::int64_t steps = 0;
    std::vector<double> reaches;  // m
    std::map<engine::StopReason, int> stops;

    void add(const Stopwatch& watch, double simulated_time, std::int64_t step_count, double reach,
             engine::StopReason stop) {
        ++trajectories;
        wall += watch.wall();
        cpu += watch.cpu();
        simulated += simulated_time;
        steps += step_count;
        reaches.push_back(reach);
        ++stops[stop];
    }
    double rate() const { return trajectories / wall; }
    double cpu_rate() const { return trajectories / cpu; }
};

std::string first_line_with(const std::filesystem::path& file, const std::string& key) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(key, 0) == 0) {
            const auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    }
    return "unknown";
}

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return one + " " + five + " " + fifteen + " (1, 5, 15 min)";
}

double median(std::vector<double> values) {
    if (values.empty()) {
        return 0.0;
    }
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

void print_machine() {
    std::cout << "machine\n"
              << "  cores (nproc):  " << std::thread::hardware_concurrency() << "\n"
              << "  CPU:            " << first_line_with("/proc/cpuinfo", "model name") << "\n"
              << "  compiler:       " << __VERSION__ << "\n"
              << "  build type:     " << ROCKFALL_BUILD_TYPE
#ifdef NDEBUG
              << " (asserts off)\n"
#else
              << " (asserts on)\n"
#endif
              << "  Bullet:         " << btGetVersion()
              << (sizeof(btScalar) == 8 ? " double precision\n" : " single precision\n");
}

void print_tally(const std::string& label, const Tally& t) {
    std::cout << label << "\n"
              << "  trajectories:          " << t.trajectories << "\n"
              << "  wall time:             " << t.wall << " s (thread CPU " << t.cpu << " s)\n"
              << "  trajectories/s:        " << t.rate() << " (per CPU s: " << t.cpu_rate() << ")\n"
              << "  mean simulated time:   " << t.simulated / t.trajectories << " s\n"
              << "  steps:                 " << t.steps << " ("
              << static_cast<double>(t.steps) / t.wall << " steps/s)\n"
              << "  reach past toe:        median " << median(t.reaches) << " m\n"
              << "  stop reasons:         ";
    for (const auto& [reason, count] : t.stops) {
        std::cout << " " << engine::to_string(reason) << " " << count;
    }
    std::cout << "\n";
}

void print_ratio(const std::string& label, double ratio, double cpu_ratio, double target) {
    std::cout << "  " << label << " = " << ratio << " (per CPU s: " << cpu_ratio
              << "), target >= " << target << ": " << (ratio >= target ? "MET" : "NOT MET") << "\n";
}

struct Options {
    std::filesystem::path scenario =
        std::filesystem::path(ROCKFALL_SAMPLES_DIR) / "seed_slope.toml";
    int rocks = 200;
    int fine_rocks = 20;
    double impact_speed = 8.0;
};

int run(const Options& options) {
    print_machine();
    const engine::Scenario base = app::load_scenario(options.scenario).scenario;
    std::cout << "scenario:   " << options.scenario.string() << "\n"
              << "rocks:      N = " << options.rocks << " (seeds 1.." << options.rocks
              << "), fine-step subset M = " << options.fine_rocks << " (seeds 1.."
              << options.fine_rocks << ")\n"
              << "coarse step " << base.numerics.time_step << " s\n"
              << "load average at start: " << load_average() << "\n"
              << std::flush;

    Tally engine_tally, bare_tally, fine_tally, engine_subset;
    std::int64_t coarse_steps = 0, fine_steps = 0;
    const auto run_engine = [&](const engine::Scenario& scenario, std::uint64_t seed) {
        const Stopwatch watch;
        const engine::Outcome outcome = engine::simulate(scenario, seed);
        engine_tally.add(watch, outcome.simulated_time, outcome.coarse_steps + outcome.fine_steps,
                         outcome.rocks.front().reach, outcome.rocks.front().stop);
        if (seed <= static_cast<std::uint64_t>(options.fine_rocks)) {
            engine_subset.add(watch, outcome.simulated_time, 0, 0.0, outcome.rocks.front().stop);
        }
        coarse_steps += outcome.coarse_steps;
        fine_steps += outcome.fine_steps;
    };
    const auto run_bare = [&](const engine::Scenario& scenario, std::uint64_t seed) {
        const Stopwatch watch;
        const bench::BareRun bare =
            bench::run_bare_bullet(scenario, seed, scenario.numerics.time_step);
        bare_tally.add(watch, bare.stop_time, bare.steps, bare.reach, bare.stop);
    };
    // (a) and (b) alternate rock by rock, and which goes first alternates too, so that a
    // change in the machine's load hits both alike.
    for (int i = 1; i <= options.rocks; ++i) {
        const auto seed = static_cast<std::uint64_t>(i);
        const engine::Scenario scenario = risk::random_rock_scenario(base, seed);
        if (i % 2 == 1) {
            run_engine(scenario, seed);
            run_bare(scenario, seed);
        } else {
            run_bare(scenario, seed);
            run_engine(scenario, seed);
        }
        if (i % 50 == 0) {
            std::cerr << "  " << i << " rocks done\n";
        }
    }
    const std::string load_after_ab = load_average();

    double fine_min = 1.0, fine_max = 0.0;
    for (int i = 1; i <= options.fine_rocks; ++i) {
        const auto seed = static_cast<std::uint64_t>(i);
        const engine::Scenario scenario = risk::random_rock_scenario(base, seed);
        const double dt = bench::fine_time_step(scenario, options.impact_speed);
        fine_min = std::min(fine_min, dt);
        fine_max = std::max(fine_max, dt);
        const Stopwatch watch;
        const bench::BareRun bare = bench::run_bare_bullet(scenario, seed, dt);
        fine_tally.add(watch, bare.stop_time, bare.steps, bare.reach, bare.stop);
        std::cerr << "  fine rock " << i << ": dt " << dt << " s, " << bare.steps << " steps, "
                  << watch.wall() << " s\n";
    }

    std::cout << std::setprecision(4) << "\n";
    print_tally("(a) engine, default settings", engine_tally);
    std::cout << "  coarse steps:          " << coarse_steps << "\n"
              << "  fine steps:            " << fine_steps << "\n";
    print_tally("(b) bare Bullet, default world, coarse step", bare_tally);
    print_tally("(c) bare Bullet, default world, fine step everywhere", fine_tally);
    std::cout << "  fine step:             " << fine_min << " .. " << fine_max
              << " s (WallContactLaw contact duration at " << options.impact_speed
              << " m/s / steps_per_contact, per rock)\n"
              << "  (a) on the same " << engine_subset.trajectories
              << " rocks: " << engine_subset.rate() << " trajectories/s\n";
    std::cout << "load average after (a), (b): " << load_after_ab << "\n"
              << "load average at the end:     " << load_average() << "\n"
              << "ratios\n";
    print_ratio("a/b", engine_tally.rate() / bare_tally.rate(),
                engine_tally.cpu_rate() / bare_tally.cpu_rate(), 1.0);
    if (fine_tally.trajectories > 0) {
        print_ratio("a/c (same rocks)", engine_subset.rate() / fine_tally.rate(),
                    engine_subset.cpu_rate() / fine_tally.cpu_rate(), 100.0);
        std::cout << "  a/c (a over all N rocks) = " << engine_tally.rate() / fine_tally.rate()
                  << "\n";
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    CLI::App cli{"Engine benchmark: trajectories/s of the engine against bare Bullet loops."};
    cli.add_option("--scenario", options.scenario, "Base scenario file (seed slope)")
        ->check(CLI::ExistingFile)
        ->capture_default_str();
    cli.add_option("--rocks", options.rocks, "Random rocks N for (a) and (b), seeds 1..N")
        ->check(CLI::Range(1, 1000000))
        ->capture_default_str();
    cli.add_option("--fine-rocks", options.fine_rocks,
                   "Rocks for (c), the first M seeds (0 skips it)")
        ->check(CLI::Range(0, 1000000))
        ->capture_default_str();
    cli.add_option("--impact-speed", options.impact_speed,
                   "Impact speed setting the fine step of (c), m/s")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    CLI11_PARSE(cli, argc, argv);
    if (options.fine_rocks > options.rocks) {
        std::cerr << "bench_engine: --fine-rocks " << options.fine_rocks
                  << " must not exceed --rocks " << options.rocks << "\n";
        return 1;
    }
    try {
        return run(options);
    } catch (const std::exception& error) {
        std::cerr << "bench_engine: " << error.what() << "\n";
        return 1;
    }
}
