// gnuplot chart scripts (see Charts.hpp). Units are chosen for reading: mm, mrad, kN m, MPa.
#include "problems/output/structure/Charts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "problems/output/structure/ModeShapes.hpp"
#include "problems/output/structure/NoiseFloor.hpp"
#include "problems/output/structure/Tables.hpp"

namespace beamrotor {

namespace {

/// A curve of a panel: a table column scaled to the panel's unit.
struct Curve {
  std::string file;   ///< CSV file, relative to the chart's directory
  int xColumn = 0;    ///< 1-based gnuplot column of x
  int column = 0;     ///< 1-based gnuplot column of the value
  std::string title;  ///< key entry (enhanced text: u_y shows a subscript)
  std::string plainTitle = {};  ///< the entry as plain text, for sizing the key
};

bool anyNonZero(const CsvTable& table, const std::string& column) {
  const auto values = table.numbers(column);
  return std::any_of(values.begin(), values.end(), [](double v) { return v != 0; });
}

/// Dashed vertical lines at the markers in every panel; names above the first panel only.
/// Their places (m) are multiplied by `factor`, into the x axis' unit. A name that would print
/// over the one before it (points close together, or shafts laid end to end) is left out, its
/// line kept; the names at the ends of the line are set inside the plot's width.
std::string markerCommands(const std::vector<ChartMarker>& markers, double factor) {
  std::ostringstream s;
  for (const ChartMarker& m : markers)
    s << "  set arrow from first " << number(m.x * factor) << ", graph 0 to first "
      << number(m.x * factor) << ", graph 1 nohead dashtype 2 linecolor rgb 'gray50'\n";
  if (markers.empty()) return s.str();
  std::vector<ChartMarker> inOrder = markers;
  std::stable_sort(inOrder.begin(), inOrder.end(),
                   [](const ChartMarker& a, const ChartMarker& b) { return a.x < b.x; });
  const double lo = inOrder.front().x, hi = inOrder.back().x;
  // A chart's plot is about 110 characters of the label font wide (900 pixels; narrower
  // panels hold names spread as far apart).
  const double character = (hi > lo ? hi - lo : 1.0) / 110;
  double lastRight = -std::numeric_limits<double>::infinity();
  for (const ChartMarker& m : inOrder) {
    const double width = double(m.name.size()) * character;
    double left = m.x - width / 2;
    const char* justify = "center";
    if (m.x - lo < width / 2) {
      left = m.x;
      justify = "left";
    } else if (hi - m.x < width / 2) {
      left = m.x - width;
      justify = "right";
    }
    if (left < lastRight + character) continue;  // it would print over the name before it
    lastRight = left + width;
    s << "  set label " << gnuplotText(m.name) << " at first " << number(m.x * factor)
      << ", graph 1 offset 0,0.7 " << justify << " textcolor rgb '#303030'\n";
  }
  return s.str();
}

/// The x axis along a line: metres, or the user's length unit (the table holds it).
std::string alongLineLabel(const OutputUnits& units) {
  const std::string unit = units.columnIn("m", {1, "m"}).unit;
  std::string label = "  set xlabel ";  // appended: GCC 12 warns (-Wrestrict) on literal + temporary
  label += gnuplotText("x along the line [" + unit + "]");
  label += "\n";
  return label;
}

/// `plot` of the curves, each column multiplied by scale; filled to the axis when `filled`
/// (the look of a moment or stress diagram; only for a single curve, since stacked translucent
/// fills of several curves mix into a muddy grey). A single curve has no key entry.
std::string plotCommand(const std::vector<Curve>& curves, double scale, bool filled) {
  std::ostringstream s;
  s << "  plot ";
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const std::string data = gnuplotFile(curves[i].file) + " skip 1 using " +
                             std::to_string(curves[i].xColumn) + ":($" +
                             std::to_string(curves[i].column) + "*" + number(scale) + ")";
    if (i) s << ", \\\n       ";
    if (filled && curves.size() == 1)
      s << data << " with filledcurves y=0 fillstyle transparent solid 0.2 noborder " << colour(i)
        << " notitle, \\\n       ";
    // One curve needs no key: the axis label names it.
    s << data << " with lines linewidth 2 " << colour(i)
      << (curves.size() == 1 ? std::string(" notitle") : " title " + curves[i].title);
  }
  s << "\n";
  return s.str();
}

/// "12.35 Hz", or in the user's frequency unit.
std::string frequencyText(double hz, const OutputUnits& units) {
  const OutputUnits::Shown shown = units.valueIn("Hz", {1, "Hz"});
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g ", hz * shown.factor);
  return buffer + shown.unit;
}

}  // namespace

