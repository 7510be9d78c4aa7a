#include "problems/run/RunTransient.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "fem/model/DofMap.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/transient/PeriodicSteadyState.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/Field.hpp"

namespace beamrotor {

namespace {

TransientOptions optionsOf(const DeckTransient& t, const Model& model) {
  TransientOptions o;
  o.scheme = t.scheme;
  o.timeStep = t.dt;
  o.endTime = t.end;
  o.hhtAlpha = t.hhtAlpha;
  o.rayleighMass = t.rayleighMass;
  o.rayleighStiffness = t.rayleighStiffness;
  o.restitution = t.restitution;
  o.maxFrames = t.frames;
  o.sampleEvery = t.sampleEvery;
  for (const DeckTimeLoad& l : t.loads)
    o.loads.push_back(pointTimeLoad(model, l.point, l.dof, 1.0, l.value));
  if (!t.initial.empty()) {
    o.initialDisplacement = NodalField::Zero(model.nodeCount(), kDofKinds);
    o.initialVelocity = NodalField::Zero(model.nodeCount(), kDofKinds);
    for (const DeckInitialState& s : t.initial) {
      o.initialDisplacement(model.node(s.point), dofIndex(s.dof)) = s.u;
      o.initialVelocity(model.node(s.point), dofIndex(s.dof)) = s.v;
    }
  }
  for (const DeckHistory& h : t.histories)
    if (h.expression.empty()) o.histories.push_back({model.node(h.point), h.dof});
  return o;
}

/// The explicit scheme's step must be below 2 / omega_max: refused at the deck's dt.
void requireStableStep(const Deck& deck, const DeckTransient& t, const Model& model) {
  const StabilityLimit limit = centralDifferenceLimit(model);
  if (t.dt <= limit.dtCritical) return;
  std::ostringstream msg;
  msg << "dt = " << formatNumber(t.dt) << " s exceeds the central-difference stability limit "
      << "2/omega_max = " << formatNumber(limit.dtCritical)
      << " s (omega_max = " << formatNumber(limit.omegaMax)
      << " rad/s); take dt below it or scheme: newmark";
  throw DeckError(deck.path, t.dtPlace, msg.str());
}

/// Loads, initial states and histories must sit on dofs some element carries (an initial
/// state, also a free one): bad input otherwise, reported at the entry.
void requireCarried(const Deck& deck, const DeckTransient& t, const Model& model) {
  const DofMap dofs(model);
  const auto check = [&](const std::string& point, Dof d, const DeckPlace& place, bool mustBeFree) {
    const int eq = dofs.equation(model.node(point), d);
    if (eq < 0)
      throw DeckError(deck.path, place,
                      "no element carries " + std::string(dofName(d)) + " at point '" + point +
                          "' (nothing there has stiffness or mass along it)");
    if (mustBeFree && !dofs.isFree(eq))
      throw DeckError(deck.path, place,
                      std::string(dofName(d)) + " at point '" + point +
                          "' is held by a support; an initial state there would be ignored");
  };
  for (const DeckTimeLoad& l : t.loads) check(l.point, l.dof, l.place, false);
  for (const DeckInitialState& s : t.initial) check(s.point, s.dof, s.place, true);
  for (const DeckHistory& h : t.histories)
    if (h.expression.empty()) check(h.point, h.dof, h.place, false);
}

/// A time grid that does not end at `end`: the run ends at the nearest whole step.
void noteRounding(const DeckTransient& t, TransientResult& r) {
  const double steps = t.end / t.dt;
  if (std::abs(steps - std::round(steps)) > 1e-6 * std::max(1.0, steps))
    r.warnings.push_back("end / dt = " + formatNumber(steps) + " is not a whole number: the run " +
                         "ends at t = " + formatNumber(r.steps * r.timeStep) + " s");
}

/// What the periodic start was, and when the stops spoilt it.
void notePeriodic(const PeriodicStart& p, TransientResult& r) {
  r.warnings.push_back(
      "started from the periodic steady state (the fixed point of the one-period map; largest "
      "multiplier " + formatNumber(p.largestMultiplier) + "; nearest resonance " +
      formatNumber(p.nearestHarmonic) + " x 2 pi / period, its multiplier " +
      formatNumber(p.resonanceDistance) + " from 1, Newmark's period error " +
      formatNumber(p.periodError) + " rad: amplitude error about " +
      formatNumber(p.periodError / p.resonanceDistance) + ")");
  if (!r.impacts.empty())
    r.warnings.push_back("the motion struck a stop, which the periodic steady state leaves "
                         "out: from the first impact on the run is not that state");
}

/// The parameters and derived values as constants, for the derived histories.
void defineDeckNames(const Deck& deck, ExpressionEvaluator& ev) {
  for (const auto& [name, value] : deck.parameters) ev.define(name, value);
  for (const auto& [name, value] : deck.derived) ev.define(name, value);
}

}  // namespace

TransientOutcome runTransient(const Deck& deck, const DeckTransient& t, const Model& model) {
  requireCarried(deck, t, model);
  if (t.scheme == TimeScheme::centralDifference) requireStableStep(deck, t, model);

  TransientOutcome out;
  TransientOptions options = optionsOf(t, model);
  std::optional<PeriodicStart> periodic;
  if (t.periodicPeriod > 0) {
    try {
      periodic = periodicStart(model, options, t.periodicPeriod);
    } catch (const SolveError& e) {
      // No periodic state for these inputs (resonance): bad input, at the field that asked.
      throw DeckError(deck.path, t.periodicPlace, e.what());
    }
    options.initialDisplacement = periodic->displacement;
    options.initialVelocity = periodic->velocity;
  }
  out.result = solveTransient(model, options);
  noteRounding(t, out.result);
  if (periodic) notePeriodic(*periodic, out.result);

  // Named histories in deck order: a dof's displacement, or a value of the earlier ones and t.
  ExpressionEvaluator ev;
  defineDeckNames(deck, ev);
  std::vector<std::string> names;
  std::size_t recorded = 0;
  for (const DeckHistory& h : t.histories) {
    NamedHistory named{h.name, h.unit, {}};
    if (h.expression.empty()) {
      named.values = out.result.histories.at(recorded++).displacement;
    } else {
      std::vector<std::string> variables = names;
      variables.push_back("t");
      const CompiledExpression formula = ev.compile(h.expression, variables);
      std::vector<double> values(variables.size());
      for (std::size_t i = 0; i < out.result.times.size(); ++i) {
        for (std::size_t k = 0; k < names.size(); ++k) values[k] = out.histories[k].values[i];
        values.back() = out.result.times[i];
        named.values.push_back(formula(values));
      }
    }
    names.push_back(h.name);
    out.histories.push_back(std::move(named));
  }
  return out;
}

}  // namespace beamrotor
