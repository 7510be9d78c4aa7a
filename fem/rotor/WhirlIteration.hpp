// A damped mode found with the bearing coefficients at its own frequency. Bearings whose
// coefficients depend on the frequency of the journal's motion (tilting pads, tables by whirl
// frequency; SpeedDependentElement::dependsOnWhirl) make the eigenproblem nonlinear:
//   (lambda^2 M + lambda (C(Omega, lambda) + Omega G) + K(Omega, lambda)) q = 0.
// Each mode is found by a fixed-point iteration from its eigenvalue with the synchronous set:
// the coefficients are evaluated at the mode's last eigenvalue, the quadratic problem solved
// again near it, and the mode recognised among the nearest eigenvalues by its shape (MAC),
// until the eigenvalue moves by less than the tolerance the onset of instability is refined
// to (kSpeedTolerance, relative). The fixed point is an eigenvalue of the nonlinear problem.
#pragma once

#include <complex>

#include "fem/rotor/RotorEigen.hpp"
#include "fem/rotor/RotorSystem.hpp"
#include "fem/rotor/SpeedRoot.hpp"

namespace beamrotor {

/// Iterations after which a mode that has not settled is reported as not converged.
inline constexpr int kMaxWhirlIterations = 40;

struct WhirlMode {
  std::complex<double> eigenvalue;  ///< 1/s, Im >= 0 for a mode that oscillates
  Eigen::VectorXcd vector;          ///< free dofs, unit norm
  int iterations = 0;               ///< eigen-solutions done
  bool converged = false;
  double startShape = 0;  ///< MAC of the end vector against the start's (1: the same shape)
};

/// The mode whose eigenvalue with the synchronous coefficients is `lambda` (vector `q`), found
/// with `system`'s whirl-dependent elements at its own eigenvalue, at spin speed Omega (rad/s).
/// Throws SolveError when an eigen-solution fails.
WhirlMode modeAtOwnWhirl(const RotorSystem& system, double speed, std::complex<double> lambda,
                         const Eigen::VectorXcd& q, QuadraticEigenSolver& solver,
                         EigenMethod method, double tolerance = kSpeedTolerance);

}  // namespace beamrotor
