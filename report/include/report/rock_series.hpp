#pragma once
/// Series derived from a run's trajectory samples (engine::RunOptions::trajectory): each rock's
/// speed against the distance its centre of mass travelled, and the front of a cluster against
/// time. SI units.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"

#include <cstddef>
#include <vector>

namespace rockfall::report {

/// One trajectory sample of a rock with the distance travelled up to it.
struct SeriesPoint {
    /// Simulated time, s.
    double time = 0.0;
    /// Path length of the centre of mass since the first sample, m: the trapezoidal integral of
    /// |v| dt over the samples.
    double distance = 0.0;
    /// Speed of the centre of mass, m/s.
    double speed = 0.0;
    /// Centre of mass, m.
    engine::Vec3 position = engine::Vec3::Zero();
};

/// One rock's samples in time order.
struct RockSeries {
    std::vector<SeriesPoint> points;
    /// Distance travelled over the whole run, m (0 without samples).
    double distance() const { return points.empty() ? 0.0 : points.back().distance; }
};

/// Collects trajectory samples per rock (a sink for engine::RunOptions::trajectory).
class SeriesRecorder {
  public:
    /// Appends a sample of rock `rock` (0-based, outcome order); samples of one rock must come
    /// in time order (the engine's do).
    void add(int rock, const engine::RockState& state);
    /// The series of every rock seen, indexed by rock (rocks never sampled stay empty).
    const std::vector<RockSeries>& series() const { return series_; }

  private:
    std::vector<RockSeries> series_;
};

/// The cluster front at one time: the rock furthest downslope among those in the world.
struct FrontPoint {
    /// Simulated time, s.
    double time = 0.0;
    /// Horizontal distance of the leading centre of mass past the toe, m (negative above it).
    double past_toe = 0.0;
    /// Distance along the surface from the crown to the surface point below it, m.
    double along_surface = 0.0;
    /// How far the front moved along the surface since t = 0, m (along_surface minus its
    /// first value).
    double travel = 0.0;
    /// The leading rock, 0-based in outcome order.
    int rock = 0;
};

/// The front at every sample time of any rock (rocks that left the run are out of it after
/// their stop time; resting rocks stay). Empty without samples.
std::vector<FrontPoint> cluster_front(const engine::Scenario& scenario,
                                      const std::vector<RockSeries>& series,
                                      const engine::Outcome& outcome);

/// The sample at distance travelled `s` (m), linearly interpolated between the samples around
/// it (time, speed, position); the first sample before the start, the last beyond the end.
/// The series must not be empty.
SeriesPoint point_at_distance(const RockSeries& series, double s);

/// `count` points evenly spaced in distance travelled from 0 to the series' end (count >= 2),
/// interpolated: a compact view of speed against distance.
std::vector<SeriesPoint> sampled_by_distance(const RockSeries& series, std::size_t count);

}  // namespace rockfall::report
