// A shift for the lowest eigenvalues of K x = lambda M x that sits just below them, found by
// Sturm counts (the inertia of LDL' factors of K - sigma M). Shift-invert Lanczos converges at
// the ratios (lambda_k - sigma) / (lambda_k+1 - sigma): at sigma = 0 these are all near 1 for
// a clustered spectrum (a continuous beam of many equal spans has as many modes within 1e-5
// of each other as spans), while just below the cluster they are far from 1.
#pragma once

#include <limits>

#include "fem/assembly/Assembly.hpp"
#include "fem/solvers/LinearSolver.hpp"

namespace beamrotor {

class SturmCounter {
 public:
  /// K, M symmetric with M positive definite on the free dofs; both must outlive this.
  /// `nodeOfRow` (optional) names each row's node, for the factor's ordering (SparseLDLT).
  SturmCounter(const SparseMatrix& K, const SparseMatrix& M, std::span<const int> nodeOfRow = {});
  /// Number of eigenvalues below sigma; -1 when K - sigma M is singular to working precision.
  /// The sigma of the last count again costs nothing (its factor is still held).
  int below(double sigma);
  /// Factorisations done so far.
  int factorisations() const { return factorisations_; }
  /// The factor of K - sigma M for the last sigma counted (valid when below() was >= 0). The
  /// next below() overwrites it in place (same symbolic analysis, same storage).
  const SparseLDLT& factor() const { return ldlt_; }

 private:
  const SparseMatrix& K_;
  const SparseMatrix& M_;
  /// K - sigma M on the union of K's and M's nonzeros: the pattern is built once, the values
  /// are refilled in place for every sigma (no allocation per count).
  SparseMatrix shifted_;
  SparseLDLT ldlt_;
  std::vector<int> nodeOfRow_;
  bool analysed_ = false;
  int factorisations_ = 0;
  double factorisedAt_ = std::numeric_limits<double>::quiet_NaN();  ///< sigma of ldlt_
  int countThere_ = -1;
};

/// For the `count` lowest eigenvalues above sigma (no eigenvalue below sigma): a shift in
/// [sigma, lambda_1) within a few per cent of the wanted band's width below lambda_1, or sigma
/// itself when the search cannot improve on it or the band is wider than sigma's distance
/// from it (then sigma is near enough already). `upperBound` is any value >= lambda_1 (e.g. a
/// Rayleigh quotient).
double shiftBelowLowest(SturmCounter& counter, double sigma, double upperBound, int count);

}  // namespace beamrotor
