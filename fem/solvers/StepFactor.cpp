#include "fem/solvers/StepFactor.hpp"

#include <algorithm>
#include <cmath>

namespace beamrotor {

void StepFactor::compute(const SparseMatrix& A) {
  dense_ = A.rows() <= kDenseLimit;
  A_ = A;
  A_.makeCompressed();
  if (!dense_) {
    sparseLu_.compute(A_);
    return;
  }
  Eigen::MatrixXd dense = Eigen::MatrixXd(A);
  rowScale_ = dense.cwiseAbs().rowwise().sum().cwiseInverse();
  for (Eigen::Index i = 0; i < rowScale_.size(); ++i)
    if (!std::isfinite(rowScale_[i])) rowScale_[i] = 1;  // an empty row: singular either way
  dense = rowScale_.asDiagonal() * dense;
  denseLu_.compute(dense);
  const Eigen::VectorXd u = denseLu_.matrixLU().diagonal().cwiseAbs();
  const double largest = u.size() ? u.maxCoeff() : 0;
  denseRcond_ = largest > 0 && std::isfinite(largest) ? u.minCoeff() / largest : 0;
}

bool StepFactor::factorize(const SparseMatrix& A) {
  if (factorizations_ == 0 || !sameAsLast(A)) {
    compute(A);
    ++factorizations_;
  }
  return healthy(kSingularRcond);
}

bool StepFactor::sameAsLast(const SparseMatrix& A) const {
  if (!A.isCompressed() || A.rows() != A_.rows() || A.cols() != A_.cols() ||
      A.nonZeros() != A_.nonZeros())
    return false;
  const auto n = A.nonZeros();
  return std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1,
                    A_.outerIndexPtr()) &&
         std::equal(A.innerIndexPtr(), A.innerIndexPtr() + n, A_.innerIndexPtr()) &&
         std::equal(A.valuePtr(), A.valuePtr() + n, A_.valuePtr());
}

bool StepFactor::healthy(double tol) const {
  return dense_ ? denseRcond_ > tol : sparseLu_.healthy(tol);
}

double StepFactor::rcond() const { return dense_ ? denseRcond_ : sparseLu_.rcond(); }

double StepFactor::factorEntries() const {
  return dense_ ? double(rowScale_.size()) * double(rowScale_.size())
                : sparseLu_.factorEntries();
}

Eigen::VectorXd StepFactor::solve(const Eigen::VectorXd& b) const {
  if (dense_) return denseLu_.solve(rowScale_.asDiagonal() * b);
  return sparseLu_.solve(b);
}

}  // namespace beamrotor
