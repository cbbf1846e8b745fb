#pragma once
/// Seed 001's published results as data (Gharehdash et al.'s flume with rock clusters: Table 2,
/// the peak wall force per marked rock, and the text's speeds of the marked rocks at 1.4 m of
/// travel), and how simulated values compare with them: each cell's mean over several runs
/// against the published value with a relative tolerance, and the paper's trends.

#include "risk/sample_summary.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rockfall::risk::seed001 {

/// The paper's two clusters: C1 (53 rocks, 0.006 m3) and C2 (99 rocks, 0.010 m3).
enum class Cluster { c1, c2 };
inline constexpr std::array<Cluster, 2> clusters = {Cluster::c1, Cluster::c2};

/// The flume's three inclinations, deg.
inline constexpr std::array<int, 3> angles_deg = {30, 45, 60};

/// The numerical rows of Table 2: every rock of the cluster, marked ones included, has this
/// shape (the paper's 10-ball tetrahedral, 27-ball cubic and 19-ball octahedral clumps, and
/// spheres), in ascending sphericity.
enum class Shape { tetrahedron, cube, octahedron, sphere };
inline constexpr std::array<Shape, 4> shapes = {Shape::tetrahedron, Shape::cube, Shape::octahedron,
                                                Shape::sphere};

/// The physical rows: the experiment's four painted rocks, in ascending sphericity.
enum class Marked { yellow, green, blue, red };
inline constexpr std::array<Marked, 4> marked_rocks = {Marked::yellow, Marked::green, Marked::blue,
                                                       Marked::red};

/// "c1" or "c2".
std::string to_string(Cluster cluster);
/// "tetrahedron", "cube", "octahedron" or "sphere".
std::string to_string(Shape shape);
/// "yellow", "green", "blue" or "red".
std::string to_string(Marked rock);

/// Sphericity as Table 2 gives it: 0.67, 0.80, 0.85, 1.0 (clumps); 0.72, 0.80, 0.85, 0.89.
double sphericity(Shape shape);
double sphericity(Marked rock);

/// Table 2, numerical: the marked rock's peak wall force, N. Throws std::invalid_argument for
/// an angle that is not 30, 45 or 60.
double published_force(Shape shape, Cluster cluster, int angle_deg);
/// Table 2, physical: the painted rock's peak force on the TactArray pad, N.
double published_force(Marked rock, Cluster cluster, int angle_deg);
/// The text (section "Effect of cluster size"): the painted rock's measured speed when its
/// travelled distance reached 1.4 m, m/s.
double published_speed_at_1_4m(Marked rock, Cluster cluster, int angle_deg);

/// Where one simulated quantity of one case stands against its published value.
struct Comparison {
    /// What and which case, e.g. "peak force, cube, C2, 45 deg".
    std::string label;
    /// Unit of published and simulated values ("N", "m/s").
    std::string unit;
    /// The published value.
    double published = 0.0;
    /// The simulated values (one per run and rock); empty when no run gave one.
    std::vector<double> simulated;
    /// Runs that should have given a value, to say how many did not (a rock that never
    /// touched the wall, a rock that did not travel 1.4 m).
    int expected = 0;
    /// Largest relative error |mean - published| / published the target allows.
    double tolerance = 0.0;

    /// Mean, spread and 95 % interval of the simulated values (count 0 when empty).
    SampleSummary summary() const;
    /// (mean - published) / published; NaN without values.
    double relative_error() const;
    /// Whether there are values and the relative error is within the tolerance.
    bool within() const;
};

/// One of the paper's qualitative findings, checked on simulated means.
struct Trend {
    /// The finding, e.g. "force grows with sphericity, C1, 30 deg".
    std::string label;
    /// The means it compares, in the order the finding says they should rise or fall.
    std::vector<double> values;
    /// Whether the finding holds for the published numbers themselves.
    bool published_holds = false;
    /// Whether it holds for the simulated means.
    bool holds = false;
};

/// Mean simulated peak force per numerical cell, N (NaN where a cell has no value), indexed
/// [cluster][angle][shape] in the order of clusters, angles_deg and shapes.
using ForceGrid = std::array<std::array<std::array<double, 4>, 3>, 2>;

/// The paper's trends on a grid of numerical-cell means: for each cluster and angle, force
/// grows with sphericity (tetrahedron < cube < octahedron < sphere); for each cluster, the
/// sphericity effect (F_sphere - F_tetrahedron) / F_sphere shrinks as the angle grows; for each
/// shape and angle, C2's force is above C1's. Each trend also says whether Table 2 itself
/// shows it.
std::vector<Trend> trends(const ForceGrid& simulated);

/// Table 2's numerical cells as a grid (what trends() reads for published_holds).
ForceGrid published_grid();

/// What one marked rock gave in one run.
struct RockRecord {
    /// Its name: the painted rock's colour in a physical run; in a numerical run the colour of
    /// the spot it took (all four marked rocks have the run's shape).
    std::string name;
    /// Its largest force as the pressure cells read it (sampled), N; NaN when it never touched
    /// the wall.
    double sampled_peak_force = 0.0;
    /// Its largest force in any one contact step, N; NaN when it never touched the wall.
    double peak_force = 0.0;
    /// Its speed when its travelled distance reached 1.4 m as a camera with frames every 0.04 s
    /// reads it (report::camera_series), m/s; NaN when it did not.
    double speed_at_1_4m = 0.0;
};

/// One simulated run of the flume.
struct RunRecord {
    Cluster cluster = Cluster::c2;
    int angle_deg = 45;
    /// The numerical row's shape, or none for a physical run (the cluster as in the
    /// experiment, with the four painted rocks).
    std::optional<Shape> shape;
    std::uint64_t seed = 1;
    std::vector<RockRecord> rocks;
    /// CPU time of the run, s, and its simulated time, s.
    double runtime = 0.0;
    double simulated_time = 0.0;
};

/// Targets of the reproduction (issue 14): every numerical force cell within 25 %, every
/// speed within 20 %.
inline constexpr double force_tolerance = 0.25;
inline constexpr double speed_tolerance = 0.20;

/// The comparison of a set of runs with the paper.
struct Reproduction {
    /// Table 2's numerical cells: the four marked rocks of every run of that shape, cluster
    /// and angle pooled (force_tolerance), in the order clusters, angles, shapes.
    std::vector<Comparison> numerical_forces;
    /// Table 2's physical cells: each painted rock over the physical runs (force_tolerance),
    /// in the order clusters, angles, marked_rocks.
    std::vector<Comparison> physical_forces;
    /// The painted rocks' speeds at 1.4 m over the physical runs (speed_tolerance), same order.
    std::vector<Comparison> speeds;
    /// trends() on the numerical cells' means.
    std::vector<Trend> trends;
    /// Distinct seeds among the runs.
    int seeds = 0;
};

/// Compares runs with the paper. A cell without runs has no values (its expected count 0).
Reproduction compare(const std::vector<RunRecord>& runs);

}  // namespace rockfall::risk::seed001
