// gnuplot scripts of the rotor analyses (see RotorCharts.hpp).
#include "problems/output/rotor/RotorCharts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/LabelPlacement.hpp"
#include "problems/output/rotor/OperatingBand.hpp"
#include "problems/output/rotor/RotorTables.hpp"
#include "problems/output/rotor/SpeedAxes.hpp"

namespace beamrotor {

namespace {

/// Palette slots of the whirl senses.
constexpr int kForward = 1, kBackward = 0, kPlanar = 2;

}  // namespace

ChartScript campbellDiagram(const std::string& caption, const std::string& chartName,
                            const CsvTable& campbell, const std::string& csvFile,
                            const CsvTable& critical, const std::string& criticalFile,
                            const std::vector<double>& orders,
                            const std::optional<OperatingBand>& band, const OutputUnits& units) {
  const SpeedAxes axes = speedAxes(units);
  const auto rpm = campbell.numbers("speed_rpm");  // in axes.speed's unit
  const int x = campbell.column("speed_rpm");
  const int lines = campbellLineCount(campbell);
  // The frequency axis is fixed here (0 to the highest line or speed line, 5 % headroom) so
  // that data map to known pixels and the critical speeds' labels can be kept apart.
  const double highestOrder = *std::max_element(orders.begin(), orders.end());
  double top =
      highestOrder * std::max(std::abs(rpm.front()), std::abs(rpm.back())) * axes.oncePerTurn();
  bool planar = false;
  for (int l = 1; l <= lines; ++l) {
    for (double f : campbell.numbers(campbellColumn(l, "frequency")))
      if (std::isfinite(f)) top = std::max(top, f);
    for (double w : campbell.numbers(campbellColumn(l, "whirl"))) planar = planar || w == 0;
  }
  top = top > 0 ? 1.05 * top : 1;

  // Key entries only for what is drawn: a planar line only when some line is planar.
  std::vector<std::pair<int, std::string>> senses{{kForward, "forward whirl"},
                                                  {kBackward, "backward whirl"}};
  if (planar) senses.emplace_back(kPlanar, "planar");
  std::vector<std::string> titles{"critical speeds"};
  if (orders.size() > 1) titles.push_back("further orders' crossings");
  for (double order : orders) titles.push_back(number(order) + "x speed");
  for (const auto& [slot, title] : senses) titles.push_back(title);
  const BandCommands shading = operatingBandCommands(band, axes.speed.factor);
  titles.insert(titles.end(), shading.titles.begin(), shading.titles.end());
  const int width = 1000, height = 640;
  const int captionLines = 1 + int(std::count(caption.begin(), caption.end(), '\n'));
  const PixelBox plot{90, 40.0 + 20.0 * captionLines, double(width - keyWidth(titles)),
                      height - 60.0};
  const double x0 = rpm.front(), x1 = rpm.back(), span = x1 > x0 ? x1 - x0 : 1;
  const double across = plot.right - plot.left, down = plot.bottom - plot.top;
  const auto pixelX = [&](double v) { return plot.left + (v - x0) / span * across; };
  const auto pixelY = [&](double f) { return plot.bottom - f / top * down; };
  const auto dataX = [&](double px) { return x0 + (px - plot.left) / across * span; };
  const auto dataY = [&](double py) { return (plot.bottom - py) / down * top; };

  std::ostringstream body;
  body << "  set encoding utf8\n"
       << "  set title " << captionText(caption) << " font ',13'\n"
       << "  set lmargin at screen " << number(plot.left / width) << "\n  set rmargin at screen "
       << number(plot.right / width) << "\n  set tmargin at screen "
       << number(1 - plot.top / height) << "\n  set bmargin at screen "
       << number(1 - plot.bottom / height) << "\n"
       << "  set grid\n  set key outside right top\n"
       << "  set xlabel " << gnuplotText("spin speed [" + axes.speed.unit + "]")
       << "\n  set ylabel " << gnuplotText("whirl frequency [" + axes.frequency.unit + "]") << "\n"
       << "  set xrange [" << number(x0) << ":" << number(x0 + span) << "]\n"
       << "  set yrange [0:" << number(top) << "]\n"
       << "  whirl(w) = w > 0 ? " << colourValue(kForward) << " : w < 0 ? "
       << colourValue(kBackward) << " : " << colourValue(kPlanar) << "\n";
  // Each critical speed labelled in rpm and whirl (forward: driven by unbalance; backward: not
  // on isotropic bearings), beside its point, clear of the other labels.
  const auto speeds = critical.numbers("speed_rpm"), frequencies = critical.numbers("frequency");
  const auto whirls = critical.numbers("whirl");
  constexpr double kLabelFont = 9, kLabelHeight = 13;
  std::vector<PointLabel> labels;
  std::vector<std::string> texts;
  const auto whirlText = [](double w) {
    return std::string(w > 0 ? "forward" : w < 0 ? "backward" : "planar");
  };
  for (std::size_t k = 0; k < speeds.size(); ++k) {
    const std::string rpmText = axes.speedText(speeds[k] / axes.speed.factor) + " ";
    std::string text = rpmText;
    text += whirlText(whirls[k]);
    // A double mode (the two planes of an isotropic rotor) crosses twice at one point: one
    // label naming both whirls.
    std::size_t same = labels.size();
    for (std::size_t j = 0; j < labels.size(); ++j)
      if (texts[j].rfind(rpmText, 0) == 0 && std::abs(labels[j].x - pixelX(speeds[k])) < 1 &&
          std::abs(labels[j].y - pixelY(frequencies[k])) < 1)
        same = j;
    if (same < labels.size()) {
      if (texts[same].find(whirlText(whirls[k])) == std::string::npos) {
        texts[same] += " + ";
        texts[same] += whirlText(whirls[k]);
        labels[same].width = textWidth(texts[same]) * kLabelFont / 12.0;
      }
      continue;
    }
    labels.push_back({pixelX(speeds[k]), pixelY(frequencies[k]),
                      textWidth(text) * kLabelFont / 12.0, kLabelHeight});
    texts.push_back(text);
  }
  const std::vector<PixelBox> boxes = placeLabels(labels, plot);
  // gnuplot centres a label's text vertically on its position.
  for (std::size_t k = 0; k < boxes.size(); ++k)
    body << "  set label " << gnuplotText(texts[k]) << " at first " << number(dataX(boxes[k].left))
         << ", first " << number(dataY((boxes[k].top + boxes[k].bottom) / 2)) << " left font ',"
         << kLabelFont << "'\n";
  body << shading.setup << "  plot ";
  for (int l = 1; l <= lines; ++l)
    body << gnuplotFile(csvFile) << " skip 1 using " << x << ":"
         << campbell.column(campbellColumn(l, "frequency")) << ":(whirl($"
         << campbell.column(campbellColumn(l, "whirl"))
         << ")) with lines linewidth 2 linecolor rgb variable notitle, \\\n       ";
  // Key entries for the colours (NaN draws nothing).
  for (const auto& [slot, title] : senses)
    body << "NaN with lines linewidth 2 " << colour(slot) << " title " << gnuplotText(title)
         << ", \\\n       ";
  // The excitation lines: the first order (the critical speeds') darkest, further ones lighter.
  for (std::size_t k = 0; k < orders.size(); ++k)
    body << (k > 0 ? ", \\\n       " : "") << "x * " << number(orders[k] * axes.oncePerTurn())
         << " with lines dashtype " << (k == 0 ? 2 : 3 + int(k % 3)) << " linecolor rgb '"
         << (k == 0 ? "gray30" : "gray45") << "' linewidth " << (k == 0 ? 1 : 1.5) << " title "
         << gnuplotText(number(orders[k]) + "x speed");
  // The critical speeds (the first order's crossings) filled, the further orders' open.
  const int orderColumn = critical.column("order");
  const auto crossings = [&](bool first, const char* style, const std::string& title) {
    body << ", \\\n       " << gnuplotFile(criticalFile) << " skip 1 using "
         << critical.column("speed_rpm") << ":($" << orderColumn << (first ? " == " : " != ")
         << number(orders.front()) << " ? $" << critical.column("frequency") << " : NaN)"
         << " with points " << style << " linecolor rgb 'black' title " << gnuplotText(title);
  };
  if (critical.rowCount() > 0) {
    crossings(true, "pointtype 7 pointsize 1.4", "critical speeds");
    if (orders.size() > 1) crossings(false, "pointtype 6 pointsize 1.4", "further orders' crossings");
  }
  body << shading.keyEntries << "\n";
  return {chartName, "Campbell diagram: whirl frequencies against spin speed", width, height,
          body.str()};
}

ChartScript unbalanceResponseChart(const std::string& caption, const std::string& chartName,
                                   const CsvTable& response, const std::string& csvFile,
                                   const std::vector<std::string>& points,
                                   const std::optional<OperatingBand>& band,
                                   std::optional<double> unstableFromRpm,
                                   const OutputUnits& units) {
  const SpeedAxes axes = speedAxes(units);
  const OutputUnits::Shown amplitude = units.columnIn("m", {1e6, "µm"});
  const OutputUnits::Shown phase = units.columnIn("deg", {1, "deg"});
  const int x = response.column("speed_rpm");
  // The amplitude axis in whole decades of the positive amplitudes (um), at most
  // kAmplitudeDecades below the largest: the response at rest is no reader's question.
  PositiveRange amplitudes;
  for (const std::string& p : points)
    for (double a : response.numbers(p + "_amplitude")) amplitudes.include(a * amplitude.factor);
  amplitudes.low = std::max(amplitudes.low, amplitudes.high * std::pow(10.0, -kAmplitudeDecades));
  // A marker every few rows (about 15 along the curve) and each curve thinner than the last.
  const std::size_t every = std::max<std::size_t>(1, response.rowCount() / 15);
  const auto width_ = [](std::size_t k) { return number(std::max(1.0, 3.5 - 1.0 * double(k))); };
  BandCommands shading = operatingBandCommands(band, axes.speed.factor);
  if (unstableFromRpm) {
    // Beyond the onset no steady response exists: shaded in red and named in the key.
    std::string name = "unstable above ";
    name += labelNumber(*unstableFromRpm * axes.speed.factor);
    name += " " + axes.speed.unit;
    const std::string fill = " fillstyle transparent solid 0.15 noborder fillcolor rgb '#c0392b'";
    shading.setup += "  set object 90 rectangle from first ";
    shading.setup += number(*unstableFromRpm * axes.speed.factor);
    shading.setup += ", graph 0 to graph 1, graph 1 back" + fill + "\n";
    shading.keyEntries += ", \\\n       NaN with boxes" + fill + " title " + gnuplotText(name);
    shading.titles.push_back(name);
  }
  std::vector<std::string> titles = points;
  titles.insert(titles.end(), shading.titles.begin(), shading.titles.end());
  const int keyMargin = keyWidth(titles);
  const int width = 770 + keyMargin, height = 800;
  // Amplitudes on a log scale skip the zeros (no force at rest); phases come unwrapped.
  const auto panel = [&](const std::string& what, double scale, bool positive) {
    std::ostringstream s;
    s << shading.setup << "  plot ";
    for (std::size_t k = 0; k < points.size(); ++k) {
      const int column = response.column(points[k] + "_" + what);
      if (k) s << ", \\\n       ";
      s << gnuplotFile(csvFile) << " skip 1 using " << x << ":";
      if (positive)
        s << "($" << column << " > 0 ? $" << column << "*" << number(scale) << " : NaN)";
      else
        s << column;
      s << " with linespoints linewidth " << width_(k) << " pointtype 7 pointsize 0.6 "
        << "pointinterval " << every << " " << lineStyle(k) << " title " << gnuplotText(points[k]);
    }
    return s.str() + shading.keyEntries + "\n";
  };
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(2, 1, caption, width, height, keyMargin) << "  set grid\n"
       << "  set key outside right top\n" << logAxis("y", amplitudes)
       << "  set ylabel " << gnuplotText("orbit semi-major axis [" + amplitude.unit + "]") << "\n"
       << panel("amplitude", amplitude.factor, true) << "  unset logscale y\n  set format y '%g'\n"
       << "  set ytics autofreq\n  set mytics default\n"
       << "  set xlabel " << gnuplotText("spin speed [" + axes.speed.unit + "]") << "\n"
       << "  set ylabel " << gnuplotText("phase of u_y, lag negative [" + phase.unit + "]") << "\n"
       << "  set yrange [*:*]\n  set ytics " << number(90 * units.valueIn("deg", {1, "deg"}).factor)
       << "\n"
       << panel("uy_phase", 1, false) << "  unset multiplot\n";
  return {chartName, "Unbalance response: amplitude and phase against spin speed", width, height,
          body.str()};
}

ChartScript frequencyResponseDiagram(const std::string& caption, const std::string& chartName,
                                     const CsvTable& response, const std::string& csvFile,
                                     const std::string& what, const OutputUnits& units) {
  const OutputUnits::Shown hz = units.columnIn("Hz", {1, "Hz"});
  const OutputUnits::Shown receptance = units.columnIn("m/N", {1, "m/N"});
  const OutputUnits::Shown phase = units.columnIn("deg", {1, "deg"});
  const int x = response.column("frequency");
  PositiveRange magnitudes;
  for (double m : response.numbers("magnitude")) magnitudes.include(m);
  const std::vector<std::string> titles{what};
  const int keyMargin = keyWidth(titles);
  const int width = 770 + keyMargin, height = 800;
  const auto curve = [&](const std::string& using_) {
    return "  plot " + gnuplotFile(csvFile) + " skip 1 using " + std::to_string(x) + ":" +
           using_ + " with lines linewidth 2 " + colour(0) + " title " + gnuplotText(what) + "\n";
  };
  const int m = response.column("magnitude"), p = response.column("phase");
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(2, 1, caption, width, height, keyMargin) << "  set grid\n"
       << "  set key outside right top\n" << logAxis("y", magnitudes)
       << "  set ylabel " << gnuplotText("receptance magnitude [" + receptance.unit + "]") << "\n"
       << curve("($" + std::to_string(m) + " > 0 ? $" + std::to_string(m) + " : NaN)")
       << "  unset logscale y\n  set format y '%g'\n  set ytics autofreq\n  set mytics default\n"
       << "  set xlabel " << gnuplotText("excitation frequency [" + hz.unit + "]") << "\n"
       << "  set ylabel " << gnuplotText("phase, lag negative [" + phase.unit + "]") << "\n"
       << "  set yrange [*:*]\n  set ytics " << number(90 * units.valueIn("deg", {1, "deg"}).factor)
       << "\n" << curve(std::to_string(p))
       << "  unset multiplot\n";
  return {chartName, "Frequency response: receptance magnitude and phase against frequency",
          width, height, body.str()};
}

}  // namespace beamrotor
