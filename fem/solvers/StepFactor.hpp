// The factor of a time step's effective matrix, applied once a step: UMFPACK's LU (SparseLU)
// for a sparse system; for a small one (at most kDenseLimit equations) a dense LU with partial
// pivoting of the row-scaled matrix, whose solve costs a few n^2 flops where UMFPACK's own
// per-call work (its timers, its workspace) costs microseconds: a one-dof body stepped 10^5
// times spent a fifth of its run there. Either way rcond() is UMFPACK's measure: min |U_ii| /
// max |U_ii| with every row scaled by the sum of its |a_ij|.
#pragma once

#include <Eigen/Dense>

#include "fem/assembly/Assembly.hpp"
#include "fem/solvers/SparseLU.hpp"
#include "fem/solvers/Tolerances.hpp"

namespace beamrotor {

class StepFactor {
 public:
  static constexpr Eigen::Index kDenseLimit = 64;

  StepFactor() = default;
  StepFactor(const StepFactor&) = delete;  // UMFPACK's factor points into A_
  StepFactor& operator=(const StepFactor&) = delete;

  /// Factorises A (square).
  void compute(const SparseMatrix& A);
  /// compute(A), counted, unless A equals the matrix last factorised entry for entry (a
  /// run-up whose matrices do not change with the speed keeps one factor); true when the
  /// factor is healthy (rcond > kSingularRcond).
  bool factorize(const SparseMatrix& A);
  /// How many factorisations factorize() did.
  int factorizations() const { return factorizations_; }
  /// True when the factorisation succeeded and rcond() > tol.
  bool healthy(double tol) const;
  double rcond() const;
  /// Entries of the factors (n^2 for the dense one).
  double factorEntries() const;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  bool dense_ = false;
  int factorizations_ = 0;
  Eigen::VectorXd rowScale_;  ///< 1 / (sum of |a_ij| of the row), dense path
  Eigen::PartialPivLU<Eigen::MatrixXd> denseLu_;
  double denseRcond_ = 0;
  SparseMatrix A_;  // the matrix last factorised (UMFPACK's solve refines with it)
  SparseLU sparseLu_;
};

}  // namespace beamrotor
