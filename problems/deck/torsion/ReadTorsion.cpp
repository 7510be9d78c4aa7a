// The torsion row's reader (TorsionKind.hpp).
#include <algorithm>
#include <numbers>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/deck/torsion/TorsionKind.hpp"
#include "problems/scenes/CrankTorque.hpp"

namespace beamrotor {

namespace {
/// The eigenvalue omega^2 the modes are sought nearest (rad^2/s^2), as a modal analysis'.
constexpr FieldUnit kTorsionShift{Dimension::of(0, 0, -2, 2)};
/// The most excitation orders, harmonic torques and speeds a torsion analysis may have.
constexpr int kMaxTorsionOrders = 100;
constexpr int kMaxTorsionSpeeds = 10000;

int shaftNamed(const reader::Context& c, const Field& f) {
  const std::vector<TrainShaft>& shafts = c.deck.train.shafts;
  std::vector<std::string> names;
  for (const TrainShaft& s : shafts) names.push_back(s.name);
  const auto it = std::find(names.begin(), names.end(), f.name());
  if (it == names.end())
    f.fail("no shaft named '" + f.name() + "'" + didYouMean(f.name(), names) + " (shafts: " +
           joinNames(names) + ")");
  return int(it - names.begin());
}

/// `crank: {analysis, at, orders, pressure}`: the harmonics of the torque a crank-slider
/// analysis' cranks need (problems/scenes/CrankTorque.hpp), as load torques on a station.
void readCrankTorques(const reader::Context& c, const Field& f, TorsionSpec& spec) {
  f.allowOnly({"analysis", "at", "orders", "pressure"}, "a crank excitation");
  const Field af = f.require("analysis");
  const CrankSliderSpec* crank = nullptr;
  std::vector<std::string> cranks;
  for (const DeckAnalysis& a : c.deck.analyses)
    if (const auto* k = a.as<CrankSliderSpec>()) {
      cranks.push_back(a.name);
      if (a.name == af.name()) crank = k;
    }
  if (!crank)
    af.fail("no crank-slider analysis named '" + af.name() + "' before this one" +
            didYouMean(af.name(), cranks) +
            (cranks.empty() ? std::string(" (the deck has none)") : " (" + joinNames(cranks) + ")"));
  const DeckCrankSlider& m = crank->mechanism;
  crank::CrankLoads loads;
  if (m.masses) {
    loads.reciprocatingMass = crank::reduce(*m.masses, m.geometry).reciprocating;
    loads.rodResidualInertia = m.masses->rod.residualInertia;
  }
  if (auto p = f.get("pressure")) {
    if (!(m.plungerDiameter > 0))
      p->fail("a delivery pressure acts on the plungers: give analysis '" + af.name() +
              "' plunger_diameter");
    loads.plungerForce = p->nonNegative(c.evaluator, dim::pressure) * std::numbers::pi *
                         m.plungerDiameter * m.plungerDiameter / 4;
  }
  if (loads.reciprocatingMass == 0 && loads.plungerForce == 0)
    f.fail("analysis '" + af.name() + "' has no masses and no pressure is given: no torque");
  const TrainStation at = reader::trainStation(c, f.require("at"));
  const int orders = f.has("orders") ? f.require("orders").integer(c.evaluator, 1, kMaxTorsionOrders) : 12;
  const crank::TorqueSeries series =
      crank::crankTorqueSeries(m.geometry, loads, m.phases, m.speed, orders);
  // The cranks' need is a load on the train: it acts against the rotation (phase + pi).
  // Harmonics within the series' accuracy of zero (the orders a multi-crank drive balances,
  // ~1e-8 of the mean) are left out.
  double largest = 0;
  for (const auto& h : series.harmonics) largest = std::max(largest, h.amplitude);
  for (const auto& h : series.harmonics)
    if (h.amplitude > 1e-5 * largest)
      spec.torques.push_back({at, double(h.order), h.amplitude, h.phase + std::numbers::pi,
                              af.name()});
}

void readTrainExcitation(const reader::Context& c, const Field& f, TorsionSpec& spec) {
  const ExpressionEvaluator& ev = c.evaluator;
  if (auto r = f.get("reference")) spec.reference = shaftNamed(c, *r);
  // kRpmField reads a value in rpm; the spec holds rad/s.
  const double radPerS = kRpmField.bareSize;
  if (auto s = f.get("speed")) spec.speed = s->positive(ev, kRpmField) * radPerS;
  if (auto s = f.get("speeds")) {
    s->allowOnly({"from", "to", "steps"}, "a speed range");
    TorsionSpeeds range;
    range.from = s->require("from").nonNegative(ev, kRpmField) * radPerS;
    range.to = s->require("to").positive(ev, kRpmField) * radPerS;
    if (!(range.to > range.from)) s->require("to").fail("'to' must exceed 'from'");
    if (auto n = s->get("steps")) range.steps = n->integer(ev, 1, kMaxTorsionSpeeds);
    spec.speeds = range;
  }
  if (auto list = f.get("orders")) {
    for (const Field& o : list->itemsOrSingle()) spec.orders.push_back(o.positive(ev, dim::none));
    if (spec.orders.size() > std::size_t(kMaxTorsionOrders))
      list->fail("at most " + std::to_string(kMaxTorsionOrders) + " orders");
  }
  if (auto list = f.get("torques"))
    for (const Field& t : list->items()) {
      t.allowOnly({"at", "order", "amplitude", "phase"}, "a harmonic torque");
      HarmonicTorque h;
      h.at = reader::trainStation(c, t.require("at"));
      h.order = t.require("order").positive(ev, dim::none);
      h.amplitude = t.require("amplitude").nonNegative(ev, dim::moment);
      if (auto p = t.get("phase")) h.phase = p->number(ev, dim::angle);
      spec.torques.push_back(h);
    }
  if (auto crankField = f.get("crank")) readCrankTorques(c, *crankField, spec);
  if (spec.torques.size() > std::size_t(kMaxTorsionOrders))
    f.fail("at most " + std::to_string(kMaxTorsionOrders) + " harmonic torques");
  if (!spec.torques.empty() && spec.speed == 0 && !spec.speeds)
    f.fail("harmonic torques need the speed they turn at: give `speed` or `speeds`");
  if (!spec.orders.empty() && !spec.speeds)
    f.fail("an interference diagram of `orders` needs the range `speeds: {from, to}`");
}

}  // namespace

void TorsionSpec::read(const reader::Context& c, const Field& f) {
  const bool train = !c.deck.train.shafts.empty();
  if (train)
    f.allowOnly({"type", "name", "modes", "shift", "reference", "speed", "speeds", "orders",
                 "torques", "crank"},
                "a torsion analysis of a train");
  else
    f.allowOnly({"type", "name", "modes", "shift"}, "a torsion analysis");
  if (!train && (c.deck.frame || c.deck.segments.empty()))
    f.fail(
        "a torsion analysis twists a drive train (train:) or a shaft line (segments: along x); "
        "a frame's members twist in a modal analysis of its 3d model");
  if (auto m = f.get("modes")) modes = m->integer(c.evaluator, 1, kMaxModes);
  if (auto s = f.get("shift")) {
    shift = s->number(c.evaluator, kTorsionShift);
    shiftGiven = true;
  }
  if (train) readTrainExcitation(c, f, *this);
}

}  // namespace beamrotor

