// The charts of one results directory drawn together at its end: every chart a writer hands
// drawChart while a ChartBatch is open on the thread is collected, and draw() runs one gnuplot
// per usable core over all of them, instead of one gnuplot per chart. The batch also carries
// the format the charts are drawn in (none: no chart, no script).
#pragma once

#include <filesystem>
#include <vector>

#include "problems/deck/OutputChoices.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor {

class ChartBatch {
 public:
  /// Opens the batch on this thread: drawChart hands its charts here until it closes.
  explicit ChartBatch(ChartFormat format);
  /// Closes it (the batch opened before it, if any, is the thread's again); charts not drawn
  /// yet are dropped, as on an error before draw().
  ~ChartBatch();
  ChartBatch(const ChartBatch&) = delete;
  ChartBatch& operator=(const ChartBatch&) = delete;

  /// Takes a chart to draw into dir; false when the batch draws no charts. Throws
  /// std::invalid_argument for a name outside the directory, as drawChart does.
  bool add(const std::filesystem::path& dir, const ChartScript& chart);
  /// Draws every chart taken so far (drawCharts, one gnuplot per usable core) and forgets
  /// them; returns how many were drawn.
  int draw();

  /// The batch open on this thread, or null.
  static ChartBatch* active();

 private:
  ChartFormat format_;
  ChartBatch* previous_;
  std::vector<std::pair<std::filesystem::path, std::vector<ChartScript>>> charts_;  ///< per dir
};

}  // namespace beamrotor
