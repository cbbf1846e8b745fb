// `rockfall simulate`: one release of a scenario, summary or JSON, optional trajectory CSV,
// ParaView series and SVG figures.

#include "commands.hpp"
#include "integer_option.hpp"
#include "output_file.hpp"
#include "report/run_figures.hpp"
#include "report/simulation_report.hpp"
#include "report/vtk_output.hpp"
#include "scenario/scenario_file.hpp"
#include "threads.hpp"

#include "db/results_db.hpp"
#include "engine/simulation.hpp"
#include "risk/sampling.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::app {
namespace {

namespace fs = std::filesystem;

struct SimulateArgs {
    std::string scenario;
    std::uint64_t seed = 1;
    bool json = false;
    std::string trajectory;
    double trajectory_interval = 0.01;
    std::string from;
    std::int64_t sample = -1;
    std::vector<std::size_t> rocks;
    bool all_rocks = false;
    std::string vtk_dir;
    double vtk_interval = 0.02;
    std::string figures_dir;
    double camera_interval = report::default_camera_interval;
    int threads = 0;
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

/// Trajectory rows as CSV, committed only when the run completed. When the engine samples more
/// often than `interval` (a finer --vtk-interval), a rock's row is kept at the first sample at
/// or after each multiple of the interval, as the engine samples.
class TrajectoryCsv {
  public:
    TrajectoryCsv(std::filesystem::path path, double interval, bool thin)
        : file_(std::move(path)), interval_(interval), thin_(thin) {
        file_.stream() << "rock,time_s,x_m,y_m,z_m,qw,qx,qy,qz,vx_m_s,vy_m_s,vz_m_s,wx_rad_s,"
                          "wy_rad_s,wz_rad_s,translational_energy_J,rotational_energy_J\n"
                       << std::setprecision(9);
    }
    void add(int rock, const engine::RockState& s) {
        if (thin_) {
            const auto index = static_cast<std::size_t>(rock);
            if (next_.size() <= index) next_.resize(index + 1, 0);
            if (s.time < static_cast<double>(next_[index]) * interval_) return;
            next_[index] = static_cast<long>(std::floor(s.time / interval_)) + 1;
        }
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
    double interval_;
    bool thin_;
    std::vector<long> next_;
};

/// Creates the directory of `option` with its parents; throws naming the option and the path
/// when it cannot (a file there, no permission).
void create_output_directory(const char* option, const fs::path& dir) {
    std::error_code error;
    fs::create_directories(dir, error);
    if (error || !fs::is_directory(dir)) {
        throw std::invalid_argument(std::string(option) + " " + dir.string() +
                                    ": cannot create the directory (" +
                                    (error ? error.message() : "not a directory") + ")");
    }
}

/// The ParaView series of a run in a directory: static.vtp (the static geometry),
/// rocks_NNNNN.vtp (the rocks at each frame) and rocks.pvd (the frames with their times),
/// each written by the output-file rule after the run, the .pvd last.
class VtkSeries {
  public:
    VtkSeries(fs::path dir, double interval) : dir_(std::move(dir)), frames_(interval) {
        create_output_directory("--vtk", dir_);
        // A path in it that may not be written (a directory named rocks.pvd) is refused now.
        output_target(dir_ / "rocks.pvd");
        output_target(dir_ / "static.vtp");
    }
    void add(int rock, const engine::RockState& s) { frames_.add(rock, s); }
    void set_geometry(const engine::RunGeometry& geometry) { geometry_ = geometry; }
    /// Writes every file; returns the number of frames.
    std::size_t write(const engine::Scenario& scenario) const {
        OutputFile scene(dir_ / "static.vtp");
        report::write_vtp(scene.stream(), report::static_surface(scenario, geometry_.solids),
                          std::nan(""));
        scene.commit();
        std::vector<report::PvdEntry> entries;
        const std::vector<report::RockFrame> frames = frames_.frames();
        for (std::size_t k = 0; k < frames.size(); ++k) {
            char name[32];
            std::snprintf(name, sizeof name, "rocks_%05zu.vtp", k);
            OutputFile file(dir_ / name);
            report::write_vtp(file.stream(), report::rocks_surface(geometry_.rocks, frames[k]),
                              frames[k].time);
            file.commit();
            entries.push_back({frames[k].time, name});
        }
        OutputFile pvd(dir_ / "rocks.pvd");
        report::write_pvd(pvd.stream(), entries);
        pvd.commit();
        return frames.size();
    }

