// Deck reader, rotor part: bearings and proportional damping on the model, the fields of the
// rotor analyses (rotor, campbell, unbalance, rigid-body, frequency-response,
// critical-speed-map), and the names their check
// quantities refer to. Speeds are written in rpm in the deck and kept in rad/s.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include "elements/FiniteJournalBearing.hpp"
#include "elements/PlainJournalBearing.hpp"
#include "elements/TiltingPadBearing.hpp"
#include "elements/WhirlTable.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/rotor/JournalTable.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor::reader {

namespace {

constexpr double kRadPerRpm = std::numbers::pi / 30;
/// Bounds that keep a typo (dt: 1e-12) from running for days or filling the disk.
constexpr double kMaxRunUpSteps = 1e7;
constexpr double kMaxRunUpSamples = 1e6;

/// Stiffness and damping keys in the bearing's own axes (x_b, y_b) = global (y, z), see
/// elements/Bearing.hpp.
const std::vector<std::string> kCoefficients{"kxx", "kyy", "kxy", "kyx",
                                             "cxx", "cyy", "cxy", "cyx"};

/// One row of coefficients from a map that also holds `extra` keys. Direct stiffnesses and
/// dampings must be >= 0; cross terms may have either sign.
BearingCoefficients readCoefficients(const Context& c, const Field& f,
                                     const std::vector<std::string>& extra,
                                     const std::string& what) {
  std::vector<std::string> keys = extra;
  keys.insert(keys.end(), kCoefficients.begin(), kCoefficients.end());
  f.allowOnly(keys, what);
  const ExpressionEvaluator& ev = c.evaluator;
  auto value = [&](const char* key, bool direct) {
    const FieldUnit unit = key[0] == 'k' ? dim::stiffness : dim::damping;
    auto v = f.get(key);
    if (!v) return 0.0;
    return direct ? v->nonNegative(ev, unit) : v->number(ev, unit);
  };
  BearingCoefficients k;
  k.kyy = value("kxx", true);
  k.kzz = value("kyy", true);
  k.kyz = value("kxy", false);
  k.kzy = value("kyx", false);
  k.cyy = value("cxx", true);
  k.czz = value("cyy", true);
  k.cyz = value("cxy", false);
  k.czy = value("cyx", false);
  if (k.kyy == 0 && k.kzz == 0 && k.cyy == 0 && k.czz == 0)
    f.fail("a bearing needs a positive kxx, kyy, cxx or cyy (N/m, N s/m)");
  return k;
}

std::vector<double> readSpeedRange(const Context& c, const Field& f);

/// The finite film's grid: `grid: {circumferential: N, axial: M}` (cells around the journal,
/// cells from the mid-plane to an end); by default 72 around and 8 L/D (at least 8) along.
ReynoldsGrid readJournalGrid(const Context& c, const Field* f, double lengthOverDiameter) {
  ReynoldsGrid grid;
  grid.axial = std::max(8, int(std::ceil(8 * lengthOverDiameter - 1e-9)));
  if (!f) return grid;
  if (!f->isMap()) f->fail("expected {circumferential: 72, axial: 8}, got " + f->describe());
  f->allowOnly({"circumferential", "axial"}, "a film grid");
  if (auto n = f->get("circumferential")) grid.circumferential = n->integer(c.evaluator, 16, 2000);
  if (auto m = f->get("axial")) grid.axial = m->integer(c.evaluator, 2, 500);
  return grid;
}

/// A tilting-pad bearing's pads (elements/TiltingPadBearing.hpp): pads, arc, offset, preload
/// and orientation; its film grid counts cells over one pad (24 by default).
TiltingPads readTiltingPads(const Context& c, const Field& f) {
  const ExpressionEvaluator& ev = c.evaluator;
  TiltingPads pads;
  pads.count = f.require("pads").integer(ev, 2, 12);
  const Field arc = f.require("arc");
  pads.arc = arc.positive(ev, dim::angle);
  if (!(pads.count * pads.arc < 2 * std::numbers::pi))
    arc.fail(std::to_string(pads.count) + " pads of " +
             formatNumber(pads.arc * 180 / std::numbers::pi) +
             " deg do not fit around the journal (pads x arc < 360 deg)");
  if (auto o = f.get("offset")) {
    pads.pivotOffset = o->number(ev, dim::none);
    if (!(pads.pivotOffset >= 0.3 && pads.pivotOffset <= 0.8))
      o->fail("the pivot offset is the pivot's place on the arc from the leading edge, 0.3 to "
              "0.8 (0.5: centred; typical 0.5 to 0.6)");
  }
  if (auto m = f.get("preload")) {
    pads.preload = m->number(ev, dim::none);
    if (!(pads.preload > 0 && pads.preload < 0.9))
      m->fail("the preload m = 1 - c / c_pad lies between 0 and 0.9 (typical 0.2 to 0.5; a pad "
              "without preload carries nothing when the journal is centred)");
  } else {
    f.require("preload");
  }
  pads.loadOnPad = f.require("orientation").choice({"load-on-pad", "load-between-pads"}) ==
                   "load-on-pad";
  return pads;
}

/// pad_tilts: condensed (default: onto the journal, the coefficient table), dofs (each loaded
/// pad's tilt a dof of the rotor's, massless pads) or {inertia: I} (the same, each pad's polar
/// moment of inertia about its pivot, kg m^2): the pads' inertia, or nothing when condensed.
std::optional<double> readPadTilts(const Context& c, const Field& f) {
  if (f.isScalar()) {
    if (f.choice({"condensed", "dofs"}) == "condensed") return std::nullopt;
    return 0.0;
  }
  if (!f.isMap())
    f.fail("expected condensed, dofs or {inertia: KG_M2}, got " + f.describe());
  f.allowOnly({"inertia"}, "pad_tilts");
  return f.require("inertia").nonNegative(c.evaluator, dim::inertia);
}

/// A plain journal or tilting-pad bearing: geometry, oil and load, and the speeds of its
/// coefficient table. The short-bearing theory (elements/PlainJournalBearing.hpp) or the finite
/// film (elements/FiniteJournalBearing.hpp, `model: finite`) gives a plain journal's
/// coefficients there, the pads' films (elements/TiltingPadBearing.hpp) a tilting-pad bearing's.
void readPlainJournal(const Context& c, const Field& f, const Field& type, DeckBearing& b) {
  if (type.text() != "plain-journal" && type.text() != "tilting-pad")
    type.fail("unknown bearing type '" + type.text() + "'" +
              didYouMean(type.text(), {"plain-journal", "tilting-pad"}) +
              " (a bearing is plain-journal, tilting-pad, or has coefficients or a table)");
  const bool tilting = type.text() == "tilting-pad";
  if (tilting)
    f.allowOnly({"name", "at", "type", "D", "L", "c", "mu", "load", "load_angle", "pedestal",
                 "from_rpm", "to_rpm", "steps", "grid", "pads", "arc", "offset", "preload",
                 "orientation", "whirl_coefficients", "pad_tilts"},
                "a tilting-pad bearing");
  else
    f.allowOnly({"name", "at", "type", "D", "L", "c", "mu", "load", "load_angle", "pedestal",
                 "from_rpm", "to_rpm", "steps", "model", "grid"},
                "a plain-journal bearing");
  const ExpressionEvaluator& ev = c.evaluator;
  PlainJournal j;
  j.diameter = f.require("D").positive(ev, dim::length);
  const Field length = f.require("L");
  j.length = length.positive(ev, dim::length);
  const double ld = j.length / j.diameter;
  // Short theory up to L/D = 1 unless asked otherwise (decks written before the finite film
  // keep their answers), the finite film beyond.
  using Model = DeckBearing::JournalModel;
  b.journalModel = ld > 1 ? Model::finite : Model::shortBearing;
  if (auto model = f.get("model")) {
    const std::string m = model->text();
    if (m != "short" && m != "finite")
      model->fail(
          "unknown journal bearing model '" + m + "'" + didYouMean(m, {"short", "finite"}) +
          " (short: Ocvirk's closed forms, L/D <= 1; finite: Reynolds' equation on a grid)");
    b.journalModel = m == "finite" ? Model::finite : Model::shortBearing;
    if (b.journalModel == Model::shortBearing && ld > 1)
      length.fail("the short-bearing theory holds for L/D <= 1 (here L/D = " + formatNumber(ld) +
                  "); use model: finite");
  }
  if (tilting) {
    b.tiltingPads = readTiltingPads(c, f);
    if (auto w = f.get("whirl_coefficients"))
      b.eachModesWhirl = w->choice({"synchronous", "each-mode"}) == "each-mode";
    if (auto t = f.get("pad_tilts")) {
      b.padInertia = readPadTilts(c, *t);
      if (b.padInertia && b.eachModesWhirl)
        t->fail("the pads' tilts kept as dofs give every mode its own frequency already: drop "
                "whirl_coefficients: each-mode");
    }
  }
  auto grid = f.get("grid");
  if (grid && b.journalModel != Model::finite && !tilting)
    grid->fail("a film grid belongs to model: finite (the short theory has closed forms)");
  b.journalGrid = readJournalGrid(c, grid ? &*grid : nullptr, ld);
  if (tilting && !(grid && grid->has("circumferential"))) b.journalGrid.circumferential = 24;
  const Field clearance = f.require("c");
  j.clearance = clearance.positive(ev, dim::length);
  if (!(j.clearance < 0.01 * j.diameter))
    clearance.fail("a radial clearance of " + formatNumber(j.clearance) +
                   " m is not small against D (c/D must be below 0.01; typical 0.001)");
  j.viscosity = f.require("mu").positive(ev, dim::viscosity);
  const Field load = f.require("load");
  b.loadFromGravity = load.isScalar() && load.text() == "gravity";
  // load: 0 is an unloaded journal (a vertical rotor's): it runs centred
  // (elements/ConcentricJournal.hpp).
  if (!b.loadFromGravity) j.load = load.nonNegative(ev, dim::force);
  if (tilting && !b.loadFromGravity && !(j.load > 0))
    load.fail("a tilting-pad bearing is solved for a load: give it (N) or load: gravity");
  if (b.loadFromGravity && f.has("load_angle"))
    f.require("load_angle")
        .fail("load: gravity takes the rotor's weight along -y; give the load as a number (N) "
              "to set its direction with load_angle");
  b.speeds = readSpeedRange(c, f);
  if (!(b.speeds.front() > 0))
    f.require("from_rpm").fail("a plain journal bearing has no film at rest: from_rpm must be > 0 "
                               "(the lowest row is held below it)");
  b.journal = j;
  // With load: gravity the run fills the table once the rotor's weight share is known.
  if (!b.loadFromGravity) {
    try {
      fillJournalTable(b);
    } catch (const std::invalid_argument& e) {
      f.require("from_rpm").fail(e.what());
    }
  }
}

/// pedestal: {m, k, c} or with kxx, kyy, cxx, cyy (global y, z) in place of k, c: a mass
/// (kg) on stiffness (N/m) and damping (N s/m) to the ground under the bearing.
DeckPedestal readPedestal(const Context& c, const Field& f) {
  if (!f.isMap()) f.fail("expected {m: KG, k: N_PER_M, c: N_S_PER_M}, got " + f.describe());
  f.allowOnly({"m", "k", "c", "kxx", "kyy", "cxx", "cyy"}, "a pedestal");
  const ExpressionEvaluator& ev = c.evaluator;
  DeckPedestal p;
  if (auto m = f.get("m")) p.m = m->nonNegative(ev, dim::mass);
  // One value for both directions, or each its own (the other then must be given too).
  auto pair = [&](const char* both, const char* y, const char* z, const FieldUnit& unit,
                  double& vy, double& vz) {
    if (auto v = f.get(both)) {
      if (f.has(y) || f.has(z))
        v->fail(std::string("give either ") + both + " or " + y + " and " + z + ", not both");
      vy = vz = v->nonNegative(ev, unit);
      return;
    }
    if (auto v = f.get(y)) vy = v->nonNegative(ev, unit);
    if (auto v = f.get(z)) vz = v->nonNegative(ev, unit);
  };
  pair("k", "kxx", "kyy", dim::stiffness, p.kyy, p.kzz);
  pair("c", "cxx", "cyy", dim::damping, p.cyy, p.czz);
  if (!(p.kyy > 0) || !(p.kzz > 0))
    f.fail("a pedestal needs a positive stiffness to the ground in both directions (k, or kxx "
           "and kyy, N/m)");
  return p;
}

/// A table by speed and whirl frequency: rows {speed_rpm, whirl_hz, kxx ... cyx}, speed by
/// speed (ascending), each speed on the same ascending whirl frequencies. The speed table gets
/// the synchronous set (whirl = spin), which the analyses at the spin's frequency read.
void readWhirlTable(const Context& c, const Field& table, DeckBearing& b) {
  const ExpressionEvaluator& ev = c.evaluator;
  const std::vector<Field> rows = table.items();
  std::size_t column = 0;  // the row's place among its speed's whirl frequencies
  for (const Field& row : rows) {
    if (!row.isMap()) row.fail("expected a table row {speed_rpm, whirl_hz, kxx, ...}, got " +
                               row.describe());
    const Field speed = row.require("speed_rpm");
    const double w = speed.nonNegative(ev, kRpmField) * kRadPerRpm;
    const Field whirlField = row.require("whirl_hz");
    const double whirl = whirlField.nonNegative(ev, dim::frequency) * 2 * std::numbers::pi;
    const bool newSpeed = b.speeds.empty() || w != b.speeds.back();
    if (newSpeed) {
      if (!b.speeds.empty() && !(w > b.speeds.back()))
        speed.fail("speeds of a bearing table must be strictly ascending (rows speed by speed, "
                   "each speed's whirl frequencies ascending)");
      if (!b.speeds.empty() && column != b.whirls.size())
        speed.fail("every speed of a whirl table lists the same whirl frequencies (" +
                   std::to_string(b.whirls.size()) + " at the first speed, " +
                   std::to_string(column) + " at " +
                   formatNumber(b.speeds.back() / kRadPerRpm) + " rpm)");
      b.speeds.push_back(w);
      column = 0;
    }
    if (b.speeds.size() == 1) {
      if (!b.whirls.empty() && !(whirl > b.whirls.back()))
        whirlField.fail("a speed's whirl frequencies must be strictly ascending");
      b.whirls.push_back(whirl);
    } else if (column >= b.whirls.size() || whirl != b.whirls[column]) {
      whirlField.fail("every speed of a whirl table lists the same whirl frequencies as the "
                      "first (" + formatNumber(b.whirls[std::min(column, b.whirls.size() - 1)] /
                                               (2 * std::numbers::pi)) +
                      " Hz expected here)");
    }
    ++column;
    b.whirlRows.push_back(readCoefficients(c, row, {"speed_rpm", "whirl_hz"}, "a whirl table row"));
  }
  if (b.speeds.size() > 1 && column != b.whirls.size())
    rows.back().fail("every speed of a whirl table lists the same whirl frequencies (" +
                     std::to_string(b.whirls.size()) + " at the first speed, " +
                     std::to_string(column) + " at the last)");
  b.table = WhirlTable(b.speeds, b.whirls, b.whirlRows).synchronous();
}

bool carriesLateral(const Deck& deck) {
  return deck.dofs.contains(Dof::uy) && deck.dofs.contains(Dof::uz);
}

void readBearings(Context& c) {
  auto block = c.root.get("bearings");
  if (!block || block->isNull()) return;
  if (!carriesLateral(c.deck))
    block->fail("bearings act on uy and uz: use model: {dimension: lateral} (or 3d), not " +
                c.deck.dimension);
  TakenNames names;
  for (const Field& f : block->items()) {
    if (!f.isMap()) f.fail("expected a map describing a bearing, got " + f.describe());
    DeckBearing b;
    b.place = f.place();
    const Field at = f.require("at");
    b.point = c.point(at).name;
    auto nameField = f.get("name");
    b.name = nameField ? nameField->name() : b.point;
    claimName(nameField ? *nameField : at, b.name, names, "a bearing");
    if (auto angle = f.get("load_angle")) b.loadAngle = angle->number(c.evaluator, dim::angle);
    if (auto pedestal = f.get("pedestal")) b.pedestal = readPedestal(c, *pedestal);
    if (auto type = f.get("type")) {
      readPlainJournal(c, f, *type, b);
      if (b.pedestal && b.padInertia)
        f.require("pad_tilts")
            .fail("the pads' tilts as dofs act against the ground: drop the pedestal or use "
                  "pad_tilts: condensed");
    } else if (auto table = f.get("table")) {
      f.allowOnly({"name", "at", "table", "load_angle", "pedestal"}, "a tabulated bearing");
      const std::vector<Field> rows = table->items();
      if (rows.empty()) table->fail("the bearing table is empty");
      if (rows.front().isMap() && rows.front().has("whirl_hz")) {
        readWhirlTable(c, *table, b);
      } else {
        for (const Field& row : rows) {
          const Field speed = row.require("speed_rpm");
          const double w = speed.nonNegative(c.evaluator, kRpmField) * kRadPerRpm;
          if (!b.speeds.empty() && !(w > b.speeds.back()))
            speed.fail("speeds of a bearing table must be strictly ascending");
          b.speeds.push_back(w);
          b.table.push_back(readCoefficients(c, row, {"speed_rpm"}, "a bearing table row"));
        }
      }
    } else {
      b.table.push_back(
          readCoefficients(c, f, {"name", "at", "table", "load_angle", "pedestal"}, "a bearing"));
    }
    c.deck.rotor.bearings.push_back(std::move(b));
  }
}

void readDamping(Context& c) {
  auto f = c.root.get("damping");
  if (!f || f->isNull()) return;
  f->allowOnly({"alpha", "beta", "internal"}, "damping");
  if (auto a = f->get("alpha"))
    c.deck.rotor.damping.alpha = a->nonNegative(c.evaluator, dim::frequency);
  if (auto b = f->get("beta")) c.deck.rotor.damping.beta = b->nonNegative(c.evaluator, dim::time);
  if (auto i = f->get("internal")) {
    // The shaft's rotating damping beta_i (s): only lateral rotor models spin about x.
    if (!carriesLateral(c.deck))
      i->fail("internal damping acts on a spinning shaft's uy, uz: use model: "
              "{dimension: lateral}, not " + c.deck.dimension);
    c.deck.rotor.damping.internal = i->nonNegative(c.evaluator, dim::time);
  }
}

/// `fromKey`, `toKey` (in `unit`) and steps: steps intervals from `from` to `to` (the last
/// value `to` exactly), each times `scale`, the SI value of the keys' bare unit.
std::vector<double> readRange(const Context& c, const Field& f, const std::string& fromKey,
                              const std::string& toKey, const FieldUnit& unit, double scale) {
  const double from = f.require(fromKey).nonNegative(c.evaluator, unit);
  const Field toField = f.require(toKey);
  const double to = toField.number(c.evaluator, unit);
  if (!(to > from)) toField.fail(toKey + " must exceed " + fromKey + " (" + formatNumber(from) + ")");
  const int n = f.require("steps").integer(c.evaluator, 1, kMaxSweepValues - 1);
  std::vector<double> values;
  for (int i = 0; i < n; ++i) values.push_back((from + (to - from) * i / n) * scale);
  values.push_back(to * scale);
  return values;
}

/// from_rpm, to_rpm, steps: spin speeds (rad/s).
std::vector<double> readSpeedRange(const Context& c, const Field& f) {
  return readRange(c, f, "from_rpm", "to_rpm", kRpmField, kRadPerRpm);
}

/// input / output of a frequency response: {at: POINT, dof: uy | uz | ry | rz}.
void readResponseEnd(const Context& c, const Field& f, std::string& point, Dof& dof) {
  if (!f.isMap()) f.fail("expected {at: POINT, dof: uy}, got " + f.describe());
  f.allowOnly({"at", "dof"}, "an end of a frequency response");
  point = c.point(f.require("at")).name;
  const Field d = f.require("dof");
  dof = c.dof(d);
  if (dof != Dof::uy && dof != Dof::uz && dof != Dof::ry && dof != Dof::rz)
    d.fail("a rotor's frequency response acts on uy, uz, ry or rz");
}

/// from_hz, to_hz, steps: excitation frequencies (rad/s); from_hz may be 0.
std::vector<double> readFrequencyRange(const Context& c, const Field& f) {
  return readRange(c, f, "from_hz", "to_hz", dim::frequency, 2 * std::numbers::pi);
}

/// operating: {min_rpm, max_rpm, min_log_decrement}: the machine's operating speed range,
/// 0 < min < max, and the log decrement every mode must keep over it (>= 0, default 0).
OperatingRange readOperatingRange(const Context& c, const Field& f, double& minLogDecrement) {
  if (!f.isMap()) f.fail("expected {min_rpm: RPM, max_rpm: RPM}, got " + f.describe());
  f.allowOnly({"min_rpm", "max_rpm", "min_log_decrement"}, "an operating speed range");
  if (auto d = f.get("min_log_decrement")) minLogDecrement = d->nonNegative(c.evaluator, dim::none);
  OperatingRange range;
  range.minimum = f.require("min_rpm").positive(c.evaluator, kRpmField) * kRadPerRpm;
  const Field top = f.require("max_rpm");
  range.maximum = top.positive(c.evaluator, kRpmField) * kRadPerRpm;
  if (!(range.maximum > range.minimum))
    top.fail("max_rpm must exceed min_rpm (" + formatNumber(range.minimum / kRadPerRpm) + ")");
  return range;
}

void readUnbalance(const Context& c, const Field& f, DeckRotorAnalysis& r) {
  for (const Field& u : f.require("unbalance").itemsOrSingle()) {
    if (!u.isMap())
      u.fail("expected {at: POINT, me: KG_M, moment: KG_M2, phase: RAD}, got " + u.describe());
    u.allowOnly({"at", "me", "moment", "phase"}, "an unbalance");
    DeckUnbalance d;
    d.place = u.place();
    d.point = c.point(u.require("at")).name;
    // A static unbalance me, a couple unbalance moment (m e d of two opposite heavy spots a
    // distance d apart), or both at one phase.
    const auto moment = u.get("moment");
    if (moment) d.moment = moment->positive(c.evaluator, dim::inertia);
    if (!moment || u.has("me")) d.me = u.require("me").positive(c.evaluator, dim::massLength);
    if (auto p = u.get("phase")) d.phase = p->number(c.evaluator, dim::angle);
    r.unbalance.push_back(std::move(d));
  }
  for (const Field& p : f.require("response").itemsOrSingle()) {
    const std::string name = c.point(p).name;
    if (std::find(r.response.begin(), r.response.end(), name) != r.response.end())
      p.fail("point '" + name + "' is listed twice");
    r.response.push_back(name);
  }
}

/// Fails at analysis entry f when a bearing stands on a pedestal: `why` the analysis cannot.
/// (Bearings that keep their pads' tilts as dofs are taken condensed by these analyses,
/// problems/run/RunRotor.cpp.)
void refusePedestals(const Context& c, const Field& f, const std::string& why) {
  for (const DeckBearing& b : c.deck.rotor.bearings)
    if (b.pedestal)
      f.fail(why + " on the ground; bearing '" + b.name +
             "' stands on a pedestal (remove it for this analysis)");
}

/// critical-speed-map: from_k, to_k (N/m), points (log-spaced, ends included) and
/// critical_speeds; the deck's bearings are the ones replaced by the stiffness.
void readCriticalSpeedMap(const Context& c, const Field& f, DeckRotorAnalysis& r) {
  f.allowOnly({"type", "name", "from_k", "to_k", "points", "critical_speeds"},
              "a critical-speed-map analysis");
  if (c.deck.dimension != "lateral")
    f.fail("a critical-speed map needs model: {dimension: lateral} (here " + c.deck.dimension +
           ": its axial and torsional dofs would have no support)");
  if (c.deck.rotor.bearings.empty())
    f.fail("a critical-speed map puts its stiffness in place of the deck's bearings: add "
           "bearings");
  // On a pedestal the swept stiffness stands in series with it (fem/rotor/CriticalSpeedMap.hpp),
  // whose one plane stands for both: the pedestal's springs must be the same in y and z.
  for (const DeckBearing& b : c.deck.rotor.bearings)
    if (b.pedestal && b.pedestal->kyy != b.pedestal->kzz)
      f.fail("a critical-speed map solves one plane for both: bearing '" + b.name +
             "' stands on a pedestal whose kxx (" + formatNumber(b.pedestal->kyy) +
             " N/m) differs from its kyy (" + formatNumber(b.pedestal->kzz) +
             " N/m); give it one k for this analysis");
  const ExpressionEvaluator& ev = c.evaluator;
  const double from = f.require("from_k").positive(ev, dim::stiffness);
  const Field toField = f.require("to_k");
  const double to = toField.positive(ev, dim::stiffness);
  if (!(to > from)) toField.fail("to_k must exceed from_k (" + formatNumber(from) + " N/m)");
  const int n = f.require("points").integer(ev, 2, kMaxSweepValues);
  for (int i = 0; i < n; ++i)
    r.stiffnesses.push_back(i + 1 == n ? to : from * std::pow(to / from, double(i) / (n - 1)));
  if (auto k = f.get("critical_speeds")) r.criticalSpeeds = k->integer(ev, 1, 20);
}

/// bearing-loads: g (m/s^2, default 9.81), direction (-y, y, -z, z; default -y), bearings
/// (rigid or elastic) and, for elastic bearings, speed_rpm (their coefficients' speed).
/// `g` (m/s^2, default 9.81) and `direction` (-y, y, -z or z; default -y) of the map f: the
/// acceleration of gravity, global.
std::array<double, 3> readGravity(const Context& c, const Field& f) {
  double g = 9.81;
  if (auto v = f.get("g")) g = v->positive(c.evaluator, dim::acceleration);
  std::string direction = "-y";
  if (auto d = f.get("direction")) direction = d->choice({"-y", "y", "-z", "z"});
  const double sign = direction[0] == '-' ? -1 : 1;
  return {0, direction.back() == 'y' ? sign * g : 0, direction.back() == 'z' ? sign * g : 0};
}

/// run-up `speed:` {torque: N*m} | {torque_table: [[t, N*m], ...]} | {motor: [[rpm, N*m], ...]},
/// with an optional `inertia:` (kg m^2) added to the rotor's own polar inertia.
DeckDrive readDrive(const Context& c, const Field& f) {
  if (!f.isMap())
    f.fail("expected {torque: N*m}, {torque_table: [[t, N*m], ...]} or {motor: [[rpm, N*m], "
           "...]}, got " + f.describe());
  f.allowOnly({"torque", "torque_table", "motor", "inertia"}, "a driven speed");
  const ExpressionEvaluator& ev = c.evaluator;
  DeckDrive d;
  const int given = int(f.has("torque")) + int(f.has("torque_table")) + int(f.has("motor"));
  if (given != 1) f.fail("give one of torque, torque_table or motor");
  if (auto t = f.get("torque")) {
    d.x = {0};
    d.torques = {t->number(ev, dim::moment)};
  } else {
    const bool motor = f.has("motor");
    const Field table = f.require(motor ? "motor" : "torque_table");
    d.kind = motor ? DeckDrive::Kind::speed : DeckDrive::Kind::time;
    for (const Field& row : table.items()) {
      const std::vector<Field> pair = row.isList() ? row.items() : std::vector<Field>{};
      if (pair.size() != 2)
        row.fail(std::string("expected a row [") + (motor ? "rpm" : "t") + ", N*m], got " +
                 row.describe());
      const double x = motor ? pair[0].nonNegative(ev, kRpmField) * kRadPerRpm
                             : pair[0].nonNegative(ev, dim::time);
      if (!motor && d.x.empty() && x != 0) pair[0].fail("the table starts at t = 0");
      if (!d.x.empty() && !(x > d.x.back()))
        pair[0].fail(std::string(motor ? "speeds" : "times") + " must ascend strictly");
      d.x.push_back(x);
      d.torques.push_back(pair[1].number(ev, dim::moment));
    }
    if (d.x.size() < 2) table.fail("a torque table needs at least two rows");
  }
  if (auto j = f.get("inertia")) d.extraInertia = j->nonNegative(ev, dim::inertia);
  return d;
}

/// run-up `bearings: nonlinear`: the deck's plain journal bearings act by their films (short
/// or finite, as their coefficients) and its tilting-pad bearings by their pads' films, each
/// pad's tilt a dof of the run (elements/TiltingPadJournalFilm.hpp); the other bearings keep
/// their coefficients.
void readNonlinearBearings(const Context& c, const Field& f, const DeckRunUp& u) {
  bool any = false;
  for (const DeckBearing& b : c.deck.rotor.bearings) {
    if (!b.journal) continue;
    if (b.pedestal)
      f.fail("bearing '" + b.name + "' stands on a pedestal: its film force acts between journal "
             "and ground in a nonlinear run-up (remove the pedestal or run bearings: linear)");
    any = true;
  }
  if (!any)
    f.fail("bearings: nonlinear puts the journal bearings' film forces in place of their "
           "coefficients; the deck has none (type: plain-journal or tilting-pad)");
  if (!(u.speeds.front() > 0))
    f.fail("a journal bearing carries its load on a film only when the shaft turns: a nonlinear "
           "run-up starts at a speed above 0");
  // The run starts where each film carries its load: a finite film or the pads must reach that
  // equilibrium at the start speed (the table may start faster). A load from gravity is known
  // only later.
  for (const DeckBearing& b : c.deck.rotor.bearings) {
    const bool finite = b.journalModel == DeckBearing::JournalModel::finite || b.tiltingPads;
    if (!b.journal || b.loadFromGravity || !finite || b.journal->load == 0) continue;
    try {
      if (b.tiltingPads)
        tiltingPadPoint(*b.journal, *b.tiltingPads, u.speeds.front(), b.journalGrid);
      else
        finiteJournalPoint(*b.journal, u.speeds.front(), b.journalGrid);
    } catch (const std::invalid_argument& e) {
      f.fail("bearing '" + b.name + "' at the run-up's start speed (" +
             formatNumber(u.speeds.front() / kRadPerRpm) + " rpm): " + e.what() +
             "; start the run faster");
    }
  }
}

/// run-up `rub:` one station or a list, each {at: POINT, clearance, stiffness, friction, radius}
/// with optional damping, slip_velocity and name.
std::vector<DeckRub> readRubs(const Context& c, const Field& f) {
  const ExpressionEvaluator& ev = c.evaluator;
  std::vector<DeckRub> out;
  for (const Field& r : f.itemsOrSingle()) {
    if (!r.isMap())
      r.fail("expected {at: POINT, clearance: m, stiffness: N/m, friction: MU, radius: m}, got " +
             r.describe());
    r.allowOnly({"name", "at", "clearance", "stiffness", "damping", "friction", "radius",
                 "slip_velocity"},
                "a rub station");
    DeckRub d;
    d.place = r.place();
    d.point = c.point(r.require("at")).name;
    d.name = d.point;
    if (auto n = r.get("name")) d.name = n->text();
    for (const DeckRub& other : out)
      if (other.name == d.name)
        r.fail("rub '" + d.name + "' is listed twice (give each station its own name:)");
    d.clearance = r.require("clearance").positive(ev, dim::length);
    d.stiffness = r.require("stiffness").positive(ev, dim::stiffness);
    if (auto k = r.get("damping")) d.damping = k->nonNegative(ev, dim::damping);
    d.friction = r.require("friction").nonNegative(ev, dim::none);
    d.radius = r.require("radius").positive(ev, dim::length);
    if (auto v = r.get("slip_velocity")) d.slipVelocity = v->positive(ev, dim::velocity);
    out.push_back(std::move(d));
  }
  if (out.empty()) f.fail("expected one or more rub stations");
  return out;
}

/// run-up: the speed against time (a ramp from_rpm -> to_rpm over duration, or speed_table
/// rows [t, rpm]), the time grid and scheme, the start, gravity, unbalance and response.
void readRunUp(const Context& c, const Field& f, DeckRotorAnalysis& r) {
  f.allowOnly({"type", "name", "from_rpm", "to_rpm", "duration", "speed_table", "speed", "dt",
               "scheme", "alpha", "start", "gravity", "sample_every", "unbalance", "response",
               "bearings", "rub"},
              "a run-up analysis");
  const ExpressionEvaluator& ev = c.evaluator;
  DeckRunUp& u = r.runUp;
  if (auto drive = f.get("speed")) {
    for (const char* key : {"to_rpm", "speed_table"})
      if (auto other = f.get(key))
        other->fail("speed: drives the rotor by a torque; its speed is a result, not given by " +
                    std::string(key));
    u.drive = readDrive(c, *drive);
    const double from = f.require("from_rpm").nonNegative(ev, kRpmField) * kRadPerRpm;
    u.times = {0, f.require("duration").positive(ev, dim::time)};
    u.speeds = {from, from};
  } else if (auto table = f.get("speed_table")) {
    for (const char* key : {"from_rpm", "to_rpm", "duration"})
      if (auto other = f.get(key))
        other->fail("give either speed_table: or from_rpm, to_rpm and duration, not both");
    for (const Field& row : table->items()) {
      const std::vector<Field> pair = row.isList() ? row.items() : std::vector<Field>{};
      if (pair.size() != 2) row.fail("expected a row [t, rpm], got " + row.describe());
      const double t = pair[0].nonNegative(ev, dim::time);
      if (u.times.empty() && t != 0) pair[0].fail("the table starts at t = 0");
      if (!u.times.empty() && !(t > u.times.back()))
        pair[0].fail("times must ascend strictly (the previous is " + formatNumber(u.times.back()) +
                     ")");
      u.times.push_back(t);
      u.speeds.push_back(pair[1].nonNegative(ev, kRpmField) * kRadPerRpm);
    }
    if (u.times.size() < 2) table->fail("a speed table needs at least two rows [t, rpm]");
  } else {
    const double from = f.require("from_rpm").nonNegative(ev, kRpmField) * kRadPerRpm;
    const Field to = f.require("to_rpm");
    const double top = to.nonNegative(ev, kRpmField) * kRadPerRpm;
    if (top == from)
      to.fail("to_rpm equals from_rpm: a run-up (to_rpm > from_rpm) or coast-down (to_rpm < "
              "from_rpm) changes the speed");
    u.times = {0, f.require("duration").positive(ev, dim::time)};
    u.speeds = {from, top};
  }
  const Field dt = f.require("dt");
  u.dt = dt.positive(ev, dim::time);
  const double steps = std::round(u.times.back() / u.dt);
  if (!(u.times.back() / u.dt <= kMaxRunUpSteps))
    dt.fail("the run asks for " + formatNumber(steps) + " steps; at most " +
            formatNumber(kMaxRunUpSteps) + " (use a larger dt)");
  if (!(steps >= 1)) dt.fail("dt exceeds the run's duration " + formatNumber(u.times.back()) + " s");
  if (auto s = f.get("scheme"); s && s->choice({"newmark", "hht"}) == "hht") u.alpha = -0.05;
  if (auto a = f.get("alpha")) {
    if (u.alpha == 0) a->fail("alpha is the HHT parameter; set scheme: hht");
    u.alpha = a->number(ev, dim::none);
    if (!(u.alpha >= -1.0 / 3 && u.alpha <= 0))
      a->fail("HHT alpha must lie in [-1/3, 0], got " + formatNumber(u.alpha));
  }
  if (auto s = f.get("start")) u.steadyStart = s->choice({"rest", "steady"}) == "steady";
  if (auto g = f.get("gravity")) {
    if (!g->isMap()) g->fail("expected {g: 9.81, direction: -y}, got " + g->describe());
    g->allowOnly({"g", "direction"}, "gravity");
    u.gravity = readGravity(c, *g);
  }
  if (auto n = f.get("sample_every")) u.sampleEvery = n->integer(ev, 1, int(kMaxRunUpSteps));
  if (steps / u.sampleEvery > kMaxRunUpSamples)
    dt.fail("the run would record " + formatNumber(std::round(steps / u.sampleEvery)) +
            " samples; at most " + formatNumber(kMaxRunUpSamples) + " (set sample_every)");
  if (auto b = f.get("bearings")) {
    u.nonlinearBearings = b->choice({"linear", "nonlinear"}) == "nonlinear";
    if (u.nonlinearBearings) readNonlinearBearings(c, *b, u);
  }
  if (auto rub = f.get("rub")) u.rubs = readRubs(c, *rub);
  readUnbalance(c, f, r);
}

void readBearingLoads(const Context& c, const Field& f, DeckRotorAnalysis& r) {
  f.allowOnly({"type", "name", "g", "direction", "bearings", "speed_rpm"},
              "a bearing-loads analysis");
  if (c.deck.rotor.bearings.empty())
    f.fail("a bearing-loads analysis reports the loads of the deck's bearings: add bearings");
  refusePedestals(c, f, "a bearing-loads analysis pins the bearings");
  r.gravity = readGravity(c, f);
  if (auto b = f.get("bearings")) r.rigidBearings = b->choice({"rigid", "elastic"}) == "rigid";
  if (auto s = f.get("speed_rpm")) {
    if (r.rigidBearings) s->fail("speed_rpm sets the elastic bearings' coefficients: add bearings: elastic");
    r.speed = s->nonNegative(c.evaluator, kRpmField) * kRadPerRpm;
  }
}

/// level1-stability `stages:` a list of API 617 stages, each with its rated power, impeller
/// diameter, restrictive tip width and discharge / suction densities.
std::vector<CompressorStage> readStages(const Context& c, const Field& f) {
  const std::vector<Field> items = f.items();
  if (items.empty()) f.fail("expected a list of one or more stages");
  std::vector<CompressorStage> out;
  const ExpressionEvaluator& ev = c.evaluator;
  for (const Field& item : items) {
    item.allowOnly({"power", "diameter", "tip_width", "discharge_density", "suction_density"},
                   "an API 617 stage");
    CompressorStage s;
    s.power = item.require("power").nonNegative(ev, dim::power);
    s.diameter = item.require("diameter").positive(ev, dim::length);
    s.tipWidth = item.require("tip_width").positive(ev, dim::length);
    s.dischargeDensity = item.require("discharge_density").positive(ev, dim::density);
    s.suctionDensity = item.require("suction_density").positive(ev, dim::density);
    out.push_back(s);
  }
  return out;
}

/// campbell `order:` a positive number, or a list of distinct ones: the first gives the critical
/// speeds (checks, API margins), the others are drawn as further excitation lines with their
/// crossings (e.g. [1, 0.5, 2] for oil whirl and twice-per-revolution excitation).
void readOrders(const Field& f, const ExpressionEvaluator& ev, DeckRotorAnalysis& r) {
  if (!f.isList()) {
    r.order = f.positive(ev, dim::none);
    return;
  }
  const std::vector<Field> items = f.items();
  if (items.empty() || items.size() > 10) f.fail("expected one to ten excitation orders");
  std::vector<double> orders;
  for (const Field& item : items) {
    const double order = item.positive(ev, dim::none);
    if (std::find(orders.begin(), orders.end(), order) != orders.end())
      item.fail("this order is listed twice");
    orders.push_back(order);
  }
  r.order = orders.front();
  r.furtherOrders.assign(orders.begin() + 1, orders.end());
}

void requireLateral(const Context& c, const Field& f, std::string_view type) {
  if (!carriesLateral(c.deck))
    f.fail("a " + std::string(type) + " analysis needs uy and uz: use model: {dimension: lateral}");
}

/// `modes:` and `shift:` of the analyses that seek damped modes.
void readModeSearch(const Context& c, const Field& f, RotorFamily& settings) {
  if (auto m = f.get("modes")) settings.modes = m->integer(c.evaluator, 1, kMaxModes);
  if (auto s = f.get("shift"))
    settings.shift = s->number(c.evaluator, dim::frequency);  // on s = -d + i w
}

}  // namespace

