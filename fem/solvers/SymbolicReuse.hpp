// A sparse solver kept from one linear system to the next (the points of a design study, whose
// parameters change the values of K but seldom its connectivity), so that the symbolic
// analysis, the fill-reducing ordering and the elimination tree, is done once per sparsity
// pattern and each later system is only factorised numerically.
//
// Reuse is limited to symmetric matrices: CHOLMOD's analysis reads the pattern alone, so the
// factor of a reused analysis is the factor of a fresh one, bit for bit. UMFPACK's symbolic
// step also reads the values (its choice of strategy and pivot order depends on them), so a
// non-symmetric system is always analysed anew.
#pragma once

#include "fem/solvers/KeptPattern.hpp"
#include "fem/solvers/LinearSolver.hpp"

namespace beamrotor {

class SymbolicReuse {
 public:
  /// A solver analysed for A: the kept one when A is symmetric with the pattern of the last
  /// symmetric matrix analysed here, else the kept one analysed anew for A. Either way the
  /// caller goes on with factorize(A). The reference stays valid for this object's lifetime;
  /// one caller at a time (the next call may analyse it again).
  /// `symmetry` and `nodeOfRow` as LinearSolver::analyzePattern takes them (byConstruction
  /// skips the scan).
  LinearSolver& analysedFor(const SparseMatrix& A,
                            MatrixSymmetry symmetry = MatrixSymmetry::unknown,
                            std::span<const int> nodeOfRow = {},
                            Definiteness definiteness = Definiteness::unknown);

  /// Analyses done and analyses saved so far.
  long long analyses() const { return analyses_; }
  long long reuses() const { return reuses_; }

 private:
  LinearSolver solver_;
  bool reusable_ = false;  ///< solver_ holds a symmetric analysis of the pattern below
  Definiteness definiteness_ = Definiteness::unknown;  ///< what that analysis expected
  KeptPattern pattern_;
  long long analyses_ = 0, reuses_ = 0;
};

}  // namespace beamrotor
