// CSV tables (see CsvTable.hpp): RFC 4180 quoting, shortest exact decimals.
#include "problems/output/files/CsvTable.hpp"

#include <charconv>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "problems/output/files/FileWriting.hpp"

namespace beamrotor {

namespace {

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';  // RFC 4180: a quote inside a quoted field is doubled
    out += c;
  }
  return out + "\"";
}

/// The shortest exact decimal of x into buffer; returns its end.
char* decimalInto(char (&buffer)[32], double x) {
  if (x == 0) x = 0.0;  // "-0" (from negating a zero force) reads as a sign error to a person
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
  if (error != std::errc()) throw std::logic_error("to_chars failed");
  return end;
}

}  // namespace

std::string csvField(const std::string& text) {
  const bool plain = text.find_first_of(",\"\n\r#") == std::string::npos &&
                     (text.empty() || (text.front() != ' ' && text.back() != ' '));
  return plain ? text : quoted(text);
}

std::string exactDecimal(double x) {
  char buffer[32];
  return std::string(buffer, decimalInto(buffer, x));
}

CsvTable::CsvTable(std::string title, std::vector<CsvColumn> columns)
    : title_(std::move(title)), columns_(std::move(columns)) {}

void CsvTable::addRow(std::vector<CsvCell> row) {
  if (row.size() != columns_.size())
    throw std::invalid_argument(title_ + ": a row of " + std::to_string(row.size()) +
                                " cells for " + std::to_string(columns_.size()) + " columns");
  for (std::size_t c = 0; c < row.size(); ++c)
    if (const double* x = std::get_if<double>(&row[c]); x && !std::isfinite(*x))
      throw std::runtime_error(title_ + ": column '" + columns_[c].name + "', row " +
                               std::to_string(rowCount() + 1) + " would be " + exactDecimal(*x) +
                               "; only finite numbers are written");
  cells_.insert(cells_.end(), std::make_move_iterator(row.begin()),
                std::make_move_iterator(row.end()));
}

bool CsvTable::hasColumn(std::string_view name) const {
  for (const CsvColumn& c : columns_)
    if (c.name == name) return true;
  return false;
}

int CsvTable::column(std::string_view name) const {
  for (std::size_t c = 0; c < columns_.size(); ++c)
    if (columns_[c].name == name) return int(c) + 1;
  throw std::out_of_range(title_ + " has no column '" + std::string(name) + "'");
}

std::vector<double> CsvTable::numbers(std::string_view name) const {
  const int c = column(name) - 1;
  std::vector<double> values;
  values.reserve(rowCount());
  for (std::size_t r = 0; r < rowCount(); ++r) {
    const CsvCell& value = cell(r, std::size_t(c));
    if (const double* x = std::get_if<double>(&value))
      values.push_back(*x);
    else if (const long long* n = std::get_if<long long>(&value))
      values.push_back(double(*n));
    else if (std::holds_alternative<std::monostate>(value))
      values.push_back(std::numeric_limits<double>::quiet_NaN());
    else
      throw std::invalid_argument(title_ + ": column '" + std::string(name) + "' holds text");
  }
  return values;
}

void CsvTable::write(const std::filesystem::path& file) const {
  writeFile(file, [&](std::ostream& out) { writeTo(out); });
}

void CsvTable::writeTo(std::ostream& out) const {
  // The names, then their units on a comment line (skipped by gnuplot, NumPy's genfromtxt and
  // pandas' read_csv(comment='#')), so that a name reads as a name: "speed", not "speed_rpm".
  std::string names, units = "# units: ";
  bool anyUnit = false;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    if (c) names += ',', units += ',';
    names += csvField(columns_[c].name);
    units += csvField(columns_[c].unit);
    anyUnit = anyUnit || !columns_[c].unit.empty();
  }
  out << names << '\n';
  if (anyUnit) out << units << '\n';
  // A row at a time into a buffer, one stream write each (a large table has 10^7 cells).
  char buffer[32];
  std::string line;
  for (std::size_t r = 0; r < rowCount(); ++r) {
    line.clear();
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      if (c) line += ',';
      const CsvCell& value = cell(r, c);
      if (const double* x = std::get_if<double>(&value))
        line.append(buffer, decimalInto(buffer, *x));
      else if (const long long* n = std::get_if<long long>(&value))
        line += std::to_string(*n);
      else if (const std::string* text = std::get_if<std::string>(&value))
        line += csvField(*text);
    }
    line += '\n';
    out.write(line.data(), std::streamsize(line.size()));
  }
}

}  // namespace beamrotor
