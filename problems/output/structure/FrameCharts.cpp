// Whole-frame charts (see FrameCharts.hpp).
#include "problems/output/structure/FrameCharts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

#include "fem/assembly/Recovery.hpp"
#include "fem/model/LineElement.hpp"
#include "problems/output/files/ChartParts.hpp"
#include "problems/output/structure/ModeShapes.hpp"

namespace beamrotor {

namespace {

/// Fractions of the frame's size that the largest displacement and the largest moment take
/// on the chart: visible, yet the frame stays recognisable.
constexpr double kDeformedShare = 0.08;
constexpr double kDiagramShare = 0.15;
// The scale of a 3d view (`set view`'s third number): at 1 the cubic box of axesSetup, its
// tick labels and axis labels fill a panel of viewLayout (checked by eye on a lone column, a
// tower and a frame, and by the projection in tests/problems/output/test_frame_chart_view.cpp).
constexpr double kViewScale = 1.0;

/// A round factor for the caption: 1, 2 or 5 times a power of ten, at most `scale`.
double roundFactor(double scale) {
  if (!(scale > 0) || !std::isfinite(scale)) return 1;
  const double decade = std::pow(10.0, std::floor(std::log10(scale)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * decade <= scale) return m * decade;
  return decade;
}

/// How finely a member is drawn: every station, its elements' ends, or its own two ends.
enum class Detail { stations, elementEnds, memberEnds };

/// The stations drawn along a member at a detail, from its start.
std::vector<const StaticStation*> drawnStations(const std::vector<int>& elements,
                                                const StationsByElement& stations, Detail d) {
  std::vector<const StaticStation*> out;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const auto along = stations.of(elements[i]);
    if (along.empty()) continue;
    const bool first = i == 0, last = i + 1 == elements.size();
    if (d == Detail::stations)
      for (const StaticStation& st : along) out.push_back(&st);
    else if (d == Detail::elementEnds || first)
      out.push_back(&along.front());
    if (d != Detail::stations && last) out.push_back(&along.back());
  }
  return out;
}

/// The finest detail whose places over all members stay within kOutlinePoints.
Detail outlineDetail(const Model& model, const StationsByElement& stations) {
  std::size_t all = 0, ends = 0;
  for (const auto& [name, elements] : model.members()) {
    for (int e : elements) all += stations.of(e).size();
    ends += elements.size() + 1;
  }
  if (all <= kOutlinePoints) return Detail::stations;
  return ends <= kOutlinePoints ? Detail::elementEnds : Detail::memberEnds;
}

/// The larger in magnitude of a range's two ends.
const MemberValue& largerEnd(const ComponentRange& r) {
  return std::abs(r.max.value) >= std::abs(r.min.value) ? r.max : r.min;
}

/// Writes the coordinates of a place in the drawn axes' order, separated by spaces.
class Coordinates {
 public:
  /// `perMetre`: the axes' length unit in metres' stead (1000 for mm).
  Coordinates(bool planar, double perMetre)
      : drawn_(planar ? std::vector<int>{0, 1} : std::vector<int>{0, 2, 1}), perMetre_(perMetre) {}
  std::string text(const Eigen::Vector3d& x, const char* separator = ",") const {
    std::string out;
    for (std::size_t i = 0; i < drawn_.size(); ++i) {
      if (i) out += separator;
      out += number(x[drawn_[i]] * perMetre_);
    }
    return out;
  }
  /// "1:2" or "1:2:3": the using clause of the first columns, then of the next ones from
  /// column `from` on when given.
  std::string columns(int from = 1) const {
    std::string out;
    for (std::size_t i = 0; i < drawn_.size(); ++i) {
      if (i) out += ':';
      out += std::to_string(from + int(i));
    }
    return out;
  }
  std::size_t count() const { return drawn_.size(); }

 private:
  std::vector<int> drawn_;  ///< planar: x, y; 3d: x, z, y (global y, up, is the vertical)
  double perMetre_ = 1;
};

/// The frame charts' length axes: metres, or the user's length unit.
OutputUnits::Shown axisLength(const OutputUnits& units) {
  return units.valueIn("m", {1, "m"});
}

/// A gnuplot datablock: blocks of lines separated by two blank lines (separate curves).
class Datablock {
 public:
  explicit Datablock(std::string name) : name_(std::move(name)) {
    text_ = name_;
    text_ += " << EOD\n";
  }
  void line(const std::string& values) {
    text_ += values;
    text_ += '\n';
    empty_ = false;
  }
  void endCurve() { text_ += "\n\n"; }
  std::string finished() const { return text_ + "EOD\n"; }
  const std::string& name() const { return name_; }
  bool empty() const { return empty_; }

