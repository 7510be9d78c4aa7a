#include "problems/output/rotor/LevelOneOutput.hpp"

#include <algorithm>
#include <sstream>

#include "problems/output/files/ChartParts.hpp"

namespace beamrotor {

CsvTable levelOneTable(const std::string& title, const LevelOneResult& r) {
  CsvTable table(title, {{"cross_coupling", "N/m"}, {"log_decrement", ""}});
  for (const CrossCouplingSample& s : r.curve) table.addRow({s.crossCoupling, s.logDecrement});
  return table;
}

ChartScript levelOneDiagram(const std::string& caption, const std::string& chartName,
                            const LevelOneResult& r, const std::string& csvFile,
                            const OutputUnits& units) {
  const int width = 900, height = 600;
  // Cross-coupling drawn in MN/m, or the user's stiffness unit: `column` scales the table's
  // values (N/m, or already theirs), `q` the result's (N/m).
  const OutputUnits::Shown column = units.columnIn("N/m", {1e-6, "MN/m"});
  const OutputUnits::Shown q = units.valueIn("N/m", {1e-6, "MN/m"});
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(1, 1, caption, width, height) << "  set grid\n"
       << "  set key inside top right box opaque\n  set autoscale xfix\n"
       << "  set xlabel " << gnuplotText("added cross-coupling Q [" + q.unit + "]") << "\n"
       << "  set ylabel 'least log decrement'\n"
       << "  set arrow 1 from first " << number(r.anticipated * q.factor)
       << ", graph 0 to first " << number(r.anticipated * q.factor)
       << ", graph 1 nohead dashtype 2 " << colour(1) << "\n";
  if (r.found && r.zeroDecrement > 0)
    body << "  set arrow 2 from first " << number(r.zeroDecrement * q.factor)
         << ", graph 0 to first " << number(r.zeroDecrement * q.factor)
         << ", graph 1 nohead dashtype 3 " << colour(2) << "\n";
  body << "  plot " << gnuplotFile(csvFile) << " skip 1 using ($1*" << number(column.factor)
       << "):2 with lines linewidth 2 " << colour(0) << " title 'least log decrement', \\\n"
       << "       0.1 with lines dashtype 2 lc rgb '#808080' title 'API 684: 0.1 at Qa', \\\n"
       << "       NaN with lines dashtype 2 " << colour(1) << " title "
       << gnuplotText("Qa = " + labelNumber(r.anticipated * q.factor) + " " + q.unit);
  if (r.found && r.zeroDecrement > 0)
    body << ", \\\n       NaN with lines dashtype 3 " << colour(2) << " title "
         << gnuplotText("Q0 = " + labelNumber(r.zeroDecrement * q.factor) + " " + q.unit);
  body << "\n  unset multiplot\n";
  return {chartName, "API 684 Level I: least log decrement against added cross-coupling", width,
          height, body.str()};
}

ChartScript criticalSpeedRatioDiagram(const std::string& caption, const std::string& chartName,
                                      const CriticalSpeedRatioPoint& p) {
  const int width = 900, height = 600;
  // The boundary (fem/rotor/LevelOneStability.hpp): 2.5 up to 16.53 kg/m^3, 2.0 at 60, and
  // every denser machine in region B (the line drops to 0 there); region B shaded.
  const double right = std::max(80.0, 1.25 * p.averageDensity);
  const double top = std::max(4.0, 1.2 * p.ratio);
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(1, 1, caption, width, height) << "  set grid\n"
       << "  set key inside top right box opaque\n"
       << "  set xrange [0:" << number(right) << "]\n  set yrange [0:" << number(top) << "]\n"
       << "  set xlabel 'average gas density [kg/m^3]'\n"
       << "  set ylabel 'critical speed ratio (MCOS / rigid-support critical)'\n"
       << "  set label 1 'region A' at graph 0.08, graph 0.2 textcolor rgb '#606060'\n"
       << "  set label 2 'region B' at graph 0.08, graph 0.9 textcolor rgb '#606060'\n"
       << "  set object 1 polygon from 0,2.5 to 16.53,2.5 to 60,2 to 60,0 to " << number(right)
       << ",0 to " << number(right) << "," << number(top) << " to 0," << number(top)
       << " to 0,2.5 fillcolor rgb '#fbe3e0' fillstyle solid 1.0 noborder behind\n"
       << "  set arrow 1 from 0,2.5 to 16.53,2.5 nohead linewidth 2 lc rgb '#404040'\n"
       << "  set arrow 2 from 16.53,2.5 to 60,2 nohead linewidth 2 lc rgb '#404040'\n"
       << "  set arrow 3 from 60,2 to 60,0 nohead linewidth 2 lc rgb '#404040'\n"
       << "  plot NaN with lines linewidth 2 lc rgb '#404040' title "
       << gnuplotText("API 617: boundary of region B (shaded)") << ", \\\n"
       << "       '+' using (" << number(p.averageDensity) << "):(" << number(p.ratio)
       << ") every ::0::0 with points pointtype 7 pointsize 2 " << colour(p.regionB ? 1 : 2)
       << " title "
       << gnuplotText("this machine: CSR " + labelNumber(p.ratio) +
                      (p.regionB ? ", region B" : ", region A"))
       << "\n  unset multiplot\n";
  return {chartName, "API 617 Level I: critical speed ratio against average gas density", width,
          height, body.str()};
}

std::string levelOneVerdict(const LevelOneResult& r) {
  if (r.pass)
    return r.mapDecides ? "pass (2 <= Q0/Qa < 10, region A of API's CSR map)" : "pass";
  std::string why = "Level II required:";
  if (r.logDecrementAtQa < kLevelOneLogDecrement) why += " log decrement at Qa below 0.1";
  if (r.ratio < kLevelOneMinimumRatio) {
    if (r.logDecrementAtQa < kLevelOneLogDecrement) why += ",";
    why += " Q0/Qa below 2";
  }
  if (r.mapDecides && r.map.regionB) {
    if (why.back() != ':') why += ",";
    why += " 2 <= Q0/Qa < 10 in region B of API's CSR map";
  }
  return why;
}

}  // namespace beamrotor
