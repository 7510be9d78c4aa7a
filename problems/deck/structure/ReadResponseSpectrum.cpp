// The reader of the response-spectrum row (StructureKinds.hpp): modes, damping, the spectrum
// (a table or the EN 1998-1 shape), the directions and the rules that combine them.
#include <algorithm>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/structure/StructureKinds.hpp"

namespace beamrotor {

namespace {

/// `table: [[T, Sa], ...]`: periods (s) ascending, accelerations (m/s^2) not negative.
DesignSpectrum spectrumTable(const reader::Context& c, const Field& table) {
  std::vector<double> periods, accelerations;
  for (const Field& row : table.items()) {
    const std::vector<Field> pair = row.items();
    if (pair.size() != 2) row.fail("a spectrum row is [period, acceleration]");
    const double T = pair[0].nonNegative(c.evaluator, dim::time);
    if (!periods.empty() && !(T > periods.back()))
      pair[0].fail("the periods must ascend (the row before has " +
                   formatNumber(periods.back()) + " s)");
    periods.push_back(T);
    accelerations.push_back(pair[1].nonNegative(c.evaluator, dim::acceleration));
  }
  if (periods.size() < 2) table.fail("a spectrum table needs at least two rows");
  return DesignSpectrum::table(std::move(periods), std::move(accelerations));
}

/// `{code: EN1998-1, type: 1|2, ground: A..E, ag: ...}` at the analysis' damping, or with
/// `component: vertical` the vertical spectrum (no ground).
DesignSpectrum codeSpectrum(const reader::Context& c, const Field& f, double damping) {
  f.allowOnly({"code", "type", "ground", "ag", "component"}, "a code spectrum");
  f.require("code").choice({"EN1998-1"});
  const int type = f.require("type").integer(c.evaluator, 1, 2);
  if (auto component = f.get("component");
      component && component->choice({"horizontal", "vertical"}) == "vertical") {
    if (auto ground = f.get("ground"))
      ground->fail("the vertical spectrum (EN 1998-1 Table 3.4) is the same on every ground: "
                   "remove ground");
    return DesignSpectrum::en1998Vertical(
        type, f.require("ag").positive(c.evaluator, dim::acceleration), damping);
  }
  const std::string ground = f.require("ground").choice({"A", "B", "C", "D", "E"});
  const double ag = f.require("ag").positive(c.evaluator, dim::acceleration);
  return DesignSpectrum::en1998(type, GroundType(ground[0] - 'A'), ag, damping);
}

/// A spectrum field: a table or a code shape.
DesignSpectrum readSpectrum(const reader::Context& c, const Field& s, double damping) {
  if (s.isMap() && s.has("table")) {
    s.allowOnly({"table"}, "a tabulated spectrum");
    return spectrumTable(c, s.require("table"));
  }
  if (!s.isMap())
    s.fail("a spectrum is {table: [[T, Sa], ...]} or {code: EN1998-1, type, ground, ag}");
  return codeSpectrum(c, s, damping);
}

/// Whether a code spectrum field names the vertical component.
bool namesVertical(const Field& s) {
  if (!s.isMap()) return false;
  const auto component = s.get("component");
  return component && component->text() == "vertical";
}

}  // namespace

void ResponseSpectrumSpec::read(const reader::Context& c, const Field& f) {
  reader::requireSymmetricAtRest(c, f);
  f.allowOnly({"type", "name", "modes", "shift", "damping", "spectrum", "vertical_spectrum",
               "directions", "combination", "directional"},
              "a response-spectrum analysis");
  if (auto m = f.get("modes")) modes = m->integer(c.evaluator, 1, kMaxModes);
  options.modes = modes;
  // As a modal analysis' shift: the eigenvalue omega^2 (rad^2/s^2).
  if (auto s = f.get("shift"))
    options.shift = s->number(c.evaluator, FieldUnit{Dimension::of(0, 0, -2, 2)});
  if (auto d = f.get("damping")) {
    options.dampingRatio = d->positive(c.evaluator, dim::none);
    if (options.dampingRatio >= 1) d->fail("damping is a ratio of critical below 1 (0.05 for 5 %)");
  }
  const Field s = f.require("spectrum");
  spectrum = readSpectrum(c, s, options.dampingRatio);
  if (auto r = f.get("combination"))
    options.rule = r->choice({"cqc", "srss"}) == "cqc" ? ModalRule::cqc : ModalRule::srss;
  if (auto r = f.get("directional"))
    options.directional =
        r->choice({"100/30", "srss"}) == "srss" ? DirectionalRule::srss : DirectionalRule::percent30;
  std::vector<int>& directions = options.directions;
  if (auto d = f.get("directions")) {
    directions.clear();
    for (const Field& item : d->itemsOrSingle()) {
      const int k = std::string("xyz").find(item.choice({"x", "y", "z"})[0]);
      if (std::find(directions.begin(), directions.end(), k) != directions.end())
        item.fail("direction " + item.text() + " is given twice");
      const Dof along = Dof(k);
      if (!c.deck.dofs.contains(along))
        item.fail(std::string("a ") + c.deck.dimension + " model does not move along " +
                  item.text() + " (" + c.carriedNames() + ")");
      directions.push_back(k);
    }
    if (directions.empty()) d->fail("give at least one direction (x, y or z)");
  }
  // The vertical's own spectrum beside the horizontals' (EN 1998-1 4.3.3.5.2): along y.
  if (auto v = f.get("vertical_spectrum")) {
    if (namesVertical(s))
      s.fail("with a vertical_spectrum, spectrum is the horizontal one (x and z): remove "
             "component: vertical here");
    if (v->isMap() && !v->has("table") && !namesVertical(*v))
      v->fail("a code's vertical_spectrum is its vertical component: add component: vertical");
    options.verticalSpectrum = readSpectrum(c, *v, options.dampingRatio);
    options.vertical = 1;
    if (std::find(directions.begin(), directions.end(), options.vertical) == directions.end())
      v->fail("the vertical spectrum acts along y, which directions does not list: add y to "
              "directions");
  }
}

}  // namespace beamrotor
