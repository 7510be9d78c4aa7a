#include "problems/output/structure/EnvelopeCharts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "problems/output/files/ChartParts.hpp"

namespace beamrotor {

namespace {

/// The largest magnitude of a resultant's envelope along the member (N or N m).
double largestOf(const CsvTable& table, const std::string& component) {
  double m = 0;
  for (const char* side : {"_max", "_min"})
    for (double v : table.numbers(component + side)) m = std::max(m, std::abs(v));
  return m;
}

/// One resultant's panel: its columns and how it is labelled.
struct EnvelopePanel {
  std::string component;     ///< "N", ..., "Mz"
  std::string label;         ///< y axis, with its unit
  OutputUnits::Shown shown;  ///< kN or kN m from the table's N or N m; or the user's (factor 1)
};

/// The panels worth drawing: resultants that are not zero (to round-off of the largest
/// resultant of the same kind) somewhere along the member.
std::vector<EnvelopePanel> panelsOf(const CsvTable& table, const OutputUnits& units) {
  const std::vector<std::pair<std::string, std::string>> all{
      {"N", "axial force N"}, {"Vy", "shear force Vy"}, {"Vz", "shear force Vz"},
      {"T", "torque T"},      {"My", "moment My"},      {"Mz", "moment Mz"}};
  const OutputUnits::Shown force = units.columnIn("N", {1e-3, "kN"});
  const OutputUnits::Shown moment = units.columnIn("N m", {1e-3, "kN m"});
  const auto largest = [&](const std::string& c) { return largestOf(table, c); };
  const double forces = std::max({largest("N"), largest("Vy"), largest("Vz")});
  const double moments = std::max({largest("T"), largest("My"), largest("Mz")});
  std::vector<EnvelopePanel> out;
  for (const auto& [component, label] : all) {
    const bool isForce = component == "N" || component[0] == 'V';
    const double scale = isForce ? forces : moments;
    constexpr double kRoundOff = 1e-10;  // relative: what a zero resultant shows after solving
    const OutputUnits::Shown& shown = isForce ? force : moment;
    if (largest(component) > kRoundOff * scale)
      out.push_back({component, label + " [" + shown.unit + "]", shown});
  }
  return out;
}

/// A label at the largest (side "_max") or smallest ("_min") value of the envelope, naming the
/// combination that gives it and the value in the panel's unit (`shown`), 0 where it is
/// round-off of the resultant's largest value along the member.
std::string extremeLabel(const CsvTable& table, const std::string& component,
                         const std::string& side, const OutputUnits::Shown& shown) {
  const double factor = shown.factor;
  const std::vector<double> values = table.numbers(component + side);
  const std::vector<double> s = table.numbers("s");
  const auto it = side == "_max" ? std::max_element(values.begin(), values.end())
                                 : std::min_element(values.begin(), values.end());
  const std::size_t row = std::size_t(it - values.begin());
  const CsvCell& governing = table.cell(row, std::size_t(table.column(component + side + "_case") - 1));
  const std::string name = std::get<std::string>(governing);
  // Written towards the middle of the member, so that a label at an end stays inside the plot.
  const bool rightHalf = s[row] > 0.5 * (s.front() + s.back());
  const std::string value = labelNumber(*it * factor, largestOf(table, component) * factor);
  std::ostringstream label;
  label << "  set label " << gnuplotText(name + ": " + value + " " + shown.unit) << " at first "
        << number(s[row]) << ", first " << number(*it * factor) << (rightHalf ? " right" : " left")
        << " point pointtype 7 offset " << (rightHalf ? "-0.8," : "0.8,")
        << (side == "_max" ? "0.8" : "-0.8") << " front\n";
  return label.str();
}

}  // namespace

std::string envelopeChart(const std::string& stem, const std::string& member) {
  return stem + "_envelope_" + member;
}

ChartScript memberEnvelopeChart(const std::string& caption, const std::string& chartName,
                                const CsvTable& table, const std::string& csvFile,
                                const OutputUnits& units) {
  const std::vector<EnvelopePanel> panels = panelsOf(table, units);
  const int rows = std::max<int>(1, int(panels.size()));
  const int width = 1000, height = 140 + 250 * rows;
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(rows, 1, caption, width, height, 40 + keyWidth({"smallest", "largest"}))
       << "  set grid\n"
       << "  set xzeroaxis linetype 1 linecolor rgb 'gray40'\n"
       << "  set xrange [*:*] noextend\n"
       << "  set offsets 0, 0, graph 0.15, graph 0.15\n"
       << "  set key outside right top\n";
  const std::string file = gnuplotFile(csvFile);
  const std::string x = std::to_string(table.column("s"));
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const std::string hi = std::to_string(table.column(panels[p].component + "_max"));
    const std::string lo = std::to_string(table.column(panels[p].component + "_min"));
    if (p + 1 == panels.size())
      body << "  set xlabel "
           << gnuplotText("distance s along the member [" +
                          table.columns()[std::size_t(table.column("s") - 1)].unit + "]")
           << "\n";
    std::string times = "*";  // appended: GCC 12 warns (-Wrestrict) on "*" + a temporary
    times += number(panels[p].shown.factor);
    body << "  unset label\n"
         << extremeLabel(table, panels[p].component, "_max", panels[p].shown)
         << extremeLabel(table, panels[p].component, "_min", panels[p].shown)
         << "  set ylabel " << gnuplotText(panels[p].label) << "\n"
         << "  plot " << file << " skip 1 using " << x << ":($" << lo << times << "):($" << hi
         << times << ") with filledcurves fillstyle transparent solid 0.15 noborder " << colour(0)
         << " notitle, \\\n"
         << "       " << file << " skip 1 using " << x << ":($" << hi << times
         << ") with lines linewidth 2 " << colour(0) << " title 'largest', \\\n"
         << "       " << file << " skip 1 using " << x << ":($" << lo << times
         << ") with lines linewidth 2 " << colour(1) << " title 'smallest'\n";
  }
  body << "  unset multiplot\n";
  return {chartName, "Envelope of a member's resultants over the load combinations", width,
          height, body.str()};
}

}  // namespace beamrotor
