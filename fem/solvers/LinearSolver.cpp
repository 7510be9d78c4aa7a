#include "fem/solvers/LinearSolver.hpp"

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

long long lowerEnvelope(const SparseMatrix& A) {
  long long entries = 0;
  for (int j = 0; j < A.cols(); ++j) {
    const int begin = A.outerIndexPtr()[j], end = A.outerIndexPtr()[j + 1];
    // Column j's first row is row j's first column (symmetric pattern); rows are sorted.
    const int first = begin < end ? std::min(A.innerIndexPtr()[begin], j) : j;
    entries += j - first + 1;
  }
  return entries;
}

void SparseLDLT::analyzePattern(const SparseMatrix& A) {
  const SparseMatrix::Index lowerEntries = (A.nonZeros() + A.rows()) / 2;
  const bool keepOrder = double(lowerEnvelope(A)) <= 1.2 * double(lowerEntries);
  cholmod_common& c = cholmod();
  // No room for later updates of the factor (CHOLMOD reserves 5 entries a column by
  // default, about a third of the factor's memory here): factors are only ever recomputed.
  c.grow2 = 0;
  if (keepOrder) {
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_NATURAL;
    c.postorder = false;
  } else {
    c.nmethods = 0;  // CHOLMOD's default: AMD, and METIS when AMD leaves much fill
    c.postorder = true;
  }
  Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Upper>::analyzePattern(A);
}

int SparseLDLT::negativePivots() const {
  // Simplicial LDL': each column of L starts with its diagonal entry, which holds D(j, j).
  const cholmod_factor& L = *m_cholmodFactor;
  const int* start = static_cast<const int*>(L.p);
  const double* x = static_cast<const double*>(L.x);
  int negative = 0;
  for (std::size_t j = 0; j < L.n; ++j) negative += x[start[j]] < 0;
  return negative;
}

const char* SparseLDLT::orderingName() const {
  switch (m_cholmodFactor ? m_cholmodFactor->ordering : -1) {
    case CHOLMOD_NATURAL:
      return "natural";
    case CHOLMOD_AMD:
      return "AMD";
    case CHOLMOD_METIS:
      return "METIS";
    case CHOLMOD_NESDIS:
      return "NESDIS";
    case CHOLMOD_COLAMD:
      return "COLAMD";
    default:
      return "CHOLMOD's";
  }
}

bool isNumericallySymmetric(const SparseMatrix& A, double relTol) {
  if (A.rows() != A.cols()) return false;
  const int* colStart = A.outerIndexPtr();
  const int* rows = A.innerIndexPtr();
  const double* values = A.valuePtr();
  const double scale =
      A.nonZeros() ? Eigen::Map<const Eigen::VectorXd>(values, A.nonZeros()).cwiseAbs().maxCoeff()
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

std::string LinearSolver::orderingName() const {
  return symmetric_ ? ldlt_.orderingName() : lu_.orderingName();
}

double LinearSolver::rcond() const {
  return symmetric_ ? ldlt_.rcond() : lu_.rcond();
}

bool LinearSolver::healthy(double tol) const {
  const Eigen::ComputationInfo info = symmetric_ ? ldlt_.info() : lu_.info();
  return info == Eigen::Success && rcond() > tol;
}

double LinearSolver::factorEntries() const {
  return symmetric_ ? ldlt_.factorEntries() : lu_.factorEntries();
}

}  // namespace beamrotor
