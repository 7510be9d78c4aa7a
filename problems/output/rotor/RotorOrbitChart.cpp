// Orbit charts of damped rotor modes (see RotorOrbitChart.hpp).
#include "problems/output/rotor/RotorOrbitChart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>
#include <sstream>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/BearingOnPedestal.hpp"
#include "elements/PointInertia.hpp"
#include "fem/model/LineElement.hpp"
#include "problems/output/files/ChartParts.hpp"
#include "problems/output/rotor/RotorTables.hpp"
#include "problems/output/rotor/SpeedAxes.hpp"

namespace beamrotor {

namespace {

/// Angle steps per orbit (10 degrees each): smooth at the chart's size.
constexpr int kOrbitSteps = 36;
/// Display limits of the normalised orbits (largest semi-major axis 1) on the y axis.
constexpr double kOrbitRoom = 1.35;
/// The oblique view: u_z = 1 moves a point this fraction of the shaft's length along x and
/// kOrbitRise up, so a circular orbit shows as a narrow ellipse leaning back.
constexpr double kOrbitDepth = 0.015, kOrbitRise = 0.3;
/// A whirl ratio below this is a straight line (as fem/rotor/RotorModes.cpp decides).
constexpr double kLineOrbit = 1e-6;
/// Palette slots of the senses (as on the Campbell diagram).
constexpr int kForwardSlot = 1, kBackwardSlot = 0, kPlanarSlot = 2;

/// Whether each node is on the shaft: an end of a line element, or every node of a model
/// without any (a bearing's pedestal adds a housing node beside the shaft, which is not).
std::vector<bool> nodesOnShaft(const Model& model) {
  std::vector<bool> on(model.nodes().size(), false);
  bool lines = false;
  for (const auto& e : model.elements())
    if (const LineElement* line = e->asLineElement()) {
      for (int n : line->endNodes()) on[std::size_t(n)] = true;
      lines = true;
    }
  if (!lines) on.assign(on.size(), true);
  return on;
}

/// Nodes of the shaft that carry a lateral orbit, in the order of x.
std::vector<int> stationsAlongShaft(const Model& model, const RotorMode& mode) {
  const std::vector<bool> onShaft = nodesOnShaft(model);
  std::vector<int> nodes;
  for (int n = 0; n < int(mode.shape.rows()); ++n)
    if (onShaft[std::size_t(n)]) nodes.push_back(n);
  std::stable_sort(nodes.begin(), nodes.end(),
                   [&](int a, int b) { return model.nodes()[a].x() < model.nodes()[b].x(); });
  return nodes;
}

/// The element as a disk (a point inertia with mass and a polar moment), or null.
const PointInertia* diskOf(const Element& e) {
  const auto* d = dynamic_cast<const PointInertia*>(&e);
  return d && d->Jp() > 0 && d->m() > 0 ? d : nullptr;
}

Orbit nodeOrbit(const RotorMode& mode, int node) {
  return {mode.shape(node, dofIndex(Dof::uy)), mode.shape(node, dofIndex(Dof::uz))};
}

long long senseOf(const Orbit& o) {
  const double r = o.whirlRatio();
  return r > kLineOrbit ? 1 : r < -kLineOrbit ? -1 : 0;
}

std::string modeTitle(int index, const RotorMode& m) {
  char text[160];
  const std::string decrement =
      std::isfinite(m.logDecrement) ? number(m.logDecrement) : std::string("inf (overdamped)");
  std::snprintf(text, sizeof text, "mode %d: %s Hz, log decrement %s, %s whirl", index,
                number(m.dampedFrequencyHz).c_str(), decrement.c_str(),
                std::string(whirlName(m.whirl)).c_str());
  return text;
}

}  // namespace

CsvTable modeOrbitsTable(const std::string& title, const RotorModesResult& r, const Model& model) {
  CsvTable table(title, {{"mode", ""},
                         {"node", ""},
                         {"x", "m"},
                         {"angle", "deg"},
                         {"uy", ""},
                         {"uz", ""},
                         {"duy", ""},
                         {"duz", ""},
                         {"whirl", ""}});
  for (std::size_t m = 0; m < r.modes.size(); ++m) {
    const RotorMode& mode = r.modes[m];
    const std::vector<int> nodes = stationsAlongShaft(model, mode);
    double largest = 0;
    for (int n : nodes) largest = std::max(largest, nodeOrbit(mode, n).major());
    const double scale = largest > 0 ? 1 / largest : 1;
    const auto at = [&](const Orbit& o, int step) {
      const std::complex<double> turn =
          std::polar(scale, 2 * std::numbers::pi * step / kOrbitSteps);
      return std::pair<double, double>{(o.uy * turn).real(), (o.uz * turn).real()};
    };
    for (int step = 0; step < kOrbitSteps; ++step)
      for (int n : nodes) {
        const Orbit o = nodeOrbit(mode, n);
        const auto [y, z] = at(o, step);
        const auto [y1, z1] = at(o, step + 1);
        table.addRow({(long long)(m + 1), (long long)(n + 1), model.nodes()[n].x(),
                      360.0 * step / kOrbitSteps, y, z, y1 - y, z1 - z, senseOf(o)});
      }
  }
  return table;
}

ChartScript modeOrbitsChart(const std::string& caption, const std::string& chartName,
                            const RotorModesResult& r, const Model& model,
                            const CsvTable& orbits, const std::string& csvFile,
                            const OutputUnits& units) {
  // Places along the shaft in the table's length unit (the model's metres times `along`).
  const OutputUnits::Shown lengthUnit = units.valueIn("m", {1, "m"});
  const double along = lengthUnit.factor;
  const int count = int(r.modes.size());
  const int columns = count > 1 ? 2 : 1, rows = (count + columns - 1) / columns;
  // What the model has decides the key's entries: disks (point inertias with a polar moment;
  // the widest radius of gyration about the axis sizes their bars), bearings, supports.
  double widest = 0;
  bool bearings = false;
  for (const auto& e : model.elements()) {
    if (const PointInertia* d = diskOf(*e)) widest = std::max(widest, std::sqrt(d->Jp() / d->m()));
    bearings = bearings || dynamic_cast<const Bearing*>(e.get());
  }
  const bool disks = widest > 0, supports = !model.supports().empty();
  std::vector<std::string> keyTitles{"shaft at angle 0", "forward orbit", "backward orbit",
                                     "straight-line orbit"};
  if (disks) keyTitles.push_back("disk");
  if (bearings) keyTitles.push_back("bearing");
  if (supports) keyTitles.push_back("support");
  const int keyMargin = keyWidth(keyTitles);  // the key stands right of the panels
  const int width = 620 * columns + keyMargin, height = 150 + 330 * std::max(rows, 1);
  const std::string speed = speedAxes(units).speedText(rpmOf(r.speed));
  const std::string caption2 = caption + "\nmodes at " + speed +
                               ": orbits along the shaft (oblique view, largest orbit 1)";
  const auto captionLines = 1 + std::count(caption2.begin(), caption2.end(), '\n');
  double x0 = 0, x1 = 0;
  for (const auto& p : model.nodes())
    x0 = std::min(x0, along * p.x()), x1 = std::max(x1, along * p.x());
  const double length = std::max(x1 - x0, 1e-9), pad = 0.05 * length;
  // The oblique view: a point (x, uy, uz) of an orbit is drawn at (x + depth uz, uy + rise uz),
  // so each circular orbit shows as a narrow tilted ellipse standing at its station, as on a
  // shaft seen slightly from the side and above.
  const double depth = kOrbitDepth * length, rise = kOrbitRise;
  const double room = kOrbitRoom + rise;
  const double bottom = rise - room;  // where bearings and supports are marked

  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(rows, columns, caption2, width, height, keyMargin + 10)
       << "  set xrange [" << number(x0 - pad) << ":" << number(x1 + pad) << "]\n"
       << "  set yrange [" << number(bottom) << ":" << number(room) << "]\n"
       << "  set ytics 1\n  set grid xtics\n"
       << "  unset xlabel\n  set ylabel 'u_y (u_z drawn obliquely)'\n"
       // level with the panels' top (panelLayout's: 60 px and 20 px a caption line down)
       << "  set key at screen 0.995, screen "
       << number(1 - (60.0 + 20.0 * double(captionLines)) / height)
       << " right top vertical samplen 2\n"
       << "  whirl(w) = w > 0 ? " << colourValue(kForwardSlot) << " : w < 0 ? "
       << colourValue(kBackwardSlot) << " : " << colourValue(kPlanarSlot) << "\n";
  // 1. The shaft's centre line, disks (bars across it, sized by their radius of gyration about
  //    the axis) and bearings and supports (symbols on the axis), the same in every panel.
  body << "  set arrow 1 from " << number(x0) << ",0 to " << number(x1)
       << ",0 nohead dashtype 2 linecolor rgb 'gray40' linewidth 1 back\n";
  int tag = 2;
  for (const auto& e : model.elements()) {
    const auto dofs = e->dofs();
    if (dofs.empty()) continue;
    const double x = along * model.nodes()[dofs[0].node].x();
    if (const PointInertia* d = diskOf(*e)) {
      const double half = 0.35 + 0.5 * std::sqrt(d->Jp() / d->m()) / widest;
      body << "  set arrow " << tag++ << " from " << number(x) << "," << number(-half) << " to "
           << number(x) << "," << number(half)
           << " nohead linewidth 7 linecolor rgb '#99555555' back\n";
    } else if (dynamic_cast<const Bearing*>(e.get()) ||
               dynamic_cast<const BearingOnPedestal*>(e.get())) {
      body << "  set label " << tag++ << " '' at " << number(x) << "," << number(bottom)
           << " point pointtype 9 pointsize 2.2 linecolor rgb 'black' front\n";
    }
  }
  const std::vector<bool> onShaft = nodesOnShaft(model);
  for (const Support& s : model.supports())
    if (onShaft[std::size_t(s.node)])  // not a pedestal's housing, held in its tilts only
      body << "  set label " << tag++ << " '' at " << number(along * model.nodes()[s.node].x()) << ","
         << number(bottom) << " point pointtype 5 pointsize 1.8 linecolor rgb 'black' front\n";
  // 2. One panel per mode: the orbits as short vectors (an arrow head on the first step of each
  //    orbit shows its sense), coloured by sense, and the deflected line at angle 0.
  const int cMode = orbits.column("mode"), cX = orbits.column("x"), cA = orbits.column("angle");
  const int cY = orbits.column("uy"), cZ = orbits.column("uz"), cDy = orbits.column("duy");
  const int cDz = orbits.column("duz"), cW = orbits.column("whirl");
  const auto col = [](int c) {
    std::string column = "$";  // appended: GCC 12 warns (-Wrestrict) on "$" + a temporary
    column += std::to_string(c);
    return column;
  };
  // x and y of the oblique view, for mode m (and `extra` condition), NaN elsewhere.
  const auto viewX = [&](int m, const std::string& extra) {
    return "(" + col(cMode) + " == " + std::to_string(m) + extra + " ? " + col(cX) + " + " +
           number(depth) + " * " + col(cZ) + " : NaN)";
  };
  const std::string viewY = "(" + col(cY) + " + " + number(rise) + " * " + col(cZ) + ")";
  const std::string stepX = "(" + number(depth) + " * " + col(cDz) + ")";
  const std::string stepY = "(" + col(cDy) + " + " + number(rise) + " * " + col(cDz) + ")";
  const std::string first = " && " + col(cA) + " == 0";
  const std::string file = gnuplotFile(csvFile);
  // Each panel reads only its mode's rows (`every`, the rows' first and last index; the
  // condition in `using` stays as the guard): six panels parsing every row three times each
  // made this the dearest chart of a run.
  const std::vector<double> modeOfRow = orbits.numbers("mode");
  const std::vector<double> angleOfRow = orbits.numbers("angle");
  const auto rowsOf = [&](int m, bool startOnly) {
    std::size_t from = modeOfRow.size(), to = 0;
    for (std::size_t i = 0; i < modeOfRow.size(); ++i)
      if (modeOfRow[i] == m && (!startOnly || angleOfRow[i] == 0))
        from = std::min(from, i), to = std::max(to, i);
    return from > to ? std::string(" every ::1::0")
                     : " every ::" + std::to_string(from) + "::" + std::to_string(to);
  };
  for (int m = 1; m <= count; ++m) {
    body << "  set title " << gnuplotText(modeTitle(m, r.modes[std::size_t(m - 1)]))
         << " font ',11'\n";
    if (m == 2) body << "  unset key\n";
    // x labelled under the last row only: a label above a title would crowd the next panel's
    if ((m - 1) / columns == rows - 1)
      body << "  set xlabel " << gnuplotText("x along the shaft [" + lengthUnit.unit + "]") << "\n";
    const std::string all = rowsOf(m, false), start = rowsOf(m, true);
    body << "  plot " << file << " skip 1" << all << " using " << viewX(m, "") << ":" << viewY
         << ":" << stepX << ":" << stepY << ":(whirl(" << col(cW)
         << ")) with vectors nohead linewidth 1.5 linecolor rgb variable notitle, \\\n"
         << "       " << file << " skip 1" << start << " using " << viewX(m, first) << ":"
         << viewY << ":" << stepX << ":" << stepY << ":(whirl(" << col(cW)
         << ")) with vectors head size screen 0.010,25 filled linewidth 1.5 linecolor rgb "
            "variable notitle, \\\n"
         << "       " << file << " skip 1" << start << " using " << viewX(m, first) << ":"
         << viewY
         << " with lines linewidth 2.5 linecolor rgb 'black' title 'shaft at angle 0'";
    for (const auto& [slot, what] : {std::pair<int, const char*>{kForwardSlot, "forward orbit"},
                                     {kBackwardSlot, "backward orbit"},
                                     {kPlanarSlot, "straight-line orbit"}})
      body << ", \\\n       NaN with lines linewidth 2 " << colour(slot) << " title '" << what
           << "'";
    if (disks)
      body << ", \\\n       NaN with lines linewidth 7 linecolor rgb '#99555555' title 'disk'";
    if (bearings)
      body << ", \\\n       NaN with points pointtype 9 pointsize 1.6 linecolor rgb 'black' "
              "title 'bearing'";
    if (supports)
      body << ", \\\n       NaN with points pointtype 5 pointsize 1.4 linecolor rgb 'black' "
              "title 'support'";
    body << "\n";
  }
  body << "  unset multiplot\n";
  return {chartName, "Rotor modes: orbits along the shaft", width, height, body.str()};
}

}  // namespace beamrotor
