// A small typed table written as CSV (RFC 4180): a line of column names, a comment line of
// their units ("# units: m,m,,rad"; a unitless column's unit is empty) and one row per record;
// text is quoted only where CSV or a reader needs it. The charts read the same table, asking
// for a column's position by name, so a chart never plots a column the table does not have.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <ostream>
#include <span>
#include <string>
#include <stdexcept>
#include <string_view>
#include <unordered_map>
#include <variant>
#include <vector>

namespace beamrotor {

struct CsvColumn {
  std::string name;  ///< e.g. "uy"
  std::string unit;  ///< e.g. "m"; empty for counts and text
};

/// A number, a count, a text (quoted in the file) or an empty cell: a value that a table
/// cannot hold as a number by definition (FORMAT.md: the infinite log decrement of an
/// overdamped mode, a critical speed a sweep value does not find). NaN stays refused.
using CsvCell = std::variant<double, long long, std::string, std::monostate>;

class CsvTable {
 public:
  /// `title` names the table in error messages (normally its file name).
  CsvTable(std::string title, std::vector<CsvColumn> columns);

  /// Appends a row. Throws std::invalid_argument for a row of the wrong width and
  /// std::runtime_error for a NaN or infinite number (naming the column and row), so a table
  /// that exists holds only finite numbers.
  void addRow(std::span<const CsvCell> row);
  void addRow(std::initializer_list<CsvCell> row) { addRow(std::span(row.begin(), row.size())); }
  /// Room for `rows` rows in all, so that a large table grows without copying itself.
  void reserveRows(std::size_t rows);

  /// Multiplies the numbers of a column (0-based position) by `factor` and names its unit
  /// `unit` (a table shown in other units, TableUnits.hpp); counts, texts and empty cells stay.
  void convertColumn(std::size_t column, double factor, std::string unit);

  /// 1-based position of a column (gnuplot's numbering); throws std::out_of_range if absent.
  int column(std::string_view name) const;
  bool hasColumn(std::string_view name) const;
  /// The numeric values of a column (counts converted, an empty cell NaN, which gnuplot's
  /// `valid()`, NumPy and std::isfinite all treat as missing; throws for a text column).
  std::vector<double> numbers(std::string_view name) const;

  /// The cell of a row (0-based) and column (0-based position).
  CsvCell cell(std::size_t row, std::size_t column) const;

  const std::string& title() const { return title_; }
  const std::vector<CsvColumn>& columns() const { return columns_; }
  std::size_t rowCount() const { return columns_.empty() ? 0 : kinds_.size() / columns_.size(); }

  /// Writes the table; numbers in the shortest form that reads back exactly.
  /// Throws std::runtime_error when the file cannot be written.
  void write(const std::filesystem::path& file) const;
  /// The same text onto a stream.
  void writeTo(std::ostream& out) const;
  /// Its two parts: the column names (and their units' line), then the rows, so that a table
  /// written a part at a time (the load cases' rows as results.json goes by) has one head.
  void writeColumnsTo(std::ostream& out) const;
  void writeRowsTo(std::ostream& out) const;

 private:
  /// What a cell holds; its payload is a number's or a count's bits or a text's index.
  enum class Kind : std::uint8_t { number, count, text, empty };
  /// The index of `text` in texts_, added when new: a text repeated down a table (a member's
  /// name on each of its rows, the combination governing an envelope) is held once.
  std::uint64_t textIndex(const std::string& text);
  double numberAt(std::size_t index) const;

  std::string title_;
  std::vector<CsvColumn> columns_;
  // Row by row, 9 bytes a cell (a variant with a string would take 40): the kind of each cell
  // and its payload, in two arrays that grow without an allocation per row.
  std::vector<Kind> kinds_;
  std::vector<std::uint64_t> payload_;
  std::vector<std::string> texts_;
  std::unordered_map<std::string, std::uint64_t> textIndices_;  ///< text -> index in texts_
};

/// A text cell or column name as written: bare, unless RFC 4180 needs quotes (a comma, a
/// quote, a line break; quotes inside doubled) or a reader would take it otherwise (a '#'
/// starts a comment for NumPy and gnuplot; spaces at either end are trimmed by some readers).
std::string csvField(const std::string& text);

/// The shortest decimal text that reads back as exactly x (std::to_chars); -0 is written 0.
std::string exactDecimal(double x);

}  // namespace beamrotor
