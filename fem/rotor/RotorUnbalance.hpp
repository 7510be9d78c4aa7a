// Synchronous unbalance response: the steady state of
//   M q'' + (C + Omega G) q' + K q = F(t)
// under rotating forces m e Omega^2 and rotating moments U_c Omega^2 at chosen nodes, solved at each speed as one sparse
// complex system (K - Omega^2 M + i Omega (C + Omega G)) Q = F, q = Re(Q e^{i Omega t}).
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "fem/rotor/RotorResults.hpp"
#include "fem/rotor/RotorSystem.hpp"

namespace beamrotor {

/// An unbalance at a node: mass times eccentricity (kg m), and a couple unbalance U_c (kg m^2).
/// The force m e Omega^2 rotates with the shaft, pointing along (cos(Omega t + phase),
/// sin(Omega t + phase)) in (y, z). The couple is that of two heavy spots m e' at x + d/2
/// (at the phase) and at x - d/2 (opposite), U_c = m e' d, as a skewed disk has: the moment
/// U_c Omega^2 (0, -sin(Omega t + phase), cos(Omega t + phase)) about (x, y, z), tilting the
/// +x side of the node towards the phase.
struct Unbalance {
  int node = -1;
  double me = 0;     ///< kg m
  double phase = 0;  ///< rad, angle of the heavy spot at t = 0, from +y towards +z
  double moment = 0;  ///< kg m^2, the couple unbalance U_c
};

/// The forces of the unbalances per unit Omega^2 as complex amplitudes on the free dofs: the
/// force at spin angle phi is Re(f e^{i phi}) Omega^2 (and, with an angular acceleration,
/// + Re(-i f e^{i phi}) Omega'). Throws std::invalid_argument as solveUnbalance.
Eigen::VectorXcd unbalanceForces(const RotorSystem& system,
                                 const std::vector<Unbalance>& unbalance);

/// Orbits of `nodes` at every speed (rad/s). One symbolic factorisation for the sweep.
/// Throws std::invalid_argument for an unbalance at a node without free uy and uz (and ry, rz
/// for a couple), and
/// SolveError when the dynamic stiffness is singular (undamped resonance hit exactly).
UnbalanceResult solveUnbalance(const Model& model, const std::vector<Unbalance>& unbalance,
                               const std::vector<double>& speeds, const std::vector<int>& nodes,
                               ProportionalDamping damping = {});

}  // namespace beamrotor
