// Unilateral stops in time: the model's contact constraints (one dof kept within
// [lower, upper]) honoured by an event method with Newton's law of restitution.
//
// After every step each stop's dof is compared with its bounds. A crossing is located within
// the step by linear interpolation of the dof between the two step ends (t* = t_n + dt (bound -
// u_n) / (u_n+1 - u_n)), the approach velocity v- is interpolated there the same way, and the
// rebound v+ = -e v- (Newton's impact law, 0 <= e <= 1; e = 0 a perfectly plastic impact; see
// Pfeiffer and Glocker, Multibody Dynamics with Unilateral Contacts, 1996, ch. 2). The dof then
// leaves the bound at v+ for the rest of the step (u_n+1 = bound + v+ (t_n+1 - t*)), and the
// acceleration is made consistent with the equation of motion again before the next step.
// For a body in free flight this is exact; under forces the rebound's position and velocity
// carry an O(dt) error from the last part of the step. The impulse acts on the stop's dof
// only, which is the body's true response when that dof's mass is not coupled to other dofs
// (a point mass or inertia, lumped beam mass); a stop on a consistent-mass dof is refused.
#pragma once

#include <string>
#include <vector>

#include "fem/transient/TransientResults.hpp"
#include "fem/transient/TransientSystem.hpp"

namespace beamrotor {

class TransientStops {
 public:
  /// The model's contact constraints. Throws std::invalid_argument for a restitution outside
  /// [0, 1], a stop on a dof no element carries or a support holds, or a stop dof whose mass
  /// couples to another dof or is zero.
  TransientStops(const TransientSystem& system, double restitution);

  bool empty() const { return stops_.empty(); }

  /// Throws std::invalid_argument when the initial state lies outside a stop's bounds.
  void requireWithin(const TransientState& s) const;

  /// After a step of length dt from state `before` (its u and v) to s: applies the impact law
  /// to every stop crossed, appending to `log`. Returns whether s changed (its acceleration is
  /// then stale: the caller recomputes it).
  bool apply(const Eigen::VectorXd& uBefore, const Eigen::VectorXd& vBefore, double dt,
             TransientState& s, std::vector<Impact>& log) const;

 private:
  struct Stop {
    std::string name;
    int equation = -1;  // free equation
    double lower, upper;
  };
  std::vector<Stop> stops_;
  double restitution_;
};

}  // namespace beamrotor
