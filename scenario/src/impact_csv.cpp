// Impact rows from a header-named CSV file (see impact_csv.hpp).

#include "scenario/impact_csv.hpp"

#include <cstddef>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rockfall::scenario {
namespace {

constexpr double n_per_kn = 1.0e3;

// A numeric field that must be > 0, in the unit its column name gives.
double positive(const CsvTable& table, std::size_t row, std::size_t column, const char* unit) {
    const double value = table.number(row, column);
    if (value > 0.0) return value;
    std::ostringstream message;
    message << table.where(row, column) << " = " << value << ' ' << unit << ": must be > 0";
    throw CsvError(message.str());
}

}  // namespace

std::vector<risk::ImpactRow> impact_rows(const CsvTable& table) {
    const std::size_t velocity = table.require("velocity_m_s");
    const std::optional<std::size_t> force_kn = table.find("peak_force_kN");
    const std::optional<std::size_t> force_n = table.find("peak_force_N");
    if (force_kn.has_value() == force_n.has_value()) {
        throw CsvError(table.source() + ": the header must name exactly one of peak_force_kN " +
                       "and peak_force_N (" + (force_kn ? "it names both" : "it names neither") +
                       ")");
    }
    const std::size_t force = force_kn ? *force_kn : *force_n;
    const double force_scale = force_kn ? n_per_kn : 1.0;
    const std::size_t mass = table.require("mass_kg");
    const std::size_t shape = table.require("shape");
    if (table.rows() == 0) throw CsvError(table.source() + ": no data rows after the header");

    std::vector<risk::ImpactRow> rows;
    rows.reserve(table.rows());
    for (std::size_t r = 0; r < table.rows(); ++r) {
        risk::ImpactRow row;
        row.velocity = positive(table, r, velocity, "m/s");
        row.peak_force = positive(table, r, force, force_kn ? "kN" : "N") * force_scale;
        row.mass = positive(table, r, mass, "kg");
        try {
            row.shape = risk::parse_impact_shape(table.text(r, shape));
        } catch (const std::invalid_argument& e) {
            throw CsvError(table.where(r, shape) + ": " + e.what());
        }
        rows.push_back(row);
    }
    return rows;
}

std::vector<risk::ImpactRow> read_impact_csv(const std::filesystem::path& path) {
    return impact_rows(CsvTable::read(path));
}

risk::DesignSample read_design_sample(const std::filesystem::path& path) {
    const CsvTable table = CsvTable::read(path);
    const std::size_t v_column = table.require("velocity_m_s");
    const std::size_t h_column = table.require("bounce_height_m");
    risk::DesignSample sample;
    sample.source = table.source();
    for (std::size_t row = 0; row < table.rows(); ++row) {
        for (const std::size_t column : {v_column, h_column}) {
            if (table.number(row, column) < 0.0) {
                throw CsvError(table.where(row, column) + " = " + table.text(row, column) +
                               ": must be >= 0");
            }
        }
        sample.speeds.push_back(table.number(row, v_column));
        sample.heights.push_back(table.number(row, h_column));
    }
    if (sample.speeds.empty()) throw CsvError(table.source() + ": no data rows after the header");
    return sample;
}

}  // namespace rockfall::scenario
