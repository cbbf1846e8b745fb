#pragma once
/// A table of query results written as aligned text, CSV or JSON rows: one code path for the
/// three formats of `rockfall query`. Column names carry their units ("reach_m").

#include <nlohmann/json.hpp>

#include <cstdint>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

namespace rockfall::report {

/// One value: empty, an integer, a real (NaN is empty) or text.
using Cell = std::variant<std::monostate, std::int64_t, std::uint64_t, double, std::string>;

/// Columns and rows of equal length.
struct Table {
    /// Column names, with units.
    std::vector<std::string> columns;
    /// Rows, one Cell per column.
    std::vector<std::vector<Cell>> rows;
};

/// Output format of `rockfall query`.
enum class QueryFormat {
    text,  ///< readable lines and an aligned table
    csv,   ///< RFC 4180: one header row, then the rows; empty cells for missing values
    json,  ///< one JSON document
};

/// Aligned columns under a header line; reals with 6 significant digits, "-" when missing.
void print_text(std::ostream& out, const Table& table);

/// CSV with reals as the shortest text that reads back exactly.
void print_csv(std::ostream& out, const Table& table);

/// The rows as an array of objects keyed by column name; missing values are null.
nlohmann::ordered_json rows_json(const Table& table);

/// A unit as a column-name suffix: "m/s" -> "m_s", "N s" -> "N_s".
std::string unit_suffix(const std::string& unit);

/// A share in [0, 1] as a percentage with 3 significant digits ("4.5" for 0.045).
std::string percent_text(double share);

/// A JSON number, or null for NaN or an infinity (a missing value or an open bound).
nlohmann::ordered_json json_number(double value);

}  // namespace rockfall::report
