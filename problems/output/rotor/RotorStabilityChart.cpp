// gnuplot script of the stability chart (see RotorStabilityChart.hpp).
#include "problems/output/rotor/RotorStabilityChart.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/rotor/RotorTables.hpp"

namespace beamrotor {

ChartScript stabilityDiagram(const std::string& caption, const std::string& chartName,
                             const CsvTable& campbell, const std::string& csvFile,
                             std::optional<double> onsetRpm,
                             const std::optional<OperatingBand>& band) {
  const int x = campbell.column("speed_rpm");
  const int lines = campbellLineCount(campbell);
  // The decrement axis: the finite values, with zero always in view.
  double low = 0, high = 0.1;
  for (int l = 1; l <= lines; ++l)
    for (double d : campbell.numbers(campbellColumn(l, "log_decrement")))
      if (std::isfinite(d)) low = std::min(low, d), high = std::max(high, d);
  high = std::min(high, 5.0);  // above 5 a mode is overdamped for any practical purpose
  const double pad = 0.05 * (high - low);
  low -= pad, high += pad;

  std::vector<std::string> titles;
  for (int l = 1; l <= lines; ++l) titles.push_back("line " + std::to_string(l));
  const BandCommands shading = operatingBandCommands(band);
  std::vector<std::string> keyTitles = titles;
  keyTitles.push_back("stability limit");
  const int keyMargin = std::max(keyWidth(keyTitles), 110);
  const int width = 800 + keyMargin, height = 860;
  // Decrements above the axis are drawn at its top; an empty cell (a real eigenvalue, whose
  // decrement is infinite) at the top when it decays, at the bottom when it grows.
  const auto clipped = [&](int l) {
    const std::string d = std::to_string(campbell.column(campbellColumn(l, "log_decrement")));
    const std::string z = std::to_string(campbell.column(campbellColumn(l, "damping_ratio")));
    return "(valid(" + d + ") ? ($" + d + " > " + number(high) + " ? " + number(high) + " : $" +
           d + ") : ($" + z + " > 0 ? " + number(high) + " : " + number(low) + "))";
  };
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(2, 1, caption, width, height, keyMargin) << "  set grid\n"
       << "  set key outside right top\n";
  if (onsetRpm)
    body << "  set arrow 1 from first " << number(*onsetRpm) << ", graph 0 to first "
         << number(*onsetRpm) << ", graph 1 nohead dashtype 2 linewidth 2 linecolor rgb 'red'\n"
         << "  set label 1 " << gnuplotText("onset " + std::to_string(int(std::lround(*onsetRpm))) +
                                            " rpm")
         << " at first " << number(*onsetRpm) << ", graph 0.95 offset 0.5,0 left textcolor rgb "
         << "'red'\n";
  // 1. The Campbell diagram coloured by log decrement: dark red (most negative) through orange
  //    (zero) to green (the best damped).
  body << "  set cbrange [" << number(low) << ":" << number(high) << "]\n"
       << "  set palette defined (" << number(low) << " 'dark-red', 0 'orange', "
       << number(std::max(high, 1e-3)) << " 'forest-green')\n"
       << "  set cblabel 'log decrement'\n"
       << "  set ylabel 'whirl frequency [Hz]'\n  set yrange [0:*]\n" << shading.setup
       << "  plot ";
  for (int l = 1; l <= lines; ++l)
    body << (l > 1 ? ", \\\n       " : "") << gnuplotFile(csvFile) << " skip 1 using " << x << ":"
         << campbell.column(campbellColumn(l, "frequency")) << ":"
         << clipped(l)
         << " with lines linewidth 3 palette notitle";
  // The band's key is on the Campbell diagram: here it would meet the colour box's labels.
  body << "\n  unset colorbox\n  set xlabel 'spin speed [rpm]'\n  set ylabel 'log decrement'\n"
       << "  set yrange [" << number(low) << ":" << number(high) << "]\n  plot ";
  // 2. The decrements, one colour per line, and the stability boundary.
  for (int l = 1; l <= lines; ++l)
    body << gnuplotFile(csvFile) << " skip 1 using " << x << ":"
         << clipped(l)
         << " with linespoints linewidth 2 pointtype 7 pointsize 0.5 " << lineStyle(l - 1)
         << " title " << gnuplotText(titles[l - 1]) << ", \\\n       ";
  body << "0 with lines linewidth 1 linecolor rgb 'black' title 'stability limit'\n"
       << "  unset multiplot\n";
  return {chartName, "Stability: log decrement of each Campbell line against spin speed", width,
          height, body.str()};
}

}  // namespace beamrotor
