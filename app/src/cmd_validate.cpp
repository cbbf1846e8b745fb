// `rockfall validate`: the verification and validation report of the tool (docs/reports.md):
// the analytic checks, seed 000's coefficients, seed 001's Table 2 and the marked rocks'
// speeds (docs/validation.md), the calibration tests; as text, JSON or one HTML file.

#include "commands.hpp"
#include "output_file.hpp"
#include "progress.hpp"
#include "report/reproduction_report.hpp"
#include "report/vv_report.hpp"
#include "scenario/scenario_file.hpp"
#include "threads.hpp"
#include "validate_sections.hpp"
#include "validate_seed001.hpp"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

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
    // Unset: 3 and "all", or 1 and "physical" with --quick.
    std::optional<int> seeds;
    std::uint64_t first_seed = 1;
    int threads = 0;
    std::optional<double> sample_interval;
    double max_time = 2.5;
    std::optional<std::string> rows;
    bool quick = false;
    std::string html;
    bool json = false;
    bool quiet = false;
};

// Seed 001's reproduction: the runs, the comparison, and its section of the report.
struct Seed001Result {
    risk::seed001::Reproduction reproduction;
    report::ReproductionInfo info;
};

// The seed reproductions' case files in the samples folder; throws std::invalid_argument
// naming the first one missing.
void check_samples(const std::string& samples) {
    for (const fs::path& needed : {fs::path(samples) / "seed_flume" / "flume.toml",
                                   fs::path(samples) / "rocks" / "catalogue.toml"}) {
        if (!fs::is_regular_file(needed))
            throw std::invalid_argument("--samples " + samples + ": no " + needed.generic_string() +
                                        " (give the folder of rockfall's samples)");
    }
}

Seed001Result run_reproduction(const ValidateArgs& args, const std::string& samples, int seeds,
                               const std::string& rows) {
    Seed001Options options;
    options.flume_dir = fs::path(samples) / "seed_flume";
    options.catalogue = fs::path(samples) / "rocks" / "catalogue.toml";
    options.seeds = seeds;
    options.first_seed = args.first_seed;
    options.threads = thread_count(args.threads);
    options.sample_interval = args.sample_interval;
    options.max_time = args.max_time;
    options.physical = rows != "numerical";
    options.numerical = rows != "physical";
    namespace seed001 = risk::seed001;
    const std::size_t cases = seed001::clusters.size() * seed001::angles_deg.size();
    const std::size_t per_case =
        (options.physical ? 1 : 0) + (options.numerical ? seed001::shapes.size() : 0);
    const auto planned = static_cast<std::int64_t>(cases * per_case) * seeds;
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
    info.seeds = seeds;
    info.sample_interval =
        args.sample_interval.value_or(scenario::load_scenario(options.flume_dir / "flume.toml")
                                          .scenario.wall_cells->sample_interval);
    info.runs = runs.size();
    for (const risk::seed001::RunRecord& run : runs) info.cpu_time += run.runtime;
    info.wall_time = elapsed.count();
    info.threads = options.threads;
    return {risk::seed001::compare(runs), info};
}

std::string setting_text(double value, const char* unit) {
    std::ostringstream text;
    text << value << ' ' << unit;
    return text.str();
}

