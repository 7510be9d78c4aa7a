// Reads a deck top to bottom: 1. top-level keys, 2. parameters (with overrides) and derived
// values, 3. model options, 4. materials, sections, segments and points, 5. supports, springs,
// masses, hinges and loads, 6. analyses, checks and the sweep.
#include "problems/deck/DeckReader.hpp"

#include <algorithm>
#include <optional>

#include "problems/deck/BareParameters.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/SceneFunctions.hpp"
#include "problems/deck/structure/Formulations.hpp"
#include "problems/deck/structure/MaterialPlausibility.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/structure/SectionNeeds.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/deck/parse/UnitSyntax.hpp"
#include "problems/deck/study/SweepOption.hpp"

namespace beamrotor {

namespace reader {

std::optional<int> Context::pointNamed(const std::string& name) const {
  return pointsByName.find(deck.points, name,
                           [](const DeckPoint& p) -> const std::string& { return p.name; });
}

std::optional<int> Context::segmentNamed(const std::string& name) const {
  return segmentsByName.find(deck.segments, name,
                             [](const DeckSegment& s) -> const std::string& { return s.name; });
}

std::optional<int> Context::jointNamed(const std::string& name) const {
  return jointsByName.find(deck.frame->joints, name,
                           [](const DeckJoint& j) -> const std::string& { return j.name; });
}

const DeckPoint& Context::point(const Field& f) const {
  if (f.isMap()) return memberPoint(*this, f);
  const std::string name = f.name();
  if (const auto i = pointNamed(name)) return deck.points[*i];
  std::vector<std::string> names;
  for (const DeckPoint& p : deck.points) names.push_back(p.name);
  f.fail("no point named '" + name + "'" + didYouMean(name, names) +
         " (points: " + joinNames(names) + ")");
}

int Context::segment(const Field& f) const {
  const std::string name = f.name();
  if (const auto i = segmentNamed(name)) return *i;
  std::vector<std::string> names;
  for (const DeckSegment& s : deck.segments)
    if (!s.name.empty()) names.push_back(s.name);
  const std::string what = deck.frame ? "member" : "segment";
  f.fail("no " + what + " named '" + name + "'" + didYouMean(name, names) + " (named " + what +
         "s: " + joinNames(names) + ")");
}

std::string Context::carriedNames() const {
  std::vector<std::string> names;
  for (Dof d : kAllDofs)
    if (deck.dofs.contains(d)) names.emplace_back(dofName(d));
  return joinNames(names);
}

Dof Context::dof(const Field& f) const {
  const std::string word = f.text();
  const std::optional<Dof> d = parseDof(word);
  if (!d) f.fail("'" + word + "' is not a dof (ux uy uz rx ry rz)");
  if (!deck.dofs.contains(*d))
    f.fail(word + " is not a dof of a " + deck.dimension + " model (" + carriedNames() + ")");
  return *d;
}

Dof Context::rotation(const Field& f) const {
  const Dof d = dof(f);
  if (!isRotation(d)) f.fail("expected a rotation (rx, ry or rz), got " + f.text());
  return d;
}

void claimName(const Field& f, const std::string& name, TakenNames& taken,
               const std::string& what) {
  if (!taken.claim(name)) f.fail("there is already " + what + " named '" + name + "'");
}

namespace {

const std::vector<std::string> kTopKeys{
    "title",  "parameters", "derived",  "model",    "materials", "sections", "segments",
    "points", "supports",   "springs",  "masses",   "hinges",    "loads",    "analyses",
    "checks", "sweep",      "contacts", "bearings", "damping",   "report",   "accuracy",
    "nodes",  "members",    "load_cases", "combinations", "study",    "output",
    "rigid_links", "diaphragms", "train"};

/// 2a. Parameters: named numbers in deck order, each an expression of the earlier ones, any
/// of them replaced by a command-line override.
/// Fails at `f` when the deck already has as many named values as it may.
void requireRoomForName(const Context& c, const Field& f) {
  if (c.evaluator.names().size() >= std::size_t(kMaxNamedValues))
    f.fail("a deck may have at most " + std::to_string(kMaxNamedValues) +
           " parameters and derived values together");
}

/// Makes a parameter or derived value available to later expressions, with its unit.
void define(Context& c, const Field& f, const std::string& name, const Amount& v) {
  try {
    c.evaluator.define(name, v);
  } catch (const ExpressionError& e) {
    f.fail(e.what());
  }
  if (!v.dimension.dimensionless()) c.deck.dimensions.emplace_back(name, v.dimension);
}

/// A parameter's value as written. An exact zero shows no dimension when evaluated (0 m is
/// 0 kg in every system of units), yet `a: 0 m` states one, which later expressions and values
/// rely on (`c*l*a` a moment, `--set a=0.002` a length): it is read from the same text with
/// its zeros written 1. Units that do not fit one dimension leave the zero fitting any.
Amount writtenAmount(const Context& c, const Field& f) {
  Amount v = f.amount(c.evaluator);
  if (!v.anyDimension) return v;
  try {
    const Amount units = c.evaluator.amount(zerosAsOnes(f.text()));
    if (!units.anyDimension && !units.dimension.dimensionless())
      v = Amount{v.si, units.dimension, false};
  } catch (const ExpressionError&) {
    // `0 m + 0 kg`: no one dimension; the zero keeps fitting any
  }
  return v;
}

/// A command-line override of the parameter `f`: a bare number takes the dimension of the
/// deck's own value, one with a unit must have it; one with a unit for a parameter without
/// one is used in SI and checked once the fields have told its dimension.
Amount overridden(Context& c, const Field& f, const ParameterOverride& o) {
  Dimension own;
  try {
    own = writtenAmount(c, f).dimension;
  } catch (const DeckError&) {
    // the deck's value is replaced anyway; its dimension is unknown, so the override's holds
    return Amount{o.value, o.dimension.value_or(Dimension{}), false};
  }
  if (o.dimension && own.dimensionless()) {
    c.unitOverridesOfBare.push_back(o);
    return Amount{o.value, own, false};
  }
  if (o.dimension)
    if (auto why = overrideMismatch(o.name, *o.dimension, own))
      throw DeckError(c.deck.path, {0, 0, "--set " + o.text}, *why);
  return Amount{o.value, own, false};
}

void readParameters(Context& c, const std::vector<ParameterOverride>& overrides) {
  std::vector<std::string> names;
  if (auto block = c.root.get("parameters"); block && !block->isNull()) {
    for (const auto& [name, value] : block->entries()) {
      requireRoomForName(c, value);
      const ParameterOverride* o = findOverride(overrides, name);
      const Amount v = o ? overridden(c, value, *o) : writtenAmount(c, value);
      define(c, value, name, v);
      c.deck.parameters.emplace_back(name, v.si);
      names.push_back(name);
      if (!o && v.dimension.dimensionless()) c.bareTexts.emplace_back(name, value.text());
    }
  }
  // Overrides of names the deck does not have are mistakes, never silently ignored.
  for (const ParameterOverride& o : overrides) {
    if (std::find(names.begin(), names.end(), o.name) != names.end()) continue;
    std::string why = "no parameter '" + o.name + "' in this deck" + didYouMean(o.name, names) +
                      " (parameters: " + joinNames(names) + ")";
    if (auto derived = c.root.get("derived"); derived && derived->isMap() && derived->has(o.name))
      why = "'" + o.name +
            "' is derived from the parameters, not a parameter itself; set the "
            "parameters it is computed from (parameters: " +
            joinNames(names) + ")";
    throw DeckError(c.deck.path, {0, 0, "--set " + o.text}, why);
  }
}

/// 2b. Derived values: named expressions of the parameters (and earlier derived values) that
/// the command line cannot override.
void readDerived(Context& c) {
  auto block = c.root.get("derived");
  if (!block || block->isNull()) return;
  for (const auto& [name, value] : block->entries()) {
    requireRoomForName(c, value);
    const Amount v = value.amount(c.evaluator);
    define(c, value, name, v);
    c.deck.derived.emplace_back(name, v.si);
    if (v.dimension.dimensionless()) c.bareTexts.emplace_back(name, value.text());
  }
}

BeamTheory readFormulation(const Field& f) {
  // choice() accepts only the table's names, so the lookup always finds one.
  return formulationNamed(f.choice(formulationNames())).value_or(BeamTheory::eulerBernoulli);
}

/// 3. Model options: dimension and the default beam formulation.
void readModel(Context& c) {
  auto model = c.root.get("model");
  if (!model || model->isNull()) return;
  model->allowOnly({"dimension", "formulation", "mass", "rotary_inertia"}, "model");
  if (auto f = model->get("dimension")) {
    c.deck.dimension = f->choice({"planar", "3d", "lateral"});
    c.deck.dofs = c.deck.dimension == "planar" ? DofSet::planar()
                  : c.deck.dimension == "3d"   ? DofSet::frame3d()
                                               : DofSet::lateral();
    // A spinning shaft's gyroscopic moments come from the sections' rotary inertia.
    c.deck.beam.rotaryInertia = c.deck.dimension == "lateral";
  }
  if (auto f = model->get("formulation")) c.deck.beam.theory = readFormulation(*f);
  if (auto f = model->get("mass"))
    c.deck.beam.mass =
        f->choice({"consistent", "lumped"}) == "lumped" ? MassModel::lumped : MassModel::consistent;
  if (auto f = model->get("rotary_inertia")) c.deck.beam.rotaryInertia = f->boolean();
}

}  // namespace

void checkBareParameters(Context& c, const std::vector<NumericRead>& reads) {
  std::vector<std::string> bare;
  for (const auto& [name, value] : c.deck.parameters)
    if (c.evaluator.dimensionOf(name).dimensionless()) bare.push_back(name);
  const std::map<std::string, BareUse> found =
      bareDimensions(reads, c.evaluator, bare, c.bareTexts);
  for (const auto& [name, use] : found)
    c.deck.bareDimensions.emplace_back(name, FieldUnit{use.dimension, use.bareSize});
  // Read again with the dimension found: a unit of another is refused at its field, and the
  // read is logged with its unit like any other.
  for (const auto& [name, f] : c.valuesOfBare)
    parameterValue(f, c.evaluator, name, parameterUnit(c.deck, name));
  for (const ParameterOverride& o : c.unitOverridesOfBare) {
    const auto it = found.find(o.name);
    if (it == found.end()) {
      if (auto why = overrideMismatch(o.name, *o.dimension, Dimension{}))
        throw DeckError(c.deck.path, {0, 0, "--set " + o.text}, *why);
    } else if (auto why = unitInBareUnit(o.name, *o.dimension, FieldUnit{it->second.dimension,
                                                                          it->second.bareSize})) {
      throw DeckError(c.deck.path, {0, 0, "--set " + o.text},
                      *why + " (its use at " + describeUse(it->second) + ")");
    } else if (it->second.dimension != *o.dimension) {
      throw DeckError(c.deck.path, {0, 0, "--set " + o.text},
                      o.name + " is " + describeDimension(it->second.dimension) +
                          ", as its use at " + describeUse(it->second) + " tells; got " +
                          describeDimension(*o.dimension));
    }
  }
}

BeamTheory formulationOf(const Field& f) {
  return readFormulation(f);
}

}  // namespace reader

namespace {

Deck readDeckWith(const DeckSource& source, const std::vector<ParameterOverride>& overrides,
                  ExpressionMemo* memo) {
  const ClosedFormBudget budget;  // the closed forms' work, bounded per reading
  Deck deck;
  deck.path = source.path;
  deck.stem = source.stem;
  reader::Context c{Field::root(*source.tree), deck, ExpressionEvaluator(memo), {}, {}, {}, {}, {}, {}, {}, {}};
  // A study's re-readings (with a memo) repeat its first reading: no log, no check below.
  std::optional<NumericReadLog> log;
  if (!memo) log.emplace();

  // 1. Top-level keys.
  c.root.allowOnly(reader::kTopKeys, "the deck");
  if (auto title = c.root.get("title"); title && !title->isNull()) deck.title = title->label(200);

  // 2. Numbers everything else may use.
  reader::readParameters(c, overrides);
  reader::readDerived(c);

  // 3. - 6.
  reader::readModel(c);
  reader::readMaterials(c);
  if (auto materials = c.root.get("materials"); materials && !materials->isNull())
    deck.warnings = materialWarnings(*materials, c.materials);
  reader::readSections(c);
  reader::readLine(c);
  reader::readAttachments(c);
  reader::readRotorModel(c);
  reader::readTrain(c);
  reader::readStudy(c, overrides);
  reader::readReport(c);
  reader::readAccuracy(c);
  reader::refuseTiedAnalyses(c);
  reader::readOutput(c);
  requireSectionValues(deck);
  if (log) reader::checkBareParameters(c, log->reads());
  return deck;
}

}  // namespace

Deck readDeck(const DeckSource& source, const std::vector<ParameterOverride>& overrides) {
  return readDeckWith(source, overrides, nullptr);
}

Deck readDeck(const DeckSource& source, const std::vector<ParameterOverride>& overrides,
              ExpressionMemo& memo) {
  return readDeckWith(source, overrides, &memo);
}

}  // namespace beamrotor
