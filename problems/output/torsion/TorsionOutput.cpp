#include "problems/output/torsion/TorsionOutput.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor {

namespace {

constexpr double kTrainRpm = 60 / (2 * std::numbers::pi);  // rpm per rad/s
constexpr double kTrainDegree = 180 / std::numbers::pi;

std::string interferenceCsv(const std::string& stem) { return stem + "_interference.csv"; }
std::string crossingsCsv(const std::string& stem) { return stem + "_crossings.csv"; }
std::string torquesCsv(const std::string& stem) { return stem + "_torques.csv"; }
std::string responseCsv(const std::string& stem) { return stem + "_response.csv"; }

/// "order_3", "order_1.5": a column of an order.
std::string orderColumn(double order) {
  std::string name = "order_";
  name += labelNumber(order);
  return name;
}

/// The elastic modes (the free train's rotation at 0 Hz aside), 1-based numbers.
std::vector<int> elasticModes(const TorsionOutcome& t) {
  std::vector<int> modes;
  for (std::size_t m = 0; m < t.modes.modes.size(); ++m)
    if (!t.modes.modes[m].rigidBody) modes.push_back(int(m) + 1);
  return modes;
}

CsvTable interferenceTable(const TorsionOutcome& t, const std::string& stem) {
  std::vector<CsvColumn> columns{{"speed_rpm", "rpm"}};
  const std::vector<int> modes = elasticModes(t);
  for (int m : modes) columns.push_back({"mode_" + std::to_string(m), "Hz"});
  for (double o : t.orders) columns.push_back({orderColumn(o), "Hz"});
  CsvTable table(interferenceCsv(stem), columns);
  for (double speed : {t.speedFrom, t.speedTo}) {
    std::vector<CsvCell> row{speed * kTrainRpm};
    for (int m : modes) row.push_back(t.modes.modes[m - 1].frequencyHz);
    for (double o : t.orders) row.push_back(o * speed / (2 * std::numbers::pi));
    table.addRow(std::move(row));
  }
  return table;
}

CsvTable crossingsTable(const TorsionOutcome& t, const std::string& stem) {
  CsvTable table(crossingsCsv(stem), {{"order", ""}, {"mode", ""}, {"frequency", "Hz"},
                                      {"speed_rpm", "rpm"}});
  for (const TorsionCrossing& c : t.crossings)
    table.addRow({c.order, (long long)c.mode, c.frequencyHz, c.speed * kTrainRpm});
  return table;
}

/// Torques and twists share the amplitude and peak columns: each row names its unit in its
/// quantity cell ("torque kN m"), its numbers converted into it here (the columns have none).
CsvTable torquesTable(const TorsionResponse& r, const std::string& stem,
                      const OutputUnits& units) {
  CsvTable table(torquesCsv(stem), {{"name", ""}, {"quantity", ""}, {"order", ""},
                                    {"amplitude", ""}, {"phase", "deg"}, {"peak", ""}});
  const auto add = [&](const ResponseTrace& trace, const char* quantity, const char* unit) {
    const OutputUnits::Shown shown = units.of(unit);
    std::string what = quantity;
    what += " ";
    what += shown.unit;
    for (std::size_t j = 0; j < r.orders.size(); ++j)
      table.addRow({trace.name, what, r.orders[j], std::abs(trace.amplitudes[j]) * shown.factor,
                    std::arg(trace.amplitudes[j]) * kTrainDegree, trace.peak * shown.factor});
  };
  for (const ResponseTrace& trace : r.torques) add(trace, "torque", "N m");
  for (const ResponseTrace& trace : r.twists) add(trace, "twist", "rad");
  return table;
}

CsvTable responseTable(const TorsionOutcome& t, const std::string& stem) {
  std::vector<CsvColumn> columns{{"speed_rpm", "rpm"}};
  for (const ResponseTrace& trace : t.sweep.front().torques) columns.push_back({trace.name, "N m"});
  CsvTable table(responseCsv(stem), columns);
  for (const TorsionResponse& r : t.sweep) {
    std::vector<CsvCell> row{r.speed * kTrainRpm};
    for (const ResponseTrace& trace : r.torques) row.push_back(trace.peak);
    table.addRow(std::move(row));
  }
  return table;
}

Json responseJson(const TorsionResponse& r) {
  Json out{{"speed_rpm", r.speed * kTrainRpm}, {"orders", r.orders}};
  const auto traces = [&](const std::vector<ResponseTrace>& list) {
    Json all = Json::object();
    for (const ResponseTrace& trace : list) {
      Json amplitudes = Json::array(), phases = Json::array();
      for (const auto& a : trace.amplitudes) {
        amplitudes.push_back(std::abs(a));
        phases.push_back(std::arg(a) * kTrainDegree);
      }
      all[trace.name] = {{"peak", trace.peak}, {"amplitudes", amplitudes}, {"phases_deg", phases}};
    }
    return all;
  };
  out["torques_n_m"] = traces(r.torques);
  out["twists_rad"] = traces(r.twists);
  return out;
}

}  // namespace