  private:
    fs::path dir_;
    report::FrameRecorder frames_;
    engine::RunGeometry geometry_;
};

/// The figures directory of --figures: created (with its parents) and its files' paths checked
/// before the run, the figures the run has data for written after it.
class FigureDir {
  public:
    explicit FigureDir(fs::path dir) : dir_(std::move(dir)) {
        create_output_directory("--figures", dir_);
        for (const char* name :
             {"pressure_peak.svg", "pressure_at_peak.svg", "wall_force.svg", "marked_speeds.svg"}) {
            output_target(dir_ / name);
        }
    }
    /// Writes every figure; returns them (file names and descriptions).
    std::vector<report::Figure> write(const engine::Scenario& scenario,
                                      const engine::Outcome& outcome,
                                      const report::RunSeries& series) const {
        std::vector<report::Figure> figures = report::run_figures(scenario, outcome, series);
        for (const report::Figure& figure : figures) {
            OutputFile file(dir_ / figure.file);
            file.stream() << figure.svg;
            file.commit();
        }
        return figures;
    }
    const fs::path& path() const { return dir_; }

  private:
    fs::path dir_;
};

void print_figures(const FigureDir& dir, const std::vector<report::Figure>& figures) {
    if (figures.empty()) {
        std::cout << "no figures written to " << dir.path().string()
                  << ": the run has no wall hit, no named (marked) rock and no loaded "
                     "[wall_cells]\n";
        return;
    }
    std::cout << figures.size() << (figures.size() == 1 ? " figure" : " figures") << " written to "
              << dir.path().string() << ":\n";
    for (const report::Figure& f : figures) {
        std::cout << "  " << f.file << ": " << f.description << '\n';
    }
}

// The rocks a scenario will have, when known before the run (a cluster given by volume draws
// its count); 0 when not.
std::size_t known_rock_count(const engine::Scenario& scenario) {
    if (!scenario.cluster) return scenario.rocks.size();
    if (scenario.cluster->grading.count <= 0) return 0;
    return scenario.rocks.size() + static_cast<std::size_t>(scenario.cluster->grading.count);
}

// --rock N (1-based) as 0-based indices; throws naming the number when there is no such rock.
std::vector<std::size_t> rock_indices(const std::vector<std::size_t>& numbers, std::size_t count) {
    std::vector<std::size_t> indices;
    for (const std::size_t n : numbers) {
        if (n < 1 || n > count)
            throw std::invalid_argument("--rock " + std::to_string(n) +
                                        ": the run has rocks 1 to " + std::to_string(count));
        indices.push_back(n - 1);
    }
    return indices;
}

void run_simulate(const SimulateArgs& args) {
    const Job job = job_from_arguments(args);
    if (const std::size_t count = known_rock_count(job.scenario); count > 0)
        rock_indices(args.rocks, count);
    engine::RunOptions options;
    // The engine samples at the finer of the two intervals; each consumer keeps its own.
    options.trajectory_interval = args.trajectory_interval;
    if (!args.vtk_dir.empty())
        options.trajectory_interval = std::min(args.trajectory_interval, args.vtk_interval);
    // Camera frames fall on samples (marked rocks' speeds between frames).
    options.trajectory_interval = std::min(options.trajectory_interval, args.camera_interval);
    std::unique_ptr<FigureDir> figure_dir;
    if (!args.figures_dir.empty()) figure_dir = std::make_unique<FigureDir>(args.figures_dir);
    std::unique_ptr<VtkSeries> vtk;
    if (!args.vtk_dir.empty()) {
        vtk = std::make_unique<VtkSeries>(args.vtk_dir, args.vtk_interval);
        options.geometry = [&vtk](const engine::RunGeometry& g) { vtk->set_geometry(g); };
    }
    std::unique_ptr<TrajectoryCsv> csv;
    if (!args.trajectory.empty()) {
        csv =
            std::make_unique<TrajectoryCsv>(args.trajectory, args.trajectory_interval,
                                            options.trajectory_interval < args.trajectory_interval);
    }
    report::SeriesRecorder series;
    options.trajectory = [&](int rock, const engine::RockState& s) {
        series.add(rock, s);
        if (csv) csv->add(rock, s);
        if (vtk) vtk->add(rock, s);
    };
    options.collision_threads = thread_count(args.threads);
    const auto start = std::chrono::steady_clock::now();
    const engine::Outcome outcome = engine::simulate(job.scenario, job.seed, options);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (csv) csv->commit();
    const std::size_t vtk_frames = vtk ? vtk->write(job.scenario) : 0;

    report::RockDetail detail{args.all_rocks, rock_indices(args.rocks, outcome.rocks.size())};
    report::RunSeries run_series{series.series(), {}, args.camera_interval};
    if (outcome.rocks.size() > 1)
        run_series.front = report::cluster_front(job.scenario, run_series.rocks, outcome);
    const report::RunInfo info{job.source, job.seed, elapsed.count()};
    // A replay must reproduce the stored outcome bit for bit (same binary); say so either way.
    const bool replay_matches = !job.stored || same_as_stored(*job.stored, outcome);
    const std::vector<report::Figure> figures =
        figure_dir ? figure_dir->write(job.scenario, outcome, run_series)
                   : std::vector<report::Figure>{};
    if (args.json) {
        nlohmann::json json = report::outcome_json(job.scenario, outcome, info, run_series);
        if (job.stored) json["replay_matches_database"] = replay_matches;
        if (figure_dir) {
            nlohmann::json files = nlohmann::json::array();
            for (const report::Figure& f : figures) {
                files.push_back((figure_dir->path() / f.file).string());
            }
            json["figures_written"] = files;
        }
        std::cout << json.dump(2) << '\n';
    } else {
        report::print_summary(std::cout, job.scenario, outcome, info, run_series, detail);
        if (job.stored)
            std::cout << (replay_matches
                              ? "replay matches the database's stored outcome\n"
                              : "replay differs from the stored outcome (another build or "
                                "platform made the database)\n");
        if (!args.trajectory.empty())
            std::cout << "trajectory written to " << args.trajectory << '\n';
        if (vtk)
            std::cout << vtk_frames << " VTK frames written to " << args.vtk_dir
                      << " (open rocks.pvd and static.vtp in ParaView)\n";
        if (figure_dir) print_figures(*figure_dir, figures);
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
    cmd->add_option("--rock", args->rocks,
                    "Print rock N (1-based, as in the rock table) in full; repeat for more. The "
                    "scenario's own [[rocks]] and named (marked) rocks are always in full")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--all-rocks", args->all_rocks, "Print every rock in full");
    cmd->add_option("--vtk", args->vtk_dir,
                    "Write a ParaView series to this directory: rocks.pvd (the rocks' hulls at "
                    "each frame) and static.vtp (slope, walls, lining)");
    cmd->add_option("--vtk-interval", args->vtk_interval, "Time between VTK frames, s")
        ->check(CLI::Range(1e-4, 10.0))
        ->capture_default_str();
    cmd->add_option("--figures", args->figures_dir,
                    "Write SVG figures to this directory (created): pressure_peak.svg and "
                    "pressure_at_peak.svg (with [wall_cells]), wall_force.svg (with wall hits), "
                    "marked_speeds.svg (with named rocks)");
    cmd->add_option("--camera-interval", args->camera_interval,
                    "Frame interval of the camera that tracks the named (marked) rocks, s "
                    "(seed 001: 0.04)")
        ->check(CLI::Range(1e-4, 1.0))
        ->capture_default_str();
    cmd->add_option("--threads", args->threads,
                    "Threads for the collision detection of each step; 0 = all cores. Same "
                    "result whatever the count; a cluster of many rocks runs faster")
        ->capture_default_str()
        ->transform(integer_in(0, 1024, "a thread count"));
    cmd->callback([args] { run_simulate(*args); });
}

}  // namespace rockfall::app
