// Eigenpairs of the generalised symmetric problem K x = lambda M x nearest a shift sigma:
// ARPACK's implicitly restarted Lanczos (dsaupd/dseupd) in shift-invert mode 3, with
// K - sigma M factorised once: CHOLMOD LDL' when sigma lies below every eigenvalue, at sigma
// when the lowest are well separated from it and otherwise at a shift moved up just below them
// by Sturm counts (fem/solvers/SturmShift); UMFPACK LU at sigma inside the spectrum. A final
// Sturm count proves that no mode was missed, and modes it shows missing are found by Lanczos
// in the complement of those found. Small problems go to a dense solver instead, since
// ARPACK needs more Lanczos vectors than wanted eigenpairs. Dofs that neither K nor M couples
// (a straight line's axial and bending dofs) are solved block by block
// (fem/solvers/DecoupledBlocks).
#pragma once

#include <Eigen/Dense>
#include <span>

#include "fem/assembly/Assembly.hpp"

namespace beamrotor {

struct EigenPairs {
  Eigen::VectorXd values;    ///< ascending
  Eigen::MatrixXd vectors;   ///< M-orthonormal columns
  double factorEntries = 0;  ///< fill of the factor of K - shift M (0 for the dense path)
  double shiftUsed = 0;      ///< the shift Lanczos ran at (moved up below the lowest eigenvalue)
  /// Eigenvalues a Sturm count places below the highest one returned that Lanczos did not
  /// return, after its runs in the complement of those found (0: none missed, or not
  /// checked).
  int missedBySturmCount = 0;
};

/// Lanczos vectors held for `count` wanted eigenpairs (each as long as the pencil).
int lanczosBasisSize(int count);

/// The `count` eigenpairs nearest sigma (for sigma below the spectrum: the lowest ones).
/// K symmetric, M symmetric positive semi-definite. Throws SolveError when K - sigma M is
/// singular (sigma equals an eigenvalue, e.g. sigma = 0 with rigid-body modes) or when ARPACK
/// does not converge. `nodeOfRow` (optional) names each row's node, rows of a node
/// consecutive, for the factors' fill-reducing order (fem/solvers/NodeOrdering).
EigenPairs symmetricEigenpairs(const SparseMatrix& K, const SparseMatrix& M, int count,
                               double sigma, std::span<const int> nodeOfRow = {});

}  // namespace beamrotor