std::vector<CsvTable> torsionTables(const TorsionOutcome& t, const std::string& stem,
                                   const OutputUnits& units) {
  std::vector<CsvTable> out;
  if (t.speedTo > t.speedFrom) out.push_back(interferenceTable(t, stem));
  if (!t.orders.empty()) out.push_back(crossingsTable(t, stem));
  if (t.atSpeed) out.push_back(torquesTable(*t.atSpeed, stem, units));
  if (!t.sweep.empty()) out.push_back(responseTable(t, stem));
  return out;
}

Json torsionTrainJson(const TorsionOutcome& t, const std::string& stem) {
  Json out{{"reference", t.reference}};
  Json shafts = Json::array();
  for (std::size_t i = 0; i < t.shafts.size(); ++i)
    shafts.push_back({{"name", t.shafts[i]}, {"speed_ratio", t.speedRatios[i]}});
  out["shafts"] = shafts;
  if (!t.orders.empty()) {
    Json crossings = Json::array();
    for (const TorsionCrossing& c : t.crossings)
      crossings.push_back({{"order", c.order}, {"mode", c.mode}, {"frequency_hz", c.frequencyHz},
                           {"speed_rpm", c.speed * kTrainRpm}});
    out["interference"] = {{"orders", t.orders},
                           {"from_rpm", t.speedFrom * kTrainRpm},
                           {"to_rpm", t.speedTo * kTrainRpm},
                           {"crossings", crossings}};
  }
  if (!t.excitation.empty()) {
    Json torques = Json::array();
    for (const HarmonicTorque& h : t.excitation) {
      Json entry{{"at", h.at.name()}, {"order", h.order}, {"amplitude_n_m", h.amplitude},
                 {"phase_deg", h.phase * kTrainDegree}};
      if (!h.source.empty()) entry["from_crank_slider"] = h.source;
      torques.push_back(entry);
    }
    out["excitation"] = torques;
  }
  if (t.atSpeed) out["response"] = responseJson(*t.atSpeed);
  Json files = Json::object();
  for (const CsvTable& table : torsionTables(t, stem))
    files[table.title().substr(stem.size() + 1, table.title().size() - stem.size() - 5) + "_csv"] =
        table.title();
  if (t.speedTo > t.speedFrom) files["interference_chart"] = stem + "_interference";
  if (!t.sweep.empty()) files["response_chart"] = stem + "_response";
  out["files"] = files;
  return out;
}

