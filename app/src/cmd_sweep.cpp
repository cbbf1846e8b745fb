// `rockfall sweep`: a Monte Carlo or Latin hypercube sweep of a scenario into a results
// database, on all cores, resumable, with an optional confidence-interval stop rule.

#include "commands.hpp"
#include "integer_option.hpp"
#include "progress.hpp"
#include "report/query_report.hpp"
#include "report/text_format.hpp"
#include "scenario/scenario_file.hpp"
#include "sweep_mpi.hpp"
#include "sweep_record.hpp"
#include "threads.hpp"

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
    /// --shard K/N as given ("" for the whole run).
    std::string shard;
    bool resume = false;
    bool quiet = false;
    double trajectory_interval = 0.0;
    std::int64_t crash_after = -1;
    std::int64_t pause_after = -1;
    bool interrupt_at_create = false;
    /// Names of the options given on the command line ("--seed", "scenario", ...): with
    /// --resume, every result-deciding option not among them takes the database's value.
    std::set<std::string> given;
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

// The method --method names ("mc" and "lhs" are short forms); none when it is not given.
std::optional<risk::SweepSpec::Method> method_option(const std::string& name) {
    if (name == "monte_carlo" || name == "mc") return risk::SweepSpec::Method::monte_carlo;
    if (name == "latin_hypercube" || name == "lhs") return risk::SweepSpec::Method::latin_hypercube;
    return std::nullopt;
}

