// Heap benchmark (issue 15, "Benchmark"): one heap test of 500 rocks (the funnel test of seed
// 001: fill, lift at 7.5 mm/s, settle) timed on one core, the same heap with its collision
// detection on --threads threads (2 by default: the 2-core target; bit-identical, checked), and
// --parallel heaps with their own seeds on as many threads. Prints wall-clock and CPU time,
// simulated time per phase, rock-steps per second, the speed-up and the angle of repose. Not
// run by CTest or CI.

#include "bench_machine.hpp"
#include "scenario/shape_source.hpp"

#include "risk/heap_test.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <exception>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#ifndef ROCKFALL_BUILD_TYPE
#define ROCKFALL_BUILD_TYPE "unknown"
#endif

namespace {

using namespace rockfall;

struct Options {
    std::string kind = "cube";
    int rocks = 500;
    double friction = 0.4;
    double rolling_resistance = 0.02;
    double restitution = 0.3;
    double lift_speed = 0.0075;
    double time_step = 1e-3;
    double lift_time_step = engine::HeapScenario{}.lift_time_step;
    std::uint64_t seed = 1;
    int parallel = 2;
    int threads = 2;
    int iterations = 10;
    int lift_iterations = engine::HeapScenario{}.lift_solver_iterations;
    double contact_slop = engine::HeapScenario{}.contact_slop;
};

risk::HeapTestSpec spec_of(const Options& o) {
    risk::HeapTestSpec spec;
    scenario::ShapeRequest request;
    request.kind = o.kind;
    const scenario::ShapeResult shape = scenario::make_shape(request);
    if (shape.rock.kind == shapes::RockKind::custom) {
        spec.heap.rock.kind = shapes::RockKind::custom;
        spec.heap.rock.shape = std::make_shared<const shapes::CustomShape>(
            shapes::CustomShape{shape.label, shape.rock.hull});
    } else {
        spec.heap.rock.kind = shape.rock.kind;
    }
    spec.heap.rock.material.friction = o.friction;
    spec.heap.rock.material.rolling_resistance = o.rolling_resistance;
    spec.heap.rock.material.restitution = o.restitution;
    spec.heap.grading.count = o.rocks;
    spec.heap.funnel.lift_speed = o.lift_speed;
    spec.heap.time_step = o.time_step;
    spec.heap.lift_time_step = o.lift_time_step;
    spec.heap.solver_iterations = o.iterations;
    spec.heap.lift_solver_iterations = o.lift_iterations;
    spec.heap.contact_slop = o.contact_slop;
    spec.seed = o.seed;
    return spec;
}

void print_heap(const risk::HeapMeasurement& m) {
    std::cout << "  heap " << m.index << ": " << m.rocks << " rocks (" << m.rolled_off
              << " rolled off), fill " << std::setprecision(3) << m.fill_height
              << " m, simulated fill " << m.fill_time << " s + lift " << m.lift_time
              << " s + settle " << m.settle_time << " s, " << engine::to_string(m.status)
              << "; angle " << m.angle_deg << " deg (sd " << m.angle_sd_deg << " over "
              << m.valid_planes << " planes), height " << m.heap_height << " m, foot radius "
              << m.foot_radius << " m\n";
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"Heap benchmark: one funnel test of 500 rocks, then heaps in parallel"};
    app.add_option("--kind", o.kind, "Rock kind (sphere, massive, tetrahedron, cube, ...)")
        ->capture_default_str();
    app.add_option("--rocks", o.rocks, "Rocks per heap")->capture_default_str();
    app.add_option("--friction", o.friction, "Rock friction")->capture_default_str();
    app.add_option("--rolling-resistance", o.rolling_resistance, "Rock rolling resistance")
        ->capture_default_str();
    app.add_option("--restitution", o.restitution, "Rock restitution")->capture_default_str();
    app.add_option("--lift-speed", o.lift_speed, "Funnel lift speed, m/s")->capture_default_str();
    app.add_option("--time-step", o.time_step, "Time step, s")->capture_default_str();
    app.add_option("--lift-time-step", o.lift_time_step,
                   "Time step of the lift and the settling, s; 0: --time-step")
        ->capture_default_str();
    app.add_option("--seed", o.seed, "Base seed")->capture_default_str();
    app.add_option("--iterations", o.iterations, "Solver iterations")->capture_default_str();
    app.add_option("--lift-iterations", o.lift_iterations,
                   "Solver iterations of the lift and the settling; 0: --iterations")
        ->capture_default_str();
    app.add_option("--contact-slop", o.contact_slop, "Penetration left uncorrected, g dt^2")
        ->capture_default_str();
    app.add_option("--threads", o.threads,
                   "Collision threads of the one heap's second run; 1: none")
        ->capture_default_str()
        ->check(CLI::Range(1, 64));
    app.add_option("--parallel", o.parallel, "Heaps run together on that many threads; 0: none")
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    try {
        bench::print_machine(ROCKFALL_BUILD_TYPE);
        risk::HeapTestSpec spec = spec_of(o);
        risk::check_heap_spec(spec);
        std::cout << "heap test: " << o.rocks << " " << o.kind << " rocks, d50 "
                  << spec.heap.grading.d50 << " m, friction " << o.friction
                  << ", rolling resistance " << o.rolling_resistance << ", lift " << o.lift_speed
                  << " m/s, step " << o.time_step << " s (lift "
                  << engine::effective_lift_step(spec.heap) << " s), "
                  << spec.heap.solver_iterations << " solver iterations (lift "
                  << engine::effective_lift_iterations(spec.heap) << ")\n";
        const bench::Stopwatch one;
        const risk::HeapMeasurement m = risk::run_heap(spec, 0);
        const double wall = one.wall();
        const double cpu = one.cpu();
        print_heap(m);
        const double simulated = m.fill_time + m.lift_time + m.settle_time;
        std::cout << std::setprecision(4) << "one heap on one core: wall " << wall << " s, CPU "
                  << cpu << " s, " << simulated / cpu << " simulated s per CPU s, "
                  << m.rocks * simulated / o.time_step / cpu << " rock-steps per CPU s\n";
        if (o.threads > 1) {
            risk::HeapTestSpec threaded = spec;
            threaded.heap.collision_threads = o.threads;
            const bench::Stopwatch again;
            const risk::HeapMeasurement t = risk::run_heap(threaded, 0);
            const double wall_t = again.wall();
            print_heap(t);
            const bool same = t.angle_deg == m.angle_deg && t.fill_height == m.fill_height &&
                              t.lift_time == m.lift_time && t.settle_time == m.settle_time;
            std::cout << std::setprecision(4) << "one heap, collision detection on " << o.threads
                      << " threads: wall " << wall_t << " s, CPU " << again.cpu() << " s, "
                      << wall / wall_t << " times faster than on one core; "
                      << (same ? "identical to the one-core heap"
                               : "DIFFERENT from the one-core heap")
                      << '\n';
            if (!same) return 1;
        }
        if (o.parallel > 0) {
            spec.count = o.parallel;
            const auto start = std::chrono::steady_clock::now();
            const risk::HeapTestResult r = risk::run_heap_test(spec, o.parallel);
            const double both =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            for (const risk::HeapMeasurement& h : r.heaps) print_heap(h);
            std::cout << std::setprecision(4) << o.parallel << " heaps on " << o.parallel
                      << " threads: wall " << both << " s; mean angle " << r.angle_deg.mean
                      << " deg\n";
        }
    } catch (const std::exception& e) {
        std::cerr << "bench_heap: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
