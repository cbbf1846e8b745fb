// `rockfall soil`: one soil flow (scenario C, MPM), summary or JSON, optional wall-load CSV,
// particle frames for ParaView and a results database.

#include "atomic_file.hpp"
#include "commands.hpp"
#include "query_table.hpp"
#include "soil_report.hpp"
#include "sweep_record.hpp"

#include "app/soil_file.hpp"
#include "db/soil_run.hpp"
#include "mpm/soil.hpp"
#include "mpm/vtk.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
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
            mpm::write_vtk(dir_ / name, frame);
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
    AtomicFile file(path);
    print_csv(file.stream(), soil_history(record));
    file.commit();
}

void run_soil_command(const SoilArgs& args) {
    const SoilFile file = load_soil_scenario(args.scenario);
    // Refuse an existing or unwritable database now rather than after the run.
    if (!args.db.empty()) db::check_new_database(args.db);
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

    if (args.json) {
        nlohmann::json document = soil_json(record);
        document["scenario_file"] = args.scenario;
        if (!args.db.empty()) document["database"] = args.db;
        std::cout << document.dump(2) << '\n';
        return;
    }
    print_soil_summary(std::cout, record, args.scenario);
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
    cmd->callback([args] { run_soil_command(*args); });
}

}  // namespace rockfall::app
