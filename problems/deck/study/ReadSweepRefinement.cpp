#include "problems/deck/study/ReadSweepRefinement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/deck/study/ReadDeckContext.hpp"

namespace beamrotor {

namespace {

/// An unbalance amplitude is read at a speed its analysis computes (the speeds it lists, and
/// those the deck's checks added to them): each run of the sweep reads the deck afresh, so
/// the refinement cannot add one.
void requireComputedSpeed(const Field& qf, const Quantity& q, const Deck& deck,
                          const std::string& analysis) {
  if (q.kind != Quantity::Kind::unbalanceAmplitude) return;
  const double w = q.rpm * std::numbers::pi / 30;  // rad/s, as the checks' speeds are added
  for (const DeckAnalysis& a : deck.analyses)
    if (a.name == analysis)
      if (const RotorFamily* settings = rotorSettings(a.kind))
        for (double s : settings->rotor.speeds)
          if (std::abs(s - w) <= 1e-12 * std::max(1.0, w)) return;
  qf.fail("analysis '" + analysis + "' does not compute the response at " +
          formatNumber(q.rpm) + " rpm: add the speed to its speeds: (or a check at it)");
}

}  // namespace

std::optional<DeckSweepRefinement> readSweepRefinement(const DeckSource& source, const Deck& deck) {
  const Field root = Field::root(*source.tree);
  const auto sweep = root.get("sweep");
  if (!sweep || sweep->isNull() || !sweep->isMap()) return std::nullopt;
  const auto f = sweep->get("refine");
  if (!f || f->isNull()) return std::nullopt;
  f->allowOnly({"quantity", "analysis", "tolerance", "runs"}, "a sweep's refinement");
  // Resolved as a check's quantity is: any quantity a check or a study output may name.
  const ReadDeckContext read(source, deck);
  const ExpressionEvaluator& ev = read.c.evaluator;

  DeckSweepRefinement r;
  r.place = f->place();
  r.parameter = sweep->require("parameter").text();
  // 1. The analysis and the quantity it reads.
  const Field af = f->require("analysis");
  const Field qf = f->require("quantity");
  try {
    r.quantity = parseQuantity(qf.text());
  } catch (const std::invalid_argument& e) {
    qf.fail(e.what());
  }
  r.analysis = reader::resolveQuantity(read.c, r.quantity, qf, af, true);
  requireComputedSpeed(qf, r.quantity, deck, r.analysis);

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
