// Deck reader, part 3: what to compute and what to compare: analyses, checks and the sweep.
#include <algorithm>
#include <cmath>
#include <utility>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/FieldUnits.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/structure/SpectrumQuantity.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor::reader {

namespace {

/// The items of a list of analyses or checks, at most kMaxAnalyses of them.
std::vector<Field> boundedItems(const Field& block, const std::string& what) {
  std::vector<Field> items = block.items();
  if (items.size() > std::size_t(kMaxAnalyses))
    items[kMaxAnalyses].fail("a deck may have at most " + std::to_string(kMaxAnalyses) + " " +
                             what);
  return items;
}

void readAnalyses(Context& c) {
  auto block = c.root.get("analyses");
  if (!block || block->isNull()) {
    // No analyses listed: statics, the one every deck supports.
    DeckAnalysis statics;
    statics.kind = StaticSpec{};
    statics.name = statics.type();
    statics.place = c.root.place();
    c.deck.analyses.push_back(std::move(statics));
    return;
  }
  std::vector<std::string> names;
  for (const Field& f : boundedItems(*block, "analyses")) {
    if (!f.isMap()) f.fail("expected a map such as {type: static}, got " + f.describe());
    DeckAnalysis a;
    a.place = f.place();
    a.kind = analysisKind(f.require("type"));
    readAnalysisKind(c, f, a);
    auto n = f.get("name");
    a.name = n ? n->name() : a.type();
    if (std::find(names.begin(), names.end(), a.name) != names.end())
      (n ? *n : f)
          .fail("there is already an analysis named '" + a.name +
                "'; give each analysis its own name");
    names.push_back(a.name);
    c.deck.analyses.push_back(std::move(a));
  }
  if (c.deck.analyses.empty()) block->fail("the list of analyses is empty");
}

/// A displacement quantity's side: a side needs a beam there, and a rotation a hinge releases
/// has two values (one per side), so it must name the side.
void resolveSide(const Deck& deck, const Quantity& q, const Field& f) {
  const std::string rotation(dofName(q.dof));
  const auto point = std::find_if(deck.points.begin(), deck.points.end(),
                                  [&](const DeckPoint& p) { return p.name == q.target; });
  if (deck.frame && q.side != Quantity::Side::node)
    f.fail("in a frame, 'left' and 'right' have no meaning; release rotations per member end "
           "(members: release:) and ask for a point's own rotation");
  double length = 0;
  for (const DeckSegment& s : deck.segments) length += s.length;
  const double slack = 1e-9 * length;
  const bool left = !deck.segments.empty() && point->at > slack;
  const bool right = !deck.segments.empty() && point->at < length - slack;
  if (q.side == Quantity::Side::left && !left)
    f.fail("point '" + q.target + "' has no beam on its left" +
           (right ? " (it starts the line): ask for its rotation on the right" : ""));
  if (q.side == Quantity::Side::right && !right)
    f.fail("point '" + q.target + "' has no beam on its right" +
           (left ? " (it ends the line): ask for its rotation on the left" : ""));
  if (q.side != Quantity::Side::node || !isRotation(q.dof)) return;
  for (const DeckHinge& h : deck.hinges)
    if (h.point == q.target &&
        std::find(h.released.begin(), h.released.end(), q.dof) != h.released.end()) {
      std::string sides;
      if (left) sides = "'displacement " + q.target + " " + rotation + " left'";
      if (right)
        sides += (sides.empty() ? "'" : " or '") + std::string("displacement ") + q.target + " " +
                 rotation + " right'";
      f.fail("point '" + q.target + "' is a hinge releasing " + rotation +
             ": the beam ends there turn independently and the point has no " + rotation +
             " of its own; ask for " + sides);
    }
}

/// Fails at `f` unless `name` is one of `names` (of `what`s, e.g. "point").
void requireNamed(const Field& f, const std::string& name, const std::vector<std::string>& names,
                  const std::string& what) {
  if (std::find(names.begin(), names.end(), name) == names.end())
    f.fail("no " + what + " named '" + name + "'" + didYouMean(name, names) + " (" + what +
           "s: " + joinNames(names) + ")");
}

/// `paper:` (a source's printed figure that the reference is not) and `reason:` (why they
/// differ) come together: a differing figure without its reason would only puzzle a reader.
void readPaperFigure(const Context& c, const Field& f, DeckCheck& k) {
  const auto paper = f.get("paper");
  const auto reason = f.get("reason");
  if (paper && !reason)
    paper->fail("a paper figure the reference differs from needs its reason: add reason:");
  if (reason && !paper)
    reason->fail("reason: explains a paper: figure; give the paper's value as paper:");
  if (!paper) return;
  k.paper = paper->number(c.evaluator, referenceUnit(k.quantity));
  k.reason = reason->label(300);
}

void readChecks(Context& c) {
  auto block = c.root.get("checks");
  if (!block || block->isNull()) return;
  TakenNames names;
  for (const Field& f : boundedItems(*block, "checks")) {
    f.allowOnly({"name", "quantity", "reference", "tolerance", "when", "analysis", "case",
                 "paper", "reason"},
                "a check");
    DeckCheck k;
    k.place = f.place();
    const Field nameField = f.require("name");
    k.name = nameField.label(80);
    claimName(nameField, k.name, names, "a check");
    const Field qf = f.require("quantity");
    try {
      k.quantity = parseQuantity(qf.text());
    } catch (const std::invalid_argument& e) {
      qf.fail(e.what());
    }
    if (auto when = f.get("when")) {
      k.condition = when->text();
      k.applicable = when->number(c.evaluator, dim::none) != 0;
    }
    k.analysis = resolveQuantity(c, k.quantity, qf, f.get("analysis"), k.applicable);
    addCheckedSpeed(c, k);
    if (auto lc = f.get("case")) {
      k.loadCase = lc->text();
      bool known = false;
      for (const DeckLoadCase& x : c.deck.loadCases) known = known || x.name == k.loadCase;
      for (const DeckCombination& x : c.deck.combinations) known = known || x.name == k.loadCase;
      if (!known)
        lc->fail("no load case or combination '" + k.loadCase +
                 "' (load_cases: and combinations: define them)");
      if (!answers<StaticSpec>(k.quantity))
        lc->fail("case: names a load case, which only a static quantity reads");
    }
    k.reference = f.require("reference").number(c.evaluator, referenceUnit(k.quantity));
    const Field tol = f.require("tolerance");
    k.tolerance = tol.positive(c.evaluator, dim::none);
    readPaperFigure(c, f, k);
    c.deck.checks.push_back(std::move(k));
  }
}

/// One of the sweep's values of `parameter`, in SI. A parameter written with a unit gives its
/// values that dimension now; a bare one's dimension is known only once every field has been
/// read (BareParameters.hpp), so its value is read as written, in SI, and the field kept for
/// checkBareParameters to check against the dimension found.
double sweepValue(Context& c, const Field& f, const std::string& parameter) {
  const Dimension own = c.evaluator.dimensionOf(parameter);
  if (!own.dimensionless()) return f.number(c.evaluator, FieldUnit{own});
  c.valuesOfBare.emplace_back(parameter, f);
  return f.amount(c.evaluator).si;
}

/// The sweep's values; evaluated with the deck's parameters before the sweep changes them.
void readSweep(Context& c, const std::vector<ParameterOverride>& overrides) {
  auto f = c.root.get("sweep");
  if (!f || f->isNull()) return;
  f->allowOnly({"parameter", "values", "from", "to", "steps", "refine"}, "the sweep");
  DeckSweep s;
  s.place = f->place();
  const Field pf = f->require("parameter");
  s.parameter = pf.text();
  std::vector<std::string> names;
  for (const auto& [name, v] : c.deck.parameters) names.push_back(name);
  if (std::find(names.begin(), names.end(), s.parameter) == names.end())
    pf.fail("no parameter '" + s.parameter + "'" + didYouMean(s.parameter, names) +
            " (parameters: " + joinNames(names) + ")");
  auto values = f->get("values");
  auto from = f->get("from"), to = f->get("to"), steps = f->get("steps");
  if (values && (from || to || steps))
    values->fail("give either values or from/to/steps, not both");
  if (values) {
    const std::vector<Field> items = values->items();
    if (items.empty()) values->fail("the list of values is empty");
    if (int(items.size()) > kMaxSweepValues)
      values->fail("at most " + std::to_string(kMaxSweepValues) + " values");
    for (const Field& v : items) s.values.push_back(sweepValue(c, v, s.parameter));
  } else {
    const double a = sweepValue(c, f->require("from"), s.parameter);
    const double b = sweepValue(c, f->require("to"), s.parameter);
    const int n = f->require("steps").integer(c.evaluator, 1, kMaxSweepValues - 1);
    // steps intervals, n + 1 values; the last is `to` exactly, not a rounded sum.
    for (int i = 0; i < n; ++i) s.values.push_back(a + (b - a) * i / n);
    s.values.push_back(b);
  }
  // A parameter fixed on the command line turns the sweep into a single run.
  if (findOverride(overrides, s.parameter)) return;
  c.deck.sweep = std::move(s);
}

}  // namespace

