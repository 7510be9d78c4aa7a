#include "fem/solvers/SymbolicReuse.hpp"

namespace beamrotor {

LinearSolver& SymbolicReuse::analysedFor(const SparseMatrix& A, MatrixSymmetry symmetry,
                                         std::span<const int> nodeOfRow,
                                         Definiteness definiteness) {
  const bool symmetric = symmetry == MatrixSymmetry::byConstruction || isNumericallySymmetric(A);
  if (reusable_ && symmetric && definiteness == definiteness_ && A.rows() == A.cols() &&
      pattern_.matches(A)) {
    ++reuses_;
    return solver_;
  }
  // The scan above has been done: the solver need not repeat it.
  solver_.analyzePattern(A, symmetric ? MatrixSymmetry::byConstruction : MatrixSymmetry::unknown,
                         nodeOfRow, definiteness);
  definiteness_ = definiteness;
  ++analyses_;
  reusable_ = symmetric && A.isCompressed();
  if (reusable_) pattern_.keep(A);
  return solver_;
}

}  // namespace beamrotor
