// `rockfall calibrate`: the command, and `calibrate drop`: seed 001's drop test run virtually over
// many orientations, the coefficients of restitution of the first bounce, and the surface
// restitution that reproduces a measured mean kinematic COR (docs/calibration.md).

#include "calibrate_common.hpp"
#include "calibrate_drop.hpp"
#include "calibrate_heap.hpp"
#include "calibration_record.hpp"
#include "commands.hpp"
#include "integer_option.hpp"
#include "output_file.hpp"
#include "scenario/scenario_file.hpp"
#include "scenario/shape_source.hpp"
#include "sweep_record.hpp"
#include "threads.hpp"

#include "risk/drop_test.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace rockfall::app {
namespace {

struct DropArgs {
    scenario::ShapeRequest request;
    std::optional<std::string> scenario;
    double density = 2600.0;
    double height = 1.0;
    std::int64_t count = 40;
    std::uint64_t seed = 1;
    int threads = 0;
    engine::Material surface;
    double time_step = 1e-3;
    std::optional<double> target_cor;
    std::string cor_from = "height";
    int curve_points = 11;
    CalibrationFiles files;
};

void check_args(const DropArgs& args) {
    if (!(std::isfinite(args.height) && args.height > 0.0)) {
        std::ostringstream message;
        message << "--height = " << args.height << " m: must be finite and > 0";
        throw std::invalid_argument(message.str());
    }
    require_in("--friction", args.surface.friction, "", 0.0, 2.0);
    require_in("--restitution", args.surface.restitution, "", 0.0, 1.0);
    require_in("--rolling-resistance", args.surface.rolling_resistance, "", 0.0, 1.0);
    require_in("--time-step", args.time_step, "s", 1e-5, 1e-2);
    require_in("--density", args.density, "kg/m3", 500.0, 10000.0);
    if (args.request.size) require_in("--size", *args.request.size, "m", 0.01, 10.0);
    if (args.target_cor) {
        const double t = *args.target_cor;
        if (!(std::isfinite(t) && t > 0.0 && t < 1.0)) {
            std::ostringstream message;
            message << "--target-cor = " << t << ": must be in (0, 1)";
            throw std::invalid_argument(message.str());
        }
    }
    if (!args.target_cor && (args.files.svg || args.files.fragment)) {
        throw std::invalid_argument(
            "--svg and --fragment show an identification: give --target-cor");
    }
}

void run(const DropArgs& args, const CLI::App& cmd) {
    check_args(args);
    check_calibration_files(args.files);
    CalibrationRun record_run;
    record_run.started_at = utc_now();
    const std::vector<CalibrationRock> rocks = calibration_rocks(
        args.request, args.scenario, args.density, "calibrate drop", &record_run.scenario_text);
    if (args.files.fragment && rocks.size() != 1) {
        throw std::invalid_argument(
            "--fragment holds one shape's material: " + std::to_string(rocks.size()) +
            " rocks given (pick one with --entry NAME)");
    }
    DropReport report;
    report.definition =
        args.cor_from == "speed" ? risk::CorDefinition::speed : risk::CorDefinition::height;
    report.threads = thread_count(args.threads);
    risk::RestitutionSearchOptions options;
    options.definition = report.definition;
    options.curve_points = args.curve_points;
    options.threads = report.threads;

    CalibrationProgress progress(
        args.files, args.count, args.target_cor ? options.curve_points + options.max_iterations : 0,
        rocks.size(), "drops");
    const risk::BatchProgress show = progress.callback();
    const auto start = std::chrono::steady_clock::now();
    for (const CalibrationRock& rock : rocks) {
        DropShapeRun run;
        run.label = rock.label;
        run.spec.rock = rock.spec;
        run.spec.surface = args.surface;
        run.spec.height = args.height;
        run.spec.count = args.count;
        run.spec.seed = args.seed;
        run.spec.time_step = args.time_step;
        run.sphericity = rock.spec.geometry().sphericity;
        run.result = risk::run_drop_test(run.spec, report.threads, show);
        progress.tested();
        if (args.target_cor) {
            run.identification =
                risk::identify_surface_restitution(run.spec, *args.target_cor, options, show);
            progress.identified();
        }
        report.shapes.push_back(std::move(run));
    }
    progress.finish();
    report.runtime =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    record_run.finished_at = utc_now();
    record_run.settings = option_settings(cmd);
    write_calibration_files(
        args.files, [&](std::ostream& out) { write_drop_csv(out, report); },
        [&] { return drop_figure(report); },
        [&] { return drop_fragment(report.shapes.front(), report.definition); },
        [&] { return drop_record(report, record_run); });
    if (args.files.json) {
        std::cout << drop_json(report).dump(2) << '\n';
        return;
    }
    print_drop_text(std::cout, report);
    print_calibration_files(std::cout, args.files, "drops");
}

void register_drop(CLI::App& calibrate) {
    auto args = std::make_shared<DropArgs>();
    CLI::App* cmd = calibrate.add_subcommand(
        "drop",
        "Drop test (seed 001): a rock dropped in many random orientations onto a surface; the "
        "kinematic, kinetic and energetic coefficients of restitution of its first bounce; with "
        "--target-cor the surface restitution that reproduces a measured mean COR");
    add_shape_options(*cmd, args->request,
                      "Mesh file, or a catalogue (every entry is dropped unless --entry)");
    cmd->add_option("--size", args->request.size,
                    "Volume-equivalent diameter (m), in [0.01, 10]; default 0.2, a mesh or "
                    "catalogue entry keeps its own");
    cmd->add_option("--scenario", args->scenario,
                    "Scenario file: every [[rocks]] entry (shape, size, density, material) is "
                    "dropped");
    cmd->add_option("--density", args->density, "Rock density (kg/m3), in [500, 10000]")
        ->capture_default_str();
    cmd->add_option("--height", args->height,
                    "Drop height (m) of the rock's lowest point above the surface, > 0")
        ->capture_default_str();
    cmd->add_option("--count", args->count, "Drops (random orientations), >= 1")
        ->capture_default_str()
        ->transform(integer_in(1, 10000000, "a drop count"));
    cmd->add_option("--seed", args->seed, "Base seed of the orientations")->capture_default_str();
    cmd->add_option("--threads", args->threads, "Worker threads; 0 = all cores")
        ->capture_default_str()
        ->transform(integer_in(0, 1024, "a thread count"));
    cmd->add_option("--friction", args->surface.friction, "Surface friction, in [0, 2]")
        ->capture_default_str();
    cmd->add_option("--restitution", args->surface.restitution,
                    "Surface restitution, in [0, 1] (the contact uses the mean with the rock's)")
        ->capture_default_str();
    cmd->add_option("--rolling-resistance", args->surface.rolling_resistance,
                    "Surface rolling resistance, in [0, 1]")
        ->capture_default_str();
    cmd->add_option("--time-step", args->time_step, "Time step (s), in [1e-5, 1e-2]")
        ->capture_default_str();
    cmd->add_option("--target-cor", args->target_cor,
                    "Measured mean kinematic COR, in (0, 1): identify the surface restitution "
                    "that reproduces it, with the curve COR against restitution");
    cmd->add_option("--cor-from", args->cor_from,
                    "Which kinematic COR the target is: height (sqrt(H_r/H_i), as measured) or "
                    "speed (v_out/v_in)")
        ->capture_default_str()
        ->check(CLI::IsMember({"height", "speed"}));
    cmd->add_option("--curve-points", args->curve_points,
                    "Points of the curve over surface restitution [0, 1], >= 2")
        ->capture_default_str()
        ->transform(integer_in(2, 101, "a number of curve points"));
    add_calibration_file_options(
        *cmd, args->files,
        {"Write the curve (the paper's Fig. 11) as SVG", "Write every drop's measurements as CSV",
         "Write the identified [materials.slope] as a scenario fragment (TOML) for extends"});
    cmd->callback([args, cmd] { run(*args, *cmd); });
}

}  // namespace

void register_calibrate(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "calibrate",
        "Virtual calibration experiments (seed 001) and identification of contact "
        "parameters from measured results");
    cmd->require_subcommand(1);
    register_drop(*cmd);
    register_heap(*cmd);
}

}  // namespace rockfall::app
