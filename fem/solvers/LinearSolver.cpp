#include "fem/solvers/LinearSolver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "fem/assembly/ParallelParts.hpp"
#include "fem/solvers/DecoupledBlocks.hpp"
#include "fem/solvers/NodeOrdering.hpp"

namespace beamrotor {

double SparseLDLT::rcond() const {
  if (!m_factorizationIsOk || info() != Eigen::Success) return 0;
  // Eigen keeps the workspace private and hands it out non-const only; rcond reads it.
  return cholmod_rcond(m_cholmodFactor, &const_cast<SparseLDLT*>(this)->cholmod());
}

SparseLDLT::FactorView SparseLDLT::factorView() const {
  const cholmod_factor& f = *m_cholmodFactor;
  const int n = int(f.n);
  const auto* perm = static_cast<const int*>(f.Perm);
  return {
      Eigen::Map<const SparseMatrix>(n, n, Eigen::Index(f.nzmax), static_cast<const int*>(f.p),
                                     static_cast<const int*>(f.i), static_cast<const double*>(f.x),
                                     static_cast<const int*>(f.nz)),
      f.ordering != CHOLMOD_NATURAL ? perm : nullptr};
}

void SparseLDLT::solveInto(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  // x = P' L'^-1 D^-1 L^-1 P b, by Eigen's sparse triangular solves on CHOLMOD's columns.
  // cholmod_solve would do the same with a workspace of four vectors (four times the memory
  // of x: 90 MB at 10^6 planar elements, when a static run's memory peaks).
  const FactorView f = factorView();
  const Eigen::Index n = f.L.cols();
  x.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) x[k] = b[f.perm ? f.perm[k] : k];
  f.L.triangularView<Eigen::UnitLower>().solveInPlace(x);
  for (Eigen::Index j = 0; j < n; ++j) x[j] /= f.pivot(j);
  f.L.transpose().triangularView<Eigen::UnitUpper>().solveInPlace(x);
  if (f.perm) {
    Eigen::VectorXd y(n);
    for (Eigen::Index k = 0; k < n; ++k) y[f.perm[k]] = x[k];
    x.swap(y);
  }
}

void SparseLDLT::factorize(const SparseMatrix& A) {
  diagonal_ = A.diagonal();
  Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Upper>::factorize(A);
  // CHOLMOD keeps the analysis's workspace in its Common until told (24 bytes a row: 67 MB at
  // 10^6 planar elements, held through the solves, when a static run's memory peaks); the next
  // factorisation allocates what it needs again, from the heap this process keeps.
  cholmod_free_work(&cholmod());
}

std::pair<double, double> SparseLDLT::scaledPivotRange() const {
  if (!m_factorizationIsOk || info() != Eigen::Success) return {0, 0};
  const FactorView f = factorView();
  if (diagonal_.size() != f.L.cols()) return {0, 0};
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for (Eigen::Index j = 0; j < f.L.cols(); ++j) {
    const double a = diagonal_[f.perm ? f.perm[j] : j];
    if (!(a > 0)) return {0, 0};
    const double pivot = std::abs(f.pivot(j)) / a;
    // An infinite entry (stiffnesses summing past the largest double) leaves inf / inf here;
    // nothing about such a matrix is well conditioned.
    if (!std::isfinite(pivot)) return {0, 0};
    smallest = std::min(smallest, pivot);
    largest = std::max(largest, pivot);
  }
  return largest > 0 && std::isfinite(largest) ? std::pair{smallest, largest} : std::pair{0.0, 0.0};
}

double SparseLDLT::scaledRcond() const {
  const auto [smallest, largest] = scaledPivotRange();
  return largest > 0 ? smallest / largest : 0;
}

double SparseLDLT::factorEntries() const {
  if (!m_cholmodFactor) return 0;
  // A simplicial factor keeps its column counts in nz.
  const int* counts = static_cast<const int*>(m_cholmodFactor->nz);
  double entries = 0;
  for (std::size_t j = 0; j < m_cholmodFactor->n; ++j) entries += counts[j];
  return entries;
}

