// `rockfall calibrate heap`: seed 001's funnel test run virtually, the angle of repose of the
// heap, and the rock friction that reproduces a measured angle (docs/calibration.md).

#include "calibrate_common.hpp"
#include "calibrate_heap.hpp"
#include "calibration_record.hpp"
#include "integer_option.hpp"
#include "output_file.hpp"
#include "sweep_record.hpp"
#include "threads.hpp"

#include "risk/heap_test.hpp"

#include <algorithm>
#include <chrono>
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

struct HeapArgs {
    scenario::ShapeRequest request;
    double density = 2620.0;
    engine::Material rock{0.4, 0.3, 0.02};
    risk::HeapTestSpec spec;
    bool sheet = false;
    std::optional<double> target_angle;
    std::vector<double> friction_range = {0.1, 1.0};
    int curve_points = 6;
    int threads = 0;
    CalibrationFiles files;
};

void check_args(const HeapArgs& args) {
    const engine::HeapScenario& h = args.spec.heap;
    if (args.request.size) {
        throw std::invalid_argument(
            "--size does not apply to calibrate heap: rock sizes come from the grading (--d50, "
            "--cu, --d-min, --d-max)");
    }
    require_in("--density", args.density, "kg/m3", 500.0, 10000.0);
    require_in("--friction", args.rock.friction, "", 0.0, 2.0);
    require_in("--restitution", args.rock.restitution, "", 0.0, 1.0);
    require_in("--rolling-resistance", args.rock.rolling_resistance, "", 0.0, 1.0);
    require_in("--surface-friction", h.surface.friction, "", 0.0, 2.0);
    require_in("--surface-restitution", h.surface.restitution, "", 0.0, 1.0);
    require_in("--surface-rolling-resistance", h.surface.rolling_resistance, "", 0.0, 1.0);
    require_in("--wall-friction", h.funnel.material.friction, "", 0.0, 2.0);
    require_in("--funnel-diameter", h.funnel.inner_diameter, "m", 0.02, 2.0);
    require_in("--funnel-height", h.funnel.height, "m", 0.05, 5.0);
    require_in("--lift-speed", h.funnel.lift_speed, "m/s", 1e-4, 1.0);
    require_in("--d-min", h.grading.d_min, "m", 1e-3, 100.0);
    require_in("--d-max", h.grading.d_max, "m", h.grading.d_min, 0.5 * h.funnel.inner_diameter,
               true);
    require_in("--d50", h.grading.d50, "m", h.grading.d_min, h.grading.d_max, true);
    require_in("--cu", h.grading.cu, "", 1.0, 100.0, true);
    require_in("--floor-size", h.floor_size, "m", 4.0 * h.funnel.inner_diameter, 20.0);
    require_in("--time-step", h.time_step, "s", 1e-5, 1e-2);
    if (!engine::lift_step_allowed(h.lift_time_step)) {
        std::ostringstream message;
        message << "--lift-time-step = " << h.lift_time_step
                << " s: must be 0 (the fill's step) or in [1e-05, 0.01]";
        throw std::invalid_argument(message.str());
    }
    require_in("--rest-speed", h.rest_speed, "m/s", 0.0, 1.0, true);
    require_in("--max-fill-time", h.max_fill_time, "s", 0.0, 1000.0, true);
    require_in("--max-settle-time", h.max_settle_time, "s", 0.0, 1000.0, true);
    if (args.target_angle) require_in("--target-angle", *args.target_angle, "deg", 0.0, 90.0, true);
    if (args.target_angle) {
        if (args.friction_range.size() != 2 || !(args.friction_range[0] < args.friction_range[1]))
            throw std::invalid_argument("--friction-range MIN MAX: needs MIN < MAX");
        require_in("--friction-range MIN", args.friction_range[0], "", 0.0, 2.0);
        require_in("--friction-range MAX", args.friction_range[1], "", 0.0, 2.0);
    }
    if (!args.target_angle && (args.files.svg || args.files.fragment)) {
        throw std::invalid_argument(
            "--svg and --fragment show an identification: give --target-angle");
    }
}

