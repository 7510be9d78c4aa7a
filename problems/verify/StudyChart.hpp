// A failure-case study as a chart: named series of (x, y) points, each written as a CSV table
// (CsvTable) and drawn by gnuplot (drawChart) on log or linear axes, with the sentence the
// report prints under it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace beamrotor::verify {

struct StudySeries {
  std::string title;  ///< key entry
  std::vector<double> x, y;
  bool rightAxis = false;  ///< drawn against the y2 axis (dashed)
};

struct StudyChart {
  std::string name;     ///< file stem, e.g. "shear_locking_slenderness"
  std::string title;    ///< heading above the chart
  std::string caption;  ///< one sentence saying what the chart shows
  std::string xLabel, yLabel, y2Label;
  bool logX = true, logY = true;
  std::vector<StudySeries> series;
};

/// Writes dir/<name>-<k>.csv per series (columns x, y) and draws dir/<name>.svg and .png.
/// Returns whether gnuplot drew the chart, or, inside a ChartBatch, took it (see drawChart).
bool writeStudyChart(const std::filesystem::path& dir, const StudyChart& chart);

}  // namespace beamrotor::verify
