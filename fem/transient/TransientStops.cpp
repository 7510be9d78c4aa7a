#include "fem/transient/TransientStops.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamrotor {

TransientStops::TransientStops(const TransientSystem& system, double restitution)
    : restitution_(restitution) {
  if (!(restitution >= 0 && restitution <= 1))
    throw std::invalid_argument(
        "transient analysis: the coefficient of restitution must lie in "
        "[0, 1], got " +
        std::to_string(restitution));
  const Model& model = system.model();
  const DofMap& dofs = system.dofs();
  const SparseMatrix& M = system.mass();
  for (const ContactConstraint& c : model.contacts()) {
    const NodeDof d{c.node, c.dof};
    const int eq = c.node >= 0 && c.node < model.nodeCount() ? dofs.equation(d) : -1;
    if (eq < 0 || !dofs.isFree(eq))
      throw std::invalid_argument(
          "stop '" + c.name + "' acts on " + model.describe(d) +
          (eq < 0 ? ", which no element carries" : ", which a support already holds"));
    // The impulse changes this dof's velocity alone only if M's column has nothing else.
    double diagonal = 0;
    for (SparseMatrix::InnerIterator it(M, eq); it; ++it) {
      if (it.row() == eq)
        diagonal = it.value();
      else if (it.value() != 0)
        throw std::invalid_argument(
            "stop '" + c.name + "' acts on " + model.describe(d) + ", whose mass is coupled to " +
            model.describe(dofs.dofOf(int(it.row()))) +
            "; a stop in time needs an uncoupled mass there (a point mass or lumped beam mass)");
    }
    if (!(diagonal > 0))
      throw std::invalid_argument("stop '" + c.name + "' acts on " + model.describe(d) +
                                  ", which has no mass to bounce");
    stops_.push_back({c.name, eq, c.lower, c.upper});
  }
}

void TransientStops::requireWithin(const TransientState& s) const {
  for (const Stop& stop : stops_) {
    const double u = s.u[stop.equation];
    if (u < stop.lower || u > stop.upper)
      throw std::invalid_argument("stop '" + stop.name + "': the initial value " +
                                  std::to_string(u) + " lies outside its bounds [" +
                                  std::to_string(stop.lower) + ", " + std::to_string(stop.upper) +
                                  "]");
  }
}

bool TransientStops::apply(const Eigen::VectorXd& uBefore, const Eigen::VectorXd& vBefore,
                           double dt, TransientState& s, std::vector<Impact>& log) const {
  bool changed = false;
  for (const Stop& stop : stops_) {
    const int eq = stop.equation;
    const double u = s.u[eq];
    const double bound = u > stop.upper ? stop.upper : u < stop.lower ? stop.lower : u;
    if (bound == u) continue;
    // 1. Locate the crossing in the step (uBefore is within the bounds, u is not).
    const double u0 = uBefore[eq];
    const double fraction = std::clamp((bound - u0) / (u - u0), 0.0, 1.0);
    const double approach = (1 - fraction) * vBefore[eq] + fraction * s.v[eq];
    // 2. Newton's law, then free flight off the bound for the rest of the step.
    const double rebound = -restitution_ * approach;
    const double rest = (1 - fraction) * dt;
    s.u[eq] = bound + rebound * rest;
    s.v[eq] = rebound;
    // Round-off must not leave the dof a hair outside (it would trigger again next step).
    s.u[eq] = std::clamp(s.u[eq], stop.lower, stop.upper);
    // A dof resting on its bound (approach 0 after a plastic impact) is held, not logged.
    if (approach != 0) log.push_back({s.t - rest, stop.name, approach, rebound});
    changed = true;
  }
  return changed;
}

}  // namespace beamrotor
