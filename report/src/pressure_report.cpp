// Text and JSON of the pressure-cell grid (see pressure_report.hpp).

#include "report/pressure_report.hpp"

#include "report/text_format.hpp"

#include <algorithm>
#include <string>

namespace rockfall::report {
namespace {

constexpr double kPascalPerKilopascal = 1e3;

std::string cell_name(const engine::PressureCellRecord& cell) {
    return "(column " + std::to_string(cell.column + 1) + ", row " + std::to_string(cell.row + 1) +
           ")";
}

}  // namespace

void print_pressure_cells(std::ostream& out, const engine::PressureMap& map,
                          const engine::Outcome& outcome) {
    const engine::PressureCells& spec = map.spec;
    out << "pressure cells: " << spec.columns << " x " << spec.rows << " over "
        << fmt("%.3f", spec.width) << " x " << fmt("%.3f m", spec.height) << " (cells "
        << fmt("%.1f", spec.width / spec.columns * 1e3) << " x "
        << fmt("%.1f mm", spec.height / spec.rows * 1e3) << "), capacity "
        << fmt("%.0f kPa", spec.capacity / kPascalPerKilopascal) << ", sampled every "
        << fmt("%.4g s", spec.sample_interval) << '\n';
    const auto loaded = std::count_if(map.cells.begin(), map.cells.end(),
                                      [](const auto& c) { return c.peak_force > 0.0; });
    const auto saturated = std::count_if(map.cells.begin(), map.cells.end(),
                                         [](const auto& c) { return c.saturated; });
    if (loaded == 0) {
        out << "  no cell was loaded\n";
        return;
    }
    const auto peak = std::max_element(
        map.cells.begin(), map.cells.end(),
        [](const auto& a, const auto& b) { return a.sampled_peak_force < b.sampled_peak_force; });
    out << "  " << loaded << " cells loaded, " << saturated << " saturated; highest sampled cell "
        << cell_name(*peak) << ": " << fmt("%.1f N", peak->sampled_peak_force) << " = "
        << fmt("%.1f kPa", peak->sampled_peak_force / map.cell_area / kPascalPerKilopascal)
        << " at " << fmt("%.3f s", map.sample_time(peak->sampled_peak_sample))
        << " (true peak in that cell " << fmt("%.1f N", peak->peak_force) << ")\n";
    double grid_peak = 0.0;
    for (const auto& cell : map.cells) grid_peak += cell.force[map.peak_sample];
    out << "  grid's summed force peaks at " << fmt("%.1f N", grid_peak) << " at "
        << fmt("%.3f s", map.sample_time(map.peak_sample)) << '\n';
    for (const engine::RockCellLoad& load : map.rocks) {
        const engine::RockOutcome& rock = outcome.rocks[load.rock];
        double true_peak = 0.0;
        for (const auto& hit : rock.wall_hits) true_peak = std::max(true_peak, hit.peak_normal_force);
        out << "  rock " << load.rock + 1 << (rock.name.empty() ? "" : " \"" + rock.name + "\"")
            << ": " << load.cells.size() << " cells, sampled peak "
            << fmt("%.1f N", load.sampled_peak_force) << " at "
            << fmt("%.3f s", load.sampled_peak_time) << " (load cell's peak "
            << fmt("%.1f N", true_peak) << ")\n";
    }
}

nlohmann::json pressure_cells_json(const engine::PressureMap& map,
                                   const engine::Outcome& outcome) {
    const engine::PressureCells& spec = map.spec;
    nlohmann::json cells = nlohmann::json::array();
    for (const auto& cell : map.cells) {
        if (cell.peak_force <= 0.0) continue;
        cells.push_back(
            {{"column", cell.column},
             {"row", cell.row},
             {"peak_force_N", cell.peak_force},
             {"peak_time_s", cell.peak_time},
             {"sampled_peak_force_N", cell.sampled_peak_force},
             {"sampled_peak_pressure_kPa",
              cell.sampled_peak_force / map.cell_area / kPascalPerKilopascal},
             {"sampled_peak_time_s", map.sample_time(cell.sampled_peak_sample)},
             {"saturated", cell.saturated}});
    }
    nlohmann::json rocks = nlohmann::json::array();
    for (const engine::RockCellLoad& load : map.rocks) {
        const engine::RockOutcome& rock = outcome.rocks[load.rock];
        rocks.push_back(
            {{"rock", load.rock + 1},
             {"name", rock.name.empty() ? nlohmann::json(nullptr) : nlohmann::json(rock.name)},
             {"cells", load.cells},
             {"sampled_peak_force_N", load.sampled_peak_force},
             {"sampled_peak_time_s", load.sampled_peak_time}});
    }
    nlohmann::json history = nlohmann::json::array();
    for (std::size_t k = 0; k < map.samples; ++k) {
        history.push_back({map.sample_time(k), map.total[k], map.total[k] - map.outside[k]});
    }
    return {{"columns", spec.columns},
            {"rows", spec.rows},
            {"width_m", spec.width},
            {"height_m", spec.height},
            {"capacity_kPa", spec.capacity / kPascalPerKilopascal},
            {"sample_interval_s", spec.sample_interval},
            {"cell_area_m2", map.cell_area},
            {"note", "cells: row-major index row * columns + column, 0-based, column 0 at "
                     "y = -width / 2, row 0 at the wall's foot"},
            {"loaded_cells", cells},
            {"rocks", rocks},
            {"force_history",
             {{"columns", {"start_time_s", "wall_N", "grid_N"}}, {"rows", history}}}};
}

}  // namespace rockfall::report
