#include "scenario/csv_table.hpp"
#include "scenario/load_record.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall::scenario;
using rockfall::risk::check_comparable;
using rockfall::risk::compare_histories;
using rockfall::risk::HistoryComparison;
using rockfall::risk::LoadHistory;

namespace {

LoadHistory history_of(const std::string& text) {
    return measured_history(CsvTable::parse(text, "measured.csv"));
}

// A triangle pulse: 0 at t = 1 s, `peak` N at t = 2 s, 0 at t = 3 s, sampled every `dt`.
LoadHistory triangle(double peak, double dt, double start = 0.0) {
    LoadHistory h;
    h.source = "simulated";
    const int n = static_cast<int>(std::lround((4.0 - start) / dt));
    for (int i = 0; i <= n; ++i) {
        const double t = i == n ? 4.0 : start + i * dt;
        h.time.push_back(t);
        h.load.push_back(peak * std::max(0.0, 1.0 - std::abs(t - 2.0)));
    }
    return h;
}

}  // namespace

TEST_CASE("Measured load history: units from the column name", "[scenario][load_history]") {
    const LoadHistory kn = history_of("# load cells\ntime_s,load_kN,note\n0,0,a\n0.5,1.5,b\n");
    CHECK(kn.time == std::vector<double>{0.0, 0.5});
    CHECK(kn.load == std::vector<double>{0.0, 1500.0});
    CHECK_FALSE(kn.per_metre);
    const LoadHistory per_m = history_of("load_N_per_m,time_s\n10,1\n20,2\n");
    CHECK(per_m.per_metre);
    CHECK(per_m.load == std::vector<double>{10.0, 20.0});
    CHECK(per_m.source == "measured.csv");
}

TEST_CASE("Measured load history: errors name the file, line and column",
          "[scenario][load_history]") {
    CHECK_THROWS_WITH(history_of("t,load_kN\n0,1\n1,2\n"), Contains("missing column time_s"));
    CHECK_THROWS_WITH(history_of("time_s,force\n0,1\n1,2\n"),
                      Contains("measured.csv: the header names no load column; give exactly one "
                               "of load_kN, load_N, load_kN_per_m, load_N_per_m"));
    CHECK_THROWS_WITH(history_of("time_s,load_kN,load_N\n0,1,1\n1,2,2\n"),
                      Contains("names both load_kN and load_N"));
    CHECK_THROWS_WITH(history_of("time_s,load_kN\n0,1\n"),
                      Contains("at least two data rows (it has 1)"));
    CHECK_THROWS_WITH(history_of("time_s,load_kN\n0,1\n0.5,2\n0.5,3\n"),
                      Contains("measured.csv:4: column 1 (time_s) = 0.5 s: times must be >= 0 "
                               "and increase"));
    CHECK_THROWS_WITH(history_of("time_s,load_kN\n-1,1\n0.5,2\n"),
                      Contains("measured.csv:2: column 1 (time_s) = -1 s"));
    CHECK_THROWS_WITH(
        history_of("time_s,load_kN\n0,1\n1,high\n"),
        Contains("measured.csv:3: column 2 (load_kN) = \"high\": not a finite number"));
}

TEST_CASE("Comparing a history with itself gives ratios of 1", "[scenario][load_history]") {
    const LoadHistory sim = triangle(5000.0, 0.01);
    LoadHistory measured = triangle(5000.0, 0.01);
    measured.source = "same.csv";
    const HistoryComparison c = compare_histories(sim, measured);
    CHECK_THAT(c.peak_ratio, WithinRel(1.0, 1e-12));
    CHECK_THAT(c.impulse_ratio, WithinRel(1.0, 1e-12));
    CHECK_THAT(c.loading_ratio, WithinRel(1.0, 1e-12));
    CHECK_THAT(c.after_peak_ratio, WithinRel(1.0, 1e-12));
    CHECK_THAT(c.rms_difference, WithinAbs(0.0, 1e-9));
    // The triangle's area: 1/2 * 2 s * 5000 N.
    CHECK_THAT(c.measured_impulse, WithinRel(5000.0, 1e-9));
    CHECK_THAT(c.measured_peak_time, WithinAbs(2.0, 1e-9));
}

TEST_CASE("Comparison against a sparse record: exact impulses, phases, RMS",
          "[scenario][load_history]") {
    // A record read off a figure: five points of the same pulse at half its height, and
    // shifted later by 0.5 s.
    const LoadHistory sim = triangle(5000.0, 0.01);
    const LoadHistory measured = history_of("time_s,load_kN\n0,0\n1.5,0\n2.5,2.5\n3.5,0\n4,0\n");
    const HistoryComparison c = compare_histories(sim, measured);
    CHECK(c.points == 5);
    CHECK_THAT(c.from, WithinAbs(0.0, 1e-12));
    CHECK_THAT(c.to, WithinAbs(4.0, 1e-9));
    CHECK_THAT(c.simulated_peak, WithinRel(5000.0, 1e-9));
    CHECK_THAT(c.measured_peak, WithinRel(2500.0, 1e-12));
    CHECK_THAT(c.measured_peak_time, WithinAbs(2.5, 1e-12));
    CHECK_THAT(c.peak_ratio, WithinRel(2.0, 1e-9));
    // Areas 5000 and 2500 N s: the sparse points carry the whole measured triangle.
    CHECK_THAT(c.simulated_impulse, WithinRel(5000.0, 1e-9));
    CHECK_THAT(c.measured_impulse, WithinRel(2500.0, 1e-9));
    CHECK_THAT(c.impulse_ratio, WithinRel(2.0, 1e-9));
    // Up to the measured peak (t <= 2.5 s) the simulated pulse has 4375 N s against 1250 N s;
    // after it, 625 against 1250.
    CHECK_THAT(c.loading_ratio, WithinRel(4375.0 / 1250.0, 1e-9));
    CHECK_THAT(c.after_peak_ratio, WithinRel(625.0 / 1250.0, 1e-9));
    // RMS of the difference of two piecewise-linear pulses, sampled at the union of the times:
    // positive and finite, below the larger peak.
    CHECK(c.rms_difference > 500.0);
    CHECK(c.rms_difference < 5000.0);
}

TEST_CASE("Comparison refuses mismatched units and disjoint times", "[scenario][load_history]") {
    const LoadHistory sim = triangle(5000.0, 0.01);
    const LoadHistory per_m = history_of("time_s,load_kN_per_m\n0,1\n1,2\n");
    CHECK_THROWS_WITH(compare_histories(sim, per_m),
                      Contains("a 3D run gives the total load on the wall: the measured file "
                               "needs a load_kN or load_N column"));
    LoadHistory sim_2d = sim;
    sim_2d.per_metre = true;
    CHECK_THROWS_WITH(check_comparable(true, 0.0, 4.0, history_of("time_s,load_N\n0,1\n1,2\n")),
                      Contains("needs a load_kN_per_m or load_N_per_m column"));
    CHECK_NOTHROW(compare_histories(sim_2d, per_m));
    CHECK(check_comparable(true, 0.0, 4.0, per_m) == 2);
    CHECK_THROWS_WITH(check_comparable(true, 0.01, 0.5, per_m),
                      Contains("measured.csv: the measured history (t = 0 to 1 s) shares fewer "
                               "than two times with the simulated one (t = 0.01 to 0.5 s)"));
    CHECK_THROWS_WITH(compare_histories(sim, history_of("time_s,load_N\n5,1\n6,2\n")),
                      Contains("shares fewer than two times with the simulated one"));
}
