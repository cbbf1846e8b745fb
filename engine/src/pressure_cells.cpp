// The pressure-cell grid over the reaction wall (see engine/pressure_cells.hpp).

#include "engine/pressure_cells.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>

namespace rockfall::engine {

int PressureMap::cell_at(const Vec3& point) const {
    const double across = point.y() + 0.5 * spec.width;
    const double up = point.z() - face_bottom_;
    if (across < 0.0 || up < 0.0 || across > spec.width || up > spec.height) {
        return -1;
    }
    const int column = std::min(spec.columns - 1, static_cast<int>(across / cell_width));
    const int row = std::min(spec.rows - 1, static_cast<int>(up / cell_height));
    return row * spec.columns + column;
}

namespace {

// Adds `force` (N) acting over [start, start + duration) to the samples of `series` (mean force
// per sample interval T, samples from `origin`), splitting it where it spans a sample boundary.
template <class Add>
void spread(double start, double duration, double force, double origin, double interval,
            std::size_t samples, Add&& add) {
    double t = start;
    const double end = start + duration;
    while (t < end) {
        auto k = static_cast<std::size_t>(std::floor((t - origin) / interval));
        double boundary = origin + static_cast<double>(k + 1) * interval;
        if (boundary <= t) {
            // Round-off put t on the boundary itself: it belongs to the next sample.
            ++k;
            boundary = origin + static_cast<double>(k + 1) * interval;
        }
        if (k >= samples) return;
        const double until = std::min(end, boundary);
        add(k, force * (until - t) / interval);
        t = until;
    }
}

}  // namespace

PressureMap pressure_map(const PressureCells& cells, const shapes::Slope& slope,
                         const Outcome& outcome) {
    assert(slope.wall());
    assert(cells.columns > 0 && cells.rows > 0 && cells.sample_interval > 0.0);
    PressureMap map;
    map.spec = cells;
    map.cell_width = cells.width / cells.columns;
    map.cell_height = cells.height / cells.rows;
    map.cell_area = map.cell_width * map.cell_height;
    map.face_bottom_ = slope.surface_height(slope.wall_x());

    // The samples span every force from gate opening (or the earliest force) to the last one.
    double first = 0.0;
    double last = 0.0;
    for (const RockOutcome& rock : outcome.rocks) {
        for (const WallHit& hit : rock.wall_hits) {
            for (const ForceSample& f : hit.history) {
                first = std::min(first, f.time);
                last = std::max(last, f.time + f.duration);
            }
        }
    }
    const double interval = cells.sample_interval;
    map.start_time = std::floor(first / interval) * interval;
    map.samples = static_cast<std::size_t>(std::ceil((last - map.start_time) / interval)) + 1;
    map.total.assign(map.samples, 0.0);
    map.outside.assign(map.samples, 0.0);
    map.cells.resize(static_cast<std::size_t>(cells.columns * cells.rows));
    for (int row = 0; row < cells.rows; ++row) {
        for (int column = 0; column < cells.columns; ++column) {
            PressureCellRecord& cell =
                map.cells[static_cast<std::size_t>(row * cells.columns + column)];
            cell.column = column;
            cell.row = row;
            cell.force.assign(map.samples, 0.0);
        }
    }

    for (std::size_t r = 0; r < outcome.rocks.size(); ++r) {
        RockCellLoad load;
        load.rock = r;
        // The rock's own sampled force, summed over its cells (sparse: it touches few samples).
        std::map<std::size_t, double> own;
        for (const WallHit& hit : outcome.rocks[r].wall_hits) {
            for (const ForceSample& f : hit.history) {
                if (f.normal <= 0.0) continue;
                const int index = map.cell_at(f.point);
                PressureCellRecord* cell =
                    index >= 0 ? &map.cells[static_cast<std::size_t>(index)] : nullptr;
                if (cell) {
                    if (f.normal > cell->peak_force) {
                        cell->peak_force = f.normal;
                        cell->peak_time = f.time;
                    }
                    load.cells.push_back(index);
                }
                spread(f.time, f.duration, f.normal, map.start_time, interval, map.samples,
                       [&](std::size_t k, double part) {
                           map.total[k] += part;
                           (cell ? cell->force[k] : map.outside[k]) += part;
                           if (cell) own[k] += part;
                       });
            }
        }
        if (load.cells.empty() && own.empty()) continue;
        std::sort(load.cells.begin(), load.cells.end());
        load.cells.erase(std::unique(load.cells.begin(), load.cells.end()), load.cells.end());
        for (const auto& [k, force] : own) {
            if (force > load.sampled_peak_force) {
                load.sampled_peak_force = force;
                load.sampled_peak_time = map.sample_time(k);
            }
        }
        map.rocks.push_back(std::move(load));
    }

    double grid_peak = 0.0;
    for (std::size_t k = 0; k < map.samples; ++k) {
        const double on_grid = map.total[k] - map.outside[k];
        if (on_grid > grid_peak) {
            grid_peak = on_grid;
            map.peak_sample = k;
        }
    }
    for (PressureCellRecord& cell : map.cells) {
        const auto peak = std::max_element(cell.force.begin(), cell.force.end());
        cell.sampled_peak_force = *peak;
        cell.sampled_peak_sample = static_cast<std::size_t>(peak - cell.force.begin());
        cell.saturated = cell.sampled_peak_force / map.cell_area > cells.capacity;
    }
    return map;
}

}  // namespace rockfall::engine
