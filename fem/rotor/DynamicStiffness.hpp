// The dynamic stiffness Z(w) = K - w^2 M + i w D of a rotor at one excitation frequency,
// factorised for a harmonic response (unbalance, frequency response).
#pragma once

#include <complex>
#include <string>

#include "fem/solvers/RotorFactor.hpp"

namespace beamrotor {

/// Factorises Z into factor (reusing its symbolic analysis). Throws SolveError naming
/// `analysis` when Z is singular at w (rad/s): an undamped natural frequency coincides with
/// `excitation` (e.g. "the speed").
void factorizeDynamicStiffness(RepeatedFactor<std::complex<double>>& factor,
                               ComplexSparseMatrix Z, double w, const std::string& analysis,
                               const std::string& excitation);

}  // namespace beamrotor
