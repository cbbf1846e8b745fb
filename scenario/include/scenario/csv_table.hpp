#pragma once
/// A small reader for the CSV files engineers hand to the program (measured impacts, samples
/// of speeds and heights): a header line names the columns, so their order is free and extra
/// columns are ignored; every problem is reported with the file, line and column.
///
/// Format: fields separated by commas and trimmed of blanks; no quoting (no field may contain
/// a comma); lines that are blank or start with '#' are skipped anywhere in the file; a UTF-8
/// byte-order mark and CR LF line ends are accepted.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rockfall::scenario {

/// Bad CSV input; the message names the file, line and column. Exit code 2 in the program.
class CsvError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

/// The header and data rows of a CSV file, as text, with the line number of every row.
class CsvTable {
  public:
    /// Reads and splits a file; throws CsvError when it cannot be read, has no header line or
    /// has a row whose number of fields differs from the header's.
    static CsvTable read(const std::filesystem::path& path);
    /// The same from text; `source` names it in messages (a file name).
    static CsvTable parse(std::string_view text, std::string source);

    /// The name of the source, for messages.
    const std::string& source() const { return source_; }
    /// The column names, in file order.
    const std::vector<std::string>& header() const { return header_; }
    /// Number of data rows (may be 0).
    std::size_t rows() const { return rows_.size(); }

    /// Index of the column with this exact name, if the header has it.
    std::optional<std::size_t> find(std::string_view name) const;
    /// Index of the column; throws CsvError "FILE:LINE: missing column NAME (header: ...)"
    /// naming the header line.
    std::size_t require(std::string_view name) const;

    /// The text of a field (trimmed).
    const std::string& text(std::size_t row, std::size_t column) const;
    /// A field as a finite number; throws CsvError naming the line, the column (1-based
    /// number and name) and the text when it is not one.
    double number(std::size_t row, std::size_t column) const;
    /// "FILE:LINE: column N (NAME)" for a field, to start a message about its value.
    std::string where(std::size_t row, std::size_t column) const;

  private:
    std::string source_;
    std::size_t header_line_ = 0;
    std::vector<std::string> header_;
    std::vector<std::vector<std::string>> rows_;
    std::vector<std::size_t> lines_;
};

}  // namespace rockfall::scenario
