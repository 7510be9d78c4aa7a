#include "fem/solvers/SturmShift.hpp"

#include <algorithm>
#include <cmath>

#include "fem/solvers/Tolerances.hpp"

namespace beamrotor {

namespace {

/// The union of the patterns of A and B (compressed, rows sorted in each column, same size),
/// values zero.
SparseMatrix unionPattern(const SparseMatrix& A, const SparseMatrix& B) {
  const int n = int(A.cols());
  const int *ap = A.outerIndexPtr(), *ai = A.innerIndexPtr();
  const int *bp = B.outerIndexPtr(), *bi = B.innerIndexPtr();
  // Walks the merged rows of column `col`, calling visit(row) once per distinct row.
  auto mergeColumn = [&](int col, auto&& visit) {
    int a = ap[col], b = bp[col];
    while (a < ap[col + 1] || b < bp[col + 1]) {
      const int row = b == bp[col + 1] || (a < ap[col + 1] && ai[a] < bi[b]) ? ai[a] : bi[b];
      if (a < ap[col + 1] && ai[a] == row) ++a;
      if (b < bp[col + 1] && bi[b] == row) ++b;
      visit(row);
    }
  };
  long long nnz = 0;
  for (int col = 0; col < n; ++col) mergeColumn(col, [&](int) { ++nnz; });
  SparseMatrix U(A.rows(), n);
  U.resizeNonZeros(Eigen::Index(nnz));
  int* start = U.outerIndexPtr();
  int* rows = U.innerIndexPtr();
  int next = 0;
  for (int col = 0; col < n; ++col) {
    start[col] = next;
    mergeColumn(col, [&](int row) { rows[next++] = row; });
  }
  start[n] = next;
  std::fill_n(U.valuePtr(), nnz, 0.0);
  return U;
}

/// Writes K - sigma M into `shifted`, whose pattern is the union of K's and M's: the same
/// operations, in the same order, as Eigen's K - sigma * M.
void fillShifted(const SparseMatrix& K, const SparseMatrix& M, double sigma,
                 SparseMatrix& shifted) {
  const int *kp = K.outerIndexPtr(), *ki = K.innerIndexPtr();
  const int *mp = M.outerIndexPtr(), *mi = M.innerIndexPtr();
  const int *sp = shifted.outerIndexPtr(), *si = shifted.innerIndexPtr();
  const double *kx = K.valuePtr(), *mx = M.valuePtr();
  double* out = shifted.valuePtr();
  for (int col = 0; col < int(shifted.cols()); ++col) {
    int k = kp[col], m = mp[col];
    for (int e = sp[col]; e < sp[col + 1]; ++e) {
      double value = 0;
      if (k < kp[col + 1] && ki[k] == si[e]) value = kx[k++];
      if (m < mp[col + 1] && mi[m] == si[e]) value -= sigma * mx[m++];
      out[e] = value;
    }
  }
}

}  // namespace

SturmCounter::SturmCounter(const SparseMatrix& K, const SparseMatrix& M)
    : K_(K), M_(M), shifted_(unionPattern(K, M)) {}

int SturmCounter::below(double sigma) {
  fillShifted(K_, M_, sigma, shifted_);
  if (!analysed_) {
    ldlt_.analyzePattern(shifted_);
    analysed_ = true;
  }
  ldlt_.factorize(shifted_);
  ++factorisations_;
  if (ldlt_.info() != Eigen::Success) return -1;
  return ldlt_.negativePivots();
}

double shiftBelowLowest(SturmCounter& counter, double sigma, double upperBound, int count) {
  // Bisection keeps three points: lo with no eigenvalue below it, hi1 with at least one and
  // hiN with at least `count`. It stops once [lo, hi1] (which holds lambda_1) is narrow next to
  // [lo, hiN] (which holds the wanted band): then lo is a good shift.
  constexpr int kMaxFactorisations = 60;
  constexpr double kNarrow = 0.05;
  // Closer than this (relative) to lambda_1, K - sigma M is too near singular to trust rcond.
  constexpr double kClosest = 1e-7;
  auto exhausted = [&] { return counter.factorisations() > kMaxFactorisations; };

  // 1. hiN: widen from the upper bound until the wanted band lies below it.
  double hiN = upperBound;
  int atHiN = counter.below(hiN);
  const bool boundHoldsOne = atHiN >= 1;
  double width = std::max(upperBound - sigma, 1e-6 * std::abs(upperBound));
  while (atHiN < count) {
    if (atHiN < 0 || exhausted()) return sigma;
    width *= 2;
    hiN = sigma + width;
    atHiN = counter.below(hiN);
  }
  // 2. Bisect [lo, hi1] towards lambda_1.
  double lo = sigma;
  double hi1 = boundHoldsOne ? upperBound : hiN;
  while (hi1 - lo > kNarrow * (hiN - lo) && hi1 - lo > kClosest * std::abs(hi1) && !exhausted()) {
    const double mid = 0.5 * (lo + hi1);
    const int n = counter.below(mid);
    if (n < 0) break;  // mid sits on an eigenvalue: keep the bracket we have
    if (n == 0) {
      lo = mid;
    } else {
      hi1 = mid;
      if (n >= count) hiN = mid;
    }
  }
  // lo lies below lambda_1 but may be very close to it: keep a relative margin.
  return std::max(sigma, std::min(lo, hi1 - kClosest * std::abs(hi1)));
}

}  // namespace beamrotor
