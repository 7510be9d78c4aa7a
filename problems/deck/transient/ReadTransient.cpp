// Deck reader, transient analyses (FORMAT.md, "Transient analysis"): the scheme and time grid,
// damping, stops, the initial state, loads as functions of time (an expression of t, pieces,
// a harmonic series or a table, optionally repeated with a period) and the histories to record.
#include <algorithm>
#include <cmath>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/FieldUnits.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor::reader {

namespace {

/// Bounds that keep a typo (dt: 1e-12) from running for days or filling the disk.
constexpr double kMaxSteps = 1e7;
constexpr double kMaxSamples = 1e6;  // recorded states: histories and energy at each
constexpr int kMaxFrames = 1000;

/// An expression of t as a function of time; a failure at run time names the field.
TimeFunction expressionOfTime(const Context& c, const Field& f) {
  try {
    const CompiledExpression e = c.evaluator.compile(f.text(), {"t"});
    const std::string where = f.path();
    return [e, where](double t) {
      try {
        return e(t);
      } catch (const ExpressionError& error) {
        throw std::runtime_error(where + ": " + error.what());
      }
    };
  } catch (const ExpressionError& e) {
    f.fail(e.what());
  }
}

TimeFunction piecesOf(const Context& c, const Field& f) {
  std::vector<TimePiece> pieces;
  for (const Field& item : f.items()) {
    item.allowOnly({"from", "value"}, "a piece");
    const Field from = item.require("from");
    const double start = from.number(c.evaluator, dim::time);
    if (!pieces.empty() && !(start > pieces.back().start))
      from.fail("pieces must start in ascending order (the previous starts at " +
                formatNumber(pieces.back().start) + ")");
    pieces.push_back({start, expressionOfTime(c, item.require("value"))});
  }
  if (pieces.empty()) f.fail("the list of pieces is empty");
  return timefn::piecewise(std::move(pieces));
}

TimeFunction harmonicsOf(const Context& c, const Field& f, const FieldUnit& unit) {
  f.allowOnly({"omega", "mean", "terms"}, "a harmonic series");
  const double omega = f.require("omega").positive(c.evaluator, dim::angularSpeed);
  const double mean = f.get("mean") ? f.get("mean")->number(c.evaluator, unit) : 0;
  std::vector<Harmonic> terms;
  const Field list = f.require("terms");
  for (const Field& t : list.items()) {
    t.allowOnly({"k", "amplitude", "phase"}, "a harmonic");
    Harmonic h;
    h.k = t.require("k").integer(c.evaluator, 0, 100000);
    h.amplitude = t.require("amplitude").number(c.evaluator, unit);
    if (auto p = t.get("phase")) h.phase = p->number(c.evaluator, dim::angle);
    terms.push_back(h);
  }
  if (terms.empty()) list.fail("a harmonic series needs at least one term");
  return timefn::harmonicSeries(omega, std::move(terms), mean);
}

TimeFunction tableOf(const Context& c, const Field& f, const FieldUnit& unit) {
  std::vector<double> times, values;
  for (const Field& row : f.items()) {
    const std::vector<Field> pair = row.isList() ? row.items() : std::vector<Field>{};
    if (pair.size() != 2) row.fail("expected a row [t, value], got " + row.describe());
    const double t = pair[0].number(c.evaluator, FieldUnit{dim::time});
    if (!times.empty() && !(t > times.back()))
      pair[0].fail("times must ascend strictly (the previous is " + formatNumber(times.back()) +
                   ")");
    times.push_back(t);
    values.push_back(pair[1].number(c.evaluator, unit));
  }
  if (times.empty()) f.fail("the table is empty");
  return timefn::tabulated(std::move(times), std::move(values));
}

/// value, pieces, harmonics or table, repeated with `period` when given; `unit` is the load's
/// (a force or a moment).
TimeFunction loadFunction(const Context& c, const Field& f, const FieldUnit& unit) {
  const std::vector<std::string> forms{"value", "pieces", "harmonics", "table"};
  std::vector<std::string> given;
  for (const std::string& k : forms)
    if (f.has(k)) given.push_back(k);
  if (given.size() != 1)
    f.fail(given.empty() ? "a load in time needs one of value (an expression of t), pieces, "
                           "harmonics or table"
                         : "give one of " + joinNames(given) + ", not several");
  const Field g = *f.get(given[0]);
  TimeFunction fn = given[0] == "value"       ? expressionOfTime(c, g)
                    : given[0] == "pieces"    ? piecesOf(c, g)
                    : given[0] == "harmonics" ? harmonicsOf(c, g, unit)
                                              : tableOf(c, g, unit);
  if (auto p = f.get("period"))
    fn = timefn::periodic(std::move(fn), p->positive(c.evaluator, dim::time));
  return fn;
}

void readLoads(const Context& c, const Field& block, DeckTransient& t) {
  for (const Field& f : block.items()) {
    f.allowOnly({"at", "dof", "value", "pieces", "harmonics", "table", "period"}, "a load in time");
    DeckTimeLoad l;
    l.place = f.place();
    l.point = c.point(f.require("at")).name;
    l.dof = c.dof(f.require("dof"));
    l.value = loadFunction(c, f, unitForDof(l.dof, dim::force, dim::moment));
    t.loads.push_back(std::move(l));
  }
}

void readInitial(const Context& c, const Field& block, DeckTransient& t) {
  for (const Field& f : block.items()) {
    f.allowOnly({"at", "dof", "u", "v"}, "an initial state");
    DeckInitialState s;
    s.place = f.place();
    s.point = c.point(f.require("at")).name;
    s.dof = c.dof(f.require("dof"));
    if (!f.has("u") && !f.has("v"))
      f.fail("an initial state needs u (displacement) or v (velocity)");
    if (auto u = f.get("u"))
      s.u = u->number(c.evaluator, unitForDof(s.dof, dim::length, dim::angle));
    if (auto v = f.get("v"))
      s.v = v->number(c.evaluator, unitForDof(s.dof, dim::velocity, dim::angularSpeed));
    for (const DeckInitialState& other : t.initial)
      if (other.point == s.point && other.dof == s.dof)
        f.fail(std::string(dofName(s.dof)) + " of point '" + s.point + "' is given twice");
    t.initial.push_back(std::move(s));
  }
}

void readHistories(const Context& c, const Field& block, DeckTransient& t) {
  TakenNames names;
  for (const Field& f : block.items()) {
    f.allowOnly({"name", "at", "dof", "value", "unit"}, "a history");
    DeckHistory h;
    h.place = f.place();
    if (f.has("value")) {
      if (f.has("at") || f.has("dof"))
        f.fail("a history is either a dof (at, dof) or a value, not both");
      h.name = f.require("name").text();
      h.expression = f.require("value").text();
      if (auto u = f.get("unit")) h.unit = u->label(32);
    } else {
      if (f.has("unit")) f.get("unit")->fail("a dof's unit is m or rad; unit is for values");
      h.point = c.point(f.require("at")).name;
      h.dof = c.dof(f.require("dof"));
      h.unit = isRotation(h.dof) ? "rad" : "m";
      h.name =
          f.has("name") ? f.require("name").text() : h.point + "_" + std::string(dofName(h.dof));
    }
    const Field at = f.has("name") ? f.require("name") : f;
    if (!ExpressionEvaluator::isIdentifier(h.name) || h.name == "t" || c.evaluator.defines(h.name))
      at.fail(
          "a history name must be a new name of letters, digits and '_' (not t or a "
          "parameter), got '" +
          h.name + "'");
    if (!h.expression.empty()) {
      std::vector<std::string> variables = names.inOrder();
      variables.push_back("t");
      try {
        c.evaluator.compile(h.expression, variables);  // parses, and names only what exists
      } catch (const ExpressionError& e) {
        f.require("value").fail(e.what());
      }
    }
    claimName(at, h.name, names, "a history");
    t.histories.push_back(std::move(h));
  }
}

}  // namespace

