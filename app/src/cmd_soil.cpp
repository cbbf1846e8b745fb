// `rockfall soil`: one soil flow (scenario C, MPM), summary or JSON, optional wall-load CSV,
// particle frames for ParaView and a results database; or, with --refine, a grid-refinement
// study of the scenario with its Richardson extrapolation.

#include "commands.hpp"
#include "output_file.hpp"
#include "report/query_table.hpp"
#include "report/refine_report.hpp"
#include "report/soil_report.hpp"
#include "scenario/load_record.hpp"
#include "scenario/soil_file.hpp"
#include "soil_record.hpp"
#include "sweep_record.hpp"

#include "db/soil_run.hpp"
#include "mpm/refine.hpp"
#include "mpm/soil.hpp"
#include "mpm/vtk.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

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
    std::string refine;
    std::optional<double> steady_window;
    std::optional<int> repeats;
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

// --refine H1,H2,H3[,...]: at least three cell sizes in m, each finite, > 0 and smaller than
// the one before.
std::vector<double> parse_cell_sizes(const std::string& text) {
    const std::string allowed =
        "; allowed: at least 3 cell sizes in m, each > 0 and smaller than the one before, "
        "comma-separated (e.g. --refine 0.2,0.1,0.05)";
    std::vector<double> cells;
    for (std::size_t from = 0; from <= text.size();) {
        const std::size_t comma = std::min(text.find(',', from), text.size());
        const std::string item = text.substr(from, comma - from);
        from = comma + 1;
        char* end = nullptr;
        const double value = std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(value)) {
            throw std::invalid_argument("--refine " + text + ": '" + item + "' is not a number" +
                                        allowed);
        }
        if (!(value > 0.0) || (!cells.empty() && !(value < cells.back()))) {
            std::ostringstream message;
            message << "--refine " << text << ": cell size " << cells.size() + 1 << " = " << value
                    << " m must be " << (value > 0.0 ? "smaller than the one before" : "> 0")
                    << allowed;
            throw std::invalid_argument(message.str());
        }
        cells.push_back(value);
    }
    if (cells.size() < 3) {
        throw std::invalid_argument("--refine " + text + ": " + std::to_string(cells.size()) +
                                    " cell sizes" + allowed);
    }
    return cells;
}

// Options of a single run that a refinement study does not take.
void check_refine_args(const SoilArgs& args) {
    const std::pair<const char*, const std::string*> single_run[] = {{"--vtk", &args.vtk_dir},
                                                                     {"--csv", &args.csv},
                                                                     {"--db", &args.db},
                                                                     {"--measured", &args.measured},
                                                                     {"--svg", &args.svg}};
    for (const auto& [name, value] : single_run) {
        if (!value->empty()) {
            throw std::invalid_argument(std::string(name) +
                                        " does not apply with --refine: a refinement study "
                                        "prints its table (or --json) only");
        }
    }
}

void run_refinement_command(const SoilArgs& args) {
    check_refine_args(args);
    mpm::RefinementSettings settings;
    settings.cell_sizes = parse_cell_sizes(args.refine);
    const scenario::SoilFile file = scenario::load_soil_scenario(args.scenario);
    const double duration = file.scenario.output.duration;
    if (args.steady_window) {
        const double w = *args.steady_window;
        if (!(std::isfinite(w) && w > 0.0 && w <= duration)) {
            std::ostringstream message;
            message << "--steady-window = " << w
                    << " s: must be in (0, output.duration = " << duration << " s] of "
                    << args.scenario;
            throw std::invalid_argument(message.str());
        }
        settings.steady_window = w;
    } else {
        settings.steady_window = std::min(settings.steady_window, duration);
    }
    if (args.repeats) {
        if (*args.repeats < 1 || *args.repeats > mpm::kMaxRepeats) {
            throw std::invalid_argument("--repeats = " + std::to_string(*args.repeats) +
                                        ": must be an integer in [1, " +
                                        std::to_string(mpm::kMaxRepeats) + "]");
        }
        settings.repeats = *args.repeats;
    }
    report::RefinementContext context{
        args.scenario,          file.scenario.numerics.dimension,   duration,
        settings.steady_window, file.scenario.output.filter_window, {}};
    const int count = static_cast<int>(settings.cell_sizes.size());
    std::fprintf(stderr, "refinement study: %d levels of %g s of flow each, %d run(s) per level\n",
                 count, duration, settings.repeats);
    auto start = std::chrono::steady_clock::now();
    const mpm::RefinementStudy study =
        mpm::run_refinement(file.scenario, settings, [&](int i, const mpm::RefinementLevel& level) {
            const auto now = std::chrono::steady_clock::now();
            context.runtime.push_back(std::chrono::duration<double>(now - start).count());
            start = now;
            std::fprintf(stderr, "%s\n",
                         report::refinement_progress_line(level, i, count, context.dimension,
                                                          context.runtime.back())
                             .c_str());
        });
    if (args.json) {
        std::cout << report::refinement_json(study, context).dump(2) << '\n';
    } else {
        report::print_refinement(std::cout, study, context);
    }
}