// The spec as run: the file's [sweep] table with the command line's overrides.
risk::SweepSpec effective_spec(const scenario::ScenarioFile& file, const SweepArgs& args) {
    risk::SweepSpec spec = file.has_sweep ? file.sweep : risk::sweep_defaults(file.scenario);
    if (args.samples) spec.samples = *args.samples;
    if (args.seed) spec.seed = *args.seed;
    if (const auto method = method_option(args.method)) spec.method = *method;
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

// --resume: every option deciding the results or the stopping point that the command line
// does not give takes the value the database stores; one it gives must equal the stored one.
// The scenario, seed, method and sample count are then checked by check_resumable (which
// compares with the scenario hash too).
void take_stored_settings(SweepArgs& args, const db::RunRecord& run, const std::string& db_path) {
    const auto given = [&](const std::string& option) { return args.given.contains(option); };
    if (!given("--seed")) args.seed = run.seed;
    if (!given("--samples")) args.samples = run.samples_planned;
    if (!given("--method")) args.method = run.method;
    // Before the method's own checks (--until with Latin hypercube), which would hide this.
    const auto method_given = method_option(args.method);
    const std::string method = method_given ? risk::to_string(*method_given) : args.method;
    if (method != run.method)
        throw std::invalid_argument(db_path + ": cannot resume: the database's method is " +
                                    run.method + " but this command gives " + method +
                                    "; leave the option out to take the stored value, or start "
                                    "a new database");
    const nlohmann::json settings = stored_settings(run, db_path, "cannot resume: ");
    const auto take = [&](const std::string& option, auto& value, const std::string& key) {
        using T = std::decay_t<decltype(value)>;
        if (!settings.contains(key)) return false;
        T stored{};
        try {
            stored = settings.at(key).get<T>();
        } catch (const nlohmann::json::exception&) {
            throw std::invalid_argument(db_path + ": cannot resume: run.settings_json " + key +
                                        " = " + settings.at(key).dump() +
                                        " is not a valid value (the file is damaged)");
        }
        const auto shown = [](const T& v) {
            const nlohmann::json json(v);
            return json.is_string() && json.get<std::string>().empty() ? "(none)" : json.dump();
        };
        if (given(option) && value != stored)
            throw std::invalid_argument(
                db_path + ": cannot resume: the database's " + option + " is " + shown(stored) +
                " but this command gives " + shown(value) +
                "; leave the option out to take the stored value, or start a new database");
        value = stored;
        return true;
    };
    take("--trajectories", args.trajectory_interval, "trajectory_interval_s");
    // A shard continues as that shard; a whole run (which stores no shard) stays whole.
    if (!take("--shard", args.shard, "shard") && given("--shard"))
        throw std::invalid_argument(db_path +
                                    ": cannot resume: the database holds a whole run, "
                                    "not a shard, but this command gives --shard " +
                                    args.shard + "; leave --shard out, or start a new database");
    if (take("--until", args.until, "until")) {
        if (!args.until.empty()) {
            take("--half-width", args.half_width, "half_width");
            take("--confidence", args.confidence, "confidence");
            take("--check-every", args.check_every, "check_every");
        }
        return;
    }
    // Written before the --until options were stored: a stop rule other than a plain sample
    // count cannot be rebuilt exactly from its description (rounded to 6 digits).
    if (!given("--until") && run.stop_rule != std::to_string(run.samples_planned) + " samples")
        throw std::invalid_argument(
            db_path + ": cannot resume: the database's stop rule is \"" + run.stop_rule +
            "\" but it does not store the --until options (written by an older rockfall): give "
            "--until, --half-width, --confidence and --check-every as the run was started");
}

// The scenario of a sweep: the SCENARIO file, or with --resume and no file, the scenario
// text the database stores (complete in itself: resolved `extends`, meshes as vertices).
scenario::ScenarioFile sweep_scenario(const SweepArgs& args, const db::RunRecord* run) {
    if (!args.scenario.empty()) return scenario::load_scenario(args.scenario);
    if (run == nullptr)
        throw std::invalid_argument(
            "sweep needs a SCENARIO file; only `rockfall sweep --db FILE.db --resume` takes the "
            "scenario from a database");
    return scenario::parse_scenario_file(run->scenario_text, args.db + " (stored scenario)");
}

// The samples of this process's threads.
class LocalSource final : public SampleSource {
  public:
    LocalSource(const risk::SweepSpec& spec, const engine::Scenario& base,
                std::vector<std::int64_t> pending, const risk::RunnerOptions& options)
        : runner_(spec, base, std::move(pending), options) {}
    std::vector<risk::SampleResult> collect(std::chrono::milliseconds timeout) override {
        return runner_.collect(timeout);
    }
    void stop() override { runner_.stop(); }
    bool finished() const override { return runner_.finished(); }

  private:
    risk::SweepRunner runner_;
};

// A rank other than 0 of an MPI sweep: the setup from rank 0, then its chunks until the end.
int serve_rank(mpi::Session& session, SweepArgs& args) {
    install_interrupt_handlers();
    const std::optional<mpi::Setup> setup = session.receive_setup();
    if (!setup) return 0;  // rank 0 ended without a sweep and says why
    const std::filesystem::path path = setup->scenario_path;
    const scenario::ScenarioFile as_stored =
        scenario::parse_scenario_file(setup->scenario_text, path.string(), path.parent_path());
    args.seed = setup->seed;
    args.samples = setup->samples;
    args.method = setup->method;
    risk::RunnerOptions options;
    options.threads = thread_count(args.threads);
    options.trajectory_interval = setup->trajectory_interval;
    session.pause_after(args.pause_after);
    try {
        return session.serve(effective_spec(as_stored, args), as_stored.scenario, options,
                             interrupt_signal);
    } catch (const std::exception& error) {
        std::cerr << "rockfall (MPI rank " << session.rank() << "): " << error.what() << '\n';
        session.abort(exit_failure);
    }
}

int sweep_as_owner(SweepArgs& args, mpi::Session* session) {
    // --resume opens the database first: what the command line leaves out comes from it.
    std::optional<db::ResultsDb> opened;
    std::optional<db::RunRecord> stored_run;
    if (args.resume) {
        opened.emplace(db::ResultsDb::open(args.db, true));
        stored_run = opened->run();
        take_stored_settings(args, *stored_run, args.db);
    }
    const scenario::ScenarioFile file = sweep_scenario(args, stored_run ? &*stored_run : nullptr);
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
    std::optional<Shard> shard;
    if (!args.shard.empty()) shard = parse_shard(args.shard, "--shard");
    if (shard && until)
        throw std::invalid_argument(
            "--until cannot be used with --shard " + args.shard +
            ": the stop rule is checked on the completed prefix of the whole run, which no "
            "shard holds; give the shards a fixed --samples and merge them (rockfall merge), or "
            "run one sweep over MPI ranks with --until (docs/cluster.md)");
    // Rank 0 of several leaves one core of its node to receiving and writing the others'
    // samples when the thread count is left to it (docs/cluster.md).
    const int threads = session && args.threads == 0 ? std::max(1, thread_count(args.threads) - 1)
                                                     : thread_count(args.threads);
    const std::string stop_rule =
        until ? until->describe() + ", at most " + std::to_string(spec.samples) + " samples"
              : std::to_string(spec.samples) + " samples";
    // Stored for --resume, which takes from them what its command line leaves out.
    nlohmann::json settings = {{"threads", threads},
                               {"trajectory_interval_s", args.trajectory_interval},
                               {"until", args.until}};
    if (shard) settings["shard"] = shard->text();
    if (until)
        settings.update({{"half_width", args.half_width},
                         {"confidence", args.confidence},
                         {"check_every", args.check_every}});
    const db::RunRecord wanted = make_run_record(file, spec, stop_rule, settings);

    // Handlers before the database is made: a Ctrl-C while it is created then ends the run as
    // interrupted, with a whole file that --resume continues, instead of killing the process
    // and leaving the hidden part file.
    install_interrupt_handlers();
    if (args.interrupt_at_create) std::raise(SIGINT);
    if (args.resume) {
        check_resumable(*stored_run, wanted, args.db);
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
        for (std::int64_t i = shard ? shard->index : 0; i < limit; i += shard ? shard->count : 1)
            if (!done.contains(i)) pending.push_back(i);
    }
    // The samples this process is to hold when it is done: its shard's, or all.
    const std::int64_t share =
        shard ? (limit - shard->index + shard->count - 1) / shard->count : limit;

    // A finished run is left as it is, byte for byte.
    if (args.resume && pending.empty() && stored_run->status == "complete") {
        std::cerr << args.db << ": the run is complete already (" << stored.size()
                  << " samples stored); nothing to run\n";
        report::write_summary(std::cout, report::QueryFormat::text, args.db,
                              db::summarize(results));
        return 0;
    }
    if (!args.quiet) {
        std::cerr << "sweep " << file.scenario.name << ": " << stop_rule
                  << (shard
                          ? ", shard " + shard->text() + " (" + std::to_string(share) + " samples)"
                          : std::string())
                  << ", " << risk::to_string(spec.method) << ", seed " << spec.seed << ", "
                  << threads << " thread" << (threads == 1 ? "" : "s")
                  << (session ? " on rank 0 of " + std::to_string(session->size()) + " MPI ranks"
                              : "")
                  << " -> " << args.db << '\n';
        if (!stored.empty())
            std::cerr << "resuming: " << stored.size() << " samples stored, " << pending.size()
                      << " to run\n";
    }
    Progress progress(std::cerr, progress_mode_for_stderr(args.quiet), share, "samples");
    auto done = static_cast<std::int64_t>(stored.size());
    progress.set_already(done);

    risk::RunnerOptions options;
    options.threads = threads;
    options.trajectory_interval = args.trajectory_interval;
    std::unique_ptr<SampleSource> source;
    if (session) {
        session->send_setup({file.text, file.path.string(), spec.seed, spec.samples,
                             risk::to_string(spec.method), args.trajectory_interval});
        source =
            session->owner_source(spec, as_stored.scenario, pending, options, interrupt_signal);
    } else {
        source = std::make_unique<LocalSource>(spec, as_stored.scenario, pending, options);
    }
    SampleSource& runner = *source;
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
        // --crash-after samples however fast the machine is; so does the pause test.
        const std::size_t batch_limit = args.crash_after >= 0 || args.pause_after >= 0 ? 1 : 256;
        if (batch.size() >= batch_limit ||
            (!batch.empty() && now - last_write > std::chrono::seconds(1))) {
            const std::int64_t before = done;
            results.write_batch(batch);
            done += static_cast<std::int64_t>(batch.size());
            batch.clear();
            last_write = now;
            if (args.crash_after >= 0 && done >= args.crash_after) crash_mid_batch(results);
            // Ranks other than 0 pause in Session::serve.
            if (!session) pause_after_samples(args.pause_after, before, done);
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
                  << "; continue with the same command and --resume, or with just `rockfall "
                     "sweep --db "
                  << args.db << " --resume`\n";
        return exit_interrupted;
    }
    if (monitor && !monitor->stop_at())
        std::cerr << "warning: the target half-width " << until->half_width
                  << " was not reached within " << spec.samples << " samples (it is "
                  << report::fmt("%.4f", monitor->half_width()) << "); raise --samples\n";
    report::write_summary(std::cout, report::QueryFormat::text, args.db, db::summarize(results));
    return 0;
}

int run_sweep(SweepArgs& args) {
    if (!mpi::launched_as_ranks()) return sweep_as_owner(args, nullptr);
    mpi::Session session;
    if (session.rank() != 0) return serve_rank(session, args);
    try {
        return sweep_as_owner(args, &session);
    } catch (const std::exception& error) {
        // The other ranks are running: end them all (what is committed stays for --resume).
        if (session.others_running()) {
            std::cerr << "rockfall (MPI rank 0): " << error.what() << '\n';
            session.abort(exit_failure);
        }
        throw;
    }
}

}  // namespace

