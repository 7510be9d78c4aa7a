#include "fem/LinearSolver.hpp"

#include <algorithm>
#include <cmath>

namespace beamrotor {

double SparseLDLT::rcond() const {
  if (!m_factorizationIsOk || info() != Eigen::Success) return 0;
  // Eigen keeps the workspace private and hands it out non-const only; rcond reads it.
  return cholmod_rcond(m_cholmodFactor, &const_cast<SparseLDLT*>(this)->cholmod());
}

double SparseLDLT::factorEntries() const {
  if (!m_cholmodFactor) return 0;
  // A simplicial factor keeps its column counts in nz.
  const int* counts = static_cast<const int*>(m_cholmodFactor->nz);
  double entries = 0;
  for (std::size_t j = 0; j < m_cholmodFactor->n; ++j) entries += counts[j];
  return entries;
}

bool isNumericallySymmetric(const SparseMatrix& A, double relTol) {
  if (A.rows() != A.cols()) return false;
  const int* colStart = A.outerIndexPtr();
  const int* rows = A.innerIndexPtr();
  const double* values = A.valuePtr();
  const double scale = A.nonZeros() ? Eigen::Map<const Eigen::VectorXd>(values, A.nonZeros())
                                          .cwiseAbs()
                                          .maxCoeff()
                                    : 0.0;
  const double tol = relTol * scale;
  for (int col = 0; col < A.cols(); ++col)
    for (int k = colStart[col]; k < colStart[col + 1]; ++k) {
      const int row = rows[k];
      if (row <= col) continue;
      // The mirror entry (col, row) lives in column `row`.
      const int* first = rows + colStart[row];
      const int* last = rows + colStart[row + 1];
      const int* mirror = std::lower_bound(first, last, col);
      const double other = (mirror != last && *mirror == col) ? values[mirror - rows] : 0.0;
      if (std::abs(values[k] - other) > tol) return false;
    }
  return true;
}

void LinearSolver::analyzePattern(const SparseMatrix& A) {
  symmetric_ = isNumericallySymmetric(A);
  if (symmetric_)
    ldlt_.analyzePattern(A);
  else
    lu_.analyzePattern(A);
}

void LinearSolver::factorize(const SparseMatrix& A) {
  if (symmetric_)
    ldlt_.factorize(A);
  else
    lu_.factorize(A);
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& b) const {
  if (symmetric_) return ldlt_.solve(b);
  return lu_.solve(b);
}

std::string LinearSolver::methodName() const {
  return symmetric_ ? "CHOLMOD LDL'" : "UMFPACK LU";
}

double LinearSolver::rcond() const { return symmetric_ ? ldlt_.rcond() : lu_.rcond(); }

bool LinearSolver::healthy(double tol) const {
  const Eigen::ComputationInfo info = symmetric_ ? ldlt_.info() : lu_.info();
  return info == Eigen::Success && rcond() > tol;
}

double LinearSolver::factorEntries() const {
  return symmetric_ ? ldlt_.factorEntries() : lu_.factorEntries();
}

}  // namespace beamrotor
