#include "problems/output/rotor/RunUpOutput.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <sstream>
#include <string>
#include <utility>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/rotor/RotorTables.hpp"
#include "problems/output/rotor/SpeedAxes.hpp"

namespace beamrotor {

CsvTable runUpTable(const std::string& title, const RunUpOutcome& r) {
  std::vector<CsvColumn> columns{{"time", "s"}, {"speed", "rad/s"}, {"speed_rpm", "rpm"}};
  for (const std::string& p : r.responsePoints)
    for (const char* what : {"_amplitude", "_uy_half_range", "_uz_half_range"})
      columns.push_back({p + what, "m"});
  CsvTable table(title, columns);
  const auto& histories = r.runUp.histories;
  const std::size_t rows = histories.empty() ? 0 : histories[0].revolutions.speed.size();
  for (std::size_t i = 0; i < rows; ++i) {
    const RevolutionAmplitudes& first = histories[0].revolutions;
    std::vector<CsvCell> row{first.time[i], first.speed[i], rpmOf(first.speed[i])};
    for (const RunUpHistory& h : histories) {
      const RevolutionAmplitudes& a = h.revolutions;
      row.insert(row.end(), {a.amplitude[i], a.halfRangeY[i], a.halfRangeZ[i]});
    }
    table.addRow(std::move(row));
  }
  return table;
}

CsvTable runUpHistoryTable(const std::string& title, const RunUpOutcome& r) {
  std::vector<CsvColumn> columns{
      {"time", "s"}, {"speed", "rad/s"}, {"speed_rpm", "rpm"}, {"angle", "rad"}};
  for (const std::string& p : r.responsePoints)
    for (const char* what : {"_uy", "_uz"}) columns.push_back({p + what, "m"});
  if (r.runUp.driven)
    for (const char* what : {"drive_torque", "unbalance_torque"}) columns.push_back({what, "N m"});
  for (const JournalTrack& j : r.runUp.journals) {
    for (const char* what : {"_y", "_z"}) columns.push_back({j.name + what, "m"});
    columns.push_back({j.name + "_eccentricity", ""});
    // A film's own dofs: the tilting pads' tilts (rad), the only ones there are.
    for (const std::string& own : j.ownNames) columns.push_back({j.name + "_" + own, "rad"});
  }
  if (!r.runUp.journals.empty()) columns.push_back({"film_torque", "N m"});
  for (const RubTrack& t : r.runUp.rubs) {
    columns.push_back({t.name + "_radial", "m"});
    for (const char* what : {"_normal_force", "_friction_force"})
      columns.push_back({t.name + what, "N"});
    columns.push_back({t.name + "_rub_torque", "N m"});
  }
  for (const char* what : {"kinetic", "strain", "dissipated", "gyroscopic", "film", "rub", "work",
                           "energy_balance"})
    columns.push_back({what, "J"});
  CsvTable table(title, columns);
  const RunUpResult& u = r.runUp;
  for (std::size_t i = 0; i < u.times.size(); ++i) {
    // The row filled in place (GCC 12 warns falsely on variants built one by one).
    std::vector<CsvCell> row(columns.size());
    std::size_t at = 0;
    const auto put = [&](std::initializer_list<double> values) {
      for (double v : values) row[at++].emplace<double>(v);
    };
    put({u.times[i], u.speed[i], rpmOf(u.speed[i]), u.angle[i]});
    for (const RunUpHistory& h : u.histories) put({h.uy[i], h.uz[i]});
    if (u.driven) put({u.driveTorque[i], u.unbalanceTorque[i]});
    for (const JournalTrack& j : u.journals) {
      put({j.y[i], j.z[i], j.eccentricity[i]});
      for (const std::vector<double>& own : j.own) put({own[i]});
    }
    if (!u.journals.empty()) put({u.filmTorque[i]});
    for (const RubTrack& t : u.rubs) put({t.radial[i], t.normal[i], t.friction[i], t.torque[i]});
    const RunUpEnergy& e = u.energy;
    put({e.kinetic[i], e.strain[i], e.dissipated[i], e.gyroscopic[i], e.film[i], e.rub[i],
         e.work[i], e.balance(i)});
    table.addRow(std::move(row));
  }
  return table;
}

ChartScript runUpAmplitudeChart(const std::string& caption, const std::string& chartName,
                                const CsvTable& table, const std::string& csvFile,
                                const RunUpOutcome& r, const OutputUnits& units) {
  const SpeedAxes axes = speedAxes(units);
  // The table's column (already in the user's unit where they set one) and the peak (SI).
  const OutputUnits::Shown amplitude = units.columnIn("m", {1e6, "µm"});
  const OutputUnits::Shown peak = units.valueIn("m", {1e6, "µm"});
  std::vector<std::string> titles;
  for (std::size_t k = 0; k < r.responsePoints.size(); ++k) {
    const RunUpHistory& h = r.runUp.histories[k];
    titles.push_back(r.responsePoints[k] + ": peak " +
                     labelNumber(h.peakAmplitude * peak.factor) + " " + peak.unit +
                     " at " + labelNumber(rpmOf(h.speedAtPeak) * axes.speed.factor) + " " +
                     axes.speed.unit);
  }
  const int keyMargin = keyWidth(titles);
  const int width = 770 + keyMargin, height = 560;
  const int x = table.column("speed_rpm");
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(1, 1, caption, width, height, keyMargin) << "  set grid\n"
       << "  set key outside right top\n"
       << "  set xlabel " << gnuplotText("spin speed [" + axes.speed.unit + "]") << "\n"
       << "  set ylabel "
       << gnuplotText("amplitude per revolution [" + amplitude.unit + "]") << "\n"
       << "  set autoscale xfix\n  set yrange [0:*]\n  plot ";
  for (std::size_t k = 0; k < r.responsePoints.size(); ++k) {
    const int y = table.column(r.responsePoints[k] + "_amplitude");
    if (k) body << ", \\\n       ";
    body << gnuplotFile(csvFile) << " skip 1 using " << x << ":($" << y << "*"
         << number(amplitude.factor) << ") with lines linewidth "
         << number(std::max(1.0, 2.5 - 0.5 * double(k))) << " " << lineStyle(k) << " title "
         << gnuplotText(titles[k]);
  }
  body << "\n  unset multiplot\n";
  return {chartName, "run-up: amplitude per revolution against spin speed", width, height,
          body.str()};
}

namespace {

/// Opens a square chart of orbits in `body`: one panel at equal scales on both axes, the key
/// of `titles` beside it. Returns the chart's width and height (px).
std::pair<int, int> squarePanel(std::ostringstream& body, const std::string& caption,
                                const std::vector<std::string>& titles, const std::string& xlabel,
                                const std::string& ylabel) {
  const int keyMargin = keyWidth(titles);
  const int width = 700 + keyMargin, height = 700;
  body << "  set encoding utf8\n"
       << panelLayout(1, 1, caption, width, height, keyMargin) << "  set grid\n"
       << "  set key outside right top\n  set size ratio -1\n"
       << "  set xlabel " << gnuplotText(xlabel) << "\n"
       << "  set ylabel " << gnuplotText(ylabel) << "\n";
  return {width, height};
}

}  // namespace

ChartScript runUpOrbitsChart(const std::string& caption, const std::string& chartName,
                             const CsvTable& history, const std::string& csvFile,
                             const RunUpOutcome& r, const OutputUnits& units) {
  const OutputUnits::Shown length = units.columnIn("m", {1e6, "µm"});
  // The history's columns are in the user's length unit where they set one; c is SI.
  const double shown = length.factor * units.valueIn("m", {1, "m"}).factor;
  std::vector<std::string> titles = r.responsePoints;
  for (const RubTrack& t : r.runUp.rubs) titles.push_back("clearance of rub '" + t.name + "'");
  std::ostringstream body;
  const auto [width, height] = squarePanel(body, caption, titles, "uy [" + length.unit + "]",
                                           "uz [" + length.unit + "]");
  if (!r.runUp.rubs.empty()) {
    // Centred on the stators, the clearance circles and the orbits in view.
    double extent = 0;
    for (const RubTrack& t : r.runUp.rubs) extent = std::max(extent, t.clearance);
    for (const RunUpHistory& h : r.runUp.histories)
      for (std::size_t i = 0; i < h.uy.size(); ++i)
        extent = std::max(extent, std::hypot(h.uy[i], h.uz[i]));
    const std::string e = number(1.1 * extent * shown);
    body << "  set parametric\n  set trange [0:2*pi]\n  set xrange [-" << e << ":" << e
         << "]\n  set yrange [-" << e << ":" << e << "]\n";
  }
  body << "  plot ";
  const std::string last = std::to_string(std::max<std::size_t>(history.rowCount(), 1) - 1);
  for (std::size_t k = 0; k < r.responsePoints.size(); ++k) {
    const int y = history.column(titles[k] + "_uy"), z = history.column(titles[k] + "_uz");
    const std::string columns = " skip 1 using ($" + std::to_string(y) + "*" +
                                number(length.factor) + "):($" + std::to_string(z) + "*" +
                                number(length.factor) + ")";
    if (k) body << ", \\\n       ";
    body << gnuplotFile(csvFile) << columns << " with lines linewidth 0.8 " << colour(k)
         << " title " << gnuplotText(titles[k]);
    // Where the point ends (a still point draws no line).
    body << ", \\\n       " << gnuplotFile(csvFile) << columns << " every ::" << last << "::"
         << last << " with points pointtype 7 pointsize 1.2 " << colour(k) << " notitle";
  }
  // Each rub's clearance circle, in its point's colour.
  for (std::size_t k = 0; k < r.runUp.rubs.size(); ++k) {
    const auto& points = r.responsePoints;
    const std::size_t at = std::size_t(
        std::find(points.begin(), points.end(), r.rubPoints[k]) - points.begin());
    const std::string c = number(r.runUp.rubs[k].clearance * shown);
    body << ", \\\n       " << c << "*cos(t), " << c << "*sin(t) with lines linewidth 1.5 dashtype 2 "
         << colour(at) << " title " << gnuplotText(titles[points.size() + k]);
  }
  body << "\n  unset multiplot\n";
  return {chartName, "run-up: orbits of the response points over the run", width, height,
          body.str()};
}

ChartScript runUpJournalsChart(const std::string& caption, const std::string& chartName,
                               const CsvTable& history, const std::string& csvFile,
                               const RunUpOutcome& r, const OutputUnits& units) {
  // The history's positions are in the user's length unit where they set one: so is c here.
  const double toTable = units.valueIn("m", {1, "m"}).factor;
  std::vector<std::string> titles;
  for (const JournalTrack& j : r.runUp.journals) titles.push_back(j.name);
  titles.push_back("clearance");
  std::ostringstream body;
  const auto [width, height] = squarePanel(body, caption, titles, "y / c", "z / c");
  body << "  set xrange [-1.05:1.05]\n  set yrange [-1.05:1.05]\n"
       << "  set parametric\n  set trange [0:2*pi]\n  plot ";
  for (std::size_t k = 0; k < r.runUp.journals.size(); ++k) {
    const JournalTrack& j = r.runUp.journals[k];
    const int y = history.column(j.name + "_y"), z = history.column(j.name + "_z");
    const std::string clearance = number(j.clearance * toTable);
    body << gnuplotFile(csvFile) << " skip 1 using ($" << y << "/" << clearance << "):($" << z
         << "/" << clearance << ") with lines linewidth " << (k % 2 ? "1.2 dashtype 2 " : "0.8 ")
         << colour(k) << " title " << gnuplotText(j.name) << ", \\\n       ";
  }
  body << "cos(t), sin(t) with lines linewidth 1.5 lc rgb 'black' title "
       << gnuplotText("clearance") << "\n  unset multiplot\n";
  return {chartName, "run-up: the journals' centres in their bearings over the run", width,
          height, body.str()};
}

}  // namespace beamrotor
