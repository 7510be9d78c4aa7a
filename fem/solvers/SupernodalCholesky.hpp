// CHOLMOD's supernodal Cholesky factorisation, P A P' = L L', for a large symmetric matrix
// expected to be positive definite (a supported structure's stiffness). Its dense blocks run
// on BLAS: a 3D frame of 10^5 beams (5e5 equations, 3e7 factor entries) factorises in about
// 5 s where the simplicial LDL' column by column takes 80 s. It reports, not hides, a matrix
// that is not positive definite (a mechanism, negative springs): the caller then falls back to
// the LDL' factor, which names mechanisms and factorises indefinite matrices.
#pragma once

#include <cholmod.h>

#include <utility>
#include <vector>

#include "fem/assembly/Assembly.hpp"

namespace beamrotor {

class SupernodalCholesky {
 public:
  SupernodalCholesky();
  ~SupernodalCholesky();
  SupernodalCholesky(const SupernodalCholesky&) = delete;
  SupernodalCholesky& operator=(const SupernodalCholesky&) = delete;

  /// Symbolic analysis of the upper triangle of A (structurally symmetric) in `order` (row k of
  /// P A P' is row order[k] of A), then postordered.
  void analyse(const SparseMatrix& A, const std::vector<int>& order);
  /// Numeric factorisation of A (the analysed pattern); false when A is not positive definite
  /// to working precision (no factor is then kept).
  bool factorize(const SparseMatrix& A);
  /// x = A^-1 b for the last factorisation.
  void solveInto(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// The smallest and largest pivot D_jj = L_jj^2 of the symmetrically scaled matrix
  /// D^-1/2 A D^-1/2 (as SparseLDLT::scaledPivotRange); {0, 0} without a factor.
  std::pair<double, double> scaledPivotRange() const;
  /// Entries of L (the analysis' column counts, diagonal included).
  double factorEntries() const;
  bool factorised() const { return factorised_; }

 private:
  mutable cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  Eigen::VectorXd diagonal_;  ///< of the matrix last factorised
  bool factorised_ = false;
};

}  // namespace beamrotor
