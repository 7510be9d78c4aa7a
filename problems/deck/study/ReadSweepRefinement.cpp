#include "problems/deck/study/ReadSweepRefinement.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor {

namespace {

/// The names the quantity refers to must exist in the deck (a check's reader does the same).
void requireNames(const Field& qf, const Quantity& q, const Deck& deck, const DeckAnalysis& a) {
  std::vector<std::string> names;
  const auto require = [&](const std::string& what) {
    if (std::find(names.begin(), names.end(), q.target) == names.end())
      qf.fail("no " + what + " named '" + q.target + "'" + didYouMean(q.target, names) + " (" +
              joinNames(names) + ")");
  };
  switch (q.kind) {
    case Quantity::Kind::reaction:
      return reader::requireReactionTarget(deck, q, qf);
    case Quantity::Kind::displacement:
      for (const DeckPoint& p : deck.points) names.push_back(p.name);
      return require("point");
    case Quantity::Kind::historyMax:
    case Quantity::Kind::historyMin:
    case Quantity::Kind::historyMaxAbs:
      for (const DeckHistory& h : a.as<TransientSpec>()->run.histories) names.push_back(h.name);
      return require("history");
    case Quantity::Kind::frequency:
    case Quantity::Kind::maxStress:
    case Quantity::Kind::maxShear:
    case Quantity::Kind::maxMoment:
    case Quantity::Kind::maxDisplacement:
      return;
    default:
      qf.fail("a sweep refines on a reaction, a displacement, a frequency, a largest stress, "
              "shear, moment or displacement, or a history's max, min or maxabs");
  }
}

}  // namespace

std::optional<DeckSweepRefinement> readSweepRefinement(const DeckSource& source, const Deck& deck) {
  const Field root = Field::root(*source.tree);
  const auto sweep = root.get("sweep");
  if (!sweep || sweep->isNull() || !sweep->isMap()) return std::nullopt;
  const auto f = sweep->get("refine");
  if (!f || f->isNull()) return std::nullopt;
  f->allowOnly({"quantity", "analysis", "tolerance", "runs"}, "a sweep's refinement");
  ExpressionEvaluator ev;
  for (const auto& [name, value] : deck.parameters) ev.define(name, value);
  for (const auto& [name, value] : deck.derived) ev.define(name, value);

  DeckSweepRefinement r;
  r.place = f->place();
  r.parameter = sweep->require("parameter").text();
  // 1. The analysis and the quantity it reads.
  const Field af = f->require("analysis");
  r.analysis = af.text();
  const DeckAnalysis* analysis = nullptr;
  std::vector<std::string> names;
  for (const DeckAnalysis& a : deck.analyses) {
    if (a.name == r.analysis) analysis = &a;
    names.push_back(a.name);
  }
  if (!analysis)
    af.fail("no analysis named '" + r.analysis + "'" + didYouMean(r.analysis, names) +
            " (analyses: " + joinNames(names) + ")");
  const Field qf = f->require("quantity");
  try {
    r.quantity = parseQuantity(qf.text());
  } catch (const std::invalid_argument& e) {
    qf.fail(e.what());
  }
  if (!answers(analysis->kind, r.quantity))
    qf.fail("'" + r.quantity.text + "' needs a " + defaultAnalysisType(r.quantity) +
            " analysis; '" + r.analysis + "' is " + analysis->type());
  requireNames(qf, r.quantity, deck, *analysis);

  // 2. How far and how long.
  const Field tf = f->require("tolerance");
  r.tolerance = tf.positive(ev, dim::none);
  if (!(r.tolerance < 1)) tf.fail("the tolerance is a fraction of the parameter: below 1");
  const int given = deck.sweep ? int(deck.sweep->values.size()) : 1;
  r.runs = f->require("runs").integer(ev, std::max(2, given), kMaxSweepValues);
  if (deck.sweep && deck.sweep->parameter == r.parameter &&
      !std::is_sorted(deck.sweep->values.begin(), deck.sweep->values.end()))
    f->fail("a refined sweep needs its values in ascending order");
  return r;
}

}  // namespace beamrotor
