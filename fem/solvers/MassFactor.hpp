// A factor M = G G' of the mass matrix, for Lanczos in standard form. Shift-invert Lanczos on
// K x = lambda M x works with the operator (K - sigma M)^-1 M in the M inner product, which
// costs about three products with M a step (ARPACK's mode 3). With G, the same eigenvalues
// are those of the symmetric G' (K - sigma M)^-1 G in the plain inner product (ARPACK's mode
// 1), with eigenvectors G' x (Ericsson and Ruhe, Math. Comp. 35 (1980) 1251): a step then
// costs a product with G and one with G', each reading a triangle. That is cheaper only when
// the triangle holds little fill, as a line's banded M factorises in its own order.
#pragma once

#include <memory>

#include "fem/solvers/LinearSolver.hpp"

namespace beamrotor {

/// G = L D^1/2 from CHOLMOD's M = L D L', in M's own order.
class MassFactor {
 public:
  /// The factor of M when Lanczos in standard form suits it: M positive definite and well
  /// conditioned on the scaled system (the eigenvectors come back through G'^-1), and its
  /// factor in its own order holding no more entries than M (little fill); null otherwise (a
  /// lumped M with massless rotations, a 3D frame's fill, a numbering without a band).
  static std::unique_ptr<MassFactor> ofMass(const SparseMatrix& M);

  /// y = G x.
  void multiply(Eigen::Ref<const Eigen::VectorXd> x, Eigen::Ref<Eigen::VectorXd> y) const;
  /// y = G' x.
  void multiplyTransposed(Eigen::Ref<const Eigen::VectorXd> x, Eigen::Ref<Eigen::VectorXd> y) const;
  /// x <- G'^-1 x: an eigenvector of the pencil from one of G' (K - sigma M)^-1 G.
  void solveTransposed(Eigen::Ref<Eigen::VectorXd> x) const;

 private:
  MassFactor() = default;
  SparseMatrix lower_;  ///< L D^1/2
  /// The same by rows: G x as one dot product a row, rows split over the cores, each sum in
  /// the order of the product by columns (the same bits).
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> rows_;
};

}  // namespace beamrotor
