#include "report/query_table.hpp"

#include "report/text_format.hpp"

#include "risk/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace rockfall::report {
namespace {

bool is_number(const Cell& cell) { return !std::holds_alternative<std::string>(cell); }

// Reals as text: `real_format` for people, or (null) the shortest text that reads back as the
// same double, for CSV.
std::string cell_text(const Cell& cell, const char* real_format, const char* missing) {
    return std::visit(
        [&](const auto& value) -> std::string {
            using T = std::decay_t<decltype(value)>;
            if constexpr (std::is_same_v<T, std::monostate>) {
                return missing;
            } else if constexpr (std::is_same_v<T, double>) {
                if (std::isnan(value)) return missing;
                if (real_format != nullptr) return fmt(real_format, value);
                return risk::number_text(value);
            } else if constexpr (std::is_same_v<T, std::string>) {
                return value;
            } else {
                return std::to_string(value);
            }
        },
        cell);
}

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

}  // namespace

void print_text(std::ostream& out, const Table& table) {
    std::vector<std::vector<std::string>> cells;
    std::vector<std::size_t> widths;
    for (const std::string& column : table.columns) widths.push_back(column.size());
    for (const auto& row : table.rows) {
        auto& texts = cells.emplace_back();
        for (std::size_t c = 0; c < row.size(); ++c) {
            texts.push_back(cell_text(row[c], "%.6g", "-"));
            widths[c] = std::max(widths[c], texts.back().size());
        }
    }
    const auto pad = [&](const std::string& text, std::size_t c, bool right) {
        const std::string fill(widths[c] - text.size(), ' ');
        return right ? fill + text : text + fill;
    };
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
        const bool right = !table.rows.empty() && is_number(table.rows[0][c]);
        out << (c == 0 ? "" : "  ") << pad(table.columns[c], c, right);
    }
    out << '\n';
    for (std::size_t r = 0; r < cells.size(); ++r) {
        for (std::size_t c = 0; c < cells[r].size(); ++c) {
            out << (c == 0 ? "" : "  ") << pad(cells[r][c], c, is_number(table.rows[r][c]));
        }
        out << '\n';
    }
}

void print_csv(std::ostream& out, const Table& table) {
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
        out << (c == 0 ? "" : ",") << csv_field(table.columns[c]);
    }
    out << '\n';
    for (const auto& row : table.rows) {
        for (std::size_t c = 0; c < row.size(); ++c) {
            out << (c == 0 ? "" : ",") << csv_field(cell_text(row[c], nullptr, ""));
        }
        out << '\n';
    }
}

nlohmann::ordered_json rows_json(const Table& table) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const auto& row : table.rows) {
        nlohmann::ordered_json object = nlohmann::ordered_json::object();
        for (std::size_t c = 0; c < row.size(); ++c) {
            std::visit(
                [&](const auto& value) {
                    using T = std::decay_t<decltype(value)>;
                    if constexpr (std::is_same_v<T, std::monostate>) {
                        object[table.columns[c]] = nullptr;
                    } else if constexpr (std::is_same_v<T, double>) {
                        object[table.columns[c]] = json_number(value);
                    } else {
                        object[table.columns[c]] = value;
                    }
                },
                row[c]);
        }
        rows.push_back(std::move(object));
    }
    return rows;
}

std::string unit_suffix(const std::string& unit) {
    std::string suffix = unit;
    std::replace(suffix.begin(), suffix.end(), '/', '_');
    std::replace(suffix.begin(), suffix.end(), ' ', '_');
    return suffix;
}

std::string percent_text(double share) { return fmt("%.3g", 100.0 * share); }

nlohmann::ordered_json json_number(double value) {
    return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json();
}

}  // namespace rockfall::report
