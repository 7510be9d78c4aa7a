#include "problems/output/structure/BaseMotionOutput.hpp"

#include <algorithm>
#include <numbers>
#include <sstream>
#include <utility>
#include <vector>

#include "fem/modal/ResponseSpectrum.hpp"
#include "problems/output/structure/BaseMotionVtk.hpp"
#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor {

namespace {

/// The named points that move relative to the ground somewhere in the sweep, by name.
std::vector<std::pair<std::string, int>> movingPoints(const BaseMotionResult& r,
                                                      const Model& model) {
  std::vector<std::pair<std::string, int>> out;
  const int d = r.options.direction;
  for (const auto& [name, node] : model.namedNodes())
    if (std::any_of(r.points.begin(), r.points.end(),
                    [&](const BaseMotionPoint& p) { return std::abs(p.relative(node, d)) > 0; }))
      out.emplace_back(name, node);
  return out;
}

}  // namespace

CsvTable baseMotionTable(const BaseMotionResult& r, const Model& model, const std::string& stem) {
  const auto points = movingPoints(r, model);
  std::vector<CsvColumn> columns{{"frequency", "Hz"}, {"ground_acceleration", "m/s^2"},
                                 {"base_force", "N"}};
  for (const auto& [name, node] : points) {
    columns.push_back({"T_" + name, ""});
    columns.push_back({"relative_" + name, "m"});
    columns.push_back({"absolute_" + name, "m"});
    columns.push_back({"phase_" + name, "deg"});
  }
  CsvTable t(stem + "_base_motion.csv", columns);
  const int d = r.options.direction;
  for (const BaseMotionPoint& p : r.points) {
    std::vector<CsvCell> row;  // filled in place: GCC 12 misreads a braced list of variants
    row.reserve(columns.size());
    row.emplace_back(p.frequencyHz);
    row.emplace_back(std::abs(p.groundAcceleration));
    row.emplace_back(std::abs(p.baseForce));
    for (const auto& [name, node] : points) {
      row.push_back(p.transmissibility(node, d));
      row.push_back(std::abs(p.relative(node, d)));
      row.push_back(std::abs(p.absolute(node, d)));
      // The absolute acceleration's phase against the ground's.
      row.push_back(std::arg(-p.absolute(node, d)) * 180 / std::numbers::pi);
    }
    t.addRow(std::move(row));
  }
  return t;
}

Json baseMotionJson(const std::string& type, const std::string& name, const BaseMotionResult& r,
                    const Model& model) {
  const BaseMotionOptions& o = r.options;
  Json out = {{"type", type}, {"name", name}};
  out["direction"] = directionName(o.direction);
  out["method"] = o.method == BaseMotionMethod::modal ? "modal" : "direct";
  if (o.displacement > 0)
    out["ground_displacement_m"] = o.displacement;
  else
    out["ground_acceleration_m_s2"] = o.acceleration;
  out["total_mass_kg"] = r.totalMass;
  if (o.method == BaseMotionMethod::modal) {
    Json modes = Json::array();
    for (std::size_t j = 0; j < r.modal.modes.size(); ++j)
      modes.push_back({{"mode", j + 1},
                       {"frequency_hz", r.modal.modes[j].frequencyHz},
                       {"damping_ratio", r.modalDamping[j]},
                       {"effective_mass_kg", r.modal.modes[j].effectiveMass[o.direction]}});
    out["modes"] = modes;
  }
  Json frequencies = Json::array(), force = Json::array();
  for (const BaseMotionPoint& p : r.points) {
    frequencies.push_back(p.frequencyHz);
    force.push_back(std::abs(p.baseForce));
  }
  out["frequencies_hz"] = frequencies;
  out["base_force_n"] = force;
  Json points = Json::object();
  for (const auto& [point, node] : movingPoints(r, model)) {
    Json T = Json::array(), relative = Json::array(), absolute = Json::array();
    for (const BaseMotionPoint& p : r.points) {
      T.push_back(p.transmissibility(node, o.direction));
      relative.push_back(std::abs(p.relative(node, o.direction)));
      absolute.push_back(std::abs(p.absolute(node, o.direction)));
    }
    points[point] = {{"transmissibility", T}, {"relative_m", relative}, {"absolute_m", absolute}};
  }
  out["points"] = points;
  out["csv"] = fileStem(name) + "_base_motion.csv";
  out["peak_frequency_hz"] = r.points[peakPoint(r)].frequencyHz;
  out["vtu"] = baseMotionVtu(fileStem(name));
  return out;
}

void drawBaseMotionChart(const std::filesystem::path& dir, const CsvTable& table,
                         const std::string& stem, const std::string& caption) {
  std::vector<std::string> names;
  for (const CsvColumn& c : table.columns())
    if (c.name.starts_with("T_")) names.push_back(c.name.substr(2));
  if (names.empty()) return;
  const std::string file = table.title();
  const int width = 1000, height = 760;
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(2, 1, caption, width, height, 90 + keyWidth(names)) << "  set grid\n"
       << "  set logscale y\n  set format y '10^{%L}'\n"
       << "  set key outside right top\n  set xrange [*:*] noextend\n";
  // "NAME [UNIT]" with the unit of the table's column (the user's, inUnits). Appended piece
  // by piece: `"..." + temporary` trips GCC 12's false -Wrestrict.
  const auto label = [&](const std::string& name, const std::string& column) {
    std::string text = name;
    text += " [";
    text += table.columns().at(std::size_t(table.column(column) - 1)).unit;
    text += "]";
    return text;
  };
  for (int panel = 0; panel < 2; ++panel) {
    const std::string prefix = panel == 0 ? "T_" : "relative_";
    body << "  set ylabel "
         << gnuplotText(panel == 0 ? std::string("transmissibility |a_abs| / |a_g| [-]")
                                   : label("relative displacement |u|", prefix + names.front()))
         << "\n";
    if (panel == 1) body << "  set xlabel " << gnuplotText(label("frequency", "frequency")) << "\n";
    body << "  plot ";
    for (std::size_t i = 0; i < names.size(); ++i)
      body << (i ? ", \\\n       " : "") << gnuplotFile(file) << " skip 1 using "
           << table.column("frequency") << ":" << table.column(prefix + names[i])
           << " with lines linewidth 2 " << lineStyle(i) << " title " << gnuplotText(names[i]);
    body << "\n";
  }
  body << "  unset multiplot\n";
  drawChart(dir, {stem + "_base_motion", "Transfer functions of the ground's motion", width, height,
                  body.str()});
}

}  // namespace beamrotor