void drawTorsionCharts(const std::filesystem::path& dir, const TorsionOutcome& t,
                       const std::string& stem, const std::string& caption,
                       const OutputUnits& units) {
  if (!(t.speedTo > t.speedFrom)) return;
  // The tables hold speeds in rpm, frequencies in Hz and torques in N m, or (inUnits) the
  // user's units of them: the axes' ranges and labels follow.
  const OutputUnits::Shown rpm = units.of("rpm");
  const OutputUnits::Shown hz = units.of("Hz");
  const OutputUnits::Shown torque = units.of("N m");
  const std::string speedAxis = "speed of " + t.reference + " [" + rpm.unit + "]";
  const CsvTable diagram = interferenceTable(t, stem);
  const std::string file = interferenceCsv(stem);
  std::vector<std::string> titles;
  std::ostringstream plot;
  plot << "  plot ";
  std::size_t curve = 0;
  const auto line = [&](const std::string& column, const std::string& title, bool order) {
    if (curve) plot << ", \\\n       ";
    plot << gnuplotFile(file) << " skip 1 using 1:" << diagram.column(column) << " with lines "
         << (order ? "linewidth 1 dashtype 2 linecolor rgb 'gray30'" : "linewidth 2 " + colour(curve))
         << " title " << gnuplotText(title);
    titles.push_back(title);
    ++curve;
  };
  // Up to the highest order's frequency at the top speed, or the first elastic mode: the modes
  // far above every order cannot be crossed and would flatten the region that matters.
  double top = 0;
  for (double o : t.orders) top = std::max(top, o * t.speedTo / (2 * std::numbers::pi));
  const std::vector<int> modes = elasticModes(t);
  if (!modes.empty()) top = std::max(top, t.modes.modes[modes.front() - 1].frequencyHz);
  top *= 1.2;
  for (int m : modes)
    if (const double f = t.modes.modes[m - 1].frequencyHz; f <= top)
      line("mode_" + std::to_string(m),
           "mode " + std::to_string(m) + ": " + labelNumber(f * hz.factor) + " " + hz.unit, false);
  for (double o : t.orders) line(orderColumn(o), "order " + labelNumber(o), true);
  std::ostringstream body;
  const int width = 900 + keyWidth(titles);
  body << "  set encoding utf8\n  set title " << captionText(caption) << "\n  set grid\n"
       << "  set key outside right top\n"
       << "  set xlabel " << gnuplotText(speedAxis) << "\n"
       << "  set ylabel " << gnuplotText("frequency [" + hz.unit + "]") << "\n"
       << "  set xrange [" << number(t.speedFrom * kTrainRpm * rpm.factor) << ":"
       << number(t.speedTo * kTrainRpm * rpm.factor) << "]\n"
       << "  set yrange [0:" << number(std::max(top * hz.factor, 1e-300)) << "]\n";
  for (const TorsionCrossing& c : t.crossings)
    body << "  set object circle at " << number(c.speed * kTrainRpm * rpm.factor) << ","
         << number(c.frequencyHz * hz.factor)
         << " size screen 0.006 fillcolor rgb 'black' fillstyle solid front\n";
  body << plot.str() << "\n";
  drawChart(dir, {stem + "_interference",
                  "Interference diagram: natural frequencies and excitation orders against speed",
                  width, 650, body.str()});
  if (t.sweep.empty()) return;
  const CsvTable response = responseTable(t, stem);
  std::ostringstream rbody;
  PositiveRange range;
  for (const TorsionResponse& r : t.sweep)
    for (const ResponseTrace& trace : r.torques) range.include(trace.peak * torque.factor);
  std::vector<std::string> names;
  for (const ResponseTrace& trace : t.sweep.front().torques) names.push_back(trace.name);
  rbody << "  set encoding utf8\n  set title " << captionText(caption) << "\n  set grid\n"
        << "  set key outside right top\n"
        << "  set xlabel " << gnuplotText(speedAxis) << "\n"
        << "  set ylabel " << gnuplotText("vibratory torque, peak [" + torque.unit + "]") << "\n";
  if (range.high > 0) rbody << logAxis("y", range);
  rbody << "  plot ";
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i) rbody << ", \\\n       ";
    rbody << gnuplotFile(responseCsv(stem)) << " skip 1 using 1:" << response.column(names[i])
          << " with lines linewidth 2 " << lineStyle(i) << " title " << gnuplotText(names[i]);
  }
  rbody << "\n";
  drawChart(dir, {stem + "_response", "Vibratory torques against speed", 900 + keyWidth(names),
                  650, rbody.str()});
}

}  // namespace beamrotor
