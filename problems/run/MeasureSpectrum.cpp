#include "problems/run/MeasureSpectrum.hpp"

#include <algorithm>
#include <stdexcept>

#include "fem/assembly/MemberExtrema.hpp"
#include "fem/model/DofMap.hpp"

namespace beamrotor {

namespace {

double peakReaction(const Quantity& q, const PeakResponse& p) {
  bool found = false;
  double value = 0;
  for (const auto* list : {&p.reactions, &p.elementForces}) {
    for (const ReactionComponent& c : *list)
      if (c.support == q.target) {
        found = true;
        if (c.dof == q.dof) value = std::max(value, c.value);
      }
    if (found) return value;
  }
  throw std::invalid_argument("'" + q.text + "': no support or spring named '" + q.target + "'");
}

double peakAlongMember(const Quantity& q, const PeakResponse& p, const Model& model) {
  for (const auto& [name, elements] : model.members()) {
    if (name != q.target) continue;
    ForceComponent component{};
    for (ForceComponent c : kForceComponents)
      if (q.extreme == componentName(c)) component = c;
    double peak = 0;
    for (const BeamStation& s : p.stations)
      if (std::find(elements.begin(), elements.end(), s.element) != elements.end())
        peak = std::max(peak, componentOf(s.forces, component));
    return peak;
  }
  throw std::invalid_argument("'" + q.text + "': the model has no member '" + q.target + "'");
}

}  // namespace

double measureSpectrum(const Quantity& q, const ResponseSpectrumResult& r, const Model& model) {
  const int d = dofIndex(q.dof);
  if (q.kind == Quantity::Kind::effectiveMass) {
    if (q.mode == 0) return r.capturedFraction()[d];
    if (q.mode > int(r.modal.modes.size()))
      throw std::invalid_argument("'" + q.text + "': the analysis found only " +
                                  std::to_string(r.modal.modes.size()) + " modes");
    return r.modal.modes[q.mode - 1].effectiveMass[d];
  }
  const PeakResponse& p = r.combined;
  if (q.property == "displacement") {
    const int node = model.node(q.target);
    if (DofMap(model).equation(node, q.dof) < 0)
      throw std::invalid_argument("point '" + q.target + "' has no " + std::string(dofName(q.dof)));
    return p.displacement(node, d);
  }
  if (q.property == "reaction") return peakReaction(q, p);
  if (q.property == "base_shear") return p.baseForce[d];
  return peakAlongMember(q, p, model);
}

double measureBaseMotion(const Quantity& q, const BaseMotionResult& r, const Model& model) {
  const int d = r.options.direction;
  double best = 0, at = 0;
  if (q.property == "base_force") {
    for (const BaseMotionPoint& p : r.points) best = std::max(best, std::abs(p.baseForce));
    return best;
  }
  const int node = model.node(q.target);
  for (const BaseMotionPoint& p : r.points) {
    const double v = q.property == "relative" ? std::abs(p.relative(node, d))
                     : q.property == "absolute" ? std::abs(p.absolute(node, d))
                                                : p.transmissibility(node, d);
    if (v > best) {
      best = v;
      at = p.frequencyHz;
    }
  }
  return q.property == "peak_frequency" ? at : best;
}

}  // namespace beamrotor