void run(HeapArgs args, const CLI::App& cmd) {
    check_args(args);
    check_calibration_files(args.files);
    if (args.sheet) args.spec.heap.sheet = shapes::PerforatedSheet{};
    CalibrationRun record_run;
    record_run.started_at = utc_now();
    std::vector<CalibrationRock> rocks =
        calibration_rocks(args.request, std::nullopt, args.density, "calibrate heap");
    if (args.files.fragment && rocks.size() != 1) {
        throw std::invalid_argument(
            "--fragment holds one shape's material: " + std::to_string(rocks.size()) +
            " rocks given (pick one with --entry NAME)");
    }
    HeapReport report;
    report.threads = thread_count(args.threads);
    risk::FrictionOptions options;
    options.curve_points = args.curve_points;
    options.friction_min = args.friction_range[0];
    options.friction_max = args.friction_range[1];
    options.threads = report.threads;
    for (CalibrationRock& rock : rocks) {
        rock.spec.material = args.rock;
        HeapShapeRun run;
        run.label = rock.label;
        run.spec = args.spec;
        run.spec.heap.rock = rock.spec;
        risk::check_heap_spec(run.spec);
        run.sphericity = rock.spec.geometry().sphericity;
        report.shapes.push_back(std::move(run));
    }

    const std::int64_t count = args.spec.count;
    CalibrationProgress progress(
        args.files, count, args.target_angle ? options.curve_points + options.max_iterations : 0,
        rocks.size(), "heaps");
    const risk::BatchProgress show = progress.callback();
    const auto start = std::chrono::steady_clock::now();
    for (HeapShapeRun& run : report.shapes) {
        run.result = risk::run_heap_test(run.spec, report.threads, show);
        progress.tested();
        if (args.target_angle) {
            run.identification =
                risk::identify_friction(run.spec, *args.target_angle, options, show);
            progress.identified();
        }
    }
    progress.finish();
    report.runtime =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    record_run.finished_at = utc_now();
    record_run.settings = option_settings(cmd);
    write_calibration_files(
        args.files, [&](std::ostream& out) { write_heap_csv(out, report); },
        [&] { return heap_figure(report); }, [&] { return heap_fragment(report.shapes.front()); },
        [&] { return heap_record(report, record_run); });
    if (args.files.json) {
        std::cout << heap_json(report).dump(2) << '\n';
        return;
    }
    print_heap_text(std::cout, report);
    print_calibration_files(std::cout, args.files, "heap outlines");
}

}  // namespace

