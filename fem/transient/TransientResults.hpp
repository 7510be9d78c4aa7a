// Results of a transient (time-domain) analysis as plain values: time histories at chosen dofs,
// the energy account, a bounded number of full-field frames, and the explicit stability limit.
#pragma once

#include <string>
#include <vector>

#include "fem/model/Dof.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// The motion of one dof at the sample times of TransientResult::times.
/// m, m/s, m/s^2 for translations; rad, rad/s, rad/s^2 for rotations; global frame.
struct DofHistory {
  NodeDof dof;
  std::vector<double> displacement, velocity, acceleration;
};

/// Energy account at the sample times (J). With E0 the initial kinetic + strain energy,
/// kinetic + strain + damping - external = E0 holds to round-off for Newmark's average
/// acceleration rule (the increments below are exact for it); for HHT the shortfall is the
/// energy the scheme dissipates numerically; for central difference it is an O(dt^2) error.
struct EnergyHistory {
  std::vector<double> kinetic;  ///< 1/2 v^T M v over the free dofs
  std::vector<double> strain;   ///< 1/2 u^T K u over the free dofs
  /// Work done against the dampers so far: sum over steps of du^T C (v_n + v_n+1) / 2.
  std::vector<double> damping;
  /// Work of the loads so far: sum of du^T (f_n + f_n+1) / 2; f includes what prescribed
  /// support motion pushes onto the free dofs.
  std::vector<double> external;

  /// kinetic + strain + damping - external at sample i (constant for an exact balance).
  double balance(std::size_t i) const { return kinetic[i] + strain[i] + damping[i] - external[i]; }
};

/// A stored full-field snapshot (displacements, m and rad, global frame, per node).
struct Frame {
  double time = 0;  ///< s
  NodalField displacement;
};

/// Stability limit of the central-difference scheme, dt_crit = 2 / omega_max (undamped).
struct StabilityLimit {
  /// Largest natural frequency (rad/s) of K x = omega^2 M x with the lumped mass: dense
  /// eigenvalues for small models, ARPACK Lanczos (largest algebraic eigenvalue of
  /// M^-1/2 K M^-1/2) otherwise.
  double omegaMax = 0;
  double dtCritical = 0;  ///< 2 / omegaMax (s)
  /// Gershgorin bound max_i sum_j |K_ij| / sqrt(m_i m_j) >= omegaMax^2, as a frequency
  /// (rad/s): rigorous, cheap, usually a little pessimistic.
  double omegaMaxBound = 0;
  double dtCriticalSafe = 0;  ///< 2 / omegaMaxBound (s): any step below it is certainly stable
  std::string method;         ///< "dense" or "arpack-lanczos"
};

/// One impact on a stop (a contact constraint honoured in time, see TransientStops).
struct Impact {
  double time = 0;  ///< s, located within its step
  std::string stop;
  double velocityBefore = 0, velocityAfter = 0;  ///< m/s or rad/s, of the stop's dof
};

struct TransientResult {
  std::string scheme;   ///< "newmark", "hht" or "central-difference"
  double timeStep = 0;  ///< s
  int steps = 0;
  std::vector<double> times;          ///< sample times (s), the initial state included
  std::vector<DofHistory> histories;  ///< one per requested dof, in request order
  EnergyHistory energy;               ///< at the sample times (empty when not requested)
  std::vector<Frame> frames;          ///< evenly spaced in time, at most maxFrames
  /// Central difference only: the limit the step was checked against (zeros otherwise).
  StabilityLimit stability;
  /// Factorisations of the effective matrix (implicit schemes): 1 for a constant step.
  int factorizations = 0;
  std::vector<Impact> impacts;        ///< in time order
  std::vector<std::string> warnings;  ///< e.g. a step above the explicit stability limit
  SystemSize size;
  SolveTimings time;  ///< factor: factorisations; solve: the time loop
};

}  // namespace beamrotor