 private:
  std::string name_, text_;
  bool empty_ = true;
};

/// A panel's plot (plot in 2d, splot in 3d) of curves, each "using" part with its style.
std::string plotOf(bool planar, const std::vector<std::string>& clauses) {
  std::string s = planar ? "  plot " : "  splot ";
  for (std::size_t i = 0; i < clauses.size(); ++i) s += (i ? ", \\\n       " : "") + clauses[i];
  return s + "\n";
}

/// How the panels of a chart of `panels` panels lie: side by side, or one above the other when
/// the frame is long and flat (a continuous beam), each as tall as its drawing.
struct PanelGrid {
  int rows = 1, columns = 1, width = 1200, height = 560;
};

/// The drawn ranges of a planar frame (x and y, m) at true proportions: the frame with room
/// for the diagrams across it, and at least a fifth of its length tall so that a flat frame's
/// panel does not shrink to a sliver crowded with ticks.
struct PlanarRanges {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  double aspect() const { return (y1 - y0) / (x1 - x0); }
};

/// The smallest box holding the model's nodes, and its largest side (m; 1 without nodes).
struct Extent {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = -low;
  double size = 1;
};
Extent extentOf(const Model& model) {
  Extent e;
  for (const auto& x : model.nodes()) e.low = e.low.cwiseMin(x), e.high = e.high.cwiseMax(x);
  if (!model.nodes().empty()) e.size = std::max((e.high - e.low).maxCoeff(), 1e-30);
  return e;
}

PlanarRanges planarRanges(const Eigen::Vector3d& low, const Eigen::Vector3d& high, double size) {
  // Diagrams stand off the members by up to kDiagramShare of the size, on either side.
  const double margin = kDiagramShare * size + 0.05 * size;
  const double half = std::max(0.5 * (high.y() - low.y()) + margin, 0.1 * size);
  const double middle = 0.5 * (low.y() + high.y());
  return {low.x() - margin, high.x() + margin, middle - half, middle + half};
}

/// Panels side by side for a planar frame about as tall as wide, else one above the other, each
/// sized to its drawing; a 3d frame's side by side.
PanelGrid panelGrid(int panels, bool planar, const PlanarRanges& r) {
  if (!planar) return {1, panels, 1400, 640};
  if (panels == 1 || r.aspect() > 0.5) {
    const int width = panels == 1 ? 1000 : 1200;
    const int plot = (width - 100 * panels) / panels;  // each panel's plot width in pixels
    return {1, panels, width, std::clamp(int(200 + plot * r.aspect()), 360, 800)};
  }
  const int plot = 900;
  return {panels, 1, 1000, std::clamp(int(120 + panels * (plot * r.aspect() + 100)), 400, 1000)};
}

/// The panels' layout: a planar frame's with margins in pixels, a 3d frame's views with
/// gnuplot's own (see viewLayout).
std::string frameLayout(bool planar, int rows, int columns, const std::string& caption, int width,
                        int height) {
  return planar ? panelLayout(rows, columns, caption, width, height) : viewLayout(rows, columns, caption);
}

/// Equal scales on every axis: a planar frame in its plane, a 3d frame in a 3d view with
/// global y (up) vertical. The vertical range holds the magnified shape and the diagrams (a
/// flat frame would otherwise get a sliver of an axis crowded with ticks); the view shrunk a
/// little and the z ticks moved off the corner they share with the x axis' last tick; the
/// vertical axis' name clear of its tick labels.
std::string axesSetup(bool planar, const Eigen::Vector3d& lowest, const Eigen::Vector3d& highest,
                      double extent, const OutputUnits::Shown& length) {
  const Eigen::Vector3d low = lowest * length.factor, high = highest * length.factor;
  const double size = extent * length.factor;
  const auto axis = [&](const char* which, const char* name) {
    std::string text = "  set ";
    text += which;
    text += "label ";  // piece by piece: GCC 12 warns (-Wrestrict) on "literal" + a temporary
    text += gnuplotText(std::string(name) + " [" + length.unit + "]");
    text += "\n";
    return text;
  };
  if (planar) {
    const PlanarRanges r = planarRanges(low, high, size);
    std::string out = "  set size ratio -1\n";
    out += axis("x", "x");
    out += axis("y", "y");
    out += "  set xrange [" + number(r.x0) + ":" + number(r.x1) + "]\n";
    out += "  set yrange [" + number(r.y0) + ":" + number(r.y1) + "]\n";
    return out;
  }
  // The box no taller than wide, square in plan: gnuplot scales `view equal xyz` to the
  // larger horizontal range, so a box taller than wide (a lone column, a tower) would stand
  // out of its panel; a cube's projection fits the panel at the view's scale (viewLayout).
  const double bottom = low.y() - 0.2 * size, top = high.y() + 0.2 * size;
  const double half = std::max({0.5 * (high.x() - low.x()) + 0.2 * size,
                                0.5 * (high.z() - low.z()) + 0.2 * size, 0.5 * (top - bottom)});
  const double midX = 0.5 * (low.x() + high.x()), midZ = 0.5 * (low.z() + high.z());
  std::string out = "  set view equal xyz\n  set view 64, 28, " + number(kViewScale) +
                    "\n  set ytics offset 1.5,0\n";
  out += "  set xrange [" + number(midX - half) + ":" + number(midX + half) + "]\n";
  out += "  set yrange [" + number(midZ - half) + ":" + number(midZ + half) + "]\n";
  out += "  set zrange [" + number(bottom) + ":" + number(top);
  out += "]\n  set xyplane at " + number(bottom);
  out += "\n";
  out += axis("x", "x");
  out += axis("y", "z");
  out += axis("z", "y");
  // The vertical axis' name two characters further left: four-digit ticks (mm) reached it.
  out.insert(out.size() - 1, " offset -2,0");
  return out;
}

/// A diagram title's second line when only the `drawn` members of largest |M| among `total`
/// are drawn (the chart's budget), else nothing. Appended piece by piece: GCC 12 takes
/// "literal" + a temporary for an overlapping copy (a false -Wrestrict).
std::string drawnShare(std::size_t drawn, std::size_t total) {
  if (drawn == 0 || drawn >= total) return {};
  std::string line = "\n(the ";
  line += std::to_string(drawn);
  line += " members of largest |M| among ";
  line += std::to_string(total);
  line += ")";
  return line;
}

/// Where a moment of component k (Mz or My) of value M is drawn from its place on element
/// `element`: across the member on its tension side (Mz > 0 stretches the fibres on local -y,
/// My > 0 those on local +z), `scale` m per N m.
Eigen::Vector3d momentOffset(const Model& model, int element, ForceComponent k, double M,
                             double scale) {
  const Eigen::Matrix3d R = asLine(model.elements()[element])->localAxes();
  return scale * M *
         (k == ForceComponent::Mz ? Eigen::Vector3d(-R.row(1).transpose())
                                  : Eigen::Vector3d(R.row(2).transpose()));
}

/// "linecolor rgb '...'" without its "linecolor ": a label's textcolor.
std::string textColour(std::size_t i) {
  return colour(i).substr(std::string("linecolor ").size());
}

/// Each rigid tie (the first kTieLines) as a curve of its master's and its follower's places,
/// undeformed and moved by `scale` times their translations in `u` (unmoved without `u`).
Datablock tieLines(const std::string& name, const Model& model, const NodalField* u,
                   double scale, const Coordinates& coordinates) {
  Datablock block(name);
  const auto& ties = model.rigidTies();
  for (std::size_t i = 0; i < ties.size() && i < kTieLines; ++i) {
    for (int node : {ties[i].master, ties[i].slave}) {
      const Eigen::Vector3d& x = model.nodes()[node];
      Eigen::Vector3d moved = x;
      if (u) moved += scale * Eigen::Vector3d((*u)(node, 0), (*u)(node, 1), (*u)(node, 2));
      block.line(coordinates.text(x) + "," + coordinates.text(moved));
    }
    block.endCurve();
  }
  return block;
}

/// The ties' datablock, or nothing without ties (a frame without them draws as before).
std::string tieData(const Datablock& ties) {
  return ties.empty() ? std::string() : ties.finished();
}

/// The plot clauses of the ties: undeformed (`first` columns) as grey dots, moved (`second`,
/// when given) as orange dashes; none without ties.
std::vector<std::string> tieClauses(const Datablock& ties, const std::string& first,
                                    const std::string& second) {
  if (ties.empty()) return {};
  std::vector<std::string> out{ties.name() + " using " + first +
                               " with lines linewidth 1 dashtype 3 linecolor rgb 'gray55'"};
  if (!second.empty())
    out.push_back(ties.name() + " using " + second +
                  " with lines linewidth 1.5 dashtype 2 linecolor rgb '#c05a00'");
  return out;
}

/// A title's note on the ties drawn ("; rigid ties dashed"), empty without ties.
std::string tieNote(const Model& model) {
  const std::size_t n = model.rigidTies().size();
  if (n == 0) return {};
  std::string note = "; rigid ties dashed";
  if (n > kTieLines) {
    note += " (the first ";
    note += std::to_string(kTieLines);
    note += " of ";
    note += std::to_string(n);
    note += ")";
  }
  return note;
}

/// `clauses` followed by `more`.
std::vector<std::string> joined(std::vector<std::string> clauses,
                                const std::vector<std::string>& more) {
  clauses.insert(clauses.end(), more.begin(), more.end());
  return clauses;
}

/// A moment to label: its value, where it is drawn and the component.
struct MomentLabel {
  double value = 0;
  Eigen::Vector3d tip;
  ForceComponent component = ForceComponent::Mz;
  std::size_t colourIndex = 1;
};

}  // namespace

ChartScript frameChart(const std::string& caption, const std::string& chartName,
                       const FrameDrawing& frame, bool planar, const OutputUnits& units) {
  const Model& model = *frame.model;
  const StationsByElement& stations = *frame.stations;
  const auto& ranges = *frame.ranges;
  const auto& members = model.members();
  const OutputUnits::Shown length = axisLength(units);
  const Coordinates coordinates(planar, length.factor);
  const OutputUnits::Shown displacement = units.valueIn("m", {1e3, "mm"});
  const OutputUnits::Shown moment = units.valueIn("N m", {1e-3, "kN m"});

  // 1. Scales: the frame's size against the largest displacement and moment.
  const auto [low, high, size] = extentOf(model);
  const double largestU = frame.largestDisplacement;
  const double magnify = largestU > 0 ? roundFactor(kDeformedShare * size / largestU) : 1;
  const std::vector<ForceComponent> moments =
      planar ? std::vector<ForceComponent>{ForceComponent::Mz}
             : std::vector<ForceComponent>{ForceComponent::Mz, ForceComponent::My};
  // Each member's largest |moment| (exact, from its ranges), and the largest of all.
  std::vector<double> memberMoment(members.size(), 0);
  for (std::size_t m = 0; m < members.size(); ++m)
    for (ForceComponent k : moments)
      memberMoment[m] = std::max(memberMoment[m], std::abs(largerEnd(ranges[m][int(k)]).value));
  const double largestM =
      memberMoment.empty() ? 0 : *std::max_element(memberMoment.begin(), memberMoment.end());
  const double perMoment = largestM > 0 ? kDiagramShare * size / largestM : 0;

  // 2. The data: the outline and the deformed shape of every member, at the finest detail the
  //    budget allows.
  const Detail detail = outlineDetail(model, stations);
  Datablock outline("$outline");
  for (const auto& [name, elements] : members) {
    for (const StaticStation* st : drawnStations(elements, stations, detail)) {
      const Eigen::Vector3d x = placeOnElement(model, st->place.element, st->place.s);
      const Eigen::Vector3d u(st->displacement[0], st->displacement[1], st->displacement[2]);
      outline.line(coordinates.text(x) + "," + coordinates.text(x + magnify * u));
    }
    outline.endCurve();
  }

  const Datablock ties = tieLines("$ties", model, frame.displacement, magnify, coordinates);

  //    The moment diagrams of the members of the largest moments, while their stations fit.
  std::vector<std::size_t> order(members.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return memberMoment[a] > memberMoment[b]; });
  std::vector<Datablock> diagrams, hatches;
  for (ForceComponent k : moments) {
    diagrams.emplace_back(std::string("$") + componentName(k));
    hatches.emplace_back(std::string("$") + componentName(k) + "_hatch");
  }
  std::size_t drawnMembers = 0, drawnPoints = 0;
  std::vector<MomentLabel> labels;
  for (std::size_t m : order) {
    if (!(memberMoment[m] > 1e-9 * largestM)) break;  // the rest carry no moment to draw
    const std::vector<const StaticStation*> along =
        drawnStations(members[m].second, stations, Detail::stations);
    if (drawnMembers == kDiagramMembers ||
        (drawnPoints + along.size() > kDiagramPoints && drawnMembers > 0))
      break;
    drawnPoints += along.size();
    ++drawnMembers;
    for (std::size_t c = 0; c < moments.size(); ++c) {
      const ForceComponent k = moments[c];
      const ComponentRange& r = ranges[m][int(k)];
      if (!(std::max(std::abs(r.max.value), std::abs(r.min.value)) > 1e-9 * largestM)) continue;
      const auto offset = [&](int element, double value) {
        return momentOffset(model, element, k, value, perMoment);
      };
      for (const StaticStation* st : along) {
        const Eigen::Vector3d x = placeOnElement(model, st->place.element, st->place.s);
        const double M = k == ForceComponent::Mz ? st->forces.Mz : st->forces.My;
        const Eigen::Vector3d d = offset(st->place.element, M);
        diagrams[c].line(coordinates.text(x) + "," + coordinates.text(x + d));
        hatches[c].line(coordinates.text(x) + "," + coordinates.text(d));
      }
      diagrams[c].endCurve();
      const MemberValue& top = largerEnd(r);
      labels.push_back({top.value, top.x + offset(top.element, top.value), k, c + 1});
    }
  }
  std::stable_sort(labels.begin(), labels.end(), [](const MomentLabel& a, const MomentLabel& b) {
    return std::abs(a.value) > std::abs(b.value);
  });
  // One label for a peak two members share (a continuous beam's support moment, at the end of
  // one span and the start of the next): the same value, drawn at the same place.
  const auto same = [&](const MomentLabel& a, const MomentLabel& b) {
    return a.component == b.component && std::abs(a.value - b.value) <= 1e-6 * largestM &&
           (a.tip - b.tip).norm() <= 0.02 * size;
  };
  std::vector<MomentLabel> distinct;
  for (const MomentLabel& l : labels)
    if (std::none_of(distinct.begin(), distinct.end(),
                     [&](const MomentLabel& d) { return same(d, l); }))
      distinct.push_back(l);
  labels.swap(distinct);
  if (labels.size() > kMomentLabels) labels.resize(kMomentLabels);