void register_heap(CLI::App& calibrate) {
    auto args = std::make_shared<HeapArgs>();
    CLI::App* cmd = calibrate.add_subcommand(
        "heap",
        "Heap (funnel) test (seed 001): a cylinder filled with a cluster of rocks is lifted and "
        "the heap's angle of repose measured; with --target-angle the rock friction that "
        "reproduces a measured angle");
    engine::HeapScenario& h = args->spec.heap;
    add_shape_options(*cmd, args->request,
                      "Mesh file, or a catalogue (every entry is tested unless --entry)");
    cmd->add_option("--size", args->request.size, "Not used: sizes come from the grading");
    cmd->add_option("--density", args->density, "Rock density (kg/m3), in [500, 10000]")
        ->capture_default_str();
    cmd->add_option("--friction", args->rock.friction,
                    "Rock friction (rock-rock contacts), in [0, 2]")
        ->capture_default_str();
    cmd->add_option("--restitution", args->rock.restitution, "Rock restitution, in [0, 1]")
        ->capture_default_str();
    cmd->add_option("--rolling-resistance", args->rock.rolling_resistance,
                    "Rock rolling resistance, in [0, 1]")
        ->capture_default_str();
    cmd->add_option("--rocks", h.grading.count, "Rocks per heap")
        ->capture_default_str()
        ->transform(integer_in(1, shapes::max_cluster_rocks, "a rock count"));
    cmd->add_option("--d50", h.grading.d50, "Grading: size passed by 50 % of the mass (m)")
        ->capture_default_str();
    cmd->add_option("--cu", h.grading.cu, "Grading: uniformity d60/d10, > 1")
        ->capture_default_str();
    cmd->add_option("--d-min", h.grading.d_min, "Grading: smallest rock (m)")
        ->capture_default_str();
    cmd->add_option("--d-max", h.grading.d_max,
                    "Grading: largest rock (m), at most half the "
                    "funnel diameter")
        ->capture_default_str();
    cmd->add_option("--funnel-diameter", h.funnel.inner_diameter,
                    "Funnel inside diameter (m), in [0.02, 2]")
        ->capture_default_str();
    cmd->add_option("--funnel-height", h.funnel.height,
                    "Funnel height (m), in [0.05, 5]: the settled fill must stay below it")
        ->capture_default_str();
    cmd->add_option("--lift-speed", h.funnel.lift_speed, "Funnel lift speed (m/s), in [1e-4, 1]")
        ->capture_default_str();
    cmd->add_option("--wall-friction", h.funnel.material.friction,
                    "Funnel wall friction, in [0, 2]")
        ->capture_default_str();
    cmd->add_option("--surface-friction", h.surface.friction, "Surface friction, in [0, 2]")
        ->capture_default_str();
    cmd->add_option("--surface-restitution", h.surface.restitution,
                    "Surface restitution, in [0, 1]")
        ->capture_default_str();
    cmd->add_option("--surface-rolling-resistance", h.surface.rolling_resistance,
                    "Surface rolling resistance, in [0, 1]")
        ->capture_default_str();
    cmd->add_flag("--sheet", args->sheet,
                  "Lay seed 001's perforated sheet (1.5 mm, 50 mm holes at 80 mm) on the surface");
    cmd->add_option("--floor-size", h.floor_size,
                    "Side of the square surface (m), at least 4 funnel diameters, at most 20")
        ->capture_default_str();
    cmd->add_option("--time-step", h.time_step, "Time step of the fill (s), in [1e-5, 1e-2]")
        ->capture_default_str();
    cmd->add_option("--lift-time-step", h.lift_time_step,
                    "Time step of the lift and the heap's settling (s), in [1e-5, 1e-2]; 0: "
                    "--time-step")
        ->capture_default_str();
    cmd->add_option("--iterations", h.solver_iterations,
                    "Solver iterations per step of the fill, in [1, 100] (more bring a deep fill "
                    "to rest sooner: 500 cubes, 0.25 m deep, 2.9 s with 10, 1.9 s with 40)")
        ->capture_default_str()
        ->transform(integer_in(1, 100, "an iteration count"));
    cmd->add_option(
           "--lift-iterations", h.lift_solver_iterations,
           "Solver iterations per step of the lift and the heap's settling, in [0, 100]; "
           "0: as --iterations (a 2 ms lift needs about 40 for the angle of a 0.25-0.5 ms one)")
        ->capture_default_str()
        ->transform(integer_in(0, 100, "an iteration count"));
    cmd->add_option("--rest-speed", h.rest_speed,
                    "At rest below this root mean square rock speed (m/s)")
        ->capture_default_str();
    cmd->add_option("--max-fill-time", h.max_fill_time,
                    "Longest simulated fill before the lift (s)")
        ->capture_default_str();
    cmd->add_option("--max-settle-time", h.max_settle_time,
                    "Longest simulated settling of the heap after the lift (s)")
        ->capture_default_str();
    cmd->add_option("--count", args->spec.count, "Heaps (repeats with their own seeds), >= 1")
        ->capture_default_str()
        ->transform(integer_in(1, 100000, "a heap count"));
    cmd->add_option("--seed", args->spec.seed, "Base seed of the heaps")->capture_default_str();
    cmd->add_option("--planes", args->spec.method.planes,
                    "Vertical half-planes through the axis the outline is read in")
        ->capture_default_str()
        ->transform(integer_in(1, 360, "a number of planes"));
    cmd->add_option("--threads", args->threads,
                    "Worker threads; 0 = all cores. Fewer heaps than threads: the spare threads "
                    "share each heap's collision detection (same result)")
        ->capture_default_str()
        ->transform(integer_in(0, 1024, "a thread count"));
    cmd->add_option("--target-angle", args->target_angle,
                    "Measured mean angle of repose (deg), in (0, 90): identify the rock friction "
                    "that reproduces it, with the curve angle against friction");
    cmd->add_option("--friction-range", args->friction_range,
                    "The curve's rock friction range MIN MAX, in [0, 2]")
        ->expected(2)
        ->capture_default_str();
    cmd->add_option("--curve-points", args->curve_points,
                    "Points of the curve over the friction range, >= 2")
        ->capture_default_str()
        ->transform(integer_in(2, 101, "a number of curve points"));
    add_calibration_file_options(
        *cmd, args->files,
        {"Write the curve (the paper's Fig. 8) as SVG", "Write every heap's angle per plane as CSV",
         "Write the identified [cluster.material] as a scenario fragment (TOML) for extends"});
    cmd->callback([args, cmd] { run(*args, *cmd); });
}

}  // namespace rockfall::app
