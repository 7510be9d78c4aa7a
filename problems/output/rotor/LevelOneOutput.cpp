#include "problems/output/rotor/LevelOneOutput.hpp"

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

std::string levelOneVerdict(const LevelOneResult& r) {
  if (r.pass) return r.mapDecides ? "pass (2 <= Q0/Qa < 10: check API's CSR/density map)" : "pass";
  std::string why = "Level II required:";
  if (r.logDecrementAtQa < kLevelOneLogDecrement) why += " log decrement at Qa below 0.1";
  if (r.ratio < kLevelOneMinimumRatio) {
    if (r.logDecrementAtQa < kLevelOneLogDecrement) why += ",";
    why += " Q0/Qa below 2";
  }
  return why;
}

}  // namespace beamrotor
