// Undamped critical-speed map: the rotor's critical speeds (gyroscopic moments neglected)
// against an isotropic stiffness k put in place of every bearing of the model (kyy = kzz = k,
// no cross-coupling, no damping), with its two asymptotes: bearings as pinned supports
// (k -> infinity) and the free rotor's flexible modes (k -> 0). A bearing on a pedestal
// (elements/BearingOnPedestal.hpp) puts k in series with the pedestal: journal - k - housing
// (its mass and springs) - ground; its k -> infinity ties the journal to the housing (the rotor
// on its pedestals), and k -> 0 leaves the housing out of the free rotor. The pedestal's
// springs must then be isotropic (the x-y plane stands for both).
//
// A critical speed is a spin speed Omega at which the undamped rotor can whirl at Omega
// itself (the whirl unbalance drives). This map neglects gyroscopic moments: its critical
// speeds are the lateral natural frequencies of the non-rotating rotor (rotary inertia of
// shaft and disks included, as diametral inertia). With isotropic bearings and no
// cross-coupling the x-y plane (uy, rz) is then uncoupled from the x-z plane, which has the
// same frequencies, so the map solves the real symmetric problem of the x-y plane alone,
//   K_y(k) q = Omega^2 M_y q,
// by the project's shift-invert Lanczos with Sturm checks (fem/solvers/SymmetricEigen.hpp).
// Rotors whose disks' polar inertia matters belong in a Campbell diagram instead.
#pragma once

#include <vector>

#include "fem/model/Model.hpp"

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
/// asymptote. The bearings are the model's Bearing and BearingOnPedestal elements (at least
/// one; their own coefficients are ignored). Throws std::invalid_argument without bearings, SolveError when
/// the eigensolver fails or finds fewer than `count` critical speeds.
CriticalSpeedMap solveCriticalSpeedMap(const Model& model, const std::vector<double>& stiffness,
                                       int count);

/// The first critical speed on rigid supports (rad/s; gyroscopic moments neglected, as in the
/// map): every Bearing element with a direct stiffness at spin speed `speed` (rad/s) replaced
/// by a pinned support, bearings without stiffness (dampers) left out, the model's own
/// supports kept; a bearing on a pedestal pins its journal likewise, and its housing leaves
/// the model with the pedestal's mass and springs. API 617's critical speed ratio divides the
/// maximum continuous speed by it. Throws std::invalid_argument when no support holds the rotor, SolveError when the
/// eigensolver fails.
double rigidSupportCriticalSpeed(const Model& model, double speed);

}  // namespace beamrotor
