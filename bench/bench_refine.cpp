// Grid-refinement study of a soil scenario (mpm::run_refinement) with a chosen thread count:
// the table and Richardson extrapolation `rockfall soil --refine` prints (report/refine_report),
// and on standard error each level's runtime and the process's peak memory. Not a timed test.
//
// Usage: bench_refine SCENARIO.toml THREADS CELL_SIZE_m CELL_SIZE_m ...  (coarsest first)
#include "report/refine_report.hpp"
#include "scenario/soil_file.hpp"

#include "mpm/refine.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <sys/resource.h>

using namespace rockfall;

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: bench_refine SCENARIO.toml THREADS CELL_SIZE_m ...\n");
        return 2;
    }
    mpm::SoilScenario scenario = scenario::load_soil_scenario(argv[1]).scenario;
    scenario.numerics.threads = std::atoi(argv[2]);
    mpm::RefinementSettings settings;
    settings.cell_sizes.clear();
    for (int i = 3; i < argc; ++i) {
        settings.cell_sizes.push_back(std::atof(argv[i]));
    }
    report::RefinementContext context{argv[1],
                                      scenario.numerics.dimension,
                                      scenario.output.duration,
                                      settings.steady_window,
                                      scenario.output.filter_window,
                                      {}};
    const int count = static_cast<int>(settings.cell_sizes.size());
    auto start = std::chrono::steady_clock::now();
    const mpm::RefinementStudy study =
        mpm::run_refinement(scenario, settings, [&](int i, const mpm::RefinementLevel& level) {
            const auto now = std::chrono::steady_clock::now();
            context.runtime.push_back(std::chrono::duration<double>(now - start).count());
            rusage usage{};
            getrusage(RUSAGE_SELF, &usage);
            std::fprintf(stderr, "%s; peak memory %.1f MB\n",
                         report::refinement_progress_line(level, i, count, context.dimension,
                                                          context.runtime.back())
                             .c_str(),
                         static_cast<double>(usage.ru_maxrss) / 1024.0);
            start = now;
        });
    std::printf("%d thread(s)\n", scenario.numerics.threads);
    std::fflush(stdout);
    report::print_refinement(std::cout, study, context);
    return 0;
}
