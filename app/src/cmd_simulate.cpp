// `rockfall simulate`: one release of a scenario, summary or JSON, optional trajectory CSV.

#include "commands.hpp"
#include "output_file.hpp"
#include "report/simulation_report.hpp"
#include "scenario/scenario_file.hpp"

#include "db/results_db.hpp"
#include "engine/simulation.hpp"
#include "risk/sampling.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

namespace rockfall::app {
namespace {

struct SimulateArgs {
    std::string scenario;
    std::uint64_t seed = 1;
    bool json = false;
    std::string trajectory;
    double trajectory_interval = 0.01;
    std::string from;
    std::int64_t sample = -1;
};

/// What to run: a scenario file, or one sample of a sweep database.
struct Job {
    engine::Scenario scenario;
    std::uint64_t seed = 0;
    std::string source;
    /// The outcomes the database stored for the sample's rocks, to confirm the replay.
    std::optional<std::vector<engine::RockOutcome>> stored;
};

Job job_from_database(const SimulateArgs& args) {
    if (args.sample < 0)
        throw std::invalid_argument("--from " + args.from + " needs --sample INDEX (0-based)");
    const db::ResultsDb results = db::ResultsDb::open(args.from, false);
    std::optional<db::SampleRecord> record = results.sample(args.sample);
    if (!record)
        throw std::invalid_argument(args.from + ": --sample " + std::to_string(args.sample) +
                                    ": no such sample (see rockfall query " + args.from +
                                    " summary)");
    // The stored [sweep] table holds the named shapes a sample may have drawn.
    const scenario::ScenarioFile stored = scenario::parse_scenario_file(
        results.run().scenario_text, args.from + " (stored scenario)");
    std::vector<engine::RockOutcome> rocks;
    for (risk::RockResult& rock : record->rocks) rocks.push_back(std::move(rock.outcome));
    Job job{risk::sample_scenario(stored.sweep, stored.scenario, record->inputs),
            record->inputs.seed, args.from + " sample " + std::to_string(args.sample),
            std::move(rocks)};
    return job;
}

// Every rock's reach, stop time and wall hits as stored (a cluster release: all its rocks).
bool same_as_stored(const std::vector<engine::RockOutcome>& stored,
                    const engine::Outcome& outcome) {
    if (stored.size() != outcome.rocks.size()) return false;
    for (std::size_t i = 0; i < stored.size(); ++i) {
        const engine::RockOutcome& a = stored[i];
        const engine::RockOutcome& b = outcome.rocks[i];
        if (a.reach != b.reach || a.stop_time != b.stop_time ||
            a.wall_hits.size() != b.wall_hits.size())
            return false;
    }
    return true;
}

Job job_from_arguments(const SimulateArgs& args) {
    if (!args.from.empty() && !args.scenario.empty())
        throw std::invalid_argument("give either a SCENARIO file or --from DB, not both");
    if (!args.from.empty()) return job_from_database(args);
    if (args.scenario.empty())
        throw std::invalid_argument("simulate needs a SCENARIO file or --from DB --sample INDEX");
    if (args.sample >= 0) throw std::invalid_argument("--sample needs --from DB");
    return {scenario::load_scenario(args.scenario).scenario, args.seed, args.scenario,
            std::nullopt};
}

/// Trajectory rows as CSV, committed only when the run completed.
class TrajectoryCsv {
  public:
    explicit TrajectoryCsv(std::filesystem::path path) : file_(std::move(path)) {
        file_.stream() << "rock,time_s,x_m,y_m,z_m,qw,qx,qy,qz,vx_m_s,vy_m_s,vz_m_s,wx_rad_s,"
                          "wy_rad_s,wz_rad_s,translational_energy_J,rotational_energy_J\n"
                       << std::setprecision(9);
    }
    void add(int rock, const engine::RockState& s) {
        const auto& q = s.orientation;
        file_.stream() << rock + 1 << ',' << s.time << ',' << s.position.x() << ','
                       << s.position.y() << ',' << s.position.z() << ',' << q.w() << ',' << q.x()
                       << ',' << q.y() << ',' << q.z() << ',' << s.velocity.x() << ','
                       << s.velocity.y() << ',' << s.velocity.z() << ',' << s.angular_velocity.x()
                       << ',' << s.angular_velocity.y() << ',' << s.angular_velocity.z() << ','
                       << s.translational_energy << ',' << s.rotational_energy << '\n';
    }
    void commit() { file_.commit(); }

  private:
    OutputFile file_;
};

void run_simulate(const SimulateArgs& args) {
    const Job job = job_from_arguments(args);
    engine::RunOptions options;
    std::unique_ptr<TrajectoryCsv> csv;
    if (!args.trajectory.empty()) {
        csv = std::make_unique<TrajectoryCsv>(args.trajectory);
        options.trajectory = [&csv](int rock, const engine::RockState& s) { csv->add(rock, s); };
        options.trajectory_interval = args.trajectory_interval;
    }
    const auto start = std::chrono::steady_clock::now();
    const engine::Outcome outcome = engine::simulate(job.scenario, job.seed, options);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (csv) csv->commit();

    const report::RunInfo info{job.source, job.seed, elapsed.count()};
    // A replay must reproduce the stored outcome bit for bit (same binary); say so either way.
    const bool replay_matches = !job.stored || same_as_stored(*job.stored, outcome);
    if (args.json) {
        nlohmann::json json = report::outcome_json(job.scenario, outcome, info);
        if (job.stored) json["replay_matches_database"] = replay_matches;
        std::cout << json.dump(2) << '\n';
    } else {
        report::print_summary(std::cout, job.scenario, outcome, info);
        if (job.stored)
            std::cout << (replay_matches
                              ? "replay matches the database's stored outcome\n"
                              : "replay differs from the stored outcome (another build or "
                                "platform made the database)\n");
        if (!args.trajectory.empty())
            std::cout << "trajectory written to " << args.trajectory << '\n';
    }
}

}  // namespace

void register_simulate(CLI::App& app) {
    auto args = std::make_shared<SimulateArgs>();
    CLI::App* cmd = app.add_subcommand(
        "simulate", "Run one release of a scenario and print reach, stations and wall hits");
    cmd->add_option("scenario", args->scenario, "Scenario file (TOML); not with --from")
        ->check(CLI::ExistingFile);
    cmd->add_option("--seed", args->seed,
                    "Seed for random orientations and shapes (same seed, same result)")
        ->capture_default_str();
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->add_option("--trajectory", args->trajectory,
                    "Write the trajectory of every rock to this CSV file");
    cmd->add_option("--trajectory-interval", args->trajectory_interval,
                    "Time between trajectory rows, s")
        ->check(CLI::Range(1e-5, 10.0))
        ->capture_default_str();
    cmd->add_option("--from", args->from, "Replay one sample of a sweep: its results database ...")
        ->check(CLI::ExistingFile);
    cmd->add_option("--sample", args->sample, "... and the sample's index (0-based)")
        ->check(CLI::NonNegativeNumber);
    cmd->callback([args] { run_simulate(*args); });
}

}  // namespace rockfall::app
