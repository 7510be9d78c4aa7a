// File names of a results directory (see FileNames.hpp).
#include "problems/output/files/FileNames.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace beamrotor {

std::string fileStem(const std::string& analysisName) {
  std::string stem = analysisName;
  for (char& c : stem) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_' || c == '.';
    if (!safe) c = '_';
  }
  // A stem of dots only would name the directory itself or its parent.
  if (stem.find_first_not_of('.') == std::string::npos) stem = "analysis" + stem;
  return stem;
}

void requireDistinctFileStems(const std::vector<AnalysisOutcome>& analyses) {
  std::map<std::string, std::string> seen;  // stem -> the analysis name that took it
  for (const AnalysisOutcome& a : analyses) {
    const auto [it, inserted] = seen.emplace(fileStem(a.name), a.name);
    if (!inserted)
      throw std::invalid_argument("analyses '" + it->second + "' and '" + a.name +
                                  "' would write the same files ('" + it->first +
                                  "'); give them distinct names");
  }
}

namespace {

/// stem_kind_007.vtu: numbered files that sort in order.
std::string numberedVtu(const std::string& stem, const char* kind, int number, int digits) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "%0*d", digits, number);
  return stem + "_" + kind + "_" + buffer + ".vtu";
}

}  // namespace

std::string modeVtu(const std::string& stem, int number) {
  return numberedVtu(stem, "mode", number, 2);
}

std::string caseVtu(const std::string& stem, int number) {
  return numberedVtu(stem, "case", number, 2);
}

std::string caseFrameChart(const std::string& stem, int number) {
  const std::string vtu = caseVtu(stem, number);
  std::string name = stem;
  name += "_frame";
  name += vtu.substr(stem.size(), vtu.size() - stem.size() - 4);  // "_case_NN"
  return name;
}

std::string frameVtu(const std::string& stem, int number) {
  return numberedVtu(stem, "frame", number, 4);
}

std::string sweepValueDirectory(std::size_t index, std::size_t count) {
  const int width = std::max<int>(3, int(std::to_string(count > 0 ? count - 1 : 0).size()));
  std::string digits = std::to_string(index);
  return "value_" + std::string(std::max<int>(0, width - int(digits.size())), '0') + digits;
}

std::string sweepFieldsCsv(const std::string& stem, std::size_t index, std::size_t count) {
  std::string file = stem + "_fields_";
  file += sweepValueDirectory(index, count);
  return file + ".csv";
}

}  // namespace beamrotor