double SparseLDLT::predictedFactorEntries() const {
  if (!m_cholmodFactor) return 0;
  // A symbolic factor holds its predicted column counts.
  const int* counts = static_cast<const int*>(m_cholmodFactor->ColCount);
  return std::accumulate(counts, counts + m_cholmodFactor->n, 0.0);
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

void SparseLDLT::analyzePattern(const SparseMatrix& A, std::span<const int> nodeOfRow) {
  const double lowerEntries = double(A.nonZeros() + A.rows()) / 2;
  cholmod_common& c = cholmod();
  // No room for later updates of the factor (CHOLMOD reserves 5 entries a column by
  // default, about a third of the factor's memory here): factors are only ever recomputed.
  c.grow2 = 0;
  byNode_ = false;
  const auto analyseWith = [&](int ordering) {
    c.nmethods = ordering == CHOLMOD_NATURAL ? 1 : 0;  // 0: CHOLMOD's default, AMD or METIS
    c.method[0].ordering = ordering;
    c.postorder = ordering != CHOLMOD_NATURAL;
    Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Upper>::analyzePattern(A);
  };
  if (double(lowerEnvelope(A)) <= 1.2 * lowerEntries) {
    analyseWith(CHOLMOD_NATURAL);
    return;
  }
  // The envelope counts room for fill that elimination may never use: a line of beams whose
  // exact zeros were dropped (dropExactZeros) keeps its axial dofs apart from its bending ones,
  // and equal spans cancel each node's own bending-rotation coupling. The analysis in the
  // matrix's own order counts the true fill (an elimination tree and column counts, linear in
  // the entries); a fill-reducing order is sought only when that fill is large.
  analyseWith(CHOLMOD_NATURAL);
  if (predictedFactorEntries() <= 1.2 * lowerEntries) return;
  if (nodeOfRow.empty()) {
    analyseWith(CHOLMOD_AMD);
    return;
  }
  analyseInOrder(A, nodeByNodeOrdering(A, nodeOfRow));
  byNode_ = true;
}

void SparseLDLT::analyseInOrder(const SparseMatrix& A, std::vector<int> order) {
  // Eigen's analyzePattern() with CHOLMOD's analysis in a given order (postordered).
  cholmod_common& c = cholmod();
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_GIVEN;
  c.postorder = 1;
  if (m_cholmodFactor) cholmod_free_factor(&m_cholmodFactor, &c);
  cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Upper>());
  m_cholmodFactor = cholmod_analyze_p(&view, order.data(), nullptr, 0, &c);
  m_isInitialized = true;
  m_info = m_cholmodFactor ? Eigen::Success : Eigen::NumericalIssue;
  m_analysisIsOk = m_cholmodFactor != nullptr;
  m_factorizationIsOk = false;
}

std::vector<int> SparseLDLT::order() const {
  std::vector<int> out(m_cholmodFactor ? m_cholmodFactor->n : 0);
  std::iota(out.begin(), out.end(), 0);
  if (m_cholmodFactor && m_cholmodFactor->Perm && m_cholmodFactor->ordering != CHOLMOD_NATURAL) {
    const auto* perm = static_cast<const int*>(m_cholmodFactor->Perm);
    std::copy(perm, perm + out.size(), out.begin());
  }
  return out;
}

int SparseLDLT::negativePivots() const {
  const FactorView f = factorView();
  int negative = 0;
  for (Eigen::Index j = 0; j < f.L.cols(); ++j) negative += f.pivot(j) < 0;
  return negative;
}

