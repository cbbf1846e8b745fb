// Header-named CSV reading with file, line and column in every message (see csv_table.hpp).

#include "scenario/csv_table.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <system_error>

namespace rockfall::scenario {
namespace {

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}

std::vector<std::string> split(std::string_view line) {
    std::vector<std::string> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        fields.emplace_back(trim(line.substr(start, comma - start)));
        if (comma == std::string_view::npos) return fields;
        start = comma + 1;
    }
}

bool skipped(std::string_view line) {
    const std::string_view t = trim(line);
    return t.empty() || t.front() == '#';
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
    return out;
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw CsvError(path.string() + ": cannot open the file for reading");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw CsvError(path.string() + ": read error");
    return parse(text.str(), path.string());
}

CsvTable CsvTable::parse(std::string_view text, std::string source) {
    CsvTable table;
    table.source_ = std::move(source);
    // Spreadsheets often save UTF-8 with a byte-order mark, which would glue onto the first
    // column's name.
    constexpr std::string_view bom = "\xEF\xBB\xBF";
    if (text.substr(0, bom.size()) == bom) text.remove_prefix(bom.size());
    std::size_t line_number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++line_number;
        if (skipped(line)) continue;
        std::vector<std::string> fields = split(line);
        if (table.header_.empty()) {
            table.header_ = std::move(fields);
            table.header_line_ = line_number;
            continue;
        }
        if (fields.size() != table.header_.size()) {
            throw CsvError(table.source_ + ':' + std::to_string(line_number) + ": " +
                           std::to_string(fields.size()) + " fields, but the header (line " +
                           std::to_string(table.header_line_) + ") names " +
                           std::to_string(table.header_.size()) + " columns");
        }
        table.rows_.push_back(std::move(fields));
        table.lines_.push_back(line_number);
    }
    if (table.header_.empty()) {
        throw CsvError(table.source_ +
                       ": empty file: expected a header line naming the columns, then one "
                       "line per row");
    }
    return table;
}

std::optional<std::size_t> CsvTable::find(std::string_view name) const {
    for (std::size_t i = 0; i < header_.size(); ++i) {
        if (header_[i] == name) return i;
    }
    return std::nullopt;
}

std::size_t CsvTable::require(std::string_view name) const {
    if (const auto column = find(name)) return *column;
    throw CsvError(source_ + ':' + std::to_string(header_line_) + ": missing column " +
                   std::string(name) + " (the header names: " + joined(header_) + ")");
}

const std::string& CsvTable::text(std::size_t row, std::size_t column) const {
    return rows_.at(row).at(column);
}

double CsvTable::number(std::size_t row, std::size_t column) const {
    const std::string& field = text(row, column);
    double value = 0.0;
    const char* end = field.data() + field.size();
    const auto [stop, error] = std::from_chars(field.data(), end, value);
    if (field.empty() || error != std::errc() || stop != end || !std::isfinite(value)) {
        throw CsvError(where(row, column) + " = \"" + field + "\": not a finite number");
    }
    return value;
}

std::string CsvTable::where(std::size_t row, std::size_t column) const {
    return source_ + ':' + std::to_string(lines_.at(row)) + ": column " +
           std::to_string(column + 1) + " (" + header_.at(column) + ')';
}

}  // namespace rockfall::scenario
