// The torsion row's reader (TorsionKind.hpp).
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/torsion/TorsionKind.hpp"

namespace beamrotor {

namespace {
/// The eigenvalue omega^2 the modes are sought nearest (rad^2/s^2), as a modal analysis'.
constexpr FieldUnit kTorsionShift{Dimension::of(0, 0, -2, 2)};
}  // namespace

void TorsionSpec::read(const reader::Context& c, const Field& f) {
  f.allowOnly({"type", "name", "modes", "shift"}, "a torsion analysis");
  if (c.deck.frame || c.deck.segments.empty())
    f.fail(
        "a torsion analysis twists a shaft line (segments: along x); a frame's members "
        "twist in a modal analysis of its 3d model");
  if (auto m = f.get("modes")) modes = m->integer(c.evaluator, 1, kMaxModes);
  if (auto s = f.get("shift")) {
    shift = s->number(c.evaluator, kTorsionShift);
    shiftGiven = true;
  }
}

}  // namespace beamrotor
