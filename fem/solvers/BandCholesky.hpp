// LAPACK's banded Cholesky factorisation (dpbtrf) of a symmetric band matrix: no symbolic
// analysis, no ordering, no index per entry. A line of beams numbered
// node by node has no fill outside its band, so this is its whole factor; on the planar
// benchmark line it replaces a sparse LDL' whose analysis alone took longer than this
// factorisation (see the closing notes of the performance issue).
#pragma once

#include <Eigen/Dense>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/SymmetricBand.hpp"

namespace beamrotor {

class BandCholesky {
 public:
  /// A = L L' by dpbtrf in a copy of A's band (A is kept by the caller for residuals). False
  /// when a pivot is not positive (A not positive definite: a mechanism, or a structure made
  /// indefinite by negative stiffnesses), and nothing can be solved then. L is then
  /// compressed in the copy, without the band's zeros (a planar line's axial dofs couple with
  /// none of its bending ones, so half its band stays zero in L): solves read half the
  /// memory, in Eigen's sparse triangular solves: 0.037 s a solve for 2.8x10^6 equations
  /// with 5 places below the diagonal, where dpbtrs's column-by-column BLAS calls took
  /// 0.064 s.
  bool factorize(const SymmetricBand& A);
  bool factorized() const { return factorized_; }
  /// A^-1 b for the last successful factorisation, in b's storage.
  Eigen::VectorXd solve(Eigen::VectorXd b) const;
  /// The same, where x holds b.
  void solveInPlace(Eigen::Ref<Eigen::VectorXd> x) const;
  /// The reciprocal condition estimate of SparseLDLT::scaledRcond for this factor: with
  /// A = L L', the pivots of an LDL' are L_jj^2, and those of the scaled matrix
  /// D^-1/2 A D^-1/2 (D = diag(A)) are L_jj^2 / A_jj; their smallest over their largest.
  /// 0 when not factorised, or when a diagonal entry of A is not positive.
  double scaledRcond() const;
  /// Entries kept in L (diagonal included).
  double factorEntries() const;

 private:
  CompressedLower L_;
  Eigen::VectorXd pivots_;    ///< L_jj^2 / A_jj
  bool factorized_ = false;
};

}  // namespace beamrotor
