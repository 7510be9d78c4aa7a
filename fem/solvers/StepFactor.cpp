#include "fem/solvers/StepFactor.hpp"

#include <algorithm>
#include <cmath>

#include "fem/solvers/KeptPattern.hpp"

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
  if (factorizations_ == 0 || !sameEntries(A, A_)) {
    compute(A);
    ++factorizations_;
  }
  return healthy(kSingularRcond);
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
