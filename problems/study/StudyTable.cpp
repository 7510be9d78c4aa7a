#include "problems/study/StudyTable.hpp"

#include <cmath>
#include <cstdio>

namespace beamrotor {

namespace {

/// A CSV cell: quoted (quotes doubled) when it holds a comma, a quote or a space.
std::string studyCell(const std::string& text) {
  if (text.find_first_of(",\" ") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

void appendNumber(std::string& line, double v) {
  line += ',';
  if (std::isnan(v)) return;
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  line += text;
}

}  // namespace

std::string studyCsvHeader(const StudyPlan& plan) {
  std::string line = "point";
  // Appended piece by piece: `"," + temporary` trips GCC 12's false -Wrestrict when inlined.
  const auto appendCell = [&line](const std::string& text) {
    line += ',';
    line += studyCell(text);
  };
  for (const std::string& name : plan.parameterNames) appendCell(name);
  for (const StudyOutput& o : plan.spec.outputs) appendCell(o.text);
  for (const std::string& name : plan.checkNames) {
    appendCell(name);
    appendCell(name + " pass");
  }
  return line + ",status\n";
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
  return line + "," + studyCell(row.status) + "\n";
}

}  // namespace beamrotor