void readDisk(const Context& c, const Field& disk, DeckMass& mass) {
  disk.allowOnly({"D", "bore", "width", "rho"}, "a disk");
  const ExpressionEvaluator& ev = c.evaluator;
  const double D = disk.require("D").positive(ev, dim::length);
  const double w = disk.require("width").positive(ev, dim::length);
  const double rho = disk.require("rho").positive(ev, dim::density);
  double d = 0;
  if (auto bore = disk.get("bore")) {
    d = bore->nonNegative(ev, dim::length);
    if (!(d < D)) bore->fail("the bore must be smaller than D (" + formatNumber(D) + ")");
  }
  // Annular disk (a hollow cylinder) about its centre: m = rho pi (D^2 - d^2) w / 4,
  // Jp = m (D^2 + d^2) / 8, Jd = m ((D^2 + d^2) / 16 + w^2 / 12): the difference of two solid
  // cylinders, each m R^2 / 2 about its axis and m (3 R^2 + w^2) / 12 about a diameter
  // through its centre (the tables of mass moments of inertia in any dynamics text, e.g.
  // Meriam & Kraige, Engineering Mechanics: Dynamics, appendix D).
  mass.m = rho * std::numbers::pi * (D * D - d * d) * w / 4;
  mass.Jp = mass.m * (D * D + d * d) / 8;
  mass.Jd = mass.m * ((D * D + d * d) / 16 + w * w / 12);
}

