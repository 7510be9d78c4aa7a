// gnuplot script of the stability chart (see RotorStabilityChart.hpp).
#include "problems/output/rotor/RotorStabilityChart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/rotor/RotorTables.hpp"
#include "problems/output/rotor/SpeedAxes.hpp"

namespace beamrotor {

namespace {

/// The colours of decrements from least to most over the part of this scale the data reach:
/// dark red (growing), orange at the stability limit 0, gold at 0.1 (API 684's least
/// acceptable decrement), green-yellow at 0.5, green at 1 and dark green above, so that lines
/// of little and of much damping differ in colour wherever the data lie.
std::string stabilityPalette(double least, double most) {
  const std::vector<std::pair<double, const char*>> stops{
      {0, "orange"}, {0.1, "gold"}, {0.5, "greenyellow"}, {1, "forest-green"}};
  // The ends take the colour of the stop just beyond them, so the colours stay in order.
  const char* low = "dark-red";
  for (const auto& [at, colour] : stops)
    if (least >= at) low = colour;
  const char* high = "dark-green";
  for (auto it = stops.rbegin(); it != stops.rend(); ++it)
    if (most <= it->first) high = it->second;
  std::string palette = number(least) + " '" + low + "'";
  for (const auto& [at, colour] : stops)
    if (at > least && at < most) palette += ", " + number(at) + " '" + colour + "'";
  return palette + ", " + number(most) + " '" + high + "'";
}

}  // namespace

ChartScript stabilityDiagram(const std::string& caption, const std::string& chartName,
                             const CsvTable& campbell, const std::string& csvFile,
                             std::optional<double> onsetRpm,
                             const std::optional<OperatingBand>& band, const OutputUnits& units) {
  const SpeedAxes axes = speedAxes(units);
  const int x = campbell.column("speed_rpm");
  const int lines = campbellLineCount(campbell);
  // The colour scale spans the finite decrements themselves, so that lines of different
  // damping differ in colour; the decrement axis spans them too, with zero (the stability
  // limit) always in view. Nothing finite is clipped.
  double least = std::numeric_limits<double>::infinity(), most = -least;
  for (int l = 1; l <= lines; ++l)
    for (double d : campbell.numbers(campbellColumn(l, "log_decrement")))
      if (std::isfinite(d)) least = std::min(least, d), most = std::max(most, d);
  if (!(least <= most)) least = 0, most = 1;  // no finite decrement at all
  if (most - least < 1e-9 * std::max(1.0, std::abs(most))) {
    const double half = std::max(0.05 * std::abs(most), 0.05);
    least -= half, most += half;
  }
  const double pad = 0.05 * (std::max(most, 0.0) - std::min(least, 0.0));
  const double low = std::min(least, 0.0) - pad, high = std::max(most, 0.0) + pad;

  std::vector<std::string> titles;
  for (int l = 1; l <= lines; ++l) titles.push_back("line " + std::to_string(l));
  const BandCommands shading = operatingBandCommands(band, axes.speed.factor);
  std::vector<std::string> keyTitles = titles;
  keyTitles.push_back("stability limit");
  const int keyMargin = std::max(keyWidth(keyTitles), 110);
  const int width = 800 + keyMargin, height = 860;
  // An empty cell (a real eigenvalue, whose decrement is infinite) is drawn at the axis' top
  // when it decays, at its bottom when it grows.
  const auto clipped = [&](int l) {
    const std::string d = std::to_string(campbell.column(campbellColumn(l, "log_decrement")));
    const std::string z = std::to_string(campbell.column(campbellColumn(l, "damping_ratio")));
    return "(valid(" + d + ") ? $" + d + " : ($" + z + " > 0 ? " + number(high) + " : " +
           number(low) + "))";
  };
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(2, 1, caption, width, height, keyMargin) << "  set grid\n"
       << "  set key outside right top\n";
  if (onsetRpm) {
    const double onset = *onsetRpm * axes.speed.factor;
    body << "  set arrow 1 from first " << number(onset) << ", graph 0 to first " << number(onset)
         << ", graph 1 nohead dashtype 2 linewidth 2 linecolor rgb 'red'\n"
         << "  set label 1 " << gnuplotText(std::string("onset ").append(axes.speedText(*onsetRpm))) << " at first "
         << number(onset) << ", graph 0.95 offset 0.5,0 left textcolor rgb 'red'\n";
  }
  // 1. The Campbell diagram coloured by log decrement: dark red (most negative) through orange
  //    (zero) to green (the best damped).
  body << "  set cbrange [" << number(least) << ":" << number(most) << "]\n"
       << "  set palette defined (" << stabilityPalette(least, most) << ")\n"
       << "  set cblabel 'log decrement'\n"
       << "  set ylabel " << gnuplotText("whirl frequency [" + axes.frequency.unit + "]")
       << "\n  set yrange [0:*]\n" << shading.setup
       << "  plot ";
  for (int l = 1; l <= lines; ++l)
    body << (l > 1 ? ", \\\n       " : "") << gnuplotFile(csvFile) << " skip 1 using " << x << ":"
         << campbell.column(campbellColumn(l, "frequency")) << ":"
         << clipped(l)
         << " with lines linewidth 3 palette notitle";
  // The band's key is on the Campbell diagram: here it would meet the colour box's labels.
  body << "\n  unset colorbox\n  set xlabel " << gnuplotText("spin speed [" + axes.speed.unit + "]")
       << "\n  set ylabel 'log decrement'\n"
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
