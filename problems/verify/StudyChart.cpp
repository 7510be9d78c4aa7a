#include "problems/verify/StudyChart.hpp"

#include <sstream>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor::verify {

namespace {

std::string seriesFile(const StudyChart& chart, std::size_t k) {
  return chart.name + "-" + std::to_string(k + 1) + ".csv";
}

}  // namespace

bool writeStudyChart(const std::filesystem::path& dir, const StudyChart& chart) {
  std::filesystem::create_directories(dir);
  bool rightAxis = false;
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const StudySeries& s = chart.series[k];
    CsvTable table(seriesFile(chart, k), {{"x", ""}, {"y", ""}});
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) table.addRow({s.x[i], s.y[i]});
    table.write(dir / seriesFile(chart, k));
    rightAxis = rightAxis || s.rightAxis;
  }
  // The positive values on each axis, for log axes in whole decades.
  PositiveRange x, y, y2;
  for (const StudySeries& s : chart.series) {
    for (double v : s.x) x.include(v);
    for (double v : s.y) (s.rightAxis ? y2 : y).include(v);
  }
  std::ostringstream body;
  body << "set title " << gnuplotText(chart.title) << "\n"
       << "set xlabel " << gnuplotText(chart.xLabel) << "\n"
       << "set ylabel " << gnuplotText(chart.yLabel) << "\n"
       << "set grid\nset key outside bottom center horizontal\n"
       << (chart.logX ? logAxis("x", x) : "")
       << (chart.logY ? logAxis("y", y) : "");
  if (rightAxis)
    body << "set y2label " << gnuplotText(chart.y2Label) << "\n"
         << logAxis("y2", y2) << "set ytics nomirror\nset y2tics\n";
  body << "plot ";
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const StudySeries& s = chart.series[k];
    if (k) body << ", \\\n     ";
    body << gnuplotFile(seriesFile(chart, k)) << " skip 1 using 1:2"
         << (s.rightAxis ? " axes x1y2" : "") << " with linespoints linewidth 2 pointtype 7 "
         << (s.rightAxis ? "dashtype 2 " : "") << colour(k) << " title " << gnuplotText(s.title);
  }
  body << "\n";
  return drawChart(dir, {chart.name, chart.title, 900, 520, body.str()});
}

}  // namespace beamrotor::verify