  // 3. The panels' common set-up: equal scales on every axis.
  const PanelGrid grid = panelGrid(2, planar, planarRanges(low, high, size));
  const int width = grid.width, height = grid.height;
  std::string data = outline.finished() + tieData(ties);
  for (std::size_t c = 0; c < moments.size(); ++c)
    data += diagrams[c].finished() + hatches[c].finished();
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << frameLayout(planar, grid.rows, grid.columns, caption, width, height) << "  unset key\n"
       << "  set grid\n";
  body << axesSetup(planar, low, high, size, length);
  const std::string undeformedStyle = " with lines linewidth 1.5 dashtype 2 linecolor rgb 'gray55'";
  const std::string first = coordinates.columns(), second = coordinates.columns(1 + int(coordinates.count()));

  // 4. Panel 1: deformed over undeformed, joints labelled when they are few enough to read.
  char largest[32];
  std::snprintf(largest, sizeof largest, "%.3g ", largestU * displacement.factor);
  body << "  set title " << gnuplotText("deformed shape, displacements × " + number(magnify) +
                                        " (largest " + largest + displacement.unit + ")" +
                                        tieNote(model))
       << "\n";
  if (model.namedNodes().size() <= kJointLabels)
    for (const auto& [name, node] : model.namedNodes())
      body << "  set label " << gnuplotText(name) << " at "
           << coordinates.text(model.nodes()[node], ", ")
           << " offset 0.6,0.6 textcolor rgb '#303030'\n";
  body << plotOf(planar, joined({outline.name() + " using " + first + undeformedStyle,
                                 outline.name() + " using " + second +
                                     " with lines linewidth 2.5 " + colour(0)},
                                tieClauses(ties, first, second)))
       << "  unset label\n";

