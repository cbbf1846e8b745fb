// MPM benchmark: the seed soil flow (scenario C) in 3D, run with 1 and 2 threads.
// Prints particle-updates per second per core (wall clock, and per CPU second, which is the
// robust figure on a shared machine), the wall-clock time of the whole scenario and the
// 2-thread speed-up, with the machine it ran on and how busy it was (the load average before
// each run: wall-clock rates and speed-ups mean little when it exceeds the free cores).
//
// It runs the shipped scenario file samples/soil/seed_3d.toml (the paper's Table 1, the wall
// 0.5 m past the toe), so the benchmark times the flow that `rockfall soil` runs, wall load
// included; the arguments override its cell size and duration.
//
// Usage: bench_mpm [cell_size_m] [duration_s] [max_threads] [rounds] [flip]
#include "scenario/soil_file.hpp"

#include "mpm/soil.hpp"
#include "risk/statistics.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <thread>
#include <vector>

using namespace rockfall::mpm;

namespace {

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0) {
            return line.substr(line.find(':') + 2);
        }
    }
    return "unknown";
}

double cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

struct Timing {
    double wall;
    double cpu;
    double updates;
    SoilOutcome outcome;
};

// One-minute load average: runnable processes, ours included once running.
double load_average() {
    double load[1] = {0.0};
    return getloadavg(load, 1) == 1 ? load[0] : -1.0;
}

Timing run(const SoilScenario& scenario) {
    const double cpu0 = cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    SoilOutcome outcome = run_soil(scenario);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = cpu_seconds() - cpu0;
    const double updates =
        static_cast<double>(outcome.particles) * static_cast<double>(outcome.steps);
    return {wall, cpu, updates, std::move(outcome)};
}

}  // namespace

int main(int argc, char** argv) {
    const std::string file = ROCKFALL_SAMPLES_DIR "/soil/seed_3d.toml";
    SoilScenario scenario = rockfall::scenario::load_soil_scenario(file).scenario;
    if (argc > 1) {
        scenario.numerics.cell_size = std::atof(argv[1]);
    }
    if (argc > 2) {
        scenario.output.duration = std::atof(argv[2]);
    }
    const int max_threads = argc > 3 ? std::atoi(argv[3]) : 2;
    const int repeats = argc > 4 ? std::max(1, std::atoi(argv[4])) : 5;
    if (argc > 5) {
        scenario.numerics.flip = std::atof(argv[5]);
    }

    std::printf("machine: %u hardware threads, %s\n", std::thread::hardware_concurrency(),
                cpu_model().c_str());
    std::printf(
        "scenario: %s, %dD, cell %.3f m, %d particles per cell edge, %.1f s, flip %g; %d runs "
        "per thread count, interleaved\n",
        file.c_str(), scenario.numerics.dimension, scenario.numerics.cell_size,
        scenario.numerics.particles_per_cell, scenario.output.duration, scenario.numerics.flip,
        repeats);
    // Runs interleave the thread counts so that a change in the machine's load hits all alike;
    // the speed-up is the median of the per-round ratios.
    std::vector<std::vector<double>> walls(static_cast<std::size_t>(max_threads));
    std::vector<std::vector<double>> ratios(static_cast<std::size_t>(max_threads));
    for (int round = 0; round < repeats; ++round) {
        double single_wall = 0.0;
        for (int threads = 1; threads <= max_threads; ++threads) {
            scenario.numerics.threads = threads;
            const double load = load_average();
            const Timing t = run(scenario);
            if (threads == 1) {
                single_wall = t.wall;
            }
            walls[static_cast<std::size_t>(threads - 1)].push_back(t.wall);
            ratios[static_cast<std::size_t>(threads - 1)].push_back(single_wall / t.wall);
            std::printf(
                "round %d, threads %d (load average %.1f): %ld particles, %ld steps, wall "
                "%.2f s, cpu %.2f s; %.2f M particle-updates/s/core (wall), %.2f M/s per "
                "cpu second; speed-up %.2f\n",
                round + 1, threads, load, t.outcome.particles, t.outcome.steps, t.wall, t.cpu,
                t.updates / t.wall / threads / 1e6, t.updates / t.cpu / 1e6, single_wall / t.wall);
            if (round == 0) {
                std::printf(
                    "           peak wall load %.1f N at %.2f s, runout %.2f m past the "
                    "toe\n",
                    t.outcome.peak_wall_force, t.outcome.peak_wall_force_time,
                    t.outcome.deposit.runout_past_toe);
            }
        }
    }
    std::printf("\nmedians over %d rounds:\n", repeats);
    for (int threads = 1; threads <= max_threads; ++threads) {
        const auto k = static_cast<std::size_t>(threads - 1);
        std::printf(
            "  threads %d: wall-clock %.2f s for the whole scenario, speed-up %.2f "
            "(range %.2f to %.2f)\n",
            threads, rockfall::risk::median(walls[k]), rockfall::risk::median(ratios[k]),
            *std::min_element(ratios[k].begin(), ratios[k].end()),
            *std::max_element(ratios[k].begin(), ratios[k].end()));
    }
    return 0;
}