namespace beamrotor::reader {

void resolveTorsionQuantity(const Context& c, const Quantity& q, const Field& f,
                            const DeckAnalysis& a) {
  const auto* spec = a.as<TorsionSpec>();
  if (q.kind != Quantity::Kind::torsion || !spec) return;
  const TrainSpec& train = c.deck.train;
  if (train.shafts.empty()) f.fail("torsion quantities need a train (train:)");
  if (spec->torques.empty() || spec->speed == 0)
    f.fail("analysis '" + a.name + "' has no harmonic torques at an operating speed (speed:)");
  std::vector<std::string> names;
  if (q.property == "torque") {
    for (const TrainShaft& s : train.shafts) names.push_back(s.name);
    for (const TrainJoint& j : train.couplings) names.push_back(j.name);
    for (const TrainJoint& j : train.gears) names.push_back(j.name);
  } else {
    for (const TrainShaft& s : train.shafts) {
      names.push_back(s.name + ".start");
      names.push_back(s.name + ".end");
      for (const NamedPoint& p : s.stations) names.push_back(s.name + "." + p.name);
    }
  }
  if (std::find(names.begin(), names.end(), q.target) == names.end())
    f.fail("no " + std::string(q.property == "torque" ? "shaft, coupling or gear" : "station") +
           " '" + q.target + "' in the train" + didYouMean(q.target, names) + " (" +
           joinNames(names) + ")");
}

}  // namespace beamrotor::reader
