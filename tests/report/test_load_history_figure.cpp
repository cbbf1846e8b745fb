#include "report/load_history_figure.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using Catch::Matchers::WithinRel;
using rockfall::report::load_history_plot;
using rockfall::report::Plot;
using rockfall::risk::LoadHistory;

namespace {

// A triangle pulse: 0 at t = 1 s, `peak` N at t = 2 s, 0 at t = 3 s, sampled every `dt`.
LoadHistory triangle(double peak, double dt) {
    LoadHistory h;
    h.source = "simulated";
    const int n = static_cast<int>(std::lround(4.0 / dt));
    for (int i = 0; i <= n; ++i) {
        const double t = i == n ? 4.0 : i * dt;
        h.time.push_back(t);
        h.load.push_back(peak * std::max(0.0, 1.0 - std::abs(t - 2.0)));
    }
    return h;
}

}  // namespace

TEST_CASE("Load history figure: series, units and legend", "[report][load_history]") {
    const LoadHistory sim = triangle(5000.0, 0.1);
    LoadHistory measured;
    measured.source = "records/measured.csv";
    measured.time = {0.0, 2.0, 4.0};
    measured.load = {0.0, 4000.0, 0.0};
    const Plot with = load_history_plot("t", sim, "per 0.1 s", sim, "filtered", &measured);
    REQUIRE(with.series.size() == 3);
    CHECK(with.y_label == "wall load normal to the wall (kN)");
    CHECK_THAT(with.series[0].y[20], WithinRel(5.0, 1e-9));  // kN
    CHECK(with.series[2].label == "measured (measured.csv)");
    CHECK(with.series[2].y[1] == 4.0);
    LoadHistory sim_2d = sim;
    sim_2d.per_metre = true;
    const Plot without = load_history_plot("t", sim_2d, "a", sim_2d, "b", nullptr);
    CHECK(without.series.size() == 2);
    CHECK(without.y_label == "wall load normal to the wall (kN/m)");
}
