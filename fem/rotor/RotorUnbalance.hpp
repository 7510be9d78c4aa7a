// Synchronous unbalance response: the steady state of
//   M q'' + (C + Omega G) q' + K q = F(t)
// under rotating forces m e Omega^2 at chosen nodes, solved at each speed as one sparse
// complex system (K - Omega^2 M + i Omega (C + Omega G)) Q = F, q = Re(Q e^{i Omega t}).
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "fem/rotor/RotorResults.hpp"
#include "fem/rotor/RotorSystem.hpp"

namespace beamrotor {

/// An unbalance at a node: mass times eccentricity (kg m). Its force m e Omega^2 rotates with
/// the shaft, pointing along (cos(Omega t + phase), sin(Omega t + phase)) in (y, z).
struct Unbalance {
  int node = -1;
  double me = 0;     ///< kg m
  double phase = 0;  ///< rad, angle of the heavy spot at t = 0, from +y towards +z
};

/// Orbits of `nodes` at every speed (rad/s). One symbolic factorisation for the sweep.
/// Throws std::invalid_argument for an unbalance at a node without free uy and uz, and
/// SolveError when the dynamic stiffness is singular (undamped resonance hit exactly).
UnbalanceResult solveUnbalance(const Model& model, const std::vector<Unbalance>& unbalance,
                               const std::vector<double>& speeds, const std::vector<int>& nodes,
                               ProportionalDamping damping = {});

}  // namespace beamrotor