std::vector<ChartMarker> namedPointMarkers(const Model& model) {
  const auto coordinate = lineCoordinates(model);
  std::vector<ChartMarker> markers;
  for (const auto& [name, node] : model.namedNodes())
    if (coordinate[node]) markers.push_back({name, *coordinate[node]});
  std::stable_sort(markers.begin(), markers.end(),
                   [](const ChartMarker& a, const ChartMarker& b) { return a.x < b.x; });
  // The automatic "start" and "end" would print over a deck's own point at the same place.
  std::vector<ChartMarker> shown;
  for (const ChartMarker& m : markers) {
    const bool automatic = m.name == "start" || m.name == "end";
    const bool covered = std::any_of(markers.begin(), markers.end(), [&](const ChartMarker& o) {
      return o.name != "start" && o.name != "end" &&
             std::abs(o.x - m.x) <= 1e-12 * (1 + std::abs(m.x));
    });
    if (!automatic || !covered) shown.push_back(m);
  }
  return shown;
}

std::vector<ChartMarker> commonPointMarkers(const std::vector<const Model*>& models) {
  std::vector<ChartMarker> common;
  for (const ChartMarker& m : namedPointMarkers(*models.front())) {
    bool everywhere = true;
    for (const Model* model : models) {
      const auto markers = namedPointMarkers(*model);
      everywhere = everywhere && std::any_of(markers.begin(), markers.end(), [&](const auto& o) {
                     return o.name == m.name && std::abs(o.x - m.x) <= 1e-12 * (1 + std::abs(m.x));
                   });
    }
    if (everywhere) common.push_back(m);
  }
  return common;
}