void readRotorModel(Context& c) {
  readBearings(c);
  readDamping(c);
}

void requireSymmetricAtRest(const Context& c, const Field& analysis) {
  for (const DeckBearing& b : c.deck.rotor.bearings) {
    if (b.loadFromGravity)  // a plain journal: cross-coupled at every speed
      analysis.fail("bearing '" + b.name +
                    "' is a plain journal (cross-coupled): the modal analysis needs a symmetric "
                    "stiffness; use {type: rotor, speed_rpm: 0}");
    const Bearing atRest =
        b.speeds.empty() ? Bearing(0, b.table.front()) : Bearing(0, b.speeds, b.table);
    const BearingCoefficients k = atRest.coefficientsAt(0);
    if (k.kyz != k.kzy)
      analysis.fail("bearing '" + b.name +
                    "' is cross-coupled at rest (kxy != kyx): the "
                    "modal analysis needs a symmetric stiffness; use {type: rotor, speed_rpm: 0}");
  }
}

void resolveRotorQuantity(const Context& c, const Quantity& q, const Field& f,
                          const DeckAnalysis& a) {
  const RotorFamily* settings = rotorSettings(a.kind);
  if (!settings) return;
  if (q.kind == Quantity::Kind::padMode &&
      std::none_of(c.deck.rotor.bearings.begin(), c.deck.rotor.bearings.end(),
                   [](const DeckBearing& b) { return b.padInertia.has_value(); }))
    f.fail("analysis '" + a.name + "' has no pad modes: no bearing keeps its pads' tilts as "
           "dofs (pad_tilts: dofs)");
  if (q.kind == Quantity::Kind::logDecrement && q.mode > settings->modes)
    f.fail("mode " + std::to_string(q.mode) + " asked for, but analysis '" + a.name +
           "' computes " + std::to_string(settings->modes) + " modes (set its modes:)");
  if (q.kind != Quantity::Kind::unbalanceAmplitude && q.kind != Quantity::Kind::runUp) return;
  const DeckRotorAnalysis& r = settings->rotor;
  if (q.kind == Quantity::Kind::runUp && q.property == "end_speed") return;
  if (q.kind == Quantity::Kind::runUp && q.property == "film_torque") {
    if (!r.runUp.nonlinearBearings)
      f.fail("analysis '" + a.name + "' runs its bearings linear: the films' drag torque is "
             "followed with bearings: nonlinear");
    return;
  }
  if (q.kind == Quantity::Kind::runUp && q.property.starts_with("rub_")) {
    std::vector<std::string> names;
    for (const DeckRub& rub : r.runUp.rubs) names.push_back(rub.name);
    if (std::find(names.begin(), names.end(), q.target) == names.end())
      f.fail("analysis '" + a.name + "' has no rub station '" + q.target + "'" +
             didYouMean(q.target, names) +
             (names.empty() ? " (it has no rub:)" : " (rub: " + joinNames(names) + ")"));
    return;
  }
  if (q.kind == Quantity::Kind::runUp && q.property == "eccentricity") {
    if (!r.runUp.nonlinearBearings)
      f.fail("analysis '" + a.name + "' runs its bearings linear: a journal's eccentricity is "
             "followed with bearings: nonlinear");
    return;  // the bearing's name is checked when the run measures it
  }
  const auto& points = r.response;
  if (std::find(points.begin(), points.end(), q.target) == points.end())
    f.fail("analysis '" + a.name + "' reports no response at '" + q.target + "'" +
           didYouMean(q.target, points) + " (response: " + joinNames(points) + ")");
  if (q.kind == Quantity::Kind::runUp) return;
  const double w = q.rpm * kRadPerRpm;
  if (w < r.speeds.front() * (1 - 1e-12) || w > r.speeds.back() * (1 + 1e-12))
    f.fail("speed " + formatNumber(q.rpm) + " rpm lies outside analysis '" + a.name + "' (" +
           formatNumber(r.speeds.front() / kRadPerRpm) + " to " +
           formatNumber(r.speeds.back() / kRadPerRpm) + " rpm)");
}

