// `rockfall simulate`: one release of a scenario, summary or JSON, optional trajectory CSV.

#include "atomic_file.hpp"
#include "commands.hpp"
#include "report.hpp"

#include "app/scenario_file.hpp"
#include "engine/simulation.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
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
};

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
    AtomicFile file_;
};

void run_simulate(const SimulateArgs& args) {
    const ScenarioFile file = load_scenario(args.scenario);
    engine::RunOptions options;
    std::unique_ptr<TrajectoryCsv> csv;
    if (!args.trajectory.empty()) {
        csv = std::make_unique<TrajectoryCsv>(args.trajectory);
        options.trajectory = [&csv](int rock, const engine::RockState& s) { csv->add(rock, s); };
        options.trajectory_interval = args.trajectory_interval;
    }
    const auto start = std::chrono::steady_clock::now();
    const engine::Outcome outcome = engine::simulate(file.scenario, args.seed, options);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (csv) csv->commit();

    const RunInfo info{args.scenario, args.seed, elapsed.count()};
    if (args.json) {
        std::cout << outcome_json(file.scenario, outcome, info).dump(2) << '\n';
    } else {
        print_summary(std::cout, file.scenario, outcome, info);
        if (!args.trajectory.empty())
            std::cout << "trajectory written to " << args.trajectory << '\n';
    }
}

}  // namespace

void register_simulate(CLI::App& app) {
    auto args = std::make_shared<SimulateArgs>();
    CLI::App* cmd = app.add_subcommand(
        "simulate", "Run one release of a scenario and print reach, stations and wall hits");
    cmd->add_option("scenario", args->scenario, "Scenario file (TOML)")
        ->required()
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
    cmd->callback([args] { run_simulate(*args); });
}

}  // namespace rockfall::app