const char* SparseLDLT::orderingName() const {
  if (byNode_) return "AMD by node";
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

namespace {

/// work(block) for both of LinearSolver's blocks (const or not), at the same time when there
/// are cores for it.
template <class Blocks, class Work>
void forBothBlocks(Blocks& blocks, Work&& work) {
  runTogether(
      blocks[0].rows.size() + blocks[1].rows.size(), [&] { work(blocks[0]); },
      [&] { work(blocks[1]); });
}

}  // namespace

bool LinearSolver::splitIfDecoupled(const SparseMatrix& A, std::span<const int> nodeOfRow) {
  // Below ~5e4 equations a factorisation takes milliseconds, less than splitting it; a second
  // block under a quarter of the rows leaves one core with most of the work.
  // The split does not depend on the cores: one thread does the blocks one after the other
  // and gets the same bits.
  constexpr Eigen::Index kSplitFrom = 50000;
  if (A.rows() < kSplitFrom) return false;
  LargestBlock split = largestBlockOfPattern(A);
  if (4 * split.rest.size() < std::size_t(A.rows())) return false;
  blocks_.resize(2);
  blocks_[0].rows = std::move(split.dofs);
  blocks_[1].rows = std::move(split.rest);
  forBothBlocks(blocks_, [&](Block& b) {
    b.A = principalSubmatrix(A, b.rows);
    b.ldlt->analyzePattern(b.A, entriesAt(nodeOfRow, b.rows));
  });
  return true;
}

void LinearSolver::analyzePattern(const SparseMatrix& A, MatrixSymmetry symmetry,
                                  std::span<const int> nodeOfRow, Definiteness definiteness) {
  symmetric_ = symmetry == MatrixSymmetry::byConstruction || isNumericallySymmetric(A);
  blocks_.clear();
  cholesky_.reset();
  usingCholesky_ = false;
  if (symmetric_) {
    if (splitIfDecoupled(A, nodeOfRow)) return;
    ldlt_.analyzePattern(A, nodeOfRow);
    if (definiteness == Definiteness::positiveExpected &&
        ldlt_.predictedFactorEntries() >= kSupernodalFrom) {
      cholesky_ = std::make_unique<SupernodalCholesky>();
      cholesky_->analyse(A, ldlt_.order());
    }
  } else {
    lu_.analyzePattern(A);
  }
}

void LinearSolver::factorize(const SparseMatrix& A) {
  if (!blocks_.empty()) {
    forBothBlocks(blocks_, [&](Block& b) {
      b.A = principalSubmatrix(A, b.rows);  // the same pattern, so nothing couples the blocks
      b.ldlt->factorize(b.A);
    });
    return;
  }
  if (symmetric_) {
    usingCholesky_ = cholesky_ && cholesky_->factorize(A);
    if (!usingCholesky_) ldlt_.factorize(A);
    return;
  }
  // UMFPACK scales rows only; the columns (the dofs' units) are scaled here.
  luScale_ = A.diagonal().cwiseAbs();
  for (Eigen::Index i = 0; i < luScale_.size(); ++i)
    luScale_[i] = luScale_[i] > 0 ? 1 / std::sqrt(luScale_[i]) : 1.0;
  // Eigen's UmfPackLU keeps a reference to the matrix it factorised: it must outlive the factor.
  luMatrix_ = luScale_.asDiagonal() * A * luScale_.asDiagonal();
  lu_.factorize(luMatrix_);
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& b) const {
  if (!blocks_.empty()) {
    Eigen::VectorXd x(b.size());
    forBothBlocks(blocks_, [&](const Block& block) {
      Eigen::VectorXd blockX;
      block.ldlt->solveInto(b(block.rows), blockX);
      x(block.rows) = blockX;
    });
    return x;
  }
  if (symmetric_) {
    Eigen::VectorXd x;
    if (usingCholesky_)
      cholesky_->solveInto(b, x);
    else
      ldlt_.solveInto(b, x);
    return x;
  }
  const Eigen::VectorXd scaledB = luScale_.cwiseProduct(b);
  return luScale_.cwiseProduct(Eigen::VectorXd(lu_.solve(scaledB)));
}

std::string LinearSolver::methodName() const {
  if (!blocks_.empty()) return "CHOLMOD LDL' of 2 decoupled blocks";
  if (usingCholesky_) return "CHOLMOD supernodal LL'";
  return symmetric_ ? "CHOLMOD LDL'" : "UMFPACK LU";
}

std::string LinearSolver::orderingName() const {
  if (!blocks_.empty()) return blocks_[0].ldlt->orderingName();
  return symmetric_ ? ldlt_.orderingName() : lu_.orderingName();
}

double LinearSolver::rcond() const {
  if (usingCholesky_) {
    const auto [smallest, largest] = cholesky_->scaledPivotRange();
    return largest > 0 ? smallest / largest : 0;
  }
  if (blocks_.empty()) return symmetric_ ? ldlt_.scaledRcond() : lu_.rcond();
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for (const Block& b : blocks_) {
    const auto [low, high] = b.ldlt->scaledPivotRange();
    if (!(high > 0)) return 0;
    smallest = std::min(smallest, low);
    largest = std::max(largest, high);
  }
  return smallest / largest;
}

bool LinearSolver::healthy(double tol) const {
  const bool factorised =
      !blocks_.empty()
          ? std::all_of(blocks_.begin(), blocks_.end(),
                        [](const Block& b) { return b.ldlt->info() == Eigen::Success; })
      : usingCholesky_ ? true
      : symmetric_     ? ldlt_.info() == Eigen::Success
                   : lu_.info() == Eigen::Success;
  return factorised && rcond() > tol;
}

double LinearSolver::factorEntries() const {
  if (!blocks_.empty()) return blocks_[0].ldlt->factorEntries() + blocks_[1].ldlt->factorEntries();
  if (usingCholesky_) return cholesky_->factorEntries();
  return symmetric_ ? ldlt_.factorEntries() : lu_.factorEntries();
}

}  // namespace beamrotor