void addCheckedSpeed(Context& c, const DeckCheck& k) {
  if (k.quantity.kind != Quantity::Kind::unbalanceAmplitude) return;
  for (DeckAnalysis& a : c.deck.analyses) {
    RotorFamily* settings = rotorSettings(a.kind);
    if (a.name != k.analysis || !settings) continue;
    std::vector<double>& speeds = settings->rotor.speeds;
    const double w = k.quantity.rpm * kRadPerRpm;
    // The same rpm -> rad/s conversion as measureRotor's, so the speed is found exactly.
    const bool present = std::any_of(speeds.begin(), speeds.end(), [&](double s) {
      return std::abs(s - w) <= 1e-12 * std::max(1.0, w);
    });
    if (!present) speeds.insert(std::upper_bound(speeds.begin(), speeds.end(), w), w);
  }
}

}  // namespace beamrotor::reader

namespace beamrotor {

void RotorSpec::read(const reader::Context& c, const Field& f) {
  reader::requireLateral(c, f, deckType);
  f.allowOnly({"type", "name", "speed_rpm", "modes", "shift"}, "a rotor analysis");
  if (auto s = f.get("speed_rpm"))
    rotor.speed = s->nonNegative(c.evaluator, kRpmField) * reader::kRadPerRpm;
  reader::readModeSearch(c, f, *this);
}

void CampbellSpec::read(const reader::Context& c, const Field& f) {
  reader::requireLateral(c, f, deckType);
  f.allowOnly({"type", "name", "modes", "shift", "from_rpm", "to_rpm", "steps", "order"},
              "a campbell analysis");
  rotor.speeds = reader::readSpeedRange(c, f);
  if (auto o = f.get("order")) reader::readOrders(*o, c.evaluator, rotor);
  reader::readModeSearch(c, f, *this);
}

void CriticalSpeedMapSpec::read(const reader::Context& c, const Field& f) {
  reader::requireLateral(c, f, deckType);
  reader::readCriticalSpeedMap(c, f, rotor);
  reader::readModeSearch(c, f, *this);
}

void LevelOneSpec::read(const reader::Context& c, const Field& f) {
  reader::requireLateral(c, f, deckType);
  f.allowOnly({"type", "name", "speed_rpm", "max_continuous_rpm", "average_gas_density",
               "station", "stages", "modes", "shift"},
              "a level1-stability analysis");
  rotor.speed = f.require("speed_rpm").positive(c.evaluator, kRpmField) * reader::kRadPerRpm;
  rotor.maximumContinuousSpeed = rotor.speed;
  if (auto m = f.get("max_continuous_rpm"))
    rotor.maximumContinuousSpeed = m->positive(c.evaluator, kRpmField) * reader::kRadPerRpm;
  if (auto d = f.get("average_gas_density"))
    rotor.averageGasDensity = d->nonNegative(c.evaluator, dim::density);
  if (auto s = f.get("station")) rotor.station = c.point(*s).name;
  rotor.stages = reader::readStages(c, f.require("stages"));
  double power = 0;
  for (const CompressorStage& s : rotor.stages) power += s.power;
  if (!(power > 0)) f.require("stages").fail("the stages' power must add up to more than 0");
  reader::readModeSearch(c, f, *this);
}

void RunUpSpec::read(const reader::Context& c, const Field& f) {
  reader::requireLateral(c, f, deckType);
  reader::readRunUp(c, f, rotor);
}

void BearingLoadsSpec::read(const reader::Context& c, const Field& f) {
  reader::requireLateral(c, f, deckType);
  reader::readBearingLoads(c, f, rotor);
  reader::readModeSearch(c, f, *this);
}

void FrequencyResponseSpec::read(const reader::Context& c, const Field& f) {
  reader::requireLateral(c, f, deckType);
  f.allowOnly({"type", "name", "speed_rpm", "input", "output", "from_hz", "to_hz", "steps"},
              "a frequency-response analysis");
  if (auto s = f.get("speed_rpm"))
    rotor.speed = s->nonNegative(c.evaluator, kRpmField) * reader::kRadPerRpm;
  reader::readResponseEnd(c, f.require("input"), rotor.inputPoint, rotor.inputDof);
  reader::readResponseEnd(c, f.require("output"), rotor.outputPoint, rotor.outputDof);
  rotor.frequencies = reader::readFrequencyRange(c, f);
}

void UnbalanceSpec::read(const reader::Context& c, const Field& f) {
  reader::requireLateral(c, f, deckType);
  f.allowOnly({"type", "name", "from_rpm", "to_rpm", "steps", "unbalance", "response", "operating"},
              "an unbalance analysis");
  rotor.speeds = reader::readSpeedRange(c, f);
  reader::readUnbalance(c, f, rotor);
  if (auto o = f.get("operating"))
    rotor.operating = reader::readOperatingRange(c, *o, rotor.minLogDecrement);
}

void RigidBodySpec::read(const reader::Context& c, const Field& f) {
  f.allowOnly({"type", "name", "bearings", "body"}, "a rigid-body analysis");
  if (auto body = f.get("body")) {
    if (auto b = f.get("bearings"))
      b->fail("give either bearings: (two spring points of the model) or body: (the rigid "
              "body's own data), not both");
    reader::readTwoDofBody(c, *body, rotor);
    return;
  }
  const Field list = f.require("bearings");
  const std::vector<Field> items = list.items();
  if (items.size() != 2) list.fail("expected the two spring points [A, B]");
  for (const Field& p : items) rotor.bearingPoints.push_back(c.point(p).name);
  if (rotor.bearingPoints[0] == rotor.bearingPoints[1])
    items[1].fail("A and B must be different points");
  if (!c.deck.dofs.contains(Dof::uy) || !c.deck.dofs.contains(Dof::rz))
    f.fail("a rigid-body analysis needs uy and rz (planar, lateral or 3d model)");
  reader::requireMass(c, f, std::string(deckType));
}

bool RigidBodySpec::modelFree(const Field& entry) {
  return entry.has("body");
}

}  // namespace beamrotor
