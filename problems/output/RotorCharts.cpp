// gnuplot scripts of the rotor analyses (see RotorCharts.hpp).
#include "problems/output/RotorCharts.hpp"

#include <sstream>

#include "problems/output/ChartParts.hpp"
#include "problems/output/RotorTables.hpp"

namespace beamrotor {

namespace {

/// Palette slots of the whirl senses.
constexpr int kForward = 1, kBackward = 0, kPlanar = 2;

}  // namespace

ChartScript campbellDiagram(const std::string& caption, const std::string& chartName,
                            const CsvTable& campbell, const std::string& csvFile,
                            const CsvTable& critical, const std::string& criticalFile,
                            double order) {
  const auto rpm = campbell.numbers("speed_rpm");
  const int x = campbell.column("speed_rpm");
  const int lines = int((campbell.columns().size() - 2) / 4);
  const auto labels = [&](int first, const char* dy) {
    return gnuplotFile(criticalFile) + " skip 1 every 2::" + std::to_string(first) + " using " +
           std::to_string(critical.column("speed_rpm")) + ":" +
           std::to_string(critical.column("frequency")) + ":(sprintf('%.0f rpm', $" +
           std::to_string(critical.column("speed_rpm")) + ")) with labels left offset 0.8," + dy +
           " font ',9' notitle";
  };
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << "  set title " << captionText(caption) << " font ',13'\n"
       << "  set grid\n  set key below\n"
       << "  set xlabel 'spin speed [rpm]'\n  set ylabel 'whirl frequency [Hz]'\n"
       << "  set xrange [" << number(rpm.front()) << ":" << number(rpm.back()) << "]\n"
       << "  set yrange [0:*]\n"
       << "  whirl(w) = w > 0 ? " << colourValue(kForward) << " : w < 0 ? "
       << colourValue(kBackward) << " : " << colourValue(kPlanar) << "\n  plot ";
  for (int l = 1; l <= lines; ++l)
    body << gnuplotFile(csvFile) << " skip 1 using " << x << ":"
         << campbell.column(campbellColumn(l, "frequency")) << ":(whirl($"
         << campbell.column(campbellColumn(l, "whirl"))
         << ")) with lines linewidth 2 linecolor rgb variable notitle, \\\n       ";
  // Key entries for the colours (NaN draws nothing).
  body << "NaN with lines linewidth 2 " << colour(kForward) << " title 'forward whirl', \\\n"
       << "       NaN with lines linewidth 2 " << colour(kBackward)
       << " title 'backward whirl', \\\n"
       << "       NaN with lines linewidth 2 " << colour(kPlanar) << " title 'planar', \\\n"
       << "       x * " << number(order)
       << " / 60 with lines dashtype 2 linecolor rgb 'gray30' title "
       << gnuplotText(number(order) + "x speed");
  if (critical.rowCount() > 0)
    body << ", \\\n       " << gnuplotFile(criticalFile) << " skip 1 using "
         << critical.column("speed_rpm") << ":" << critical.column("frequency")
         << " with points pointtype 7 pointsize 1.4 linecolor rgb 'black' title 'critical speeds', "
            "\\\n"
         // Labels of neighbouring crossings (a double mode crosses twice at one speed)
         // alternate between two rows so they do not print over each other.
         << labels(0, "-0.6") << ", \\\n       " << labels(1, "-1.6");
  body << "\n";
  return {chartName, "Campbell diagram: whirl frequencies against spin speed", 900, 620,
          body.str()};
}

ChartScript unbalanceResponseChart(const std::string& caption, const std::string& chartName,
                                   const CsvTable& response, const std::string& csvFile,
                                   const std::vector<std::string>& points) {
  const int width = 900, height = 800;
  const int x = response.column("speed_rpm");
  // Amplitudes on a log scale skip the zeros (no force at rest); phases are drawn as they are.
  const auto panel = [&](const std::string& what, double scale, bool positive) {
    std::ostringstream s;
    s << "  plot ";
    for (std::size_t k = 0; k < points.size(); ++k) {
      const int column = response.column(points[k] + "_" + what);
      if (k) s << ", \\\n       ";
      s << gnuplotFile(csvFile) << " skip 1 using " << x << ":(";
      if (positive) s << "$" << column << " > 0 ? ";
      s << "$" << column << "*" << number(scale);
      if (positive) s << " : NaN";
      s << ") with linespoints linewidth 2 pointtype 7 pointsize 0.5 " << colour(k) << " title "
        << gnuplotText(points[k]);
    }
    return s.str() + "\n";
  };
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(2, 1, caption, width, height, 130) << "  set grid\n"
       << "  set key outside right top\n"
       << "  set logscale y\n"
       << "  set ylabel 'orbit semi-major axis [µm]'\n"
       << panel("amplitude", 1e6, true) << "  unset logscale y\n"
       << "  set xlabel 'spin speed [rpm]'\n  set ylabel 'phase of u_y [deg]'\n"
       << "  set yrange [-180:180]\n  set ytics 90\n"
       << panel("uy_phase", 1, false) << "  unset multiplot\n";
  return {chartName, "Unbalance response: amplitude and phase against spin speed", width, height,
          body.str()};
}

}  // namespace beamrotor