  // 5. Panel 2: moment diagrams across the members on their tension side, hatched, the
  //    largest |M| labelled.
  std::vector<std::string> clauses = joined(
      {outline.name() + " using " + first + " with lines linewidth 2 linecolor rgb 'gray30'"},
      tieClauses(ties, first, ""));
  for (std::size_t c = 0; c < moments.size(); ++c) {
    if (diagrams[c].empty()) continue;
    clauses.push_back(diagrams[c].name() + " using " + second + " with lines linewidth 2 " +
                      colour(c + 1));
    clauses.push_back(hatches[c].name() + " using " + first + ":" +
                      coordinates.columns(1 + int(coordinates.count())) +
                      " with vectors nohead linewidth 0.8 " + colour(c + 1));
  }
  for (const MomentLabel& l : labels) {
    char value[32];
    std::snprintf(value, sizeof value, "%.3g", l.value * moment.factor);
    // A peak in the right third of the frame is labelled leftwards, into the chart: equal
    // peaks (a symmetric frame's) may land on a member's right end, at the canvas' edge.
    const bool rightmost = l.tip.x() > low.x() + (high.x() - low.x()) * 2 / 3;
    std::string text = planar ? "" : componentName(l.component);
    if (!planar) text += " ";
    text += value;
    body << "  set label " << gnuplotText(text) << " at " << coordinates.text(l.tip, ", ")
         << (rightmost ? " right offset -0.4,0.4" : " offset 0.4,0.4") << " textcolor "
         << textColour(l.colourIndex) << "\n";
  }
  std::string title = planar ? "bending moment M_z" : "bending moments M_z (red), M_y (green)";
  title += " [" + moment.unit + "], drawn on the tension side";
  title += drawnShare(drawnMembers, members.size());
  body << "  set title " << captionText(title) << "\n" << plotOf(planar, clauses)
       << "  unset multiplot\n";
  return {chartName, "Deformed shape and bending moment diagram of the frame", width, height,
          body.str(), data};
}