DeckTransient readTransient(const Context& c, const Field& f) {
  f.allowOnly({"type", "name", "scheme", "dt", "end", "cycles", "period", "alpha", "rayleigh",
               "restitution", "frames", "sample_every", "initial", "loads", "record", "periodic"},
              "a transient analysis");
  const ExpressionEvaluator& ev = c.evaluator;
  DeckTransient t;
  // 1. Scheme and time grid.
  if (auto s = f.get("scheme")) {
    const std::string name = s->choice({"newmark", "hht", "central"});
    t.scheme = name == "hht"       ? TimeScheme::hht
               : name == "central" ? TimeScheme::centralDifference
                                   : TimeScheme::newmark;
  }
  const Field dt = f.require("dt");
  t.dt = dt.positive(ev, dim::time);
  t.dtPlace = dt.place();
  auto end = f.get("end"), cycles = f.get("cycles"), period = f.get("period");
  if (end && (cycles || period)) end->fail("give either end or cycles and period, not both");
  if (end) {
    t.end = end->positive(ev, dim::time);
  } else if (cycles || period) {
    t.end = f.require("cycles").positive(ev, dim::none) *
            f.require("period").positive(ev, dim::time);
  } else {
    DeckPlace at = f.place();
    at.field = f.path() + ".end";
    throw DeckError(f.file(), at, "missing required field 'end' (or 'cycles' and 'period')");
  }
  if (!(t.end / t.dt <= kMaxSteps))
    dt.fail("end / dt asks for " + formatNumber(std::round(t.end / t.dt)) + " steps; at most " +
            formatNumber(kMaxSteps) + " (use a larger dt)");
  if (!(std::round(t.end / t.dt) >= 1))
    dt.fail("dt exceeds the end time " + formatNumber(t.end) + " s: not one step");

  // 2. Scheme options, damping and stops.
  if (auto a = f.get("alpha")) {
    if (t.scheme != TimeScheme::hht) a->fail("alpha is the HHT parameter; set scheme: hht");
    t.hhtAlpha = a->number(ev, dim::none);
    if (!(t.hhtAlpha >= -1.0 / 3 && t.hhtAlpha <= 0))
      a->fail("HHT alpha must lie in [-1/3, 0], got " + formatNumber(t.hhtAlpha));
  }
  if (auto r = f.get("rayleigh")) {
    r->allowOnly({"alpha", "beta"}, "Rayleigh damping");
    if (auto a = r->get("alpha")) t.rayleighMass = a->nonNegative(ev, dim::frequency);
    if (auto b = r->get("beta")) t.rayleighStiffness = b->nonNegative(ev, dim::time);
  }
  if (auto e = f.get("restitution")) {
    t.restitution = e->nonNegative(ev, dim::none);
    if (t.restitution > 1) e->fail("the coefficient of restitution must lie in [0, 1]");
    if (c.deck.contacts.empty()) e->fail("restitution applies to contacts, and the deck has none");
  }
  if (auto n = f.get("frames")) t.frames = n->integer(ev, 0, kMaxFrames);
  if (auto n = f.get("sample_every")) t.sampleEvery = n->integer(ev, 1, int(kMaxSteps));
  if (std::round(t.end / t.dt) / t.sampleEvery > kMaxSamples)
    dt.fail("the run would record " + formatNumber(std::round(t.end / t.dt / t.sampleEvery)) +
            " samples; at most " + formatNumber(kMaxSamples) +
            " (set sample_every, or use a larger dt)");

  // 3. Initial state (or the periodic one), loads, histories.
  if (auto p = f.get("periodic"); p && p->boolean()) {
    if (!period) p->fail("periodic: true needs the loads' period: give cycles and period");
    if (t.scheme != TimeScheme::newmark)
      p->fail("the periodic steady state is found with scheme: newmark (whose state is the "
              "displacement and velocity alone)");
    if (auto b = f.get("initial"); b && !b->isNull())
      b->fail("a periodic run starts from its periodic state; leave out initial:");
    t.periodicPeriod = period->positive(ev, dim::time);
    t.periodicPlace = p->place();
    const double steps = t.periodicPeriod / t.dt;
    if (std::abs(steps - std::round(steps)) > 1e-9 * steps)
      dt.fail("periodic: true needs a whole number of steps per period; period / dt = " +
              formatNumber(steps));
  }
  if (auto b = f.get("initial"); b && !b->isNull()) readInitial(c, *b, t);
  if (auto b = f.get("loads"); b && !b->isNull()) readLoads(c, *b, t);
  if (auto b = f.get("record"); b && !b->isNull()) readHistories(c, *b, t);
  return t;
}

