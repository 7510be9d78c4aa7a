// UMFPACK factorisation of a sparse matrix whose pattern repeats (the shifted pencil of a
// Campbell sweep, the dynamic stiffness of an unbalance sweep), real or complex: the symbolic
// analysis (fill-reducing ordering) is done once and reused while the pattern stays the same.
#pragma once

#include <Eigen/UmfPackSupport>
#include <algorithm>
#include <complex>

#include "fem/solvers/KeptPattern.hpp"
#include "fem/solvers/SparseLU.hpp"

namespace beamrotor {

template <class Scalar>
using SparseMatrixOf = Eigen::SparseMatrix<Scalar, Eigen::ColMajor, int>;
using ComplexSparseMatrix = SparseMatrixOf<std::complex<double>>;

template <class Scalar>
class RepeatedFactor {
 public:
  using Matrix = SparseMatrixOf<Scalar>;

  /// refine = false skips UMFPACK's iterative refinement: an iterative eigensolver applying
  /// the inverse hundreds of times gains nothing from it (each step costs a residual and a
  /// solve), a single direct solve does.
  explicit RepeatedFactor(bool refine = true) {
    if (!refine) lu_.umfpackControl()(UMFPACK_IRSTEP) = 0;
  }

  /// Factorises A (kept inside: UMFPACK's solve reads the matrix for iterative refinement).
  /// Returns false when the factorisation fails or rcond <= kSingularRcond. A matrix equal to
  /// the last one, entry for entry, keeps its factor (a Campbell sweep at a real shift 0 on
  /// speed-independent bearings factorises K once).
  bool factorize(Matrix A) {
    if (!A.isCompressed()) A.makeCompressed();
    if (factorizations_ > 0 && sameEntries(A, A_)) return factored_;
    const bool samePattern = pattern_.matches(A);  // false before the first analysis
    A_ = std::move(A);
    if (!samePattern) {
      lu_.analyzePattern(A_);
      pattern_.keep(A_);
      ++analyses_;
    }
    lu_.factorize(A_);
    ++factorizations_;
    factored_ = lu_.info() == Eigen::Success && lu_.rcond() > kSingularRcond;
    return factored_;
  }

  template <class Rhs>
  auto solve(const Rhs& b) const {
    return lu_.solve(b);
  }
  double rcond() const { return lu_.rcond(); }
  double factorEntries() const { return lu_.factorEntries(); }
  /// How many symbolic analyses were needed so far (1 for a whole sweep on one pattern).
  int analyses() const { return analyses_; }
  /// How many numeric factorisations were done so far (a repeated matrix is not redone).
  int factorizations() const { return factorizations_; }

 private:
  /// Eigen's wrapper plus the UMFPACK statistics it keeps to itself.
  struct Lu : Eigen::UmfPackLU<Matrix> {
    double rcond() const { return this->m_umfpackInfo[UMFPACK_RCOND]; }
    double factorEntries() const {
      return this->m_umfpackInfo[UMFPACK_LNZ] + this->m_umfpackInfo[UMFPACK_UNZ];
    }
  };

  Matrix A_;
  Lu lu_;
  KeptPattern pattern_;  ///< of the matrix last analysed
  bool factored_ = false;
  int analyses_ = 0, factorizations_ = 0;
};

}  // namespace beamrotor
