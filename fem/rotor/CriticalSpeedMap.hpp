// Undamped critical-speed map: the rotor's forward synchronous critical speeds against an
// isotropic stiffness k put in place of every bearing of the model (kyy = kzz = k, no
// cross-coupling, no damping), with its two asymptotes: bearings as pinned supports
// (k -> infinity) and the free rotor's flexible modes (k -> 0).
//
// A critical speed is a spin speed Omega at which the undamped rotor can whirl at Omega
// itself (the whirl unbalance drives). With q = q0 e^{i Omega t} in M q'' + Omega G q' + K q = 0
// (fem/rotor/RotorSystem.hpp; G the gyroscopic matrix per unit speed):
//   K q0 = Omega^2 (M - i G) q0,
// a linear eigenproblem in Omega^2 whose pencil is Hermitian (G is real and skew). Written with
// q0 = a + i b as a real problem of twice the size,
//   [K 0; 0 K] x = Omega^2 [M G; -G M] x,      x = (a, b),
// (both matrices symmetric; each root appears twice, as (a, b) and (-b, a)), it is solved by the
// project's quadratic eigensolver as lambda^2 M2 + K2 = 0, lambda = i Omega. The roots include
// backward synchronous whirl (q0 turning against the spin), which unbalance does not excite:
// each root is kept when its shape whirls forward (or planar, when forward and backward
// coincide because the model has no gyroscopic moments). A root with Omega^2 < 0 (a disk whose
// polar inertia exceeds its diametral one, in a conical mode) has no critical speed.
// Gyroscopic moments are thus included wherever the model has them (disks' Jp, shafts' rotary
// inertia); without them the map is the non-rotating rotor's natural frequencies.
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "fem/rotor/RotorEigen.hpp"

namespace beamrotor {

struct CriticalSpeedMap {
  std::vector<double> stiffness;  ///< bearing stiffness k (N/m), as given
  /// speeds[i][j]: the (j+1)-th forward critical speed (rad/s) at stiffness[i], ascending
  std::vector<std::vector<double>> speeds;
  std::vector<double> pinned;    ///< bearings as pinned supports (rad/s), ascending
  std::vector<double> freeFree;  ///< the free rotor's flexible critical speeds (rad/s)
};

/// Where a speed-dependent bearing stiffness meets a line of the map: the rotor on such bearings
/// (read as isotropic with that stiffness) has its critical speed there.
struct MapCrossing {
  int line = 0;          ///< 0-based critical speed number
  double speed = 0;      ///< rad/s
  double stiffness = 0;  ///< N/m, the bearing's at that speed
};

/// The crossings of a bearing's stiffness k(Omega) (given at ascending speeds, rad/s, linear
/// between them) with every line of the map: the speeds where line(k(Omega)) = Omega, the map
/// read linearly in log k and log Omega between its points (so as exact as the map's
/// spacing), within the map's stiffness range and the bearing's speed range; ascending.
std::vector<MapCrossing> mapCrossings(const CriticalSpeedMap& map,
                                      const std::vector<double>& speeds,
                                      const std::vector<double>& stiffness);

/// The map at each stiffness (N/m, > 0) with `count` critical speeds per point and per
/// asymptote. The bearings are the model's Bearing elements (at least one; their own
/// coefficients are ignored). Throws std::invalid_argument without bearings, SolveError when
/// the eigensolver fails or finds fewer than `count` critical speeds.
CriticalSpeedMap solveCriticalSpeedMap(const Model& model, const std::vector<double>& stiffness,
                                       int count, EigenMethod method = EigenMethod::automatic);

}  // namespace beamrotor
