// The steady-state response of a model at rest to loads that vary as cos(w t + phase): the
// complex amplitudes x of (K - w^2 M + i w C) x = f on the free dofs (supports held at zero),
// assembled once and solved at any w. A torsional train excited by orders of its speed uses
// it once per order and speed.
#pragma once

#include <Eigen/Sparse>
#include <complex>
#include <string>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/RigidTies.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

using ComplexVector = Eigen::VectorXcd;

class HarmonicResponse {
 public:
  /// Assembles K, M and C of `model` (which must outlive this), with Rayleigh damping
  /// alpha M + beta K (alpha in 1/s, beta in s) added to C. Rigid ties are eliminated
  /// (fem/assembly/RigidTies.hpp): the solve reduces its load and expands its answer.
  explicit HarmonicResponse(const Model& model, double alpha = 0, double beta = 0);
  const DofMap& dofs() const { return dofs_; }
  const Model& model() const { return model_; }
  /// The free-free mass matrix (of every free dof, ties not applied).
  const SparseMatrix& mass() const { return fullMass_; }
  /// The full-length complex amplitudes (ordered as dofs(); constrained dofs 0) under the
  /// full-length complex load `f` at w (rad/s). Throws SolveError when K - w^2 M + i w C is
  /// singular at w (an undamped natural frequency at w).
  ComplexVector solve(double w, const ComplexVector& f) const;

 private:
  const Model& model_;
  DofMap dofs_;
  TieReduction ties_;
  SparseMatrix fullMass_;
  SparseMatrix K_, M_, C_;  ///< ties applied
};

}  // namespace beamrotor
