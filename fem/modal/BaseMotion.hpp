// Steady harmonic motion of the ground: every support (and every spring to the ground) moves
// along one global direction with acceleration a_g cos(w t). In the relative displacement u
// (structure minus ground), M u'' + C u' + K u = -M r a_g, r the rigid translation along the
// direction; solved by modes (each mode q_j = -Gamma_j a_g / (w_j^2 - w^2 + 2 i zeta_j w_j w),
// with modal or Rayleigh damping) or directly ((K - w^2 M + i w C) u = -M r a_g, with C the
// model's dampers plus Rayleigh alpha M + beta K). The absolute motion adds the ground's.
#pragma once

#include <complex>
#include <vector>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// Complex amplitudes per node and dof kind (as NodalField).
using ComplexNodalField =
    Eigen::Matrix<std::complex<double>, Eigen::Dynamic, kDofKinds, Eigen::RowMajor>;

enum class BaseMotionMethod { modal, direct };

struct BaseMotionOptions {
  int direction = 0;  ///< 0 x, 1 y, 2 z
  /// The ground's acceleration amplitude a_g (m/s^2); or, when `displacement` > 0, its
  /// displacement amplitude u_g (m), a_g = w^2 u_g at each frequency.
  double acceleration = 1;
  double displacement = 0;
  std::vector<double> frequenciesHz;
  BaseMotionMethod method = BaseMotionMethod::modal;
  int modes = 12;                ///< modal method: modes taken
  double modalDamping = 0;       ///< modal method: zeta of every mode (added to Rayleigh's)
  double alpha = 0, beta = 0;    ///< Rayleigh damping C = alpha M + beta K (1/s, s)
};

/// One frequency of the sweep.
struct BaseMotionPoint {
  double frequencyHz = 0;
  std::complex<double> groundAcceleration;  ///< a_g (m/s^2), phase 0
  ComplexNodalField relative;               ///< u (m, rad), relative to the ground
  /// The total force the ground exerts on the structure along the direction (N): r' M u''_abs,
  /// the inertia of the absolute motion, dampers and springs to the ground included.
  std::complex<double> baseForce;
  /// The absolute displacement amplitude of `node` along the direction: relative plus ground.
  std::complex<double> absolute(int node, int direction) const;
  /// |absolute acceleration| / |a_g| of `node` along the direction: the transmissibility.
  double transmissibility(int node, int direction) const;
};

struct BaseMotionResult {
  BaseMotionOptions options;
  std::vector<BaseMotionPoint> points;  ///< one per frequency, in the options' order
  ModalResult modal;                    ///< modal method: the modes used; empty for direct
  std::vector<double> modalDamping;     ///< modal method: each mode's zeta
  double totalMass = 0;                 ///< along the direction (kg)
};

/// Solves the sweep. Throws std::invalid_argument for a direction no mass moves along, and
/// SolveError for an undamped resonance hit exactly.
BaseMotionResult solveBaseMotion(const Model& model, const BaseMotionOptions& options);

}  // namespace beamrotor
