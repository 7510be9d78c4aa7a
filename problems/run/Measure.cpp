// Measuring a check quantity (problems/deck/Quantity.hpp) in a solved analysis: static and
// modal quantities here, the rotor ones in MeasureRotor.cpp, transient histories here.
#include "problems/run/Measure.hpp"

#include <algorithm>
#include <cmath>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/MemberExtrema.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/DofMap.hpp"
#include "problems/deck/AnalysisKinds.hpp"
#include "problems/run/MeasureRotor.hpp"
#include "problems/run/MeasureSection.hpp"
#include "problems/run/MeasureSpectrum.hpp"
#include "problems/run/RunCrankSlider.hpp"
#include "problems/run/RunMovingLoad.hpp"
#include "problems/run/TransientOutcome.hpp"

namespace beamrotor {

namespace {

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

/// A point's displacement, or the rotation of the beam end on one side of it. A dof the node
/// does not carry (a rotation every beam end there releases, a translation of a body that has
/// no mass along it) is an error, never a zero.
double measureDisplacement(const Quantity& q, const StaticResult& r,
                           const LoadedSolution& solution) {
  const Model& model = *solution.model;
  const int node = model.node(q.target);
  const std::string what = "point '" + q.target + "' ";
  const int k = dofIndex(q.dof);
  if (q.side != Quantity::Side::node) {
    const SideRotations sides = rotationsBeside(solution, node);
    const bool left = q.side == Quantity::Side::left;
    const auto& rotation = left ? sides.left : sides.right;
    if (!rotation)
      throw std::invalid_argument(what + "has no beam on its " + (left ? "left" : "right"));
    return (*rotation)[k - 3];
  }
  if (DofMap(model).equation(node, q.dof) < 0)
    throw std::invalid_argument(
        what + "has no " + std::string(dofName(q.dof)) +
        (isRotation(q.dof) && std::any_of(r.hinges.begin(), r.hinges.end(),
                                          [&](const SideRotations& h) { return h.node == node; })
             ? ": a hinge releases it on every side (name a side: "
               "left or right)"
             : ": nothing there carries it"));
  return r.displacement(node, k);
}

/// A member quantity: an extreme of one resultant, or the deflection from the chord.
double measureMember(const Quantity& q, const LoadedSolution& solution) {
  for (const auto& [name, elements] : solution.model->members()) {
    if (name != q.target) continue;
    if (q.kind == Quantity::Kind::memberDeflection)
      return largestChordDeflection(solution, elements).value;
    const auto ranges = memberForceRanges(solution, elements);
    for (std::size_t c = 0; c < kForceComponents.size(); ++c) {
      if (q.property != componentName(kForceComponents[c])) continue;
      const ComponentRange& range = ranges[c];
      if (q.extreme == "max") return range.max.value;
      if (q.extreme == "min") return range.min.value;
      return std::max(std::abs(range.max.value), std::abs(range.min.value));
    }
  }
  throw std::invalid_argument("'" + q.text + "': the model has no member '" + q.target + "'");
}

}  // namespace

double measure(const Quantity& q, const AnalysisOutcome& outcome, const RunResult& run) {
  if (q.kind == Quantity::Kind::sectionProperty)
    return measureSection(q, *run.model, run.catalogSections);
  return measure(q, outcome, *run.model);
}

double measure(const Quantity& q, const AnalysisOutcome& outcome, const Model& model) {
  if (q.kind == Quantity::Kind::sectionProperty) return measureSection(q, model, {});
  if (isRotorResult(outcome)) return measureRotor(q, outcome);
  if (const auto* crank = resultOf<CrankSliderOutcome>(outcome)) return measureCrank(q, *crank);
  if (const auto* torsion = resultOf<TorsionOutcome>(outcome);
      torsion && q.kind == Quantity::Kind::torsion)
    return measureTorsion(q.property, q.target, *torsion);
  if (q.inner) {
    const auto* moving = resultOf<MovingLoadOutcome>(outcome);
    if (!moving)
      throw std::invalid_argument("analysis '" + outcome.name + "' is not a moving-load analysis");
    const TrainEnvelope& e = moving->quantity(q.inner->text).envelope;
    return q.kind == Quantity::Kind::movingMax ? e.max.value : e.min.value;
  }
  if (q.kind == Quantity::Kind::baseMotion) {
    const auto* motion = resultOf<BaseMotionResult>(outcome);
    if (!motion) throw std::invalid_argument("analysis '" + outcome.name + "' is not a base-motion one");
    return measureBaseMotion(q, *motion, model);
  }
  if (q.kind == Quantity::Kind::spectrum || q.kind == Quantity::Kind::effectiveMass) {
    const auto* spectrum = resultOf<ResponseSpectrumResult>(outcome);
    if (!spectrum)
      throw std::invalid_argument("analysis '" + outcome.name + "' is not a response-spectrum one");
    return measureSpectrum(q, *spectrum, model);
  }
  if (q.kind == Quantity::Kind::frequency) {
    const ModalResult* modal = modesOf(outcome, model).modes;
    if (!modal) throw std::invalid_argument("analysis '" + outcome.name + "' is not modal");
    const auto& modes = modal->modes;
    if (q.mode > int(modes.size()))
      throw std::invalid_argument("analysis '" + outcome.name + "' found only " +
                                  std::to_string(modes.size()) + " modes");
    return modes[q.mode - 1].frequencyHz;
  }
  if (q.kind == Quantity::Kind::bucklingFactor) {
    const auto* buckling = resultOf<BucklingResult>(outcome);
    if (!buckling)
      throw std::invalid_argument("analysis '" + outcome.name + "' is not a buckling analysis");
    const auto& modes = buckling->modes;
    if (q.mode > int(modes.size()))
      throw std::invalid_argument("analysis '" + outcome.name + "' found only " +
                                  std::to_string(modes.size()) + " positive load factors");
    return modes[q.mode - 1].factor;
  }
  if (answers<TransientSpec>(q)) {
    const auto* transient = resultOf<TransientOutcome>(outcome);
    if (!transient) throw std::invalid_argument("analysis '" + outcome.name + "' is not transient");
    return measureHistory(q, *transient);
  }
  const StaticResult* statics = staticsOf(outcome);
  if (!statics) throw std::invalid_argument("analysis '" + outcome.name + "' is not static");
  return measureStatic(q, *statics, {model, statics->displacement});
}

double measureStatic(const Quantity& q, const StaticResult& r, const LoadedSolution& solution) {
  switch (q.kind) {
    case Quantity::Kind::reaction:
      return r.reaction(q.target, q.dof);
    case Quantity::Kind::displacement:
      return measureDisplacement(q, r, solution);
    case Quantity::Kind::maxDisplacement:
      return largestDisplacement(solution).value;
    case Quantity::Kind::memberForce:
    case Quantity::Kind::memberDeflection:
      return measureMember(q, solution);
    case Quantity::Kind::resultantAt: {
      const ResultantPlace place = resultantPlace(*solution.model, q.target);
      for (ForceComponent c : kForceComponents)
        if (q.property == componentName(c))
          return componentOf(solution.forceSeries(place.element).at(place.end), c);
      throw std::invalid_argument("'" + q.property + "' is not a resultant");
    }
    default: {
      // The exact element peaks (the same numbers results.json and the summary report); a
      // value that is not finite anywhere makes the quantity NaN, and its check fail.
      const auto kind = q.kind == Quantity::Kind::maxStress  ? &ElementPeaks::stress
                        : q.kind == Quantity::Kind::maxShear ? &ElementPeaks::shear
                                                             : &ElementPeaks::moment;
      const auto top = largestPeak(elementPeaks(solution), kind);
      if (!top) throw std::invalid_argument("'" + q.text + "': the model has no beams");
      return top->value;
    }
  }
}

}  // namespace beamrotor
