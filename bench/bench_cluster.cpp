// Cluster benchmark (issue 13, "Benchmark"): one release of a cluster scenario (by default
// samples/flume_45.toml: C2's 99 rocks on the 45 deg flume, sphere layer and perforated
// sheet) from gate opening to rest, on one core, run three ways: (a) as the scenario says
// (wall impacts sub-stepped per rock), (b) with the whole world at the fine step during wall
// impacts (numerics.wall_stepping = "world"), (c) as (a) without the lining, (d) as (a) with
// the perforated sheet as Bullet's triangle mesh (numerics.sheet_contact = "mesh") instead of
// the structured sheet contact, and (e) as (b) with every wall contact compliant, resting ones
// too (RunOptions::rigid_resting_wall = false: the design before issue 13, whose deposit held
// the whole world at the fine step). Prints simulated seconds per wall second, body-steps per
// second and the ratios a/b, a/c, a/d and a/e. Not run by CTest or CI.

#include "bench_machine.hpp"
#include "scenario/scenario_file.hpp"

#include "engine/simulation.hpp"
#include "shapes/lining.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <exception>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#ifndef ROCKFALL_SAMPLES_DIR
#define ROCKFALL_SAMPLES_DIR "samples"
#endif
#ifndef ROCKFALL_BUILD_TYPE
#define ROCKFALL_BUILD_TYPE "unknown"
#endif

namespace {

using namespace rockfall;

struct Options {
    std::string scenario = std::string(ROCKFALL_SAMPLES_DIR) + "/flume_45.toml";
    std::uint64_t seed = 1;
    bool skip_world = false;
    bool skip_mesh = false;
    bool skip_old = false;
};

// One way of running the release.
struct Measurement {
    std::string label;
    double wall = 0.0;       // s
    double cpu = 0.0;        // s, this thread
    double simulated = 0.0;  // s, from gate opening
    engine::Outcome outcome;

    double simulated_rate() const { return simulated / cpu; }
    double body_step_rate() const { return static_cast<double>(outcome.body_steps) / cpu; }
};

Measurement measure(std::string label, const engine::Scenario& scenario, std::uint64_t seed,
                    const engine::RunOptions& run_options = {}) {
    Measurement m;
    m.label = std::move(label);
    std::cout << "running " << m.label << " ..." << std::endl;
    const bench::Stopwatch watch;
    m.outcome = engine::simulate(scenario, seed, run_options);
    m.wall = watch.wall();
    m.cpu = watch.cpu();
    m.simulated = m.outcome.simulated_time;
    return m;
}

void print(const Measurement& m) {
    int at_rest = 0;
    int wall_hits = 0;
    int on_wall = 0;
    for (const engine::RockOutcome& rock : m.outcome.rocks) {
        at_rest += rock.stop == engine::StopReason::at_rest ? 1 : 0;
        wall_hits += static_cast<int>(rock.wall_hits.size());
        on_wall += rock.wall_hits.empty() ? 0 : 1;
    }
    std::cout << m.label << "\n"
              << "  wall time:              " << m.wall << " s (thread CPU " << m.cpu << " s)\n"
              << "  simulated:              " << m.simulated << " s from gate opening\n"
              << "  simulated s per CPU s:  " << m.simulated_rate() << "\n"
              << "  world steps:            " << m.outcome.coarse_steps << " coarse, "
              << m.outcome.fine_steps << " fine (per-rock: wall sub-steps of single rocks)\n"
              << "  body-steps:             " << m.outcome.body_steps << " (" << m.body_step_rate()
              << " per CPU s)\n"
              << "  rocks:                  " << m.outcome.rocks.size() << ", " << at_rest
              << " at rest; " << on_wall << " touched the wall, " << wall_hits << " hits\n";
}

void print_ratio(const std::string& label, const Measurement& a, const Measurement& b) {
    std::cout << "  " << label << ": " << b.cpu / a.cpu << " x less CPU time ("
              << a.simulated_rate() / b.simulated_rate() << " x simulated s per CPU s)\n";
}

int run(const Options& options) {
    bench::print_machine(ROCKFALL_BUILD_TYPE);
    std::cout << "load before:  " << bench::load_average() << "\n"
              << "scenario:     " << options.scenario << ", seed " << options.seed << "\n";
    const engine::Scenario base = scenario::load_scenario(options.scenario).scenario;
    if (!base.cluster) {
        throw std::invalid_argument(options.scenario + ": has no [cluster]");
    }
    std::vector<Measurement> runs;
    engine::Scenario per_rock = base;
    per_rock.numerics.wall_stepping = engine::WallStepping::per_rock;
    runs.push_back(measure("(a) per-rock wall sub-stepping", per_rock, options.seed));
    engine::Scenario bare = per_rock;
    bare.slope.lining.reset();
    runs.push_back(measure("(c) per-rock, no lining", bare, options.seed));
    const bool sheet = base.slope.lining && base.slope.lining->sheet;
    if (sheet && !options.skip_mesh) {
        engine::Scenario mesh = per_rock;
        mesh.numerics.sheet_contact = engine::SheetContact::mesh;
        runs.push_back(measure("(d) per-rock, sheet as a triangle mesh", mesh, options.seed));
    }
    if (!options.skip_world) {
        engine::Scenario world = base;
        world.numerics.wall_stepping = engine::WallStepping::world;
        runs.push_back(
            measure("(b) whole world at the fine step during impacts", world, options.seed));
        if (!options.skip_old) {
            engine::RunOptions old;
            old.rigid_resting_wall = false;
            runs.push_back(measure("(e) whole world at the fine step during every wall contact",
                                   world, options.seed, old));
        }
    }
    std::cout << std::setprecision(4);
    for (const Measurement& m : runs) {
        print(m);
    }
    std::cout
        << "load after:   " << bench::load_average() << "\n"
        << "ratios (CPU time; targets: (a) under 60 s, at least 10 times faster than the whole\n"
        << "world at the fine step: a/e for the design the issue measured)\n";
    for (const Measurement& m : runs) {
        if (m.label.starts_with("(b)")) print_ratio("a/b", runs[0], m);
        if (m.label.starts_with("(e)")) print_ratio("a/e (the design before issue 13)", runs[0], m);
        if (m.label.starts_with("(d)"))
            print_ratio("a/d (structured sheet against mesh)", runs[0], m);
    }
    print_ratio("a/c (the lining's cost)", runs[0], runs[1]);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    CLI::App cli{"Cluster benchmark: one cluster release on one core, three ways."};
    cli.add_option("--scenario", options.scenario, "Cluster scenario file")
        ->check(CLI::ExistingFile)
        ->capture_default_str();
    cli.add_option("--seed", options.seed, "Run seed")->capture_default_str();
    cli.add_flag("--skip-world", options.skip_world,
                 "Skip (b), the whole world at the fine step (the slowest)");
    cli.add_flag("--skip-mesh", options.skip_mesh, "Skip (d), the sheet as a triangle mesh");
    cli.add_flag("--skip-old", options.skip_old,
                 "Skip (e), every wall contact at the whole world's fine step");
    CLI11_PARSE(cli, argc, argv);
    try {
        return run(options);
    } catch (const std::exception& error) {
        std::cerr << "bench_cluster: " << error.what() << "\n";
        return 1;
    }
}
