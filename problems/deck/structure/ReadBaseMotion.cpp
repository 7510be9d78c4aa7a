// The reader of the base-motion row (StructureKinds.hpp): the ground's direction and amplitude,
// the frequencies, the method and the damping.
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/structure/StructureKinds.hpp"

namespace beamrotor {

void BaseMotionSpec::read(const reader::Context& c, const Field& f) {
  reader::requireSymmetricAtRest(c, f);
  f.allowOnly({"type", "name", "direction", "acceleration", "displacement", "from_hz", "to_hz",
               "steps", "method", "modes", "damping", "rayleigh"},
              "a base-motion analysis");
  const Field direction = f.require("direction");
  options.direction = int(std::string("xyz").find(direction.choice({"x", "y", "z"})[0]));
  if (!c.deck.dofs.contains(Dof(options.direction)))
    direction.fail(std::string("a ") + c.deck.dimension + " model does not move along " +
                   direction.text() + " (" + c.carriedNames() + ")");
  if (f.has("acceleration") == f.has("displacement"))
    f.fail("give the ground's motion as one of acceleration (m/s^2) or displacement (m)");
  if (auto a = f.get("acceleration")) options.acceleration = a->positive(c.evaluator, dim::acceleration);
  if (auto u = f.get("displacement")) options.displacement = u->positive(c.evaluator, dim::length);
  const double from = f.require("from_hz").positive(c.evaluator, dim::frequency);
  const Field toField = f.require("to_hz");
  const double to = toField.positive(c.evaluator, dim::frequency);
  if (!(to > from)) toField.fail("to_hz must be above from_hz (" + formatNumber(from) + " Hz)");
  const int steps = f.has("steps") ? f.require("steps").integer(c.evaluator, 1, 100000) : 200;
  options.frequenciesHz.clear();
  for (int i = 0; i <= steps; ++i) options.frequenciesHz.push_back(from + (to - from) * i / steps);
  if (auto m = f.get("method"))
    options.method =
        m->choice({"modal", "direct"}) == "direct" ? BaseMotionMethod::direct : BaseMotionMethod::modal;
  if (auto m = f.get("modes")) {
    if (options.method == BaseMotionMethod::direct)
      m->fail("the direct method solves the whole model at each frequency: modes are for "
              "method: modal");
    modes = m->integer(c.evaluator, 1, kMaxModes);
  }
  options.modes = modes;
  if (auto d = f.get("damping")) {
    if (options.method == BaseMotionMethod::direct)
      d->fail("modal damping needs method: modal; the direct method takes rayleigh: and the "
              "model's dampers");
    options.modalDamping = d->nonNegative(c.evaluator, dim::none);
    if (options.modalDamping >= 1) d->fail("damping is a ratio of critical below 1 (0.02 for 2 %)");
  }
  if (auto r = f.get("rayleigh")) {
    r->allowOnly({"alpha", "beta"}, "Rayleigh damping");
    if (auto a = r->get("alpha")) options.alpha = a->nonNegative(c.evaluator, dim::frequency);
    if (auto b = r->get("beta")) options.beta = b->nonNegative(c.evaluator, dim::time);
  }
  if (options.method == BaseMotionMethod::modal && options.modalDamping == 0 &&
      options.alpha == 0 && options.beta == 0)
    f.fail("an undamped response is infinite at every natural frequency: give damping: (a "
           "modal ratio) or rayleigh: {alpha, beta}");
}

}  // namespace beamrotor
