// Damped complex modes of a rotor at one spin speed: the quadratic eigenproblem of
//   M q'' + (C + Omega G) q' + K q = 0
// (fem/rotor/RotorEigen.hpp), each eigenvalue lambda = -zeta omega_n + i omega_d reported with its
// frequencies, damping, whirl sense and complex shape.
#pragma once

#include <complex>

#include "fem/model/Model.hpp"
#include "fem/rotor/RotorEigen.hpp"
#include "fem/rotor/RotorResults.hpp"
#include "fem/rotor/RotorSystem.hpp"

namespace beamrotor {

struct RotorOptions {
  int modes = 6;  ///< how many modes (a conjugate pair of eigenvalues counts once)
  /// sigma (1/s): the modes whose eigenvalue lies nearest it. 0 gives the lowest natural
  /// frequencies; a negative real shift for rotors with rigid-body modes; i omega to look
  /// around the frequency omega (rad/s).
  std::complex<double> shift = 0;
  ProportionalDamping damping;  ///< alpha M + beta K added to the elements' damping
  EigenMethod method = EigenMethod::automatic;
  /// With bearings' own dofs (pad tilts) the eigen-solution holds `modes` rotor modes and the
  /// pads' own beside them. false: the `modes` rotor modes nearest the shift are reported;
  /// true: every rotor mode it holds (a sweep's candidates: a pad mode counted with the
  /// rotor's then takes no place of a rotor mode). No effect without own dofs.
  bool everyRotorMode = false;
};

/// The modes at spin speed Omega (rad/s) nearest the shift. Throws SolveError when
/// P(shift) = K + shift D + shift^2 M is singular or the eigensolver fails.
RotorModesResult solveRotorModes(const Model& model, double speed,
                                 const RotorOptions& options = {});

/// Which modes a system with whirl-dependent bearings finds at their own eigenvalue
/// (WhirlIteration.hpp): every one (the default), the first `first`, or the candidates a
/// sweep's lines follow (matchByMac of `follow`'s columns, RotorCampbell.hpp). The others are
/// candidates the sweep does not report: they keep the synchronous set's eigenvalue, unflagged.
struct WhirlScope {
  const Eigen::MatrixXcd* follow = nullptr;
  int first = -1;
};

/// The same for an assembled system, reusing `solver`'s symbolic factorisation (speed
/// sweeps). options.damping is ignored: the system carries its own. With shapes = false the
/// per-node shapes are left empty (vectors are always filled).
RotorModesResult solveRotorModes(const RotorSystem& system, double speed,
                                 const RotorOptions& options, QuadraticEigenSolver& solver,
                                 bool shapes = true, WhirlScope scope = {});

}  // namespace beamrotor