void resolveHistoryQuantity(const Context& c, Quantity& q, const Field& f,
                            const DeckAnalysis& analysis, bool applicable) {
  const DeckTransient& run = analysis.as<TransientSpec>()->run;
  std::vector<std::string> names;
  bool found = false;
  for (const DeckHistory& h : run.histories) {
    found = found || h.name == q.target;
    names.push_back(h.name);
  }
  if (!found)
    f.fail("analysis '" + analysis.name + "' records no history '" + q.target + "'" +
           didYouMean(q.target, names) + " (record: " + joinNames(names) + ")");
  if (q.kind != Quantity::Kind::historyAt) return;
  try {
    const Amount time = c.evaluator.amount(q.timeText);
    if (!time.anyDimension && !time.dimension.dimensionless() && time.dimension != dim::time)
      f.fail("the time expects " + describeDimension(dim::time) + ", got " +
             describeDimension(time.dimension));
    q.time = time.si;
  } catch (const ExpressionError& e) {
    f.fail(e.what());
  }
  const double end = run.end;
  if (applicable && !(q.time >= 0 && q.time <= end * (1 + 1e-12)))
    f.fail("time " + formatNumber(q.time) + " s lies outside the run (0 to " + formatNumber(end) +
           " s)");
}

}  // namespace beamrotor::reader

namespace beamrotor {

void TransientSpec::read(const reader::Context& c, const Field& f) {
  run = reader::readTransient(c, f);
}

}  // namespace beamrotor
