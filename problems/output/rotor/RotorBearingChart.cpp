// gnuplot script of the journal bearings chart (see RotorBearingChart.hpp).
#include "problems/output/rotor/RotorBearingChart.hpp"

#include <sstream>
#include <vector>

#include "problems/output/files/ChartParts.hpp"

namespace beamrotor {

ChartScript journalBearingsDiagram(const std::string& caption, const std::string& chartName,
                                   const CsvTable& table, const std::string& csvFile,
                                   const std::vector<std::string>& bearingNames,
                                   const OutputUnits& units) {
  const OutputUnits::Shown speed = units.columnIn("rpm", {1, "rpm"});
  const OutputUnits::Shown stiffness = units.columnIn("N/m", {1e-6, "MN/m"});
  const OutputUnits::Shown damping = units.columnIn("N s/m", {1e-3, "kN s/m"});
  const int x = table.column("speed_rpm"), index = table.column("bearing_index");
  std::vector<std::string> titles;
  for (const std::string& n : bearingNames)
    for (const char* k : {"kxx", "kxy", "kyx", "kyy"}) titles.push_back(n + " " + k);
  const int keyMargin = keyWidth(titles);
  const int width = 760 + keyMargin, height = 1000;
  // One curve per bearing and column: the rows of the other bearings are NaN.
  const auto curves = [&](const std::vector<std::string>& columns, double scale) {
    std::ostringstream s;
    s << "  plot ";
    bool first = true;
    for (std::size_t b = 0; b < bearingNames.size(); ++b)
      for (std::size_t k = 0; k < columns.size(); ++k) {
        if (!first) s << ", \\\n       ";
        first = false;
        s << gnuplotFile(csvFile) << " skip 1 using " << x << ":($" << index
          << " == " << b + 1 << " ? $" << table.column(columns[k]) << " * " << number(scale)
          << " : NaN) with lines linewidth 2 dashtype " << b + 1 << " " << colour(k) << " title "
          << gnuplotText(bearingNames[b] + " " + columns[k]);
      }
    return s.str() + "\n";
  };
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(3, 1, caption, width, height, keyMargin) << "  set grid\n"
       << "  set key outside right top\n"
       << "  set ylabel 'eccentricity ratio e/c'\n  set yrange [0:1]\n"
       << curves({"eccentricity"}, 1) << "  set yrange [*:*]\n"
       << "  set ylabel " << gnuplotText("stiffness [" + stiffness.unit + "]") << "\n"
       << curves({"kxx", "kxy", "kyx", "kyy"}, stiffness.factor)
       << "  set xlabel " << gnuplotText("spin speed [" + speed.unit + "]") << "\n"
       << "  set ylabel " << gnuplotText("damping [" + damping.unit + "]") << "\n"
       << curves({"cxx", "cxy", "cyx", "cyy"}, damping.factor) << "  unset multiplot\n";
  return {chartName, "Journal bearings: eccentricity and coefficients against speed", width,
          height, body.str()};
}

}  // namespace beamrotor