void requireMass(const Context& c, const Field& f, const std::string& type) {
  if (!c.deck.masses.empty() || !c.deck.train.shafts.empty()) return;
  for (const DeckSegment& s : c.deck.segments)
    if (s.section->material.rho > 0) return;
  f.fail("a " + type + " analysis needs mass: give the materials a density rho or add masses");
}

void requireReactionTarget(const Deck& deck, const Quantity& q, const Field& f) {
  const std::string dof(dofName(q.dof));
  const auto actsAlong = [&](const std::string& what, const std::vector<Dof>& dofs) {
    std::vector<std::string> along;
    for (Dof d : dofs) {
      if (d == q.dof) return;
      along.emplace_back(dofName(d));
    }
    f.fail(what + " '" + q.target + "' acts along " + joinNames(along) + " only, not " + dof);
  };
  std::vector<std::string> names;
  for (const DeckSupport& s : deck.supports) {
    names.push_back(s.name);
    if (s.name != q.target) continue;
    std::vector<std::string> held;
    for (const auto& [d, v] : s.dofs) {
      if (d == q.dof) return;
      held.emplace_back(dofName(d));
    }
    f.fail("support '" + q.target + "' does not hold " + dof + " (it holds " + joinNames(held) +
           "), so its reaction there is zero by definition");
  }
  for (std::size_t i = 0; i < deck.springs.size(); ++i) {
    names.push_back(springName(deck, i));
    if (names.back() == q.target) return actsAlong("spring", {deck.springs[i].dof});
  }
  for (const DeckBearing& b : deck.rotor.bearings) {
    names.push_back(b.name);
    if (b.name == q.target) return actsAlong("bearing", {Dof::uy, Dof::uz});
  }
  for (const DeckContact& c : deck.contacts) {
    names.push_back(c.name);
    if (c.name == q.target) return actsAlong("contact", {c.dof});
  }
  f.fail("no support, spring, bearing or contact named '" + q.target + "'" +
         didYouMean(q.target, names) + " (" + joinNames(names) + ")");
}

