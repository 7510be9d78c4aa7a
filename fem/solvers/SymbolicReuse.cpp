#include "fem/solvers/SymbolicReuse.hpp"

#include <algorithm>

namespace beamrotor {

bool SymbolicReuse::samePattern(const SparseMatrix& A) const {
  if (!A.isCompressed() || A.rows() != A.cols()) return false;
  const std::size_t n = std::size_t(A.cols()), nnz = std::size_t(A.nonZeros());
  return columnStarts_.size() == n + 1 && rows_.size() == nnz &&
         std::equal(columnStarts_.begin(), columnStarts_.end(), A.outerIndexPtr()) &&
         std::equal(rows_.begin(), rows_.end(), A.innerIndexPtr());
}

LinearSolver& SymbolicReuse::analysedFor(const SparseMatrix& A, MatrixSymmetry symmetry) {
  const bool symmetric =
      symmetry == MatrixSymmetry::byConstruction || isNumericallySymmetric(A);
  if (reusable_ && symmetric && samePattern(A)) {
    ++reuses_;
    return solver_;
  }
  // The scan above has been done: the solver need not repeat it.
  solver_.analyzePattern(A, symmetric ? MatrixSymmetry::byConstruction : MatrixSymmetry::unknown);
  ++analyses_;
  reusable_ = symmetric && A.isCompressed();
  if (reusable_) {
    columnStarts_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1);
    rows_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  }
  return solver_;
}

}  // namespace beamrotor
