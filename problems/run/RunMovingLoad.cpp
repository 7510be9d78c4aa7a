#include "problems/run/RunMovingLoad.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "elements/Beam.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/DofMap.hpp"
#include "problems/run/Measure.hpp"

namespace beamrotor {

namespace {

/// The line elements of the path in the order the train crosses them: a frame's members as
/// named (each from the end where the one before it ends), or the whole line.
std::vector<PathElement> pathElements(const MovingLoadSpec& spec, const Model& model) {
  std::vector<PathElement> path;
  if (spec.path.empty()) {
    for (std::size_t e = 0; e < model.elements().size(); ++e)
      if (asLine(model.elements()[e])) path.push_back({int(e), false});
    return path;
  }
  const auto endsOf = [&](int element) { return asLine(model.elements()[std::size_t(element)])->endNodes(); };
  int reached = -1;
  for (std::size_t m = 0; m < spec.path.size(); ++m) {
    std::vector<int> elements;
    for (const auto& [name, list] : model.members())
      if (name == spec.path[m]) elements = list;
    if (elements.empty()) throw std::invalid_argument("the model has no member '" + spec.path[m] + "'");
    const int start = endsOf(elements.front())[0], end = endsOf(elements.back())[1];
    bool reversed = false;
    if (reached >= 0) {
      reversed = end == reached;
    } else if (m + 1 < spec.path.size()) {
      // The first member runs towards the joint it shares with the second.
      for (const auto& [name, list] : model.members())
        if (name == spec.path[m + 1]) {
          const int a = endsOf(list.front())[0], b = endsOf(list.back())[1];
          reversed = start == a || start == b;
        }
    }
    if (reversed) std::reverse(elements.begin(), elements.end());
    for (int e : elements) path.push_back({e, reversed});
    reached = reversed ? start : end;
  }
  return path;
}

/// Refuses a path the influence lines are not exact on: the consistent nodal loads are the
/// Euler-Bernoulli element's Hermite cubics, with both ends' rotations in the element.
void requireExactPath(const Model& model, const std::vector<PathElement>& path) {
  for (const PathElement& p : path) {
    const auto* beam = dynamic_cast<const Beam*>(model.elements()[std::size_t(p.element)].get());
    if (!beam || beam->options().theory != BeamTheory::eulerBernoulli)
      throw std::invalid_argument(
          "a moving load's influence lines are exact on Euler-Bernoulli beams; the path holds "
          "another element (set the path's segments to formulation: euler-bernoulli)");
    if (beam->releases(0) || beam->releases(1))
      throw std::invalid_argument(
          "a moving load's path may not hold a hinge or released member end: its elements' "
          "nodal loads would not be the beam's own (move the hinge off the path)");
  }
}

/// The quantity as a function of a static solution under nodal loads, and its units.
InfluenceQuantity linearQuantity(const Quantity& q, const Model& model, MovingQuantity& out) {
  switch (q.kind) {
    case Quantity::Kind::reaction: {
      const bool moment = isRotation(q.dof);
      out.unit = moment ? "m" : "-";
      out.valueUnit = moment ? "N m" : "N";
      return {[target = q.target, dof = q.dof](const StaticResult& r) {
        return r.reaction(target, dof);
      }};
    }
    case Quantity::Kind::displacement: {
      const int node = model.node(q.target);
      if (DofMap(model).equation(node, q.dof) < 0)
        throw std::invalid_argument("point '" + q.target + "' has no " +
                                    std::string(dofName(q.dof)));
      const bool rotation = isRotation(q.dof);
      out.unit = rotation ? "rad/N" : "m/N";
      out.valueUnit = rotation ? "rad" : "m";
      return {[node, k = dofIndex(q.dof)](const StaticResult& r) { return r.displacement(node, k); }};
    }
    default: {
      const ResultantPlace place = resultantPlace(model, q.target);
      ForceComponent component = ForceComponent::Mz;
      for (ForceComponent c : kForceComponents)
        if (q.property == componentName(c)) component = c;
      const bool moment = component == ForceComponent::My || component == ForceComponent::Mz ||
                          component == ForceComponent::T;
      out.unit = moment ? "m" : "-";
      out.valueUnit = moment ? "N m" : "N";
      const LineElement* line = asLine(model.elements()[std::size_t(place.element)]);
      return {[line, place, component](const StaticResult& r) {
                return componentOf(
                    line->sectionForceSeries(elementValues(*line, r.displacement), {}).at(place.end),
                    component);
              },
              place.element, place.end, component};
    }
  }
}

}  // namespace

ResultantPlace resultantPlace(const Model& model, const std::string& point) {
  const int node = model.node(point);
  ResultantPlace ending;
  for (std::size_t e = 0; e < model.elements().size(); ++e)
    if (const LineElement* line = asLine(model.elements()[e])) {
      if (line->endNodes()[0] == node) return {int(e), 0};
      if (line->endNodes()[1] == node && ending.element < 0) ending = {int(e), 1};
    }
  if (ending.element < 0) throw std::invalid_argument("no beam meets point '" + point + "'");
  return ending;
}

MovingLoadOutcome runMovingLoad(const MovingLoadSpec& spec, const Model& model) {
  MovingLoadOutcome out;
  out.direction = spec.direction;
  out.deckLoads = spec.deckLoads;
  for (const MovingLoadSpec::Wheel& w : spec.wheels) out.train.push_back({w.force, w.offset});
  const std::vector<PathElement> path = pathElements(spec, model);
  requireExactPath(model, path);
  std::vector<InfluenceQuantity> functions;
  for (const Quantity& q : spec.quantities) {
    MovingQuantity m;
    m.text = q.text;
    functions.push_back(linearQuantity(q, model, m));
    out.quantities.push_back(std::move(m));
  }
  const Eigen::Vector3d direction(spec.direction[0], spec.direction[1], spec.direction[2]);
  // The deck's own loads on the unit loads' factorisation (span loads in the resultants).
  const PathUnitLoads units = solvePathUnitLoads(model, path, direction, {}, spec.deckLoads);
  const std::optional<StaticResult>& still = units.modelLoads;
  NodalField stillField = NodalField::Zero(model.nodeCount(), kDofKinds);
  if (still) stillField = still->displacement;
  std::vector<double> unitValues(units.solved.size());
  for (std::size_t i = 0; i < out.quantities.size(); ++i) {
    MovingQuantity& q = out.quantities[i];
    const InfluenceQuantity& f = functions[i];
    for (std::size_t c = 0; c < units.solved.size(); ++c) unitValues[c] = f.value(units.solved[c]);
    q.line = influenceLineOf(units, unitValues, f.element, f.end, f.component);
    q.envelope = trainEnvelope(q.line, out.train);
    if (still) q.deckValue = measureStatic(spec.quantities[i], *still, {model, still->displacement});
    q.envelope.max.value += q.deckValue;
    q.envelope.min.value += q.deckValue;
    q.shapeAtMax = stillField + trainDisplacement(units, out.train, q.envelope.max.lead);
    q.shapeAtMin = stillField + trainDisplacement(units, out.train, q.envelope.min.lead);
  }
  out.length = units.length();
  if (spec.fieldEnvelopes)
    out.fields = fieldEnvelopes(model, units, out.train, still ? &*still : nullptr);
  return out;
}

const MovingQuantity& MovingLoadOutcome::quantity(const std::string& text) const {
  for (const MovingQuantity& q : quantities)
    if (q.text == text) return q;
  throw std::invalid_argument("the moving-load analysis has no quantity '" + text + "'");
}

}  // namespace beamrotor