ChartScript frameEnvelopeChart(const std::string& caption, const std::string& chartName,
                               const Model& model,
                               const std::vector<std::vector<EnvelopeStation>>& envelope,
                               const std::vector<std::string>& names, bool planar,
                               const OutputUnits& units) {
  const auto& members = model.members();
  const OutputUnits::Shown length = axisLength(units);
  const Coordinates coordinates(planar, length.factor);
  const OutputUnits::Shown moment = units.valueIn("N m", {1e-3, "kN m"});
  const auto [low, high, size] = extentOf(model);
  const std::vector<ForceComponent> moments =
      planar ? std::vector<ForceComponent>{ForceComponent::Mz}
             : std::vector<ForceComponent>{ForceComponent::Mz, ForceComponent::My};

  // 1. Each member's largest |moment| over the envelope, and the largest of all.
  std::vector<double> memberMoment(members.size(), 0);
  for (std::size_t m = 0; m < members.size() && m < envelope.size(); ++m)
    for (const EnvelopeStation& st : envelope[m])
      for (ForceComponent k : moments)
        memberMoment[m] = std::max({memberMoment[m], std::abs(st.max[int(k)]),
                                    std::abs(st.min[int(k)])});
  const double largestM =
      memberMoment.empty() ? 0 : *std::max_element(memberMoment.begin(), memberMoment.end());
  const double perMoment = largestM > 0 ? kDiagramShare * size / largestM : 0;

  // 2. The outline: every member's envelope places, or its ends when they pass the budget.
  std::size_t places = 0;
  for (const auto& along : envelope) places += along.size();
  Datablock outline("$outline");
  for (const auto& along : envelope) {
    for (std::size_t i = 0; i < along.size(); ++i)
      if (places <= kOutlinePoints || i == 0 || i + 1 == along.size())
        outline.line(coordinates.text(placeOnElement(model, along[i].element, along[i].s)));
    outline.endCurve();
  }

  // 3. The bands of the members of the largest moments, and the frame's extremes.
  std::vector<std::size_t> order(members.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return memberMoment[a] > memberMoment[b]; });
  std::vector<Datablock> largest, smallest, bands;
  struct Extreme {
    double value = 0;
    int by = -1;
    Eigen::Vector3d tip = Eigen::Vector3d::Zero();
  };
  std::vector<std::array<Extreme, 2>> extremes(moments.size());  // largest, smallest
  for (ForceComponent k : moments) {
    const std::string name = componentName(k);
    largest.emplace_back("$" + name + "_max");
    smallest.emplace_back("$" + name + "_min");
    bands.emplace_back("$" + name + "_band");
  }
  std::size_t drawnMembers = 0, drawnPoints = 0;
  for (std::size_t m : order) {
    if (m >= envelope.size() || !(memberMoment[m] > 1e-9 * largestM)) break;
    if (drawnMembers == kDiagramMembers ||
        (drawnPoints + envelope[m].size() > kDiagramPoints && drawnMembers > 0))
      break;
    drawnPoints += envelope[m].size();
    ++drawnMembers;
    for (std::size_t c = 0; c < moments.size(); ++c) {
      const ForceComponent k = moments[c];
      for (const EnvelopeStation& st : envelope[m]) {
        const Eigen::Vector3d x = placeOnElement(model, st.element, st.s);
        const Eigen::Vector3d hi = x + momentOffset(model, st.element, k, st.max[int(k)], perMoment);
        const Eigen::Vector3d lo = x + momentOffset(model, st.element, k, st.min[int(k)], perMoment);
        largest[c].line(coordinates.text(hi));
        smallest[c].line(coordinates.text(lo));
        bands[c].line(coordinates.text(lo) + "," + coordinates.text(hi - lo));
        Extreme& top = extremes[c][0];
        Extreme& bottom = extremes[c][1];
        if (top.by < 0 || st.max[int(k)] > top.value) top = {st.max[int(k)], st.maxBy[int(k)], hi};
        if (bottom.by < 0 || st.min[int(k)] < bottom.value)
          bottom = {st.min[int(k)], st.minBy[int(k)], lo};
      }
      largest[c].endCurve();
      smallest[c].endCurve();
    }
  }

  // 4. One panel per moment: the outline, the band hatched between its largest (red) and
  //    smallest (blue) curve, the extremes labelled with their combinations.
  const Datablock ties = tieLines("$ties", model, nullptr, 0, coordinates);
  std::string data = outline.finished() + tieData(ties);
  for (std::size_t c = 0; c < moments.size(); ++c)
    data += largest[c].finished() + smallest[c].finished() + bands[c].finished();
  const PanelGrid grid = panelGrid(int(moments.size()), planar, planarRanges(low, high, size));
  const int width = grid.width, height = grid.height;
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << frameLayout(planar, grid.rows, grid.columns, caption, width, height) << "  unset key\n"
       << "  set grid\n" << axesSetup(planar, low, high, size, length);
  const std::string first = coordinates.columns(),
                    second = coordinates.columns(1 + int(coordinates.count()));
  for (std::size_t c = 0; c < moments.size(); ++c) {
    const std::string name = componentName(moments[c]);
    body << "  unset label\n";
    for (std::size_t e = 0; e < 2; ++e) {
      const Extreme& x = extremes[c][e];
      if (x.by < 0 || !(std::abs(x.value) > 1e-9 * largestM)) continue;
      char value[32];
      std::snprintf(value, sizeof value, "%.3g", x.value * moment.factor);
      std::string text = value;
      text += " (";
      text += names.at(std::size_t(x.by));
      text += ")";
      body << "  set label " << gnuplotText(text) << " at " << coordinates.text(x.tip, ", ")
           << " offset 0.4," << (e == 0 ? "0.6" : "-0.6") << " textcolor "
           << textColour(e == 0 ? 1 : 0) << " front\n";
    }
    std::string title = "envelope of ";
    title += name == "Mz" ? "M_z" : "M_y";
    title += " over the combinations [" + moment.unit + "]: largest (red), smallest (blue)";
    title += drawnShare(drawnMembers, members.size());
    body << "  set title " << captionText(title) << "\n";
    std::vector<std::string> clauses = joined(
        {outline.name() + " using " + first + " with lines linewidth 2 linecolor rgb 'gray30'"},
        tieClauses(ties, first, ""));
    if (!largest[c].empty()) {
      clauses.push_back(bands[c].name() + " using " + first + ":" + second +
                        " with vectors nohead linewidth 0.6 linecolor rgb 'gray65'");
      clauses.push_back(largest[c].name() + " using " + first + " with lines linewidth 2 " +
                        colour(1));
      clauses.push_back(smallest[c].name() + " using " + first + " with lines linewidth 2 " +
                        colour(0));
    }
    body << plotOf(planar, clauses);
  }
  body << "  unset multiplot\n";
  return {chartName, "Envelope of the bending moments over the load combinations", width,
          height, body.str(), data};
}

