// Deck reader, `accuracy:`: the relative accuracy wanted on the checked quantities, with which
// the runner picks the cheapest adequate mesh and beam theory (problems/run/AdequateModel).
#include <variant>

#include "problems/deck/ReaderContext.hpp"

namespace beamrotor::reader {

void readAccuracy(Context& c) {
  auto f = c.root.get("accuracy");
  if (!f || f->isNull()) return;
  const double target = f->positive(c.evaluator, dim::none);
  if (target >= 1) f->fail("must be below 1 (a relative error), got " + formatNumber(target));
  if (c.deck.checks.empty())
    f->fail("needs at least one check: the accuracy is on the checked quantities");
  if (c.deck.segments.empty()) f->fail("needs beam segments: their mesh is what it chooses");
  for (const DeckAnalysis& a : c.deck.analyses)
    if (!a.as<StaticSpec>() && !a.as<ModalSpec>() && !a.as<RigidBodySpec>())
      f->fail("applies to static, modal and rigid-body analyses; '" + a.name + "' is a " +
              a.type() + " analysis");
  c.deck.accuracy = DeckAccuracy{target, f->place()};
}

}  // namespace beamrotor::reader
