#include "problems/study/StudyTable.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include "problems/deck/ShownFieldUnit.hpp"
#include "problems/output/files/CsvTable.hpp"

namespace beamrotor {

namespace {

void appendNumber(std::string& line, double v) {
  line += ',';
  if (std::isnan(v)) return;
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  line += text;
}

}  // namespace

std::string studyCsvHeader(const StudyPlan& plan) {
  std::string names = "point", units = "# units: ";
  bool anyUnit = false;
  // Appended piece by piece: `"," + temporary` trips GCC 12's false -Wrestrict when inlined.
  const auto appendColumn = [&](const std::string& name, const std::string& unit) {
    names += ',';
    names += csvField(name);
    units += ',';
    units += csvField(unit);
    anyUnit = anyUnit || !unit.empty();
  };
  for (std::size_t k = 0; k < plan.parameterNames.size(); ++k)
    appendColumn(plan.parameterNames[k], bareUnitName(plan.parameterUnits.at(k)));
  for (std::size_t k = 0; k < plan.spec.outputs.size(); ++k)
    appendColumn(plan.spec.outputs[k].text, bareUnitName(plan.outputUnits.at(k)));
  for (std::size_t k = 0; k < plan.checkNames.size(); ++k) {
    appendColumn(plan.checkNames[k], bareUnitName(plan.checkUnits.at(k)));
    appendColumn(plan.checkNames[k] + " pass", "");
  }
  appendColumn("status", "");
  names += '\n';
  if (!anyUnit) return names;
  units += '\n';
  return names + units;
}

std::string studyCsvRow(const StudyRow& row) {
  std::string line = std::to_string(row.index);
  for (double v : row.parameters) appendNumber(line, v);
  for (double v : row.outputs) appendNumber(line, v);
  for (std::size_t k = 0; k < row.checks.size(); ++k) {
    appendNumber(line, row.checks[k]);
    line += ',';
    if (row.passed[k] >= 0) line += row.passed[k] ? '1' : '0';
  }
  return line + "," + csvField(row.status) + "\n";
}

namespace {

/// The cells of a line written by studyCsvRow: split at commas outside quotes, quotes undone.
std::optional<std::vector<std::string>> splitCells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch != '"') {
        cells.back() += ch;
      } else if (i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else {
        quoted = false;
      }
    } else if (ch == '"' && cells.back().empty()) {
      quoted = true;
    } else if (ch == ',') {
      cells.emplace_back();
    } else {
      cells.back() += ch;
    }
  }
  if (quoted) return std::nullopt;
  return cells;
}

/// A number as appendNumber writes it: "" is NaN; anything else must be a whole number text.
bool readNumber(const std::string& cell, double& value) {
  if (cell.empty()) {
    value = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtod(cell.c_str(), &end);
  return end == cell.c_str() + cell.size() && errno != ERANGE && std::isfinite(value);
}

}  // namespace

std::optional<StudyRow> parseStudyCsvRow(const std::string& line, const StudyRow& shape) {
  const auto cells = splitCells(line);
  const std::size_t parameters = shape.parameters.size(), outputs = shape.outputs.size(),
                    checks = shape.checks.size();
  if (!cells || cells->size() != 2 + parameters + outputs + 2 * checks) return std::nullopt;
  const std::vector<std::string>& c = *cells;
  StudyRow row = shape;
  const std::string& index = c[0];
  if (index.empty() || index.size() > 18 ||
      index.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  row.index = std::stoll(index);
  std::size_t k = 1;
  for (double& v : row.parameters)
    if (!readNumber(c[k++], v) || std::isnan(v)) return std::nullopt;
  for (double& v : row.outputs)
    if (!readNumber(c[k++], v)) return std::nullopt;
  for (std::size_t j = 0; j < checks; ++j) {
    if (!readNumber(c[k++], row.checks[j])) return std::nullopt;
    const std::string& pass = c[k++];
    if (pass != "" && pass != "0" && pass != "1") return std::nullopt;
    row.passed[j] = pass.empty() ? -1 : pass == "1" ? 1 : 0;
  }
  row.status = c[k];
  if (row.status.empty()) return std::nullopt;
  row.cost = {};
  return row;
}

}  // namespace beamrotor
