// Measured wall-load records (see load_record.hpp).

#include "scenario/load_record.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

namespace rockfall::scenario {
namespace {

using risk::LoadHistory;

constexpr double n_per_kn = 1.0e3;

struct LoadColumn {
    const char* name;
    double scale;  // to N or N/m
    bool per_metre;
};
constexpr std::array<LoadColumn, 4> load_columns{{{"load_kN", n_per_kn, false},
                                                  {"load_N", 1.0, false},
                                                  {"load_kN_per_m", n_per_kn, true},
                                                  {"load_N_per_m", 1.0, true}}};

std::string column_names() {
    std::string names;
    for (const LoadColumn& c : load_columns) {
        names += (names.empty() ? "" : ", ") + std::string(c.name);
    }
    return names;
}

}  // namespace

LoadHistory measured_history(const CsvTable& table) {
    const std::size_t time = table.require("time_s");
    std::optional<LoadColumn> chosen;
    std::size_t load = 0;
    for (const LoadColumn& c : load_columns) {
        if (const std::optional<std::size_t> index = table.find(c.name)) {
            if (chosen) {
                throw CsvError(table.source() + ": the header names both " + chosen->name +
                               " and " + c.name + "; give exactly one load column of " +
                               column_names());
            }
            chosen = c;
            load = *index;
        }
    }
    if (!chosen) {
        throw CsvError(table.source() + ": the header names no load column; give exactly one of " +
                       column_names());
    }
    if (table.rows() < 2) {
        throw CsvError(table.source() + ": a history needs at least two data rows (it has " +
                       std::to_string(table.rows()) + ")");
    }
    LoadHistory h;
    h.source = table.source();
    h.per_metre = chosen->per_metre;
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const double t = table.number(r, time);
        if (t < 0.0 || (!h.time.empty() && t <= h.time.back())) {
            std::ostringstream message;
            message << table.where(r, time) << " = " << t << " s: times must be >= 0 and increase "
                    << "from row to row (since the release)";
            if (!h.time.empty()) message << "; the row before has " << h.time.back() << " s";
            throw CsvError(message.str());
        }
        h.time.push_back(t);
        h.load.push_back(table.number(r, load) * chosen->scale);
    }
    return h;
}

LoadHistory read_measured_history(const std::filesystem::path& path) {
    return measured_history(CsvTable::read(path));
}

}  // namespace rockfall::scenario
