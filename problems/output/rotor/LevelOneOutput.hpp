// The files of a level1-stability analysis (API 684 Level I screening): the least log
// decrement against added cross-coupling as a table and a chart, with Qa and Q0 marked, and
// the machine on API 617's map of the critical speed ratio against the average gas density.
#pragma once

#include <string>

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/run/RotorRunResult.hpp"

namespace beamrotor {

inline std::string levelOneCsv(const std::string& stem) {
  return stem + "_level1.csv";
}
inline std::string levelOneChart(const std::string& stem) {
  return stem + "_level1";
}
inline std::string criticalSpeedRatioChart(const std::string& stem) {
  return stem + "_csr_map";
}

/// Columns cross_coupling (N/m), log_decrement: the screening's curve.
CsvTable levelOneTable(const std::string& title, const LevelOneResult& r);

/// The least log decrement against added cross-coupling, with Qa, Q0 (when found) and the
/// 0.1 line marked.
ChartScript levelOneDiagram(const std::string& caption, const std::string& chartName,
                            const LevelOneResult& r, const std::string& csvFile,
                            const OutputUnits& units = {});

/// API 617's map of the critical speed ratio against the average gas density: the boundary of
/// regions A and B, and the machine's point.
ChartScript criticalSpeedRatioDiagram(const std::string& caption, const std::string& chartName,
                                      const CriticalSpeedRatioPoint& p);

/// "pass", or what sends the machine to Level II.
std::string levelOneVerdict(const LevelOneResult& r);

}  // namespace beamrotor