void register_sweep(CLI::App& app) {
    auto args = std::make_shared<SweepArgs>();
    CLI::App* cmd = app.add_subcommand(
        "sweep", "Run a Monte Carlo sweep of a scenario into an SQLite results database");
    cmd->add_option("scenario", args->scenario,
                    "Scenario file (TOML) with a [sweep] table; with --resume, default: the "
                    "scenario stored in --db")
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
    cmd->add_option("--shard", args->shard,
                    "Run only shard K of N (sample indices i with i % N == K) into --db, for "
                    "`rockfall merge`; K/N, e.g. 0/4 (docs/cluster.md)");
    cmd->add_flag("--resume", args->resume,
                  "Continue the sweep stored in --db; options left out take the stored values");
    cmd->add_flag("--quiet", args->quiet, "No progress display");
    cmd->add_option("--trajectories", args->trajectory_interval,
                    "Store every rock's trajectory every this many s (0: none)")
        ->check(CLI::Range(0.0, 10.0))
        ->capture_default_str();
    // For the resume tests: crash in the middle of a batch once this many samples are stored.
    cmd->add_option("--crash-after", args->crash_after)->group("");
    // For the signal tests: pause (pause_after_samples) once this many samples are stored (one
    // process) or sent to rank 0 (the other ranks of an MPI sweep).
    cmd->add_option("--pause-after", args->pause_after)->group("");
    // For the interrupt test: SIGINT to itself just before the database is created.
    cmd->add_flag("--interrupt-at-create", args->interrupt_at_create)->group("");
    cmd->callback([args, cmd] {
        for (const CLI::Option* option : cmd->get_options())
            if (option->count() > 0) args->given.insert(option->get_name());
        const int code = run_sweep(*args);
        if (code != 0) throw CLI::RuntimeError(code);
    });
}

}  // namespace rockfall::app
