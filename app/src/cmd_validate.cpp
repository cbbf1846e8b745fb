// `rockfall validate`: the tool against published results. Today: seed 001's Table 2 and the
// marked rocks' speeds (docs/validation.md), as text tables or JSON.

#include "commands.hpp"
#include "progress.hpp"
#include "report/reproduction_report.hpp"
#include "scenario/scenario_file.hpp"
#include "threads.hpp"
#include "validate_seed001.hpp"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#ifndef ROCKFALL_SAMPLES_DIR
#define ROCKFALL_SAMPLES_DIR "samples"
#endif

namespace rockfall::app {
namespace {

namespace fs = std::filesystem;

// The samples an installed program ships (PREFIX/share/rockfall/samples beside PREFIX/bin), or
// else those of the source tree it was built from.
std::string default_samples() {
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (!error) {
        const fs::path installed = exe.parent_path().parent_path() / "share/rockfall/samples";
        if (fs::is_directory(installed, error)) return installed.string();
    }
    return ROCKFALL_SAMPLES_DIR;
}

struct ValidateArgs {
    std::string samples;
    int seeds = 3;
    std::uint64_t first_seed = 1;
    int threads = 0;
    std::optional<double> sample_interval;
    double max_time = 2.5;
    std::string rows = "all";
    bool json = false;
    bool quiet = false;
};

void run_validate(const ValidateArgs& args) {
    const std::string samples = args.samples.empty() ? default_samples() : args.samples;
    Seed001Options options;
    options.flume_dir = fs::path(samples) / "seed_flume";
    options.catalogue = fs::path(samples) / "rocks" / "catalogue.toml";
    for (const fs::path& needed : {options.flume_dir / "flume.toml", options.catalogue}) {
        if (!fs::is_regular_file(needed))
            throw std::invalid_argument("--samples " + samples + ": no " + needed.generic_string() +
                                        " (give the folder of rockfall's samples)");
    }
    options.seeds = args.seeds;
    options.first_seed = args.first_seed;
    options.threads = thread_count(args.threads);
    options.sample_interval = args.sample_interval;
    options.max_time = args.max_time;
    options.physical = args.rows != "numerical";
    options.numerical = args.rows != "physical";
    namespace seed001 = risk::seed001;
    const std::size_t cases = seed001::clusters.size() * seed001::angles_deg.size();
    const std::size_t per_case =
        (options.physical ? 1 : 0) + (options.numerical ? seed001::shapes.size() : 0);
    const auto planned = static_cast<std::int64_t>(cases * per_case) * args.seeds;
    Progress progress(std::cerr, progress_mode_for_stderr(args.quiet || args.json), planned,
                      "runs");
    options.progress = [&progress](std::int64_t done, std::int64_t) { progress.update(done); };

    const auto start = std::chrono::steady_clock::now();
    const std::vector<risk::seed001::RunRecord> runs = run_seed001(options);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    progress.finish(static_cast<std::int64_t>(runs.size()));

    report::ReproductionInfo info;
    info.source = options.flume_dir.generic_string();
    info.first_seed = args.first_seed;
    info.seeds = args.seeds;
    info.sample_interval =
        args.sample_interval.value_or(scenario::load_scenario(options.flume_dir / "flume.toml")
                                          .scenario.wall_cells->sample_interval);
    info.runs = runs.size();
    for (const risk::seed001::RunRecord& run : runs) info.cpu_time += run.runtime;
    info.wall_time = elapsed.count();
    info.threads = options.threads;
    const risk::seed001::Reproduction reproduction = risk::seed001::compare(runs);
    if (args.json) {
        std::cout << report::seed001_json(reproduction, info).dump(2) << '\n';
    } else {
        report::print_seed001(std::cout, reproduction, info);
    }
}

}  // namespace

void register_validate(CLI::App& app) {
    auto args = std::make_shared<ValidateArgs>();
    CLI::App* cmd = app.add_subcommand(
        "validate",
        "Reproduce published results: seed 001's Table 2 (peak wall forces of the marked rocks) "
        "and the marked rocks' speeds at 1.4 m, over several cluster seeds");
    cmd->add_option("--samples", args->samples,
                    "Folder of rockfall's samples (seed_flume/ and rocks/catalogue.toml); default: "
                    "PREFIX/share/rockfall/samples of an installed program, else the source "
                    "tree's samples/");
    cmd->add_option("--seeds", args->seeds, "Cluster seeds per case")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd->add_option("--first-seed", args->first_seed, "First cluster seed")->capture_default_str();
    cmd->add_option("--threads", args->threads,
                    "Worker threads; 0 for the cores this process may use")
        ->check(CLI::Range(0, 4096))
        ->capture_default_str();
    cmd->add_option("--sample-interval", args->sample_interval,
                    "Replace the cases' pressure-cell sample interval, s (sensitivity study)")
        ->check(CLI::Range(1e-5, 0.1));
    cmd->add_option("--max-time", args->max_time,
                    "Simulated time of each run after the gate opens, s (the marked rocks reach "
                    "the wall within about 1.5 s; their deposit takes up to 10 s to rest)")
        ->check(CLI::Range(0.5, 30.0))
        ->capture_default_str();
    cmd->add_option("--rows", args->rows,
                    "Table 2's rows to run: all, physical (blocky cluster, painted rocks) or "
                    "numerical (every rock of one shape)")
        ->check(CLI::IsMember({"all", "physical", "numerical"}))
        ->capture_default_str();
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the tables");
    cmd->add_flag("--quiet", args->quiet, "No progress on standard error");
    cmd->callback([args] { run_validate(*args); });
}

}  // namespace rockfall::app
