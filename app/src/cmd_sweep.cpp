// `rockfall sweep`: a Monte Carlo or Latin hypercube sweep of a scenario into a results
// database, on all cores, resumable, with an optional confidence-interval stop rule.

#include "commands.hpp"
#include "integer_option.hpp"
#include "progress.hpp"
#include "report/query_report.hpp"
#include "report/text_format.hpp"
#include "scenario/scenario_file.hpp"
#include "sweep_record.hpp"

#include "db/queries.hpp"
#include "db/results_db.hpp"
#include "risk/sweep_runner.hpp"

#include <sqlite3.h>

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

namespace rockfall::app {
namespace {

struct SweepArgs {
    std::string scenario;
    std::string db;
    std::optional<std::int64_t> samples;
    std::optional<std::uint64_t> seed;
    std::string method;
    int threads = 0;
    std::string until;
    double half_width = 0.01;
    double confidence = 0.95;
    std::int64_t check_every = 100;
    bool resume = false;
    bool quiet = false;
    double trajectory_interval = 0.0;
    std::int64_t crash_after = -1;
    bool interrupt_at_create = false;
};

// Set by SIGINT and SIGTERM; the sweep then stops taking samples, writes what finished and
// marks the run interrupted.
std::atomic<int> interrupt_signal{0};

extern "C" void on_interrupt(int signal) { interrupt_signal.store(signal); }

void install_interrupt_handlers() {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

std::optional<risk::UntilRule> parse_until(const SweepArgs& args) {
    if (args.until.empty()) return std::nullopt;
    risk::UntilRule rule;
    rule.half_width = args.half_width;
    rule.confidence = args.confidence;
    rule.check_every = args.check_every;
    if (args.until == "wall") {
        rule.statistic = risk::UntilRule::Statistic::wall;
    } else if (args.until.rfind("exceed:", 0) == 0) {
        rule.statistic = risk::UntilRule::Statistic::exceed;
        const std::string number = args.until.substr(7);
        std::size_t used = 0;
        try {
            rule.distance = std::stod(number, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != number.size() || !std::isfinite(rule.distance))
            throw std::invalid_argument("--until " + args.until +
                                        ": the distance after exceed: must be a number of m, "
                                        "e.g. exceed:4.5");
    } else {
        throw std::invalid_argument("--until " + args.until +
                                    ": must be wall or exceed:D (D: distance past the toe, m)");
    }
    return rule;
}

// The spec as run: the file's [sweep] table with the command line's overrides.
risk::SweepSpec effective_spec(const scenario::ScenarioFile& file, const SweepArgs& args) {
    risk::SweepSpec spec = file.has_sweep ? file.sweep : risk::sweep_defaults(file.scenario);
    if (args.samples) spec.samples = *args.samples;
    if (args.seed) spec.seed = *args.seed;
    if (args.method == "monte_carlo" || args.method == "mc")
        spec.method = risk::SweepSpec::Method::monte_carlo;
    if (args.method == "latin_hypercube" || args.method == "lhs")
        spec.method = risk::SweepSpec::Method::latin_hypercube;
    scenario::validate_sweep(spec, file.scenario);
    return spec;
}

// Simulates a crash in the middle of a batch for the resume tests: a transaction is opened
// and written to, then the process ends without committing or closing anything.
[[noreturn]] void crash_mid_batch(db::ResultsDb& results) {
    sqlite3_exec(results.handle(),
                 "BEGIN; DELETE FROM outcomes; INSERT INTO zones VALUES "
                 "(9999, 'half-written');",
                 nullptr, nullptr, nullptr);
    std::_Exit(3);
}

// Success flags of the samples already stored, for the --until rule after --resume.
void replay_stored(const db::ResultsDb& results, const risk::UntilRule& rule,
                   risk::UntilMonitor& monitor) {
    // A sample succeeds when any of its rocks does: its largest reach and its total of wall
    // hits decide that.
    for (const db::StoredOutcome& stored : db::stored_outcomes(results)) {
        engine::RockOutcome outcome;
        outcome.reach = stored.reach;
        outcome.wall_hits.resize(static_cast<std::size_t>(stored.wall_hits));
        monitor.add(stored.sample, rule.success(outcome));
    }
}

int run_sweep(const SweepArgs& args) {
    const scenario::ScenarioFile file = scenario::load_scenario(args.scenario);
    // Samples run on the scenario and [sweep] table as the database stores them (parsed back
    // from its text), so that `simulate --from` replays them bit for bit: a mesh rock's or a
    // named shape's hull read back from stored vertices may list them in another order than
    // the mesh file gave them.
    const scenario::ScenarioFile as_stored =
        scenario::parse_scenario_file(file.text, file.path.string(), file.path.parent_path());
    const risk::SweepSpec spec = effective_spec(as_stored, args);
    const std::optional<risk::UntilRule> until = parse_until(args);
    if (until && spec.method == risk::SweepSpec::Method::latin_hypercube)
        throw std::invalid_argument(
            "--until cannot be used with Latin hypercube sampling: its strata need the sample "
            "count fixed in advance; use method = \"monte_carlo\" or drop --until");
    const int threads = args.threads > 0
                            ? args.threads
                            : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    const std::string stop_rule =
        until ? until->describe() + ", at most " + std::to_string(spec.samples) + " samples"
              : std::to_string(spec.samples) + " samples";
    const nlohmann::json settings = {{"threads", threads},
                                     {"trajectory_interval_s", args.trajectory_interval}};
    const db::RunRecord wanted = make_run_record(file, spec, stop_rule, settings);

    // Handlers before the database is made: a Ctrl-C while it is created then ends the run as
    // interrupted, with a whole file that --resume continues, instead of killing the process
    // and leaving the hidden part file.
    install_interrupt_handlers();
    if (args.interrupt_at_create) std::raise(SIGINT);
    std::optional<db::ResultsDb> opened;
    if (args.resume) {
        opened.emplace(db::ResultsDb::open(args.db, true));
        check_resumable(opened->run(), wanted, args.db);
    } else {
        opened.emplace(db::ResultsDb::create(args.db, wanted));
    }
    db::ResultsDb& results = *opened;

    const std::vector<std::int64_t> stored = results.stored_samples();
    std::optional<risk::UntilMonitor> monitor;
    if (until) {
        monitor.emplace(*until);
        replay_stored(results, *until, *monitor);
    }
    const std::int64_t limit = monitor && monitor->stop_at() ? *monitor->stop_at() : spec.samples;
    std::vector<std::int64_t> pending;
    {
        const std::set<std::int64_t> done(stored.begin(), stored.end());
        for (std::int64_t i = 0; i < limit; ++i)
            if (!done.contains(i)) pending.push_back(i);
    }

    if (!args.quiet) {
        std::cerr << "sweep " << file.scenario.name << ": " << stop_rule << ", "
                  << risk::to_string(spec.method) << ", seed " << spec.seed << ", " << threads
                  << " thread" << (threads == 1 ? "" : "s") << " -> " << args.db << '\n';
        if (!stored.empty())
            std::cerr << "resuming: " << stored.size() << " samples stored, " << pending.size()
                      << " to run\n";
    }
    Progress progress(std::cerr, progress_mode_for_stderr(args.quiet), limit, "samples");
    auto done = static_cast<std::int64_t>(stored.size());
    progress.set_already(done);

    risk::RunnerOptions options;
    options.threads = threads;
    options.trajectory_interval = args.trajectory_interval;
    risk::SweepRunner runner(spec, as_stored.scenario, pending, options);
    std::vector<db::SampleRecord> batch;
    auto last_write = std::chrono::steady_clock::now();
    const auto note = [&] {
        return monitor ? "half-width " + report::fmt("%.4f", monitor->half_width()) : std::string();
    };
    while (!runner.finished()) {
        for (risk::SampleResult& result : runner.collect(std::chrono::milliseconds(200))) {
            if (monitor) monitor->add(result.inputs.index, until->success(result.rocks));
            batch.push_back(std::move(result));
        }
        const auto now = std::chrono::steady_clock::now();
        // Batches bound the work lost to a crash (one second) and amortise the commit.
        // The crash test writes every sample at once, so that it crashes after exactly
        // --crash-after samples however fast the machine is.
        const std::size_t batch_limit = args.crash_after >= 0 ? 1 : 256;
        if (batch.size() >= batch_limit ||
            (!batch.empty() && now - last_write > std::chrono::seconds(1))) {
            results.write_batch(batch);
            done += static_cast<std::int64_t>(batch.size());
            batch.clear();
            last_write = now;
            if (args.crash_after >= 0 && done >= args.crash_after) crash_mid_batch(results);
        }
        progress.update(done, note());
        if (interrupt_signal.load() != 0 || (monitor && monitor->stop_at())) runner.stop();
    }
    if (!batch.empty()) {
        results.write_batch(batch);
        done += static_cast<std::int64_t>(batch.size());
    }
    // Samples finished past the stopping point are dropped, so that the result is the same
    // however far the workers had run ahead.
    if (monitor && monitor->stop_at()) {
        results.delete_samples_from(*monitor->stop_at());
        done = *monitor->stop_at();
    }
    progress.finish(done, note());

    const bool interrupted = interrupt_signal.load() != 0;
    results.finish(interrupted ? "interrupted" : "complete", utc_now());
    if (interrupted) {
        std::cerr << "interrupted: " << done << " samples are stored in " << args.db
                  << "; continue with the same command and --resume\n";
        return exit_interrupted;
    }
    if (monitor && !monitor->stop_at())
        std::cerr << "warning: the target half-width " << until->half_width
                  << " was not reached within " << spec.samples << " samples (it is "
                  << report::fmt("%.4f", monitor->half_width()) << "); raise --samples\n";
    report::write_summary(std::cout, report::QueryFormat::text, args.db, db::summarize(results));
    return 0;
}

}  // namespace

void register_sweep(CLI::App& app) {
    auto args = std::make_shared<SweepArgs>();
    CLI::App* cmd = app.add_subcommand(
        "sweep", "Run a Monte Carlo sweep of a scenario into an SQLite results database");
    cmd->add_option("scenario", args->scenario, "Scenario file (TOML) with a [sweep] table")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--db", args->db, "Results database to create (or continue with --resume)")
        ->required();
    cmd->add_option("--samples", args->samples,
                    "Number of samples (with --until: the most to run); default: [sweep] samples")
        ->transform(integer_in(1, risk::max_samples, "a sample count"));
    cmd->add_option("--seed", args->seed, "Run seed; default: [sweep] seed");
    cmd->add_option("--method", args->method, "Sampling method; default: [sweep] method")
        ->check(CLI::IsMember({"monte_carlo", "mc", "latin_hypercube", "lhs"}));
    cmd->add_option("--threads", args->threads, "Worker threads; 0 = all cores")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cmd->add_option("--until", args->until,
                    "Stop when a proportion is known well enough: wall (P of hitting the wall) "
                    "or exceed:D (P of reach >= D m past the toe)");
    cmd->add_option("--half-width", args->half_width,
                    "Target half-width of the --until interval (a proportion)")
        ->check(CLI::Range(1e-6, 0.5))
        ->capture_default_str();
    cmd->add_option("--confidence", args->confidence, "Confidence of the --until interval")
        ->check(CLI::Range(0.5, 0.9999))
        ->capture_default_str();
    cmd->add_option("--check-every", args->check_every, "Samples between --until checks")
        ->check(CLI::Range(std::int64_t{1}, std::int64_t{1} << 30))
        ->capture_default_str();
    cmd->add_flag("--resume", args->resume,
                  "Continue an interrupted sweep in --db (same scenario and options)");
    cmd->add_flag("--quiet", args->quiet, "No progress display");
    cmd->add_option("--trajectories", args->trajectory_interval,
                    "Store every rock's trajectory every this many s (0: none)")
        ->check(CLI::Range(0.0, 10.0))
        ->capture_default_str();
    // For the resume tests: crash in the middle of a batch once this many samples are stored.
    cmd->add_option("--crash-after", args->crash_after)->group("");
    // For the interrupt test: SIGINT to itself just before the database is created.
    cmd->add_flag("--interrupt-at-create", args->interrupt_at_create)->group("");
    cmd->callback([args] {
        const int code = run_sweep(*args);
        if (code != 0) throw CLI::RuntimeError(code);
    });
}

}  // namespace rockfall::app
