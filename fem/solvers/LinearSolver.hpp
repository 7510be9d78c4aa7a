// The sparse direct solver for one matrix, chosen from the matrix itself: CHOLMOD's simplicial
// LDL' when it is symmetric (beams, springs, masses: every static and most dynamic systems),
// UMFPACK's LU otherwise (cross-coupled bearings, gyroscopic terms). On the benchmark models
// LDL' stores half the factor of LU and factorises 2-3x faster (see the closing notes of the
// performance issue); both report the same kind of reciprocal condition estimate.
#pragma once

#include <Eigen/CholmodSupport>
#include <string>

#include "fem/assembly/Assembly.hpp"
#include "fem/solvers/SparseLU.hpp"

namespace beamrotor {

/// CHOLMOD's simplicial LDL' plus what Eigen's wrapper keeps to itself.
class SparseLDLT : public Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Upper> {
 public:
  /// Quiet: a zero pivot is reported through info() and rcond(), never printed.
  SparseLDLT() { cholmod().print = 0; }
  /// CHOLMOD's cheap reciprocal condition estimate, min |D_ii| / max |D_ii| (0 when singular).
  double rcond() const;
  /// Entries in the factor L (including its unit diagonal, which holds D).
  double factorEntries() const;
  /// Negative entries of D. By Sylvester's law of inertia, for A = K - sigma M this is the
  /// number of eigenvalues of K x = lambda M x below sigma (M positive definite).
  int negativePivots() const;
  /// Symbolic analysis. When the matrix as numbered already has (almost) no room for fill,
  /// as a line of beams numbered node by node does, its own order is kept and the fill-
  /// reducing ordering (AMD/METIS), which would cost more than the factorisation, is skipped.
  void analyzePattern(const SparseMatrix& A);
  /// The fill-reducing ordering the analysis chose: "natural", "AMD", "METIS", "NESDIS".
  const char* orderingName() const;
};

/// Entries in the lower envelope of a structurally symmetric A: for each row, from its first
/// entry to the diagonal. Cholesky in A's own order fills at most this (George and Liu 1981).
long long lowerEnvelope(const SparseMatrix& A);

/// True when A (structurally symmetric, as every assembled pattern is) equals its transpose to
/// within `relTol` of the largest entry in absolute value.
bool isNumericallySymmetric(const SparseMatrix& A, double relTol = 1e-13);

class LinearSolver {
 public:
  /// Chooses the method from A's values and computes the symbolic factorisation; later
  /// factorize() calls must pass matrices with the same pattern (and the same symmetry).
  void analyzePattern(const SparseMatrix& A);
  /// Numeric factorisation. Check healthy() before solving.
  void factorize(const SparseMatrix& A);
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  bool symmetric() const { return symmetric_; }
  /// "CHOLMOD LDL'" or "UMFPACK LU".
  std::string methodName() const;
  /// The fill-reducing ordering of the symbolic analysis (SparseLDLT, SparseLU).
  std::string orderingName() const;
  double rcond() const;
  /// True when the factorisation succeeded and rcond is above tol.
  bool healthy(double tol) const;
  /// Fill-in: entries of the factor(s).
  double factorEntries() const;

 private:
  bool symmetric_ = false;
  SparseLDLT ldlt_;
  SparseLU lu_;
};

}  // namespace beamrotor
