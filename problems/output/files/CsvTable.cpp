// CSV tables (see CsvTable.hpp): RFC 4180 quoting, shortest exact decimals.
#include "problems/output/files/CsvTable.hpp"

#include <bit>
#include <charconv>
#include <cmath>
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

void CsvTable::addRow(std::span<const CsvCell> row) {
  if (row.size() != columns_.size())
    throw std::invalid_argument(title_ + ": a row of " + std::to_string(row.size()) +
                                " cells for " + std::to_string(columns_.size()) + " columns");
  for (std::size_t c = 0; c < row.size(); ++c)
    if (const double* x = std::get_if<double>(&row[c]); x && !std::isfinite(*x))
      throw std::runtime_error(title_ + ": column '" + columns_[c].name + "', row " +
                               std::to_string(rowCount() + 1) + " would be " + exactDecimal(*x) +
                               "; only finite numbers are written");
  for (const CsvCell& cell : row) {
    if (const double* x = std::get_if<double>(&cell)) {
      kinds_.push_back(Kind::number);
      payload_.push_back(std::bit_cast<std::uint64_t>(*x));
    } else if (const long long* n = std::get_if<long long>(&cell)) {
      kinds_.push_back(Kind::count);
      payload_.push_back(std::bit_cast<std::uint64_t>(*n));
    } else if (const std::string* text = std::get_if<std::string>(&cell)) {
      kinds_.push_back(Kind::text);
      payload_.push_back(textIndex(*text));
    } else {
      kinds_.push_back(Kind::empty);
      payload_.push_back(0);
    }
  }
}

void CsvTable::reserveRows(std::size_t rows) {
  kinds_.reserve(rows * columns_.size());
  payload_.reserve(rows * columns_.size());
}

std::uint64_t CsvTable::textIndex(const std::string& text) {
  const auto [at, added] = textIndices_.try_emplace(text, texts_.size());
  if (added) texts_.push_back(text);
  return at->second;
}

double CsvTable::numberAt(std::size_t index) const {
  return std::bit_cast<double>(payload_[index]);
}

CsvCell CsvTable::cell(std::size_t row, std::size_t column) const {
  if (column >= columns_.size() || row >= rowCount())
    throw std::out_of_range(title_ + ": no such cell");
  const std::size_t i = row * columns_.size() + column;
  switch (kinds_[i]) {
    case Kind::number: return numberAt(i);
    case Kind::count: return std::bit_cast<long long>(payload_[i]);
    case Kind::text: return texts_[payload_[i]];
    case Kind::empty: break;
  }
  return std::monostate{};
}

void CsvTable::convertColumn(std::size_t column, double factor, std::string unit) {
  if (column >= columns_.size()) throw std::out_of_range(title_ + ": no such column");
  columns_[column].unit = std::move(unit);
  if (factor == 1) return;
  for (std::size_t i = column; i < kinds_.size(); i += columns_.size()) {
    if (kinds_[i] != Kind::number) continue;
    const double x = numberAt(i) * factor;
    if (!std::isfinite(x))
      throw std::runtime_error(title_ + ": column '" + columns_[column].name + "', row " +
                               std::to_string(i / columns_.size() + 1) + " would be " +
                               exactDecimal(x) + "; only finite numbers are written");
    payload_[i] = std::bit_cast<std::uint64_t>(x);
  }
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
  const std::size_t c = std::size_t(column(name) - 1);
  std::vector<double> values;
  values.reserve(rowCount());
  for (std::size_t i = c; i < kinds_.size(); i += columns_.size()) {
    if (kinds_[i] == Kind::number)
      values.push_back(numberAt(i));
    else if (kinds_[i] == Kind::count)
      values.push_back(double(std::bit_cast<long long>(payload_[i])));
    else if (kinds_[i] == Kind::empty)
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
  writeColumnsTo(out);
  writeRowsTo(out);
}

void CsvTable::writeColumnsTo(std::ostream& out) const {
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
}

void CsvTable::writeRowsTo(std::ostream& out) const {
  // A row at a time into a buffer, one stream write each (a large table has 10^7 cells).
  // Each distinct text's field once.
  std::vector<std::string> fields;
  fields.reserve(texts_.size());
  for (const std::string& text : texts_) fields.push_back(csvField(text));
  char buffer[32];
  std::string line;
  const std::size_t width = columns_.size();
  for (std::size_t first = 0; first < kinds_.size(); first += width) {
    line.clear();
    for (std::size_t i = first; i < first + width; ++i) {
      if (i > first) line += ',';
      switch (kinds_[i]) {
        case Kind::number: line.append(buffer, decimalInto(buffer, numberAt(i))); break;
        case Kind::count: {
          const auto [end, error] =
              std::to_chars(buffer, buffer + sizeof buffer, std::bit_cast<long long>(payload_[i]));
          line.append(buffer, end);
          break;
        }
        case Kind::text: line += fields[payload_[i]]; break;
        case Kind::empty: break;
      }
    }
    line += '\n';
    out.write(line.data(), std::streamsize(line.size()));
  }
}

}  // namespace beamrotor
