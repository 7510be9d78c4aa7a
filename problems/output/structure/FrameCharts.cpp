// Whole-frame charts (see FrameCharts.hpp).
#include "problems/output/structure/FrameCharts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "fem/assembly/MemberExtrema.hpp"
#include "problems/output/files/ChartParts.hpp"

namespace beamrotor {

namespace {

/// Fractions of the frame's size that the largest displacement and the largest moment take
/// on the chart: visible, yet the frame stays recognisable.
constexpr double kDeformedShare = 0.08;
constexpr double kDiagramShare = 0.15;

/// "$k" for gnuplot's using: column k (1-based) of a member table.
std::string columnRef(const CsvTable& t, const std::string& name) {
  std::string ref = "$";  // appended, not "$" + a temporary: see joined() below (GCC 12)
  ref += std::to_string(t.column(name));
  return ref;
}

/// A drawn coordinate: column `axis` plus scale times `value` (a gnuplot expression).
std::string shiftedCoordinate(const CsvTable& t, const std::string& axis, const std::string& value,
                    double scale) {
  const std::string column = columnRef(t, axis);
  return "(" + column + "+" + number(scale) + "*" + value + ")";
}

double largestAbs(const std::vector<MemberSeries>& members, const std::vector<std::string>& cols) {
  double m = 0;
  for (const MemberSeries& s : members)
    for (const std::string& c : cols)
      for (double v : s.table->numbers(c)) m = std::max(m, std::abs(v));
  return m;
}

/// A round factor for the caption: 1, 2 or 5 times a power of ten, at most `scale`.
double roundFactor(double scale) {
  if (!(scale > 0) || !std::isfinite(scale)) return 1;
  const double decade = std::pow(10.0, std::floor(std::log10(scale)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * decade <= scale) return m * decade;
  return decade;
}

/// A panel's plot (plot in 2d, splot in 3d) of curves, each "using" part with its style.
std::string plotOf(bool planar, const std::vector<std::string>& clauses) {
  std::string s = planar ? "  plot " : "  splot ";
  for (std::size_t i = 0; i < clauses.size(); ++i) s += (i ? ", \\\n       " : "") + clauses[i];
  return s + "\n";
}

}  // namespace

ChartScript frameChart(const std::string& caption, const std::string& chartName,
                       const Model& model, const NodalField& displacement,
                       const std::vector<MemberSeries>& members, bool planar) {
  // 1. Scales: the frame's size against the largest displacement and moment.
  Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = -low;
  for (const auto& x : model.nodes()) low = low.cwiseMin(x), high = high.cwiseMax(x);
  const double size = model.nodes().empty() ? 1 : std::max((high - low).maxCoeff(), 1e-30);
  const double largestU = largestDisplacement(model, displacement).value;
  const double magnify = largestU > 0 ? roundFactor(kDeformedShare * size / largestU) : 1;
  const std::vector<std::string> moments =
      planar ? std::vector<std::string>{"Mz"} : std::vector<std::string>{"Mz", "My"};
  const double largestM = largestAbs(members, moments);
  const double perMoment = largestM > 0 ? kDiagramShare * size / largestM : 0;

  // 2. The panels' common set-up: equal scales on every axis.
  const int width = planar ? 1200 : 1400, height = planar ? 560 : 640;
  std::ostringstream body;
  body << "  set encoding utf8\n"
       // A 3d view's z axis and its label stand out right of its panel: room for them.
       << panelLayout(1, 2, caption, width, height, planar ? 30 : 80) << "  unset key\n"
       << "  set grid\n";
  // Drawn axes: a planar frame's x and y; a 3d frame's x, z, y, so that global y (up, the
  // direction of self-weight) is the chart's vertical.
  const std::vector<int> drawn = planar ? std::vector<int>{0, 1} : std::vector<int>{0, 2, 1};
  const std::array<std::string, 3> names{"x", "y", "z"};
  // Appended piece by piece: GCC 12 takes "literal" + a temporary string for an overlapping
  // copy (a false -Wrestrict, GCC bugs 105329 and 105651).
  const auto joined = [&](auto part) {
    std::string out;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      if (i) out += ':';
      out += part(drawn[i]);
    }
    return out;
  };
  const auto placeText = [&](const Eigen::Vector3d& x) {
    std::string out;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      if (i) out += ", ";
      out += number(x[drawn[i]]);
    }
    return out;
  };
  if (planar)
    body << "  set size ratio -1\n  set xlabel 'x [m]'\n  set ylabel 'y [m]'\n"
         << "  set offsets graph 0.08, graph 0.08, graph 0.08, graph 0.08\n";
  else
    // The vertical range holds the magnified shape and the diagrams (a flat frame would
    // otherwise get a sliver of an axis crowded with ticks).
    // Shrunk a little and the z ticks moved off the corner they share with the x axis' last tick.
    body << "  set view equal xyz\n  set view 64, 28, 0.9\n  set ytics offset 1.5,0\n  set zrange ["
         << number(low.y() - 0.2 * size) << ":" << number(high.y() + 0.2 * size)
         << "]\n  set xyplane at " << number(low.y() - 0.2 * size)
         << "\n  set xlabel 'x [m]'\n  set ylabel 'z [m]'\n  set zlabel 'y [m]'\n";
  // Coordinates shifted by k times the expressions d[axis].
  const auto at = [&](const CsvTable& t, const std::array<std::string, 3>& d, double k) {
    return joined([&](int axis) { return shiftedCoordinate(t, names[axis], d[axis], k); });
  };
  const std::array<std::string, 3> none{"0", "0", "0"};
  const std::string undeformedStyle = " with lines linewidth 1.5 dashtype 2 linecolor rgb 'gray55'";

