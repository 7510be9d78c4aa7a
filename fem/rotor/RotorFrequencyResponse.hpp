// Frequency response between two points of a rotor at a fixed spin speed: the receptance
//   H(omega) = q_out / F_in,   (K(Omega) - omega^2 M + i omega (C(Omega) + Omega G)) q = e_in F,
// a harmonic force F e^{i omega t} on one dof and the complex amplitude of another. The
// bearings are taken at the spin speed Omega whatever the excitation frequency omega
// (coefficients depend on the speed, as the deck's tables give them).
#pragma once

#include <complex>
#include <vector>

#include "fem/model/Model.hpp"
#include "fem/rotor/RotorResults.hpp"
#include "fem/rotor/RotorSystem.hpp"

namespace beamrotor {

struct FrequencyResponseResult {
  double speed = 0;                                ///< spin speed Omega (rad/s)
  std::vector<double> frequencies;                 ///< excitation omega (rad/s)
  std::vector<std::complex<double>> receptance;    ///< m/N (or rad/N, m/(N m), ...)
  SystemSize size;
  SolveTimings time;
  int symbolicAnalyses = 0;
};

/// H at each frequency (rad/s). Throws std::invalid_argument for a constrained input or output
/// dof, SolveError when the dynamic stiffness is singular (an undamped natural frequency hit).
FrequencyResponseResult solveFrequencyResponse(const Model& model, double speed, NodeDof input,
                                               NodeDof output,
                                               const std::vector<double>& frequencies,
                                               ProportionalDamping damping = {});

}  // namespace beamrotor