std::string resolveQuantity(const Context& c, Quantity& q, const Field& f,
                            const std::optional<Field>& analysisField, bool applicable) {
  const Deck& deck = c.deck;
  // 1. The analysis: named, or the first of the right type.
  const DeckAnalysis* analysis = nullptr;
  if (analysisField) {
    const std::string name = analysisField->name();
    std::vector<std::string> names;
    for (const DeckAnalysis& a : deck.analyses) {
      if (a.name == name) analysis = &a;
      names.push_back(a.name);
    }
    if (!analysis)
      analysisField->fail("no analysis named '" + name + "'" + didYouMean(name, names) +
                          " (analyses: " + joinNames(names) + ")");
    if (!answers(analysis->kind, q))
      analysisField->fail("'" + q.text + "' needs a " + defaultAnalysisType(q) + " analysis; '" +
                          name + "' is " + analysis->type());
  } else {
    for (const DeckAnalysis& a : deck.analyses)
      if (!analysis && answers(a.kind, q)) analysis = &a;
    if (!analysis)
      f.fail("'" + q.text + "' needs a " + defaultAnalysisType(q) +
             " analysis; add {type: " + defaultAnalysisType(q) + "} to analyses");
  }

  // 2. The names and dofs it refers to.
  if (q.kind == Quantity::Kind::reaction) requireReactionTarget(deck, q, f);
  if (q.kind == Quantity::Kind::displacement) {
    std::vector<std::string> names;
    for (const DeckPoint& p : deck.points) names.push_back(p.name);
    requireNamed(f, q.target, names, "point");
    if (!deck.dofs.contains(q.dof))
      f.fail(std::string(dofName(q.dof)) + " is not a dof of a " + deck.dimension + " model (" +
             c.carriedNames() + ")");
    resolveSide(deck, q, f);
  }
  if (q.kind == Quantity::Kind::resultantAt) {
    std::vector<std::string> names;
    for (const DeckPoint& p : deck.points) names.push_back(p.name);
    if (deck.frame)
      for (const DeckJoint& j : deck.frame->joints) names.push_back(j.name);
    requireNamed(f, q.target, names, "point");
  }
  if (const auto* moving = analysis->as<MovingLoadSpec>(); moving && q.inner) {
    std::vector<std::string> texts;
    for (const Quantity& listed : moving->quantities) texts.push_back(listed.text);
    if (std::find(texts.begin(), texts.end(), q.inner->text) == texts.end())
      f.fail("moving-load analysis '" + analysis->name + "' gives the envelopes of " +
             joinNames(texts) + ", not of '" + q.inner->text + "': add it to its quantities:");
  }
  if (q.kind == Quantity::Kind::memberForce || q.kind == Quantity::Kind::memberDeflection) {
    if (!deck.frame)
      f.fail("member quantities need a frame (nodes: and members:); this deck is a line");
    std::vector<std::string> names;
    for (const DeckSegment& s : deck.segments) names.push_back(s.name);
    requireNamed(f, q.target, names, "member");
  }
  if (q.kind == Quantity::Kind::sectionProperty) {
    // The sections the beams use: those a run can measure.
    std::vector<std::string> names;
    for (const DeckSegment& s : deck.segments)
      if (s.section && std::find(names.begin(), names.end(), s.section->name) == names.end())
        names.push_back(s.section->name);
    requireNamed(f, q.target, names, "section");
  }
  if (q.kind == Quantity::Kind::maxDisplacement && deck.segments.empty())
    f.fail("'displacement max' needs beams; name a point: 'displacement POINT DOF'");
  if (analysis->as<TransientSpec>()) resolveHistoryQuantity(c, q, f, *analysis, applicable);
  const int modes = modesComputed(analysis->kind);
  if ((q.kind == Quantity::Kind::frequency || q.kind == Quantity::Kind::bucklingFactor ||
       q.kind == Quantity::Kind::effectiveMass) &&
      q.mode > modes)
    f.fail("mode " + std::to_string(q.mode) + " asked for, but analysis '" + analysis->name +
           "' computes " + std::to_string(modes) + " modes (set its modes:)");
  resolveRotorQuantity(c, q, f, *analysis);
  resolveCrankQuantity(q, f, *analysis);
  resolveTorsionQuantity(c, q, f, *analysis);
  requireSpectrumNames(deck, q, f);
  return analysis->name;
}

void readStudy(Context& c, const std::vector<ParameterOverride>& overrides) {
  readAnalyses(c);
  readChecks(c);
  readSweep(c, overrides);
}

}  // namespace beamrotor::reader
