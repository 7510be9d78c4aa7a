#include "fem/solvers/SturmShift.hpp"

#include <cmath>

#include "fem/solvers/Tolerances.hpp"

namespace beamrotor {

SturmCounter::SturmCounter(const SparseMatrix& K, const SparseMatrix& M) : K_(K), M_(M) {}

int SturmCounter::below(double sigma) {
  const SparseMatrix A = K_ - sigma * M_;  // the union pattern of K and M, every time
  if (!analysed_) {
    ldlt_.analyzePattern(A);
    analysed_ = true;
  }
  ldlt_.factorize(A);
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