ChartScript staticDiagrams(const std::string& caption, const std::string& chartName,
                           const std::vector<FieldSeries>& series,
                           const std::vector<ChartMarker>& markers,
                           const std::vector<Diagram>& shown, const OutputUnits& units) {
  // A quantity drawn in a panel: its main column and, in 3D, the other plane's, shown only
  // when it is not zero everywhere in every series.
  struct Drawn {
    std::string column;
    std::string title;  ///< gnuplot enhanced-text literal
  };
  struct Panel {
    std::string quantity;
    Drawn main;
    std::optional<Drawn> other;
    OutputUnits::Shown shown;  ///< from the fields table's unit
    bool filled;
  };
  // Units chosen for reading (mm, mrad, kN m, MPa, kN), or the user's (the table holds them).
  const auto in = [&](const char* unit, double factor, const char* name) {
    return units.columnIn(unit, {factor, name});
  };
  const std::vector<Panel> every{
      {"deflection", {"uy", "'u_y'"}, Drawn{"uz", "'u_z'"}, in("m", 1e3, "mm"), false},
      {"rotation", {"rz", "'θ_z'"}, Drawn{"ry", "'θ_y'"}, in("rad", 1e3, "mrad"), false},
      {"bending moment", {"Mz", "'M_z'"}, Drawn{"My", "'M_y'"}, in("N m", 1e-3, "kN m"), true},
      // Signed, as the fibres carry them: tension above the axis, compression below.
      {"normal stress", {"stress_top", "'σ top fibre'"}, Drawn{"stress_bottom", "'σ bottom fibre'"},
       in("Pa", 1e-6, "MPa"), true},
      {"shear stress", {"shear_y", "'τ of V_y'"}, Drawn{"shear_z", "'τ of V_z'"},
       in("Pa", 1e-6, "MPa"), true},
      {"shear force", {"Vy", "'V_y'"}, Drawn{"Vz", "'V_z'"}, in("N", 1e-3, "kN"), true},
  };
  std::vector<Panel> panels;
  for (Diagram d : shown) panels.push_back(every.at(std::size_t(d)));
  // One series: the quantities' own names; several: the series' titles, plus the quantity's
  // name where a panel shows two.
  const auto curvesOf = [&](const Panel& panel) {
    bool other = false;
    for (const FieldSeries& f : series)
      other = other || (panel.other && anyNonZero(*f.fields, panel.other->column));
    std::vector<Curve> curves;
    for (const FieldSeries& f : series)
      for (const Drawn* q : {&panel.main, other ? &*panel.other : nullptr}) {
        if (!q) continue;
        const std::string plain = series.size() == 1 ? q->column
                                  : other            ? f.title + ", " + q->column
                                                     : f.title;
        const std::string title = series.size() == 1 ? q->title : gnuplotText(plain);
        curves.push_back(
            {f.csvFile, f.fields->column("x"), f.fields->column(q->column), title, plain});
      }
    return curves;
  };

  // Panels of several curves have their key outside, in a right margin wide enough for the
  // longest title, never over a line; a point's name centred over the right end needs half
  // its width there too.
  std::vector<std::string> keyTitles;
  for (const Panel& panel : panels)
    if (const auto curves = curvesOf(panel); curves.size() > 1)
      for (const Curve& c : curves) keyTitles.push_back(c.plainTitle);
  int rightMargin = keyTitles.empty() ? 30 : keyWidth(keyTitles);
  for (const ChartMarker& m : markers) rightMargin = std::max(rightMargin, textWidth(m.name) / 2 + 10);
  // 240 pixels a panel and 150 for the caption and the axis label: 1350 for all five.
  const int width = 800 + rightMargin, height = 150 + 240 * int(panels.size());
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(int(panels.size()), 1, caption, width, height, rightMargin)
       << "  set grid\n"
       << "  set xzeroaxis linetype 1 linecolor rgb 'gray40'\n"
       << "  set key outside right top\n"
       << "  set xrange [*:*] noextend\n"
       << markerCommands(markers, units.valueIn("m", {1, "m"}).factor);
  for (std::size_t p = 0; p < panels.size(); ++p) {
    if (p == 1) body << "  unset label\n";  // point names once, above the top panel
    if (p + 1 == panels.size()) body << alongLineLabel(units);
    body << "  set ylabel "
         << gnuplotText(panels[p].quantity + " [" + panels[p].shown.unit + "]") << "\n"
         << plotCommand(curvesOf(panels[p]), panels[p].shown.factor, panels[p].filled);
  }
  body << "  unset multiplot\n";
  return {chartName,
          "Deflection, rotation, bending moment, shear force, normal and shear stress along the line",
          width, height, body.str()};
}

std::string_view diagramName(Diagram d) {
  switch (d) {
    case Diagram::deflection: return "deflection";
    case Diagram::rotation: return "rotation";
    case Diagram::moment: return "moment";
    case Diagram::stress: return "stress";
    case Diagram::shear: return "shear";
    case Diagram::force: return "force";
  }
  return "?";
}

ChartScript labelledShapesChart(const std::string& caption, const std::string& chartName,
                                const Model& model, const std::vector<Mode>& modes,
                                const std::vector<std::string>& labels, const CsvTable& shapes,
                                const std::string& csvFile, const OutputUnits& units) {
  // Each mode is drawn by its dominant translation, a torsion mode by its rotation; the axis
  // names the dof when all agree.
  const int shown = std::min<int>(int(labels.size()), int(modes.size()));
  std::vector<Dof> along;
  for (int m = 0; m < shown; ++m) along.push_back(chartedDof(model, modes[m].shape));
  const bool same = std::all_of(along.begin(), along.end(), [&](Dof d) { return d == along[0]; });
  const std::string drawn = same && shown ? std::string(dofName(along[0])) + " " : "";
  const bool anyRotation = std::any_of(along.begin(), along.end(), isRotation);
  const bool anyTranslation = !std::all_of(along.begin(), along.end(), isRotation);
  const std::string scale = anyRotation && anyTranslation
                                ? "(largest translation = 1, torsion: largest rotation = 1 rad)"
                            : anyRotation ? "(largest rotation = 1 rad)"
                                          : "(largest translation = 1)";

  std::ostringstream body;
  body << "  set title " << captionText(caption) << " font ',13'\n"
       << "  set grid\n  set xzeroaxis linetype 1 linecolor rgb 'gray40'\n"
       << "  set key below\n  set xrange [*:*] noextend\n"
       << "  set offsets 0, 0, graph 0.08, graph 0.02\n"
       << alongLineLabel(units)
       << "  set ylabel " << gnuplotText("mode shape " + drawn + scale)
       << "\n"
       << markerCommands(namedPointMarkers(model), units.valueIn("m", {1, "m"}).factor)
       << "  plot ";
  for (int m = 0; m < shown; ++m) {
    const std::string title = "mode " + std::to_string(m + 1) + ": " + labels[m] +
                              (same ? "" : " (" + std::string(dofName(along[m])) + " drawn)");
    if (m) body << ", \\\n       ";
    body << gnuplotFile(csvFile) << " skip 1 using " << shapes.column("x") << ":"
         << shapes.column(modeShapeColumn(m + 1, along[m])) << " with lines linewidth 2 "
         << colour(m) << " title " << gnuplotText(title);
  }
  if (shown == 0) body << "0 notitle";
  body << "\n";
  return {chartName, "The first mode shapes along the line", 900, 560, body.str()};
}

