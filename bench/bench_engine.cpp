// Engine benchmark (issue 2, "Benchmark"): trajectories per second on the seed slope with
// random rocks for (a) the engine at its default settings, (b) a bare Bullet loop with
// Bullet's default world at the coarse step and (c) the same loop at the engine's fine
// near-wall step everywhere. Prints the machine, the rates and the ratios a/b and a/c.

#include "bare_bullet.hpp"
#include "bench_machine.hpp"
#include "scenario/scenario_file.hpp"

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
#include <utility>
#include <vector>

namespace {

using namespace rockfall;

// One trajectory as a method ran it.
struct Sample {
    double wall = 0.0;       // s
    double cpu = 0.0;        // s
    double simulated = 0.0;  // s
    std::int64_t steps = 0;
    double reach = 0.0;  // m
    engine::StopReason stop = engine::StopReason::time_limit;
    shapes::RockKind kind = shapes::RockKind::sphere;
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
    std::map<shapes::RockKind, std::pair<int, double>> by_kind;  // count, simulated time (s)

    void add(const Sample& sample) {
        ++trajectories;
        wall += sample.wall;
        cpu += sample.cpu;
        simulated += sample.simulated;
        steps += sample.steps;
        reaches.push_back(sample.reach);
        ++stops[sample.stop];
        auto& [count, time] = by_kind[sample.kind];
        ++count;
        time += sample.simulated;
    }
    double rate() const { return trajectories / wall; }
    double cpu_rate() const { return trajectories / cpu; }
    double simulated_rate() const { return simulated / wall; }
};

double median(std::vector<double> values) {
    if (values.empty()) {
        return 0.0;
    }
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

void print_tally(const std::string& label, const Tally& t) {
    std::cout << label << "\n"
              << "  trajectories:          " << t.trajectories << "\n"
              << "  wall time:             " << t.wall << " s (thread CPU " << t.cpu << " s)\n"
              << "  trajectories/s:        " << t.rate() << " (per CPU s: " << t.cpu_rate() << ")\n"
              << "  mean simulated time:   " << t.simulated / t.trajectories << " s ("
              << t.simulated_rate() << " simulated s per wall s)\n"
              << "  steps:                 " << t.steps << " ("
              << 1e6 * t.wall / static_cast<double>(t.steps) << " us wall, "
              << 1e6 * t.cpu / static_cast<double>(t.steps) << " us CPU per step)\n"
              << "  by kind (rocks) mean simulated time:";
    for (const auto& [kind, entry] : t.by_kind) {
        std::cout << " " << shapes::to_string(kind) << " (" << entry.first << ") "
                  << entry.second / entry.first << " s";
    }
    std::cout << "\n"
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
    // m/s; 0: the median normal speed of the first wall hits in (a).
    double impact_speed = 0.0;
};

// Impact speed for (c) when (a) saw no wall hit, m/s (the brief's typical 0.2 m rock impact).
constexpr double kFallbackImpactSpeed = 8.0;

struct Results {
    Tally engine, bare, fine;
    Tally engine_subset;  // (a) on the rocks of (c)
    std::int64_t coarse_steps = 0, fine_steps = 0, wall_hits = 0;
    std::vector<double> first_hit_speeds;   // m/s, normal impact speed of each rock's first hit
    double impact_speed = 0.0;              // m/s, for (c)
    double fine_min = 0.0, fine_max = 0.0;  // s, range of the fine steps of (c)
    std::string load_start, load_after_ab, load_end;
};

void run_engine(const engine::Scenario& scenario, std::uint64_t seed, bool in_subset, Results& r) {
    const bench::Stopwatch watch;
    const engine::Outcome outcome = engine::simulate(scenario, seed);
    const double wall = watch.wall(), cpu = watch.cpu();
    const engine::RockOutcome& rock = outcome.rocks.front();
    const Sample sample{wall,
                        cpu,
                        outcome.simulated_time,
                        outcome.coarse_steps + outcome.fine_steps,
                        rock.reach,
                        rock.stop,
                        scenario.rocks.front().rock.kind};
    r.engine.add(sample);
    if (in_subset) {
        r.engine_subset.add(sample);
    }
    r.coarse_steps += outcome.coarse_steps;
    r.fine_steps += outcome.fine_steps;
    r.wall_hits += static_cast<std::int64_t>(rock.wall_hits.size());
    if (!rock.wall_hits.empty()) {
        r.first_hit_speeds.push_back(rock.wall_hits.front().normal_speed);
    }
}

void run_bare(const engine::Scenario& scenario, std::uint64_t seed, double dt, Tally& tally) {
    const bench::Stopwatch watch;
    const bench::BareRun bare = bench::run_bare_bullet(scenario, seed, dt);
    const double wall = watch.wall(), cpu = watch.cpu();
    tally.add({wall, cpu, bare.stop_time, bare.steps, bare.reach, bare.stop,
               scenario.rocks.front().rock.kind});
}

// (a) and (b) alternate rock by rock, and which goes first alternates too, so that a change
// in the machine's load hits both alike.
void measure_coarse(const engine::Scenario& base, const Options& options, Results& r) {
    for (int i = 1; i <= options.rocks; ++i) {
        const auto seed = static_cast<std::uint64_t>(i);
        const engine::Scenario scenario = risk::random_rock_scenario(base, seed);
        const bool in_subset = i <= options.fine_rocks;
        if (i % 2 == 1) {
            run_engine(scenario, seed, in_subset, r);
            run_bare(scenario, seed, scenario.numerics.time_step, r.bare);
        } else {
            run_bare(scenario, seed, scenario.numerics.time_step, r.bare);
            run_engine(scenario, seed, in_subset, r);
        }
        if (i % 50 == 0) {
            std::cerr << "  (a), (b): " << i << " rocks done\n";
        }
    }
}

// (c): the engine's fine step for each rock (fine_time_step) at one impact speed.
void measure_fine(const engine::Scenario& base, const Options& options, Results& r) {
    r.impact_speed = options.impact_speed > 0.0   ? options.impact_speed
                     : r.first_hit_speeds.empty() ? kFallbackImpactSpeed
                                                  : median(r.first_hit_speeds);
    for (int i = 1; i <= options.fine_rocks; ++i) {
        const auto seed = static_cast<std::uint64_t>(i);
        const engine::Scenario scenario = risk::random_rock_scenario(base, seed);
        const double dt = bench::fine_time_step(scenario, r.impact_speed);
        r.fine_min = i == 1 ? dt : std::min(r.fine_min, dt);
        r.fine_max = std::max(r.fine_max, dt);
        run_bare(scenario, seed, dt, r.fine);
        std::cerr << "  (c): rock " << i << " of " << options.fine_rocks << ", dt " << dt << " s\n";
    }
}

void print_report(const engine::Scenario& base, const Options& options, const Results& r) {
    std::cout << std::setprecision(4) << "\n"
              << "scenario:   " << options.scenario.string() << "\n"
              << "rocks:      N = " << options.rocks << " (seeds 1.." << options.rocks
              << "), fine-step subset M = " << options.fine_rocks << " (seeds 1.."
              << options.fine_rocks << ")\n"
              << "coarse step " << base.numerics.time_step << " s\n"
              << "load average at start:       " << r.load_start << "\n"
              << "load average after (a), (b): " << r.load_after_ab << "\n"
              << "load average at the end:     " << r.load_end << "\n\n";
    print_tally("(a) engine, default settings", r.engine);
    std::cout << "  coarse steps:          " << r.coarse_steps << "\n"
              << "  fine steps:            " << r.fine_steps << "\n"
              << "  wall hits:             " << r.wall_hits << " by " << r.first_hit_speeds.size()
              << " rocks; median first-hit normal speed " << median(r.first_hit_speeds) << " m/s\n";
    print_tally("(b) bare Bullet, default world, coarse step", r.bare);
    if (r.fine.trajectories > 0) {
        print_tally("(c) bare Bullet, default world, fine step everywhere", r.fine);
        std::cout << "  fine step:             " << r.fine_min << " .. " << r.fine_max
                  << " s (engine::WallContactLaw contact duration at " << r.impact_speed
                  << " m/s over steps_per_contact, per rock)\n"
                  << "  (a) on the same rocks: " << r.engine_subset.rate()
                  << " trajectories/s, mean simulated time "
                  << r.engine_subset.simulated / r.engine_subset.trajectories << " s\n";
    }
    std::cout << "ratios (trajectories/s)\n";
    print_ratio("a/b", r.engine.rate() / r.bare.rate(), r.engine.cpu_rate() / r.bare.cpu_rate(),
                1.0);
    if (r.fine.trajectories > 0) {
        print_ratio("a/c (same rocks)", r.engine_subset.rate() / r.fine.rate(),
                    r.engine_subset.cpu_rate() / r.fine.cpu_rate(), 100.0);
        std::cout << "  a/c with (a) over all N rocks = " << r.engine.rate() / r.fine.rate()
                  << "\n";
    }
    // Trajectories of different lengths (the methods' contact physics differ) cost different
    // amounts; simulated seconds per wall second compare the cost of the physics alone.
    std::cout << "ratios (simulated s per wall s, for information)\n"
              << "  a/b = " << r.engine.simulated_rate() / r.bare.simulated_rate() << "\n";
    if (r.fine.trajectories > 0) {
        std::cout << "  a/c (same rocks) = "
                  << r.engine_subset.simulated_rate() / r.fine.simulated_rate() << "\n";
    }
}

int run(const Options& options) {
    bench::print_machine(ROCKFALL_BUILD_TYPE);
    const engine::Scenario base = scenario::load_scenario(options.scenario).scenario;
    Results results;
    results.load_start = bench::load_average();
    measure_coarse(base, options, results);
    results.load_after_ab = bench::load_average();
    measure_fine(base, options, results);
    results.load_end = bench::load_average();
    print_report(base, options, results);
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
                   "Impact speed setting the fine step of (c), m/s; 0: the median first-hit "
                   "normal speed of (a) (8 m/s if no rock hits the wall)")
        ->check(CLI::NonNegativeNumber)
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
