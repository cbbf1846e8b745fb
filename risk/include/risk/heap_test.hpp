#pragma once
/// The virtual heap (funnel) test of seed 001 ("Angle of repose test"): repeated heaps from
/// engine::simulate_heap, the angle of repose measured from each heap's outline in several
/// vertical planes through its axis, and the rock friction that reproduces a measured angle
/// (the paper's Fig. 8). SI units; angles in degrees where the name says so.

#include "engine/heap_test.hpp"
#include "risk/parameter_search.hpp"
#include "risk/sample_summary.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace rockfall::risk {

/// How the angle of repose is read from a heap (docs/calibration.md, "Angle of repose").
struct AngleMethod {
    /// Vertical half-planes through the heap's axis, evenly spaced in azimuth, in [1, 360].
    int planes = 8;
    /// Width of the radial bins of the outline, m (> 0); 0: half the grading's d50.
    double bin_width = 0.0;
    /// Vertical lines sampled per bin, in [1, 100].
    int samples_per_bin = 8;
    /// The flank fitted: outline points between these fractions of the plane's heap height,
    /// with 0 <= low < high <= 1.
    double low_fraction = 0.1;
    double high_fraction = 0.9;
};

/// One heap test, repeated: the heap scenario, how many heaps, and how to read them.
struct HeapTestSpec {
    /// The heap (rocks, grading, funnel, surface, stepping).
    engine::HeapScenario heap;
    /// Heaps, each with its own seed (>= 1).
    std::int64_t count = 1;
    /// Base seed: heap i runs with heap_seed(seed, i).
    std::uint64_t seed = 1;
    /// The angle measurement.
    AngleMethod method;
};

/// Throws std::invalid_argument naming the field, its value, unit and allowed range when a
/// field of `spec` is out of range (the grading by shapes::grading_model; the rock's shape and
/// material by the scenario rules are the caller's).
void check_heap_spec(const HeapTestSpec& spec);

/// The engine seed of heap `index` (>= 0): splitmix64(splitmix64(seed) + index), as the drop
/// test's, a pure function of the two.
std::uint64_t heap_seed(std::uint64_t seed, std::int64_t index);

/// A settled heap's surface as seen from above: the rocks on the surface as spheres or as the
/// face planes of their hulls in the world frame.
class HeapSurface {
  public:
    /// The rocks of `heap` with on_floor true.
    explicit HeapSurface(const engine::HeapOutcome& heap);
    /// Height of the highest rock surface above the heap's surface_z on the vertical line
    /// through (x, y), m; 0 where no rock is above the line.
    double height(double x, double y) const;

  private:
    struct Rock {
        Eigen::Vector3d center;
        double reach = 0.0;   // bounding radius, m
        double radius = 0.0;  // > 0 for a sphere
        // Outward face planes n . p <= d in the world frame (hulls).
        std::vector<Eigen::Vector4d> planes;
    };
    std::vector<Rock> rocks_;
    double surface_z_ = 0.0;
};

/// The outline of a heap in one vertical half-plane and the straight line fitted to its flank.
struct HeapProfile {
    /// Azimuth of the half-plane, deg, in [0, 360).
    double azimuth_deg = 0.0;
    /// Bin centres' distance from the axis (m) and the outline height there (m above the
    /// surface): the highest rock surface over the bin's sampled lines.
    std::vector<double> radius;
    std::vector<double> height;
    /// The plane's heap height (highest outline point), m.
    double heap_height = 0.0;
    /// The bins fitted (from the summit outwards, until the outline first falls below
    /// low_fraction of the heap height; those within [low, high] fractions of it).
    int fitted_points = 0;
    /// Radius where the outline first falls below low_fraction of the heap height, m.
    double foot_radius = 0.0;
    /// Whether at least 3 bins were fitted; otherwise the angle is 0 and the plane is left out.
    bool valid = false;
    /// Angle of repose, atan(-slope) of the least-squares line height = a + slope radius, deg.
    double angle_deg = 0.0;
};

/// The outline of `surface` in the half-plane at `azimuth_deg` through the vertical axis at
/// (axis_x, axis_y) (m), bins of `bin_width` (m, > 0) from the axis out to `max_radius` (m),
/// and the line fitted to its flank.
HeapProfile heap_profile(const HeapSurface& surface, double axis_x, double axis_y,
                         double max_radius, double azimuth_deg, double bin_width,
                         const AngleMethod& method);