ChartScript frameShapesChart(const std::string& caption, const std::string& chartName,
                             const Model& model, const std::vector<Mode>& modes,
                             const std::vector<std::string>& titles, bool planar,
                             const OutputUnits& units) {
  constexpr double kShapeShare = 0.12;  // of the frame's size: the largest translation drawn
  const OutputUnits::Shown length = axisLength(units);
  const Coordinates coordinates(planar, length.factor);
  const Extent extent = extentOf(model);
  const std::size_t panels = std::min({modes.size(), titles.size(), kShapePanels});

  // 1. How finely to sample: kIntervalsPerElement pieces per element while every panel stays
  //    within its share of kOutlinePoints, else the element ends, else the member ends.
  std::size_t elements = 0, memberCount = model.members().size();
  for (const auto& [name, list] : model.members()) elements += list.size();
  const std::size_t budget = kOutlinePoints / std::max<std::size_t>(panels, 1);
  const Detail detail = elements * (kIntervalsPerElement + 1) <= budget ? Detail::stations
                        : elements + memberCount <= budget              ? Detail::elementEnds
                                                                        : Detail::memberEnds;

  // 2. Each shape's datablock: per member one curve of (undeformed, deformed) places.
  std::string data;
  std::vector<std::string> names;
  std::vector<Datablock> tieBlocks;
  for (std::size_t m = 0; m < panels; ++m) {
    const NodalField shape = displayModeShape(model, modes[m].shape);
    Datablock block("$shape" + std::to_string(m + 1));
    const auto place = [&](int element, double s) {
      const auto& line = static_cast<const LineElement&>(*model.elements()[element]);
      const auto u = displacementAlong(line, shape, s, SpanLoad::none);
      const Eigen::Vector3d x = placeOnElement(model, element, s);
      block.line(coordinates.text(x) + "," +
                 coordinates.text(x + kShapeShare * extent.size * Eigen::Vector3d(u[0], u[1], u[2])));
    };
    for (const auto& [name, list] : model.members()) {
      for (std::size_t i = 0; i < list.size(); ++i) {
        const bool first = i == 0, last = i + 1 == list.size();
        if (detail == Detail::stations) {
          for (int k = first ? 0 : 1; k <= kIntervalsPerElement; ++k)
            place(list[i], double(k) / kIntervalsPerElement);
          continue;
        }
        if (first) place(list[i], 0);
        if (detail == Detail::elementEnds || last) place(list[i], 1);
      }
      block.endCurve();
    }
    data += block.finished();
    names.push_back(block.name());
    const Datablock ties = tieLines("$ties" + std::to_string(m + 1), model, &shape,
                                    kShapeShare * extent.size, coordinates);
    data += tieData(ties);
    tieBlocks.push_back(ties);
  }

  // 3. The panels: up to three across, the shapes in rows.
  const int columns = int(std::min<std::size_t>(panels, 3));
  const int rows = int((panels + 2) / 3);
  const int width = planar ? 500 * std::max(columns, 2) : 560 * std::max(columns, 2);
  const int height = 80 + rows * (planar ? 420 : 460);
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << frameLayout(planar, std::max(rows, 1), std::max(columns, 1), caption, width, height)
       << "  unset key\n  set grid\n"
       << axesSetup(planar, extent.low, extent.high, extent.size, length);
  const std::string first = coordinates.columns(),
                    second = coordinates.columns(1 + int(coordinates.count()));
  for (std::size_t m = 0; m < panels; ++m) {
    body << "  set title " << gnuplotText(m == 0 ? titles[m] + tieNote(model) : titles[m])
         << "\n";
    if (m == 0 && model.namedNodes().size() <= kJointLabels)
      for (const auto& [name, node] : model.namedNodes())
        body << "  set label " << gnuplotText(name) << " at "
             << coordinates.text(model.nodes()[node], ", ")
             << " offset 0.6,0.6 textcolor rgb '#303030'\n";
    body << plotOf(planar,
                   joined({names[m] + " using " + first +
                               " with lines linewidth 1.5 dashtype 2 linecolor rgb 'gray55'",
                           names[m] + " using " + second + " with lines linewidth 2.5 " +
                               colour(m % 6)},
                          tieClauses(tieBlocks[m], first, second)))
         << "  unset label\n";
  }
  body << "  unset multiplot\n";
  return {chartName, "Mode or buckling shapes of the frame, each over its outline", width, height,
          body.str(), data};
}

}  // namespace beamrotor
