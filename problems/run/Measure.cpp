// Measuring a check quantity (problems/deck/Quantity.hpp) in a solved analysis: static and
// modal quantities here, the rotor ones in MeasureRotor.cpp, transient histories here.
#include "problems/run/Measure.hpp"

#include <algorithm>
#include <cmath>

#include "fem/assembly/Recovery.hpp"
#include "problems/run/MeasureRotor.hpp"
#include "problems/run/TransientOutcome.hpp"

namespace beamrotor {

namespace {

/// Stations per element for the maxima: resultants vary at most quadratically along an
/// element (uniform distributed load), so 8 intervals place a station within L/16 of any
/// interior extremum, and the quadratic is flat there to (1/16)^2 relative.
constexpr int kStationsPerElement = 8;

double measureHistory(const Quantity& q, const TransientOutcome& outcome) {
  const NamedHistory& h = outcome.history(q.target);
  switch (q.kind) {
    case Quantity::Kind::historyMax:
      return h.max();
    case Quantity::Kind::historyMin:
      return h.min();
    case Quantity::Kind::historyMaxAbs:
      return h.maxAbs();
    default:
      return outcome.at(h, q.time);
  }
}

}  // namespace

double measure(const Quantity& q, const AnalysisOutcome& outcome, const Model& model) {
  if (outcome.rotor) return measureRotor(q, outcome);
  if (q.kind == Quantity::Kind::frequency) {
    if (!outcome.modal) throw std::invalid_argument("analysis '" + outcome.name + "' is not modal");
    const auto& modes = outcome.modal->modes;
    if (q.mode > int(modes.size()))
      throw std::invalid_argument("analysis '" + outcome.name + "' found only " +
                                  std::to_string(modes.size()) + " modes");
    return modes[q.mode - 1].frequencyHz;
  }
  if (q.analysisType() == "transient") {
    if (!outcome.transient)
      throw std::invalid_argument("analysis '" + outcome.name + "' is not transient");
    return measureHistory(q, *outcome.transient);
  }
  if (!outcome.statics)
    throw std::invalid_argument("analysis '" + outcome.name + "' is not static");
  const StaticResult& r = *outcome.statics;
  switch (q.kind) {
    case Quantity::Kind::reaction:
      return r.reaction(q.target, q.dof);
    case Quantity::Kind::displacement:
      return r.displacement(model.node(q.target), dofIndex(q.dof));
    default: {
      double largest = 0;
      for (const BeamStation& s : recoverBeamFields(model, r.displacement, kStationsPerElement)) {
        const double v = q.kind == Quantity::Kind::maxStress ? s.stress
                         : q.kind == Quantity::Kind::maxShear
                             ? s.shear
                             : std::hypot(s.forces.My, s.forces.Mz);
        largest = std::max(largest, v);
      }
      return largest;
    }
  }
}

}  // namespace beamrotor