/// One heap and its angle of repose.
struct HeapMeasurement {
    /// Heap index, its engine seed and how its run ended.
    std::int64_t index = 0;
    std::uint64_t seed = 0;
    engine::HeapStatus status = engine::HeapStatus::at_rest;
    /// Rocks, and those that rolled off the surface.
    int rocks = 0;
    int rolled_off = 0;
    /// Fill height in the funnel before the lift, m.
    double fill_height = 0.0;
    /// Whether the fill came to rest before max_fill_time (false: lifted still moving).
    bool fill_at_rest = true;
    /// Simulated times of fill, lift and settling, s.
    double fill_time = 0.0;
    double lift_time = 0.0;
    double settle_time = 0.0;
    /// Mean heap height and foot radius over the valid planes, m.
    double heap_height = 0.0;
    double foot_radius = 0.0;
    /// Every plane's outline and fit.
    std::vector<HeapProfile> planes;
    /// Mean and sample standard deviation of the valid planes' angles, deg.
    double angle_deg = 0.0;
    double angle_sd_deg = 0.0;
    /// Valid planes.
    int valid_planes = 0;
};

/// Measures a heap's angle of repose in `method.planes` half-planes (bins of `bin_width`, m).
/// When no plane has 3 fitted bins (the rocks spread as a single layer, or rolled off) the
/// angle is 0 with valid_planes 0.
HeapMeasurement measure_heap(const engine::HeapOutcome& heap, double bin_width,
                             const AngleMethod& method);

/// Runs heap `index` of a checked spec and measures it. Throws std::runtime_error naming the
/// heap and its seed on a numerical failure, and std::invalid_argument when the fill rose
/// above the funnel (fewer or smaller rocks, or a taller funnel).
HeapMeasurement run_heap(const HeapTestSpec& spec, std::int64_t index);

/// Every heap of one test and the distributions of its angle.
struct HeapTestResult {
    /// The heaps, in index order.
    std::vector<HeapMeasurement> heaps;
    /// Heaps that did not come to rest within max_settle_time (measured as they were).
    std::int64_t not_at_rest = 0;
    /// Fills still moving at max_fill_time (lifted all the same).
    std::int64_t fills_not_at_rest = 0;
    /// The heaps' mean angles, deg: the test's result and its interval.
    SampleSummary angle_deg;
    /// Every valid plane of every heap, deg: the scatter over planes and heaps (the heap means
    /// when no plane is valid).
    SampleSummary plane_angle_deg;
    /// Heap heights and fill heights, m.
    SampleSummary heap_height;
    SampleSummary fill_height;
};

/// Runs the `spec.count` heaps of a checked spec on `threads` (>= 1) worker threads; heap i's
/// result depends only on (spec, i), whatever the thread count. With fewer heaps than threads,
/// each heap's collision detection gets threads / heaps of them (spec.heap.collision_threads
/// is replaced; identify_friction does the same per batch).
HeapTestResult run_heap_test(const HeapTestSpec& spec, int threads,
                             const BatchProgress& progress = {});

/// One point of the curve angle of repose against rock friction (the paper's Fig. 8).
struct FrictionPoint {
    /// The rock's friction (rock-rock contacts), in [0, 2].
    double friction = 0.0;
    /// The heap test there (every heap with the same seeds as at the other points).
    HeapTestResult result;
};

/// Options of a friction identification.
struct FrictionOptions {
    /// Curve points, evenly spaced over [friction_min, friction_max] (>= 2).
    int curve_points = 6;
    /// The curve's range of rock friction, 0 <= min < max <= 2.
    double friction_min = 0.1;
    double friction_max = 1.0;
    /// The bracket is refined until narrower than this, in friction (> 0).
    double tolerance = 0.01;
    /// Most refinement steps after the curve.
    int max_iterations = 8;
    /// Worker threads (>= 1).
    int threads = 1;
};

/// The rock friction that reproduces a target mean angle of repose.
struct FrictionIdentification {
    /// Target mean angle, deg, in (0, 90).
    double target_deg = 0.0;
    /// The identified friction and the heap test there.
    FrictionPoint identified;
    /// Frictions whose mean angle is consistent with the target (the 95 % interval of the mean
    /// over heaps contains it; with one heap per point, where the curve crosses the target).
    Interval consistent;
    /// The curve (evenly spaced), then every refinement point, each sorted by friction.
    std::vector<FrictionPoint> curve;
    std::vector<FrictionPoint> refinements;
};

/// Finds the rock friction in [friction_min, friction_max] at which the mean angle of repose
/// of `spec`'s heaps (the same seeds at every value) equals `target_deg`, as
/// search_parameter. Throws std::invalid_argument when the target lies outside what the curve
/// reaches (naming that range), or is not in (0, 90).
FrictionIdentification identify_friction(const HeapTestSpec& spec, double target_deg,
                                         const FrictionOptions& options,
                                         const BatchProgress& progress = {});

}  // namespace rockfall::risk
