// Grid-refinement study of a soil scenario (mpm::run_refinement): each level's peak wall load,
// its time, the steady load (mean over the last second), runout and runtime, then the
// Richardson extrapolation with the observed order from the three finest levels. It stands in
// for `rockfall soil --refine` until that command is wired; it is not a timed test.
//
// Usage: bench_refine SCENARIO.toml [threads] CELL_SIZE_m CELL_SIZE_m ...  (coarsest first)
#include "scenario/soil_file.hpp"

#include "mpm/refine.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/resource.h>

using namespace rockfall::mpm;

namespace {

void print_estimate(const char* name, const char* unit, const RichardsonEstimate& e) {
    if (e.monotone) {
        std::printf(
            "  %-18s extrapolated %10.4g %-4s observed order %5.2f, finest change %5.1f %%, "
            "GCI %5.1f %%\n",
            name, e.extrapolated, unit, e.order, 100.0 * e.finest_change, 100.0 * e.gci_fine);
    } else {
        std::printf("  %-18s not monotone: no extrapolation; finest change %5.1f %%\n", name,
                    100.0 * e.finest_change);
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: bench_refine SCENARIO.toml THREADS CELL_SIZE_m ...\n");
        return 2;
    }
    SoilScenario scenario = rockfall::scenario::load_soil_scenario(argv[1]).scenario;
    scenario.numerics.threads = std::atoi(argv[2]);
    RefinementSettings settings;
    settings.cell_sizes.clear();
    for (int i = 3; i < argc; ++i) {
        settings.cell_sizes.push_back(std::atof(argv[i]));
    }
    const char* unit = scenario.numerics.dimension == 2 ? "N/m" : "N";
    std::printf("%s, %dD, %.1f s; steady load = mean over the last %.1f s\n", argv[1],
                scenario.numerics.dimension, scenario.output.duration, settings.steady_window);
    std::printf("%8s %9s %8s %12s %9s %12s %10s %9s %9s\n", "cell_m", "particles", "steps",
                (std::string("peak_") + unit).c_str(), "t_peak_s",
                (std::string("steady_") + unit).c_str(), "runout_m", "run_s", "rss_MB");
    auto start = std::chrono::steady_clock::now();
    const RefinementStudy study =
        run_refinement(scenario, settings, [&](int, const RefinementLevel& l) {
            const auto now = std::chrono::steady_clock::now();
            rusage usage{};
            getrusage(RUSAGE_SELF, &usage);
            std::printf("%8.4f %9ld %8ld %12.1f %9.3f %12.1f %10.3f %9.1f %9.1f%s\n", l.cell_size,
                        l.particles, l.steps, l.peak_wall_force, l.peak_time, l.steady_wall_force,
                        l.runout_past_toe, std::chrono::duration<double>(now - start).count(),
                        static_cast<double>(usage.ru_maxrss) / 1024.0,
                        l.status == SoilStatus::completed ? "" : " (not completed)");
            std::fflush(stdout);
            start = now;
        });
    if (study.extrapolated) {
        std::printf("Richardson extrapolation from the three finest levels (ratio %.3f):\n",
                    study.ratio);
        print_estimate("peak wall load", unit, study.peak_wall_force);
        print_estimate("time of peak", "s", study.peak_time);
        print_estimate("steady wall load", unit, study.steady_wall_force);
        print_estimate("runout past toe", "m", study.runout_past_toe);
    }
    return 0;
}
