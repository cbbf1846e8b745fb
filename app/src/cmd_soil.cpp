// `rockfall soil`: one soil flow (scenario C, MPM), summary or JSON, optional wall-load CSV,
// particle frames for ParaView and a results database.

#include "commands.hpp"
#include "output_file.hpp"
#include "report/query_table.hpp"
#include "report/soil_report.hpp"
#include "scenario/load_record.hpp"
#include "scenario/soil_file.hpp"
#include "soil_record.hpp"
#include "sweep_record.hpp"

#include "db/soil_run.hpp"
#include "mpm/soil.hpp"
#include "mpm/vtk.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace rockfall::app {
namespace {

namespace fs = std::filesystem;

struct SoilArgs {
    std::string scenario;
    bool json = false;
    std::string vtk_dir;
    std::string csv;
    std::string db;
    std::string measured;
    std::string svg;
};

// Writes particle frames as DIR/frame_NNNNN.vtk. The solver's callback must not throw, so the
// first write error is kept and rethrown after the run.
class VtkFrames {
  public:
    explicit VtkFrames(fs::path dir) : dir_(std::move(dir)) {
        std::error_code error;
        fs::create_directories(dir_, error);
        if (error || !fs::is_directory(dir_)) {
            throw std::runtime_error("cannot create the VTK directory '" + dir_.string() +
                                     "': " + (error ? error.message() : "not a directory"));
        }
    }
    void write(const mpm::ParticleFrame& frame) {
        if (!error_.empty()) return;
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.vtk", count_);
        try {
            write_output_file(dir_ / name,
                              [&frame](const fs::path& file) { mpm::write_vtk(file, frame); });
            ++count_;
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }
    void finish() const {
        if (!error_.empty()) throw std::runtime_error(error_);
    }
    int count() const { return count_; }

  private:
    fs::path dir_;
    int count_ = 0;
    std::string error_;
};

// Writes the sampled history (committed only when complete).
void write_csv(const fs::path& path, const db::SoilRunRecord& record) {
    OutputFile file(path);
    report::print_csv(file.stream(), report::soil_history(record));
    file.commit();
}

void run_soil_command(const SoilArgs& args) {
    const scenario::SoilFile file = scenario::load_soil_scenario(args.scenario);
    // Read the measured record and refuse a mismatch (units, or no shared times) now rather
    // than after the run.
    std::optional<risk::LoadHistory> measured;
    if (!args.measured.empty()) {
        measured = scenario::read_measured_history(args.measured);
        const mpm::SoilOutput& output = file.scenario.output;
        // The sampled history runs from one interval to the last whole interval.
        const double last =
            std::floor(output.duration / output.sample_interval + 1e-9) * output.sample_interval;
        risk::check_comparable(file.scenario.numerics.dimension == 2, output.sample_interval, last,
                               *measured);
    }
    // Refuse an existing or unwritable database and output paths that may not be written now
    // rather than after the run.
    if (!args.db.empty()) db::check_new_database(args.db);
    for (const std::string& output : {args.csv, args.svg})
        if (!output.empty()) output_target(output);
    std::unique_ptr<VtkFrames> frames;
    if (!args.vtk_dir.empty()) frames = std::make_unique<VtkFrames>(args.vtk_dir);
    const bool progress = isatty(STDERR_FILENO) != 0;
    const double duration = file.scenario.output.duration;
    const mpm::FrameCallback on_frame = [&](const mpm::ParticleFrame& frame) {
        if (frames) frames->write(frame);
        if (progress) std::fprintf(stderr, "\rsoil flow: t = %.2f / %.2f s", frame.time, duration);
    };

    SoilRunTimes times;
    times.started_at = utc_now();
    const auto start = std::chrono::steady_clock::now();
    const mpm::SoilOutcome outcome = mpm::run_soil(file.scenario, on_frame);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    times.runtime = elapsed.count();
    times.finished_at = utc_now();
    if (progress) std::fprintf(stderr, "\r%40s\r", "");
    if (frames) frames->finish();
    const db::SoilRunRecord record = make_soil_record(file, outcome, times);
    if (!args.csv.empty()) write_csv(args.csv, record);
    if (!args.db.empty()) db::write_soil_run(args.db, record);
    const risk::LoadHistory filtered = report::sampled_load(record, true);
    std::optional<risk::HistoryComparison> comparison;
    if (measured) comparison = risk::compare_histories(filtered, *measured);
    if (!args.svg.empty()) {
        write_svg(args.svg,
                  report::soil_load_figure(record, fs::path(args.scenario).stem().string(),
                                           measured ? &*measured : nullptr));
    }

    if (args.json) {
        nlohmann::json document = report::soil_json(record);
        document["scenario_file"] = args.scenario;
        if (!args.db.empty()) document["database"] = args.db;
        if (comparison)
            document["measured_comparison"] =
                report::measured_comparison_json(*comparison, *measured);
        std::cout << document.dump(2) << '\n';
        return;
    }
    report::print_soil_summary(std::cout, record, args.scenario);
    if (comparison) report::print_measured_comparison(std::cout, *comparison, *measured, record);
    if (!args.svg.empty()) std::cout << "wall-load figure written to " << args.svg << '\n';
    if (frames) std::cout << frames->count() << " VTK frames written to " << args.vtk_dir << '\n';
    if (!args.csv.empty()) std::cout << "wall-load history written to " << args.csv << '\n';
    if (!args.db.empty()) std::cout << "run and histories stored in " << args.db << '\n';
}

}  // namespace

void register_soil(CLI::App& app) {
    auto args = std::make_shared<SoilArgs>();
    CLI::App* cmd = app.add_subcommand(
        "soil", "Run a soil flow (MPM) and print the wall load history, runout and deposit");
    cmd->add_option("scenario", args->scenario, "Soil scenario file (TOML)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->add_option("--vtk", args->vtk_dir,
                    "Write particle frames (legacy VTK) to this directory at the scenario's "
                    "output.frame_interval");
    cmd->add_option("--csv", args->csv,
                    "Write the sampled wall-load, centre-of-mass and front history to this CSV "
                    "file");
    cmd->add_option("--db", args->db,
                    "Store the run, its wall-load, motion and deposit histories in this new "
                    "results database (never overwritten; read it with `rockfall query`)");
    cmd->add_option("--measured", args->measured,
                    "Compare the wall load with a measured history: CSV with time_s and one of "
                    "load_kN, load_N (3D) or load_kN_per_m, load_N_per_m (2D)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--svg", args->svg,
                    "Write a figure of the wall-load history (with the measured one if given) "
                    "to this SVG file");
    cmd->callback([args] { run_soil_command(*args); });
}

}  // namespace rockfall::app