// The spring-backed wall's facing: how far it moved, against the cell size (the solver keeps
// the wall's geometry in place, which holds for displacements well below a cell).
void print_spring_wall(const mpm::SoilScenario& s, const mpm::SoilOutcome& outcome) {
    const mpm::SoilBoundaries& b = s.boundaries;
    const double h = s.numerics.cell_size;
    std::printf(
        "spring-backed wall (facing %g kg/m2, stiffness %g Pa/m, damping ratio %g): the wall "
        "load is the spring and dashpot force; facing displaced at most %.3f mm (%.2f %% of a "
        "cell), %.3f mm at the end\n",
        b.wall_facing_mass, b.wall_stiffness, b.wall_damping_ratio,
        1e3 * outcome.max_wall_displacement, 100.0 * outcome.max_wall_displacement / h,
        1e3 * outcome.final_wall_displacement);
    if (outcome.max_wall_displacement > 0.1 * h) {
        std::printf(
            "warning: the facing moved more than a tenth of a cell; the wall's geometry stays "
            "in place, so the result is approximate (stiffen the wall or refine the cells "
            "less)\n");
    }
    std::fflush(stdout);
}

void run_soil_command(const SoilArgs& args) {
    if (!args.refine.empty()) {
        run_refinement_command(args);
        return;
    }
    if (args.steady_window) {
        throw std::invalid_argument("--steady-window applies only with --refine");
    }
    if (args.repeats) {
        throw std::invalid_argument("--repeats applies only with --refine");
    }
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

    const bool spring = file.scenario.boundaries.wall_support == mpm::WallSupport::spring;
    if (args.json) {
        nlohmann::json document = report::soil_json(record);
        document["scenario_file"] = args.scenario;
        document["wall_support"] = spring ? "spring" : "rigid";
        if (spring) {
            document["max_wall_displacement_m"] = outcome.max_wall_displacement;
            document["final_wall_displacement_m"] = outcome.final_wall_displacement;
        }
        if (!args.db.empty()) document["database"] = args.db;
        if (comparison)
            document["measured_comparison"] =
                report::measured_comparison_json(*comparison, *measured);
        std::cout << document.dump(2) << '\n';
    } else {
        report::print_soil_summary(std::cout, record, args.scenario);
        if (spring) print_spring_wall(file.scenario, outcome);
        if (comparison)
            report::print_measured_comparison(std::cout, *comparison, *measured, record);
        if (!args.svg.empty()) std::cout << "wall-load figure written to " << args.svg << '\n';
        if (frames)
            std::cout << frames->count() << " VTK frames written to " << args.vtk_dir << '\n';
        if (!args.csv.empty()) std::cout << "wall-load history written to " << args.csv << '\n';
        if (!args.db.empty()) std::cout << "run and histories stored in " << args.db << '\n';
    }
    // A numerical failure is a failed run, whatever was written of it (exit 1): a script must
    // not take its wall load for a result.
    if (outcome.status == mpm::SoilStatus::non_finite) {
        std::cout.flush();
        std::cerr << "rockfall: the soil run failed: " << outcome.message
                  << " (status non_finite; what was computed until then is in the outputs)\n";
        throw CLI::RuntimeError(exit_failure);
    }
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
    cmd->add_option("--refine", args->refine,
                    "Run a grid-refinement study instead: the scenario at these cell sizes (m, "
                    "at least 3, coarse to fine, comma-separated, e.g. 0.2,0.1,0.05), the table "
                    "of peak and steady wall load and runout, and the Richardson extrapolation");
    cmd->add_option("--steady-window", args->steady_window,
                    "With --refine: the steady wall load is the mean over this last part of the "
                    "run, s (default 1 s, at most output.duration)");
    cmd->add_option("--repeats", args->repeats,
                    "With --refine: run each level this many times (1 to 20, default 1), run k "
                    "with numerics.cfl times (1 - k 1e-4), and report the means and how far the "
                    "runs spread: a flow that amplifies small perturbations shows it");
    cmd->callback([args] { run_soil_command(*args); });
}

}  // namespace rockfall::app
