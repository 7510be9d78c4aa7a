// The periodic steady state of a linear model under loads of period T, found directly rather
// than by waiting for a transient to die out (which an undamped model never does): the state
// x = (u, v) of the free dofs from which one period of the time integration returns to x.
//
// One period of Newmark's average acceleration rule maps a start state x0 to
//   x(T) = Phi x0 + x_f,
// Phi (the monodromy matrix) the period map of the unloaded model and x_f the state after T
// from rest under the loads; column j of Phi is the state after T from a unit displacement or
// velocity of one free dof, less x_f. The periodic start is the fixed point (I - Phi) x0 = x_f ("shooting";
// e.g. Nayfeh & Balachandran, Applied Nonlinear Dynamics, 1995, section 7.3). The scheme's
// state is (u, v) alone, its acceleration following from the equation of motion, so a run
// started from x0 repeats itself every period to round-off.
//
// I - Phi is singular when a free vibration completes a whole number of cycles in T (an
// undamped model with a natural frequency k = n 2 pi / T: resonance), and then no periodic
// state exists; periodicStart refuses instead of returning an enormous one.
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "fem/transient/Transient.hpp"

namespace beamrotor {

struct PeriodicStart {
  NodalField displacement, velocity;  ///< per node (m, rad; m/s, rad/s), as TransientOptions'
  /// Reciprocal condition number of I - Phi (1-norm estimate of the LU) with velocities
  /// scaled by T / (2 pi): for an undamped mode near resonance about its angle |k T - n 2 pi|
  /// (rad), how far from resonance the period is. Newmark's own period error shifts that
  /// angle by k T (k dt)^2 / 12, so an undamped result with rcond within a few times that is
  /// not to be trusted (the warning of a run reports rcond).
  double rcond = 0;
  /// The eigenvalues' largest modulus of Phi (Floquet multipliers; 1 for an undamped model,
  /// below 1 with damping).
  double largestMultiplier = 0;
};

/// Below this rcond of I - Phi the fixed point is refused: its round-off eps / rcond would
/// exceed sqrt(eps), half the digits.
inline constexpr double kPeriodicMinRcond = 1.5e-8;

/// The periodic start of `options` (scheme newmark; its loads, model loads and support motions
/// of period `period` s; its time step dividing the period into whole steps) for the model
/// without its stops. Runs 2 n + 1 periods of solveTransient, n the free dofs: meant for small
/// models. Throws std::invalid_argument for another scheme or a step that does not divide the
/// period, and SolveError naming the resonance when I - Phi is singular (rcond below
/// kPeriodicMinRcond).
PeriodicStart periodicStart(const Model& model, const TransientOptions& options, double period);

}  // namespace beamrotor
