// Explicit time stepping: the central-difference scheme with lumped (diagonal) mass and
// diagonal damping, in its half-step velocity ("leapfrog") form:
//   M (v_n+1/2 - v_n-1/2) / dt + C (v_n+1/2 + v_n-1/2) / 2 + K u_n = f(t_n),
//   u_n+1 = u_n + dt v_n+1/2,
// which is M (u_n+1 - 2 u_n + u_n-1) / dt^2 + C (u_n+1 - u_n-1) / (2 dt) + K u_n = f_n exactly.
// With M and C diagonal every step is one sparse product K u and a division per dof. The
// scheme is stable for dt < 2 / omega_max (undamped; centred damping does not lower it);
// see Hughes, The Finite Element Method, 2000, sec. 9.1.
#pragma once

#include "fem/transient/TransientResults.hpp"
#include "fem/transient/TransientSystem.hpp"

namespace beamrotor {

/// The diagonal of a mass matrix central difference can use (kg, kg m^2 per free dof). Throws
/// SolveError naming the dofs when M couples two dofs (consistent mass) or a dof has no mass.
Eigen::VectorXd lumpedMassDiagonal(const SparseMatrix& M, const Model& model, const DofMap& dofs);

/// dt_crit = 2 / omega_max for K x = omega^2 diag(m) x: the largest eigenvalue of
/// diag(m)^-1/2 K diag(m)^-1/2 (dense below 64 dofs, ARPACK Lanczos above), and the Gershgorin
/// bound as a rigorous check. m > 0 everywhere.
StabilityLimit criticalTimeStep(const SparseMatrix& K, const Eigen::VectorXd& m);

class CentralDifferenceStepper {
 public:
  /// dt in s. Throws SolveError for a mass or damping matrix that is not diagonal or a dof
  /// without mass.
  CentralDifferenceStepper(const TransientSystem& system, double dt);

  /// Sets up the half-step velocity v_1/2 = v_0 + dt/2 a_0 from a consistent initial state.
  void start(const TransientState& s);
  /// Advances s by one step; v and a at integer steps are the mean and the difference of the
  /// half-step velocities around them (so they lag one force evaluation behind u).
  void step(TransientState& s);

  const Eigen::VectorXd& mass() const { return m_; }

 private:
  const TransientSystem& system_;
  double dt_;
  Eigen::VectorXd m_, c_;  // diagonals of M and C
  Eigen::VectorXd vHalf_, f_, vNext_;
};

}  // namespace beamrotor
