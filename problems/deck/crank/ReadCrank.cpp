// Reading the mechanism analyses that need no model: the crank-slider drive
// (problems/scenes/README.md section 3) and the rigid body on two springs given by its own
// inputs (`rigid-body` with `body:`, section 2), and the check quantities they give.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor::reader {

namespace {

constexpr double kStandardGravity = 9.80665;  // m/s^2 (CGPM 1901): weight -> mass
/// cranks_deg: an angle whose bare number is in degrees.
constexpr FieldUnit kDegreeField{dim::angle, std::numbers::pi / 180};

crank::DriveMasses readDriveMasses(const Context& c, const Field& f, const crank::Geometry& g) {
  f.allowOnly({"eccentric", "eccentricity", "slider", "rod", "rod_com_to_crank_pin",
               "rod_com_to_slider_pin", "rod_residual_inertia"},
              "the masses of a crank-slider");
  const ExpressionEvaluator& ev = c.evaluator;
  crank::DriveMasses m;
  m.eccentricMass = f.has("eccentric") ? f.require("eccentric").nonNegative(ev, dim::mass) : 0;
  m.eccentricity =
      f.has("eccentricity") ? f.require("eccentricity").nonNegative(ev, dim::length) : 0;
  m.sliderMass = f.require("slider").nonNegative(ev, dim::mass);
  m.rod.mass = f.require("rod").nonNegative(ev, dim::mass);
  const Field big = f.require("rod_com_to_crank_pin");
  m.rod.comToBigEnd = big.nonNegative(ev, dim::length);
  m.rod.comToSmallEnd = f.require("rod_com_to_slider_pin").nonNegative(ev, dim::length);
  if (auto j = f.get("rod_residual_inertia")) m.rod.residualInertia = j->number(ev, dim::inertia);
  try {
    crank::reduce(m, g);
  } catch (const std::invalid_argument& e) {
    big.fail(std::string(e.what()) + " (the rod's centre of mass lies on it: the two distances " +
             "add up to l = " + formatNumber(g.l) + " m)");
  }
  return m;
}

}  // namespace

bool modelFree(const Context& c) {
  for (const char* key : {"segments", "points", "nodes", "members"})
    if (c.root.has(key)) return false;
  const auto block = c.root.get("analyses");
  if (!block || !block->isList()) return false;
  const std::vector<Field> items = block->items();
  return !items.empty() && std::all_of(items.begin(), items.end(), isMechanismAnalysis);
}

DeckCrankSlider readCrankSlider(const Context& c, const Field& f) {
  f.allowOnly({"type", "name", "r", "l", "speed_rpm", "cranks_deg", "steps", "masses",
               "plunger_diameter", "lambdas"},
              "a crank-slider analysis");
  const ExpressionEvaluator& ev = c.evaluator;
  DeckCrankSlider d;
  const Field rf = f.require("r");
  const double r = rf.positive(ev, dim::length);
  const Field lf = f.require("l");
  const double l = lf.positive(ev, dim::length);
  if (!(r < l))
    lf.fail("the rod must be longer than the crank radius (r = " + formatNumber(r) +
            " m), or the crank cannot turn through a revolution");
  d.geometry = crank::makeGeometry(r, l);
  d.speed = f.require("speed_rpm").positive(ev, kRpmField) * std::numbers::pi / 30;
  d.phases = {0.0};
  if (auto cranks = f.get("cranks_deg")) {
    d.phases.clear();
    for (const Field& p : cranks->items())
      d.phases.push_back(p.number(ev, kDegreeField) * std::numbers::pi / 180);
    if (d.phases.empty()) cranks->fail("the list of cranks is empty");
    if (d.phases.size() > 64) cranks->fail("at most 64 cranks");
  }
  if (auto s = f.get("steps")) d.steps = s->integer(ev, 8, 100000);
  if (auto m = f.get("masses")) d.masses = readDriveMasses(c, *m, d.geometry);
  if (auto p = f.get("plunger_diameter")) d.plungerDiameter = p->positive(ev, dim::length);
  if (auto list = f.get("lambdas")) {
    for (const Field& x : list->items()) {
      const double lambda = x.number(ev, dim::none);
      if (!(lambda > 0 && lambda < 1)) x.fail("lambda = r/l must lie between 0 and 1");
      if (!d.lambdas.empty() && !(lambda > d.lambdas.back()))
        x.fail("the lambdas must be in ascending order");
      d.lambdas.push_back(lambda);
    }
    if (d.lambdas.size() > 1000) list->fail("at most 1000 lambdas");
  }
  return d;
}

void readTwoDofBody(const Context& c, const Field& f, DeckRotorAnalysis& r) {
  f.allowOnly({"weight", "mass", "radius_of_gyration", "l1", "l2", "C1", "C2"},
              "the body of a rigid-body analysis");
  const ExpressionEvaluator& ev = c.evaluator;
  DeckTwoDofBody b;
  const auto weight = f.get("weight");
  const auto mass = f.get("mass");
  if (weight && mass) mass->fail("give the weight (N) or the mass (kg), not both");
  if (!weight && !mass) f.fail("missing required field 'weight' (N) or 'mass' (kg)");
  b.mass = weight ? weight->positive(ev, dim::force) / kStandardGravity
                : mass->positive(ev, dim::mass);
  b.radiusOfGyration = f.require("radius_of_gyration").positive(ev, dim::length);
  b.l1 = f.require("l1").nonNegative(ev, dim::length);
  b.l2 = f.require("l2").nonNegative(ev, dim::length);
  if (!(b.l1 + b.l2 > 0))
    f.require("l2").fail("the springs must not both sit at the centre of mass");
  b.C1 = f.require("C1").positive(ev, dim::stiffness);
  b.C2 = f.require("C2").positive(ev, dim::stiffness);
  r.body = b;
}

void resolveCrankQuantity(const Quantity& q, const Field& f, const DeckAnalysis& a) {
  const auto* crank = a.as<CrankSliderSpec>();
  if (q.kind != Quantity::Kind::crankSlider || !crank) return;
  const DeckCrankSlider& d = crank->mechanism;
  const std::string& p = q.property;
  if (q.lambda > 0) {
    const bool listed = std::any_of(d.lambdas.begin(), d.lambdas.end(),
                                    [&](double x) { return std::abs(x - q.lambda) <= 1e-12; });
    if (!listed)
      f.fail("lambda " + formatNumber(q.lambda) + " is not in analysis '" + a.name +
             "' lambdas: (" + (d.lambdas.empty() ? std::string("none") : [&] {
               std::vector<std::string> names;
               for (double x : d.lambdas) names.push_back(formatNumber(x));
               return joinNames(names);
             }()) + ")");
    return;
  }
  const bool needsMasses = p == "rotating_mass" || p == "reciprocating_mass" || p[0] == 'F' ||
                           p == "force" || p.rfind("cranks_", 0) == 0 ||
                           p.rfind("moment", 0) == 0;
  if (needsMasses && !d.masses)
    f.fail("'" + q.text + "' needs the drive's masses: give analysis '" + a.name + "' masses:");
  if (p == "delivery" && !(d.plungerDiameter > 0))
    f.fail("'" + q.text + "' needs analysis '" + a.name + "' plunger_diameter:");
}

}  // namespace beamrotor::reader

namespace beamrotor {

void CrankSliderSpec::read(const reader::Context& c, const Field& f) {
  mechanism = reader::readCrankSlider(c, f);
}

}  // namespace beamrotor
