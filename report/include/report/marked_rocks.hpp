#pragma once
/// Seed 001's marked rocks tracked one by one: each named rock's speed against the distance its
/// centre of mass travelled, as the paper's camera measured it (positions in frames a fixed
/// interval apart, 0.04 s in the paper) and as the engine's trajectory samples give it, its
/// speeds at given distances of travel (1.1 m and 1.4 m in the paper), its peak wall force and
/// the pressure cells it loaded. SI units.

#include "report/rock_series.hpp"

#include "engine/outcome.hpp"
#include "engine/pressure_cells.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rockfall::report {

/// Seed 001's camera interval, s: the videos were cut "into still images taken at time
/// intervals of 0.04 s".
inline constexpr double default_camera_interval = 0.04;

/// The distances of travel at which seed 001 reads the marked rocks' speeds, m.
inline const std::vector<double> marked_speed_distances{1.1, 1.4};

/// The centre of mass at time `t` (s), linearly interpolated between the samples around it;
/// the first sample before the series, the last after it. The series must not be empty.
engine::Vec3 position_at_time(const RockSeries& series, double t);

/// The rock as a camera with frames every `interval` s (> 0) sees it: frames at t = k interval
/// (k >= 0, from gate opening) over the series' time span, the centre of mass in each
/// interpolated in time between the samples. Point j stands for the step from frame j to frame
/// j + 1: speed = |displacement| / interval, at the step's middle in time and in distance
/// travelled (the distance is the sum of the steps' chord lengths from frame 0). Empty with
/// fewer than two frames.
RockSeries camera_series(const RockSeries& series, double interval);

/// The speed at distance travelled `s` (m): linear in distance between the points around it,
/// the first point's speed before it; NaN when the series ends before `s` or is empty.
double speed_at_distance(const RockSeries& series, double s);

/// One marked (named) rock.
struct MarkedRock {
    /// Index in Outcome::rocks (0-based) and the rock's name.
    std::size_t rock = 0;
    std::string name;
    /// Speed against distance: the engine's samples (speed of the centre of mass) and the
    /// camera's points (camera_series).
    RockSeries fine;
    RockSeries camera;
    /// Speeds at each of MarkedRocks::distances, m/s: fine and camera; NaN where not reached.
    std::vector<double> fine_speed;
    std::vector<double> camera_speed;
    /// Wall hits, the largest peak normal force of any of them (the load cell's, N; 0 without
    /// hits) and its time (s; NaN without hits).
    std::size_t wall_hits = 0;
    double peak_force = 0.0;
    double peak_time = std::numeric_limits<double>::quiet_NaN();
    /// With a pressure-cell grid: the rock's sampled peak over its cells together (N) and the
    /// start of that sample (s); unset without a grid or when it loaded no cell.
    std::optional<double> sampled_peak_force;
    std::optional<double> sampled_peak_time;
    /// Cells it loaded (row * columns + column, 0-based), ascending; empty without a grid.
    std::vector<int> cells;
};

/// The marked rocks of a run.
struct MarkedRocks {
    /// Camera interval, s.
    double camera_interval = default_camera_interval;
    /// Distances of travel of the speed readings, m.
    std::vector<double> distances;
    /// Whether the run had a pressure-cell grid (and so sampled peaks and cells).
    bool has_cells = false;
    /// Columns of the grid (to name cells), when it had one.
    int columns = 0;
    /// Every named rock in outcome order.
    std::vector<MarkedRock> rocks;
};

/// The named rocks of `outcome` with their series (indexed as the outcome's rocks; a rock
/// without samples gets empty series and NaN speeds), the grid's record when the run had
/// one, the camera interval (s, > 0) and the distances of the speed readings (m).
MarkedRocks marked_rocks(const engine::Outcome& outcome, const std::vector<RockSeries>& series,
                         const engine::PressureMap* cells, double camera_interval,
                         const std::vector<double>& distances = marked_speed_distances);

/// Writes the marked rocks' table (nothing when there are none): distance travelled, camera
/// and fine speeds at each distance, peak wall force (load cell and sampled), cells loaded.
void print_marked_rocks(std::ostream& out, const MarkedRocks& marked);

/// The marked rocks as JSON (units in the key names): camera interval, distances, and per rock
/// its speeds, forces, cells and both series.
nlohmann::json marked_rocks_json(const MarkedRocks& marked);

}  // namespace rockfall::report
