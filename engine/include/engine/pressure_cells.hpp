#pragma once
/// The reaction wall as seed 001's instrument: a grid of pressure cells over its face (the
/// paper's TactArray pad: 16 x 16 cells over 0.60 x 0.30 m, capacity 345 kPa), read from the
/// load cells' force histories after a run.
///
/// Every wall force of a run (each fine step of an impact, each coarse step of a resting
/// contact, as the load cells record them in WallHit::history) acts at its contact point and is
/// given whole to the cell that holds the point: contact patches (millimetres) are smaller than
/// a cell (37.5 x 18.75 mm in the paper). A resting contact's rigid solver impulses act at their
/// force-weighted mean point. The cells are sampled like a sensor that integrates: sample k is
/// the mean normal force over [k T, (k + 1) T) from gate opening (T the sample interval). A cell
/// saturates when its sampled pressure (force over cell area) exceeds the capacity; sampled
/// values are kept as computed, with the flag.

#include "engine/outcome.hpp"
#include "shapes/slope.hpp"

#include <cstddef>
#include <vector>

namespace rockfall::engine {

/// The grid, on the wall's face towards the slope: `columns` across (y, from -width / 2 to
/// width / 2 about the centre line), `rows` up (z, from the surface at the wall's foot to
/// `height` above it). Scenario key [wall_cells].
struct PressureCells {
    /// Cells across and up, each in [1, 256].
    int columns = 16;
    int rows = 16;
    /// Extent of the grid across and up, m: width in (0, slope width], height in (0, wall
    /// height].
    double width = 0.6;
    double height = 0.3;
    /// Largest pressure a cell measures, Pa (> 0): 345 kPa (50 psi) in the paper.
    double capacity = 345e3;
    /// Sample interval, s, in [1e-5, 0.1]. Seed 001 does not give its rate.
    double sample_interval = 1e-3;
};

/// One cell's record.
struct PressureCellRecord {
    int column = 0;
    int row = 0;
    /// Largest normal force of any one fine step in the cell, N, and when it acted, s.
    double peak_force = 0.0;
    double peak_time = 0.0;
    /// Largest sampled force, N (the sensor's reading of the peak), and its sample.
    double sampled_peak_force = 0.0;
    std::size_t sampled_peak_sample = 0;
    /// The sampled pressure exceeded the capacity.
    bool saturated = false;
    /// Sampled normal force, N, one per sample.
    std::vector<double> force;
};

/// What one rock gave the grid.
struct RockCellLoad {
    /// Index of the rock in Outcome::rocks.
    std::size_t rock = 0;
    /// Cells it loaded (row * columns + column), ascending.
    std::vector<int> cells;
    /// Its largest sampled force over all cells together, N (the sensor's reading of its
    /// impact), and that sample's start time, s.
    double sampled_peak_force = 0.0;
    double sampled_peak_time = 0.0;
};

/// The grid after a run.
struct PressureMap {
    PressureCells spec;
    /// Cell size across and up, m, and area, m2.
    double cell_width = 0.0;
    double cell_height = 0.0;
    double cell_area = 0.0;
    /// Time of sample 0, s (gate opening, or earlier if a force acted before), and the number
    /// of samples.
    double start_time = 0.0;
    std::size_t samples = 0;
    /// Row-major: cells[row * columns + column].
    std::vector<PressureCellRecord> cells;
    /// Sampled normal force on the whole wall and on the part of it outside the grid, N.
    std::vector<double> total;
    std::vector<double> outside;
    /// One entry per rock that loaded the wall, in rock order.
    std::vector<RockCellLoad> rocks;
    /// The sample at which the grid's summed force peaked.
    std::size_t peak_sample = 0;

    /// Start time of sample k, s.
    double sample_time(std::size_t k) const {
        return start_time + static_cast<double>(k) * spec.sample_interval;
    }
    /// Cell index (row * columns + column) of a point on the wall's face, or -1 outside.
    int cell_at(const Vec3& point) const;

  private:
    friend PressureMap pressure_map(const PressureCells&, const shapes::Slope&, const Outcome&);
    double face_bottom_ = 0.0;  // z of the grid's lower edge, m
};

/// The grid's record of a run on `slope` (which must have a wall).
PressureMap pressure_map(const PressureCells& cells, const shapes::Slope& slope,
                         const Outcome& outcome);

}  // namespace rockfall::engine