ChartScript modeShapesChart(const std::string& caption, const std::string& chartName,
                            const Model& model, const ModalResult& modal, const CsvTable& shapes,
                            const std::string& csvFile, const OutputUnits& units, int count) {
  std::vector<std::string> labels;
  for (int m = 0; m < std::min<int>(count, int(modal.modes.size())); ++m)
    labels.push_back(frequencyText(modal.modes[m].frequencyHz, units) + ", " +
                     modal.modes[m].description);
  return labelledShapesChart(caption, chartName, model, modal.modes, labels, shapes, csvFile,
                             units);
}

ChartScript sweepChart(const std::string& caption, const std::string& chartName,
                       const std::string& parameter, const std::string& unit,
                       const std::vector<SweepQuantity>& quantities,
                       const CsvTable& table, const std::string& csvFile,
                       const OutputUnits& units) {
  // Frequencies share one panel; every reaction, the stress and each transient maximum get
  // their own, except
  // reactions that stay zero over the whole sweep (an unloaded direction: nothing to see).
  const auto largest = [&](const SweepQuantity& q) {
    double m = 0;
    for (double v : table.numbers(q.column.name)) m = std::max(m, std::abs(v));
    return m;
  };
  // A figure that stays the same at every value (an undamped rotor's log decrement 0): a flat
  // line says nothing, and gnuplot warns about its empty range. Cells left empty read as NaN,
  // equal to nothing, so they count as changing.
  const auto constant = [&](const SweepQuantity& q) {
    const auto v = table.numbers(q.column.name);
    return !v.empty() && std::all_of(v.begin(), v.end(), [&](double x) { return x == v[0]; });
  };
  double largestReaction = 0;
  for (const SweepQuantity& q : quantities)
    if (q.group == SweepGroup::reaction) largestReaction = std::max(largestReaction, largest(q));
  std::vector<std::vector<const SweepQuantity*>> panels;
  // Quantities that share a panel, by group: frequencies, critical speeds, peak orbits.
  std::vector<const SweepQuantity*> frequencies, criticals, peaks;
  for (const SweepQuantity& q : quantities) {
    if (q.group == SweepGroup::frequency)
      frequencies.push_back(&q);
    else if (q.group == SweepGroup::criticalSpeed)
      criticals.push_back(&q);
    else if (q.group == SweepGroup::peakAmplitude)
      peaks.push_back(&q);
    else if (q.group == SweepGroup::extreme && constant(q))
      continue;
    else if (q.group == SweepGroup::stress || q.group == SweepGroup::extreme ||
             (q.group == SweepGroup::reaction && largest(q) > kNegligibleShare * largestReaction))
      panels.push_back({&q});
  }
  for (const auto* shared : {&frequencies, &criticals, &peaks})
    if (!shared->empty()) panels.push_back(*shared);

  const int columns = panels.size() > 1 ? 2 : 1;
  const int rows = std::max<int>(1, int((panels.size() + columns - 1) / columns));
  const int width = 1000, height = 140 + 270 * rows;
  std::ostringstream body;
  // A key only where a panel has several curves; it sits in a right margin as wide as it needs.
  std::vector<std::string> keyTitles;
  for (const auto* shared : {&frequencies, &criticals, &peaks})
    if (shared->size() > 1)
      for (const SweepQuantity* q : *shared) keyTitles.push_back(q->label);
  const int keyMargin = keyTitles.empty() ? 30 : keyWidth(keyTitles);
  body << "  set encoding utf8\n"
       << panelLayout(rows, columns, caption, width, height, keyMargin) << "  set grid\n"
       << "  set key outside right top\n"
       << "  set xlabel "
       << gnuplotText(unit.empty() ? parameter + " (deck parameter, SI units)"
                                   : parameter + " [" + units.columnIn(unit, {1, unit}).unit + "]")
       << "\n";
  // Values spread over decades (a stiffness from 1e4 to 1e6) read better on a log axis.
  const auto values = table.numbers(parameter);
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  if (low != values.end() && *low > 0 && *high >= 30 * *low)
    body << logAxis("x", *low, *high);
  else
    body << "  set format x '%g'\n";  // 4e+07, not the wider 4x10^7, under narrow panels
  for (const auto& panel : panels) {
    // Forces in kN (N m in kN m), stresses in MPa, anything else as it is; or in the user's
    // units, which the table holds.
    const std::string unit = panel.front()->column.unit;
    const bool force = unit == "N" || unit == "N m";
    const OutputUnits::Shown own{unit == "Pa" ? 1e-6 : force ? 1e-3 : 1.0,
                                 unit == "Pa" ? "MPa" : force ? "k" + unit : unit};
    const OutputUnits::Shown axis = units.columnIn(unit, own);
    const double scale = axis.factor;
    const std::string shown = axis.unit.empty() ? "-" : axis.unit;
    const SweepGroup group = panel.front()->group;
    const std::string label = panel.size() == 1                       ? panel.front()->label
                              : group == SweepGroup::criticalSpeed   ? "critical speed"
                              : group == SweepGroup::peakAmplitude   ? "peak orbit"
                                                                      : "frequency";
    // A quantity without a unit (a ratio, a relative error) is marked [-], dimensionless.
    body << "  set ylabel " << gnuplotText(label + " [" + shown + "]")
         << "\n  plot ";
    for (std::size_t i = 0; i < panel.size(); ++i) {
      if (i) body << ", \\\n       ";
      body << gnuplotFile(csvFile) << " skip 1 using " << table.column(parameter) << ":($"
           << table.column(panel[i]->column.name) << "*" << number(scale)
           << ") with linespoints linewidth 2 pointtype 7 " << colour(i)
           << (panel.size() == 1 ? std::string(" notitle")
                                 : " title " + gnuplotText(panel[i]->label));
    }
    body << "\n";
  }
  body << "  unset multiplot\n";
  return {chartName, "Sweep quantities against " + parameter, width, height, body.str()};
}

ChartScript historyChart(const std::string& caption, const std::string& chartName,
                         const CsvTable& table, const std::string& csvFile) {
  const std::vector<CsvColumn>& columns = table.columns();
  const int panels = std::max(1, int(columns.size()) - 1);
  const int width = 1000, height = 140 + 260 * panels;
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(panels, 1, caption, width, height) << "  set grid\n"
       << "  set xzeroaxis linetype 1 linecolor rgb 'gray40'\n"
       << "  set xrange [*:*] noextend\n";
  for (std::size_t c = 1; c < columns.size(); ++c) {
    if (c + 1 == columns.size())
      body << "  set xlabel " << gnuplotText("time t [" + columns[0].unit + "]") << "\n";
    const std::string unit = " [" + (columns[c].unit.empty() ? "-" : columns[c].unit) + "]";
    body << "  set ylabel " << gnuplotText(columns[c].name + unit) << "\n"
         << plotCommand({{csvFile, table.column(columns[0].name), table.column(columns[c].name),
                         gnuplotText(columns[c].name)}},
                        1.0, false);
  }
  body << "  unset multiplot\n";
  return {chartName, "Transient histories against time", width, height, body.str()};
}

}  // namespace beamrotor
