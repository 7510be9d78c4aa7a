// The readers of the structure rows of the table of analysis kinds (StructureKinds.hpp):
// each fills its row's settings from its deck entry and refuses what its solver cannot do.
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/structure/StructureKinds.hpp"

namespace beamrotor {

void StaticSpec::read(const reader::Context& c, const Field& f) {
  f.allowOnly({"type", "name", "second_order", "accept_round_off"}, "a static analysis");
  if (auto a = f.get("accept_round_off")) acceptRoundOff = a->boolean();
  if (auto s = f.get("second_order")) {
    secondOrder = s->boolean();
    if (secondOrder && !c.deck.contacts.empty())
      s->fail("second-order statics does not support contacts: remove them or the option");
    if (secondOrder && !c.deck.loadCases.empty())
      s->fail("second-order results do not superpose, so load cases and combinations "
              "cannot be combined from them: give the loads of one case under `loads:`");
  }
}

void BucklingSpec::read(const reader::Context& c, const Field& f) {
  f.allowOnly({"type", "name", "modes", "reversed"}, "a buckling analysis");
  if (auto m = f.get("modes")) modes = m->integer(c.evaluator, 1, kMaxModes);
  if (auto r = f.get("reversed")) reversed = r->boolean();
  if (!c.deck.contacts.empty())
    f.fail("a buckling analysis needs a linear reference state: remove the contacts");
}

namespace {
/// A modal analysis' shift: the eigenvalue omega^2 the modes are sought nearest (rad^2/s^2).
constexpr FieldUnit kEigenvalueShift{Dimension::of(0, 0, -2, 2)};
}  // namespace

void ModalSpec::read(const reader::Context& c, const Field& f) {
  reader::requireSymmetricAtRest(c, f);
  f.allowOnly({"type", "name", "modes", "shift", "prestressed"}, "a modal analysis");
  if (auto m = f.get("modes")) modes = m->integer(c.evaluator, 1, kMaxModes);
  if (auto p = f.get("prestressed")) {
    prestressed = p->boolean();
    if (prestressed && !c.deck.contacts.empty())
      p->fail("prestressed modes need a linear loaded state: remove the contacts");
  }
  if (auto s = f.get("shift")) shift = s->number(c.evaluator, kEigenvalueShift);
}

}  // namespace beamrotor