void run_validate(const ValidateArgs& args) {
    const auto start = std::chrono::steady_clock::now();
    const std::string samples = args.samples.empty() ? default_samples() : args.samples;
    const int seeds = args.seeds.value_or(args.quick ? 1 : 3);
    const std::string rows = args.rows.value_or(args.quick ? "physical" : "all");
    // Missing case files and a path that may not be written are refused before the work: the
    // file is opened now (as its part file) and published at the end.
    check_samples(samples);
    std::optional<OutputFile> file;
    if (!args.html.empty()) file.emplace(args.html);
    VvOptions options;
    options.quick = args.quick;
    options.threads = thread_count(args.threads);
    const bool chatty = !args.quiet && !args.json;
    const auto stage = [chatty](const char* what) {
        if (chatty) std::cerr << "validate: " << what << '\n';
    };
    report::VvReport vv;
    vv.version = ROCKFALL_VERSION;
    vv.build = ROCKFALL_BUILD;
    vv.quick = args.quick;
    stage("engine checks");
    vv.sections.push_back(engine_section(options));
    stage("mass properties and sphericities");
    vv.sections.push_back(shapes_section(options));
    stage("MPM checks");
    vv.sections.push_back(mpm_section(options));
    stage("seed 000's coefficients");
    vv.sections.push_back(seed000_section(options));
    // The calibration before seed 001's long runs, so that a failure shows at once.
    stage(args.quick ? "calibration (drop test)" : "calibration (drop and heap tests)");
    report::VvSection calibration = calibration_section(options);
    stage("seed 001's reproduction");
    const Seed001Result seed001 = run_reproduction(args, samples, seeds, rows);
    vv.sections.push_back(report::seed001_section(seed001.reproduction, seed001.info));
    std::ostringstream details;
    report::print_seed001(details, seed001.reproduction, seed001.info);
    vv.sections.back().text = details.str();
    vv.sections.push_back(std::move(calibration));

    vv.settings = {{"seed 001", std::to_string(seeds) + " cluster seed(s) from " +
                                    std::to_string(args.first_seed) + ", rows " + rows + ", " +
                                    setting_text(args.max_time, "s") +
                                    " after the gate opens, pressure cells every " +
                                    setting_text(seed001.info.sample_interval, "s")},
                   {"case files", seed001.info.source}};
    if (rows != "all")
        vv.left_out.emplace_back("seed 001's " +
                                     std::string(rows == "physical" ? "numerical" : "physical") +
                                     " rows of Table 2",
                                 args.rows ? "--rows " + rows : "--quick");
    if (args.quick) vv.left_out.emplace_back("the heap test", "--quick");
    vv.left_out.emplace_back("seed 000's Figs. 5 and 6", "their measured data are not in the text");
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (file) {
        report::write_vv_html(file->stream(), vv);
        file->commit();
    }
    if (args.json) {
        nlohmann::json out = report::seed001_json(seed001.reproduction, seed001.info);
        out.update(report::vv_json(vv));
        out["total_wall_time_s"] = elapsed.count();
        std::cout << out.dump(2) << '\n';
    } else {
        report::print_vv_summary(std::cout, vv);
        std::cout << "whole validation: " << format_duration(elapsed.count()) << " on "
                  << options.threads << " thread(s)"
                  << (args.html.empty() ? "" : "; report written to " + args.html) << '\n';
    }
}

}  // namespace

void register_validate(CLI::App& app) {
    auto args = std::make_shared<ValidateArgs>();
    CLI::App* cmd = app.add_subcommand(
        "validate",
        "The verification and validation report of the tool: the engine's and the MPM "
        "solver's analytic checks, mass properties, seed 000's identified coefficients, seed "
        "001's Table 2 and marked rocks' speeds, the calibration tests; each as reference, "
        "simulated value, tolerance and verdict (text, --json or --html)");
    cmd->add_option("--samples", args->samples,
                    "Folder of rockfall's samples (seed_flume/ and rocks/catalogue.toml); default: "
                    "PREFIX/share/rockfall/samples of an installed program, else the source "
                    "tree's samples/");
    cmd->add_flag("--quick", args->quick,
                  "The CI subset: seed 001's physical rows over one seed, no heap test (1 to 2 "
                  "minutes on 2 cores)");
    cmd->add_option("--html", args->html,
                    "Also write the report as one self-contained HTML file (replaced whole)");
    cmd->add_option("--seeds", args->seeds,
                    "Seed 001: cluster seeds per case (default 3; 1 with --quick)")
        ->check(CLI::Range(1, 1000));
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
    cmd->add_option(
           "--rows", args->rows,
           "Seed 001: Table 2's rows to run: all, physical (blocky cluster, painted rocks) "
           "or numerical (every rock of one shape) (default all; physical with --quick)")
        ->check(CLI::IsMember({"all", "physical", "numerical"}));
    cmd->add_flag("--json", args->json,
                  "Print one JSON document instead of the tables (no progress)");
    cmd->add_flag("--quiet", args->quiet, "No progress on standard error");
    cmd->callback([args] { run_validate(*args); });
}

}  // namespace rockfall::app
