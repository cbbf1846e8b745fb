// Refinement study of the planar granular column collapse (mpm::verification::column_collapse):
// for each aspect ratio a and each number of cells per L0, the runout read four ways (the
// farthest particle; the front of the deposit thicker than 5, 10 and 20 % of H0; the toe of the
// deposit's surface where it is 10-30 % of H0 thick), how far the centre of mass moved, its final
// height and the kinetic energy at t = sqrt(H0 / g), beside the published laws of Lube et al.
// and Lajeunesse et al. The tables of docs/column_collapse.md. Not run by CTest or CI.
//
// Usage: bench_collapse [--aspects 0.5,1,2,3] [--cells 16,32,64] [--threads 2] [--phi 30]

#include "mpm/verification.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <vector>

namespace {

using namespace rockfall::mpm::verification;

struct Row {
    int cells = 0;
    double farthest = 0.0;
    double toe = 0.0;
    double travel = 0.0;
};

double change_percent(double coarse, double fine) { return 100.0 * (fine / coarse - 1.0); }

}  // namespace

int main(int argc, char** argv) {
    std::vector<double> aspects{0.5, 1.0, 2.0, 3.0};
    std::vector<int> cells{16, 32, 64};
    CollapseNumerics numerics;
    numerics.threads = 2;
    CLI::App app{"Column collapse refinement study (plane strain, Drucker-Prager)"};
    app.add_option("--aspects", aspects, "Aspect ratios a = H0 / L0")
        ->delimiter(',')
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--cells", cells, "Cells per L0, coarsest first")
        ->delimiter(',')
        ->check(CLI::Range(4, 1024))
        ->capture_default_str();
    app.add_option("--threads", numerics.threads, "Solver threads (0: all cores)")
        ->check(CLI::Range(0, 64))
        ->capture_default_str();
    app.add_option("--phi", numerics.friction_angle_deg, "Soil friction angle, deg")
        ->check(CLI::Range(5.0, 60.0))
        ->capture_default_str();
    app.add_option("--cfl", numerics.cfl, "CFL number")
        ->check(CLI::Range(0.01, 1.0))
        ->capture_default_str();
    app.add_option("--flip", numerics.flip, "FLIP fraction (0: APIC)")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);

    std::printf("phi %.1f deg, cfl %.3f, flip %.2f, %d thread(s); runouts are (L - L0) / L0\n",
                numerics.friction_angle_deg, numerics.cfl, numerics.flip, numerics.threads);
    for (const double a : aspects) {
        const double height = a * collapse_length;
        std::printf("\na = %g: Lube et al. %.2f, Lajeunesse et al. %.2f\n", a, lube_runout(a),
                    lajeunesse_runout(a));
        std::printf(
            "| L0/h | particles | farthest | front >5/10/20 %% H0 | toe 10-30 %% H0 | "
            "(x_c - L0/2)/L0 | z_c/H0 | KE at sqrt(H0/g) (J/m) | simulated (s) | run (s) |\n");
        std::vector<Row> rows;
        for (const int n : cells) {
            const auto start = std::chrono::steady_clock::now();
            const ColumnCollapse c = column_collapse(a, n, numerics);
            const double run =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const Row row{n, c.runout, surface_toe(c, 0.1 * height, 0.3 * height),
                          (c.centre_of_mass[0] - 0.5 * collapse_length) / collapse_length};
            std::printf(
                "| %d | %zu | %.2f | %.2f / %.2f / %.2f | %.2f | %.3f | %.3f | %.2f | %.2f | "
                "%.1f |%s\n",
                n, c.deposit.size(), row.farthest, deposit_front(c, 0.05 * height),
                deposit_front(c, 0.1 * height), deposit_front(c, 0.2 * height), row.toe, row.travel,
                c.centre_of_mass[1] / height, c.early_kinetic_energy, c.time, run,
                c.clamped_steps > 0 ? " (particles clamped)" : "");
            std::fflush(stdout);
            rows.push_back(row);
        }
        for (std::size_t i = 1; i < rows.size(); ++i) {
            std::printf("%d -> %d cells per L0: farthest %+.1f %%, toe %+.1f %%, travel %+.1f %%\n",
                        rows[i - 1].cells, rows[i].cells,
                        change_percent(rows[i - 1].farthest, rows[i].farthest),
                        change_percent(rows[i - 1].toe, rows[i].toe),
                        change_percent(rows[i - 1].travel, rows[i].travel));
        }
    }
    return 0;
}