  // 3. Panel 1: deformed over undeformed, joints labelled.
  std::vector<std::string> clauses;
  for (const MemberSeries& m : members) {
    const CsvTable& t = *m.table;
    const std::string data = gnuplotFile(m.csvFile) + " skip 1 using ";
    clauses.push_back(data + at(t, none, 0) + undeformedStyle);
    clauses.push_back(data + at(t, {columnRef(t, "ux"), columnRef(t, "uy"), columnRef(t, "uz")}, magnify) +
                      " with lines linewidth 2.5 " + colour(0));
  }
  char largest[32];
  std::snprintf(largest, sizeof largest, "%.3g", largestU * 1e3);
  body << "  set title " << gnuplotText("deformed shape, displacements × " + number(magnify) +
                                        " (largest " + largest + " mm)")
       << "\n";
  for (const auto& [name, node] : model.namedNodes()) {
    const Eigen::Vector3d& x = model.nodes()[node];
    body << "  set label " << gnuplotText(name) << " at " << placeText(x)
         << " offset 0.6,0.6 textcolor rgb '#303030'\n";
  }
  body << plotOf(planar, clauses) << "  unset label\n";

  // 4. Panel 2: moment diagrams across the members on their tension side (Mz > 0 stretches
  //    the -y fibres, My > 0 the +z ones), hatched, each member's largest |M| labelled.
  clauses.clear();
  std::string labels;
  for (const MemberSeries& m : members) {
    const CsvTable& t = *m.table;
    const std::string data = gnuplotFile(m.csvFile) + " skip 1 using ";
    clauses.push_back(data + at(t, none, 0) + " with lines linewidth 2 linecolor rgb 'gray30'");
    for (std::size_t c = 0; c < moments.size(); ++c) {
      const bool mz = moments[c] == "Mz";
      const std::string e = mz ? "ey" : "ez";
      const std::string sign = mz ? "-" : "";
      const std::string M = columnRef(t, moments[c]);
      if (!(largestAbs({m}, {moments[c]}) > 1e-9 * largestM)) continue;  // nothing to draw
      const auto offset = [&](int axis) {
        const std::string direction = columnRef(t, e + "_" + names[axis]);
        return "(" + sign + M + "*" + direction + ")";
      };
      clauses.push_back(data + at(t, {offset(0), offset(1), offset(2)}, perMoment) +
                        " with lines linewidth 2 " + colour(c + 1));
      // Hatching: a line from the axis to the diagram at every station.
      const std::string base =
          joined([&](int axis) { return std::to_string(t.column(names[axis])); });
      const std::string scale = number(perMoment);
      const std::string delta = joined([&](int axis) {
        const std::string shift = offset(axis);
        return "(" + scale + "*" + shift + ")";
      });
      clauses.push_back(data + base + ":" + delta + " with vectors nohead linewidth 0.8 " +
                        colour(c + 1));
    }
  }
  for (const auto& [name, elements] : model.members()) {
    const auto ranges = memberForceRanges(model, elements, displacement);
    for (std::size_t c = 0; c < moments.size(); ++c) {
      const ForceComponent k = moments[c] == "Mz" ? ForceComponent::Mz : ForceComponent::My;
      const ComponentRange& r = ranges[int(k)];
      const MemberValue& top = std::abs(r.max.value) >= std::abs(r.min.value) ? r.max : r.min;
      if (!(std::abs(top.value) > 1e-9 * largestM)) continue;
      const Eigen::Vector3d& base = top.x;
      const Eigen::Matrix3d R = asLine(model.elements()[top.element])->localAxes();
      const Eigen::Vector3d tip =
          base + perMoment * top.value *
                     (k == ForceComponent::Mz ? Eigen::Vector3d(-R.row(1).transpose())
                                              : Eigen::Vector3d(R.row(2).transpose()));
      char value[32];
      std::snprintf(value, sizeof value, "%.3g", top.value * 1e-3);
      // A peak in the right third of the frame is labelled leftwards, into the chart: equal
      // peaks (a symmetric frame's) may land on a member's right end, at the canvas' edge.
      const bool rightmost = tip.x() > low.x() + (high.x() - low.x()) * 2 / 3;
      labels += "  set label " +
                gnuplotText((planar ? "" : std::string(componentName(k)) + " ") + value) +
                " at " + placeText(tip) +
                (rightmost ? " right offset -0.4,0.4" : " offset 0.4,0.4") + " textcolor " +
                colour(c + 1).substr(std::string("linecolor ").size()) + "\n";
    }
  }
  body << "  set title " << gnuplotText(std::string(planar ? "bending moment M_z" : "bending moments M_z (red), M_y (green)") +
                                        " [kN m], drawn on the tension side")
       << "\n"
       << labels << plotOf(planar, clauses) << "  unset multiplot\n";
  return {chartName, "Deformed shape and bending moment diagram of the frame", width, height,
          body.str()};
}

}  // namespace beamrotor
