#include "fem/solvers/SturmShift.hpp"

#include <algorithm>
#include <cmath>

#include "fem/assembly/CompressedPattern.hpp"
#include "fem/solvers/Tolerances.hpp"

namespace beamrotor {

namespace {

/// The union of the patterns of A and B (compressed, rows sorted in each column, same size)
/// without their exact zeros off the diagonal (dropExactZeros), values zero.
SparseMatrix unionPattern(const SparseMatrix& A, const SparseMatrix& B) {
  const int n = int(A.cols());
  const int *ap = A.outerIndexPtr(), *ai = A.innerIndexPtr();
  const int *bp = B.outerIndexPtr(), *bi = B.innerIndexPtr();
  const double *ax = A.valuePtr(), *bx = B.valuePtr();
  // Walks the merged rows of column `col`, calling visit(row) once per distinct row where
  // A or B holds a value (or on the diagonal).
  auto mergeColumn = [&](int col, auto&& visit) {
    int a = ap[col], b = bp[col];
    while (a < ap[col + 1] || b < bp[col + 1]) {
      const int row = b == bp[col + 1] || (a < ap[col + 1] && ai[a] < bi[b]) ? ai[a] : bi[b];
      bool held = row == col;
      if (a < ap[col + 1] && ai[a] == row) held |= ax[a++] != 0;
      if (b < bp[col + 1] && bi[b] == row) held |= bx[b++] != 0;
      if (held) visit(row);
    }
  };
  return compressedPattern(int(A.rows()), n, mergeColumn);
}

/// Writes K - sigma M into `shifted`, whose pattern holds every nonzero of K and M: the same
/// operations, in the same order, as Eigen's K - sigma * M (entries of K or M outside it are
/// zeros, skipped).
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
      while (k < kp[col + 1] && ki[k] < si[e]) ++k;
      while (m < mp[col + 1] && mi[m] < si[e]) ++m;
      double value = 0;
      if (k < kp[col + 1] && ki[k] == si[e]) value = kx[k++];
      if (m < mp[col + 1] && mi[m] == si[e]) value -= sigma * mx[m++];
      out[e] = value;
    }
  }
}

}  // namespace

SturmCounter::SturmCounter(const SparseMatrix& K, const SparseMatrix& M,
                           std::span<const int> nodeOfRow)
    : K_(K), M_(M), shifted_(unionPattern(K, M)), nodeOfRow_(nodeOfRow.begin(), nodeOfRow.end()) {}

int SturmCounter::below(double sigma) {
  if (sigma == factorisedAt_) return countThere_;
  fillShifted(K_, M_, sigma, shifted_);
  if (!analysed_) {
    ldlt_.analyzePattern(shifted_, nodeOfRow_);
    analysed_ = true;
  }
  ldlt_.factorize(shifted_);
  ++factorisations_;
  factorisedAt_ = sigma;
  countThere_ = ldlt_.info() != Eigen::Success ? -1 : ldlt_.negativePivots();
  return countThere_;
}

namespace {

/// A shift with eigenvalues below it, and how many.
struct CountAbove {
  double at = 0;
  int count = 0;
};

/// Where lambda_1 lies if the counts at two shifts above it, near and far (more), come from the
/// edge of a dense band of eigenvalues, as the lowest modes of a long line of equal spans do:
/// near a one-dimensional band edge the count grows as the square root of the distance to the
/// edge (the band's density of states diverges there as its inverse), N^2 ~ sigma - lambda_1.
double bandEdgeEstimate(const CountAbove& near, const CountAbove& far) {
  const double n2 = double(near.count) * near.count, f2 = double(far.count) * far.count;
  return near.at - (far.at - near.at) * n2 / (f2 - n2);
}

}  // namespace

double shiftBelowLowest(SturmCounter& counter, double sigma, double upperBound, int count) {
  // The search keeps three points: lo with no eigenvalue below it, hi1 with at least one and
  // hiN with at least `count`. It stops once [lo, hi1] (which holds lambda_1) is narrow next to
  // [lo, hiN] (which holds the wanted band): then lo is a good shift. hiN's count is often
  // well above `count` (76 for 10 on the benchmark's 10^5 spans), so narrow means 1 %: at 5 %
  // lo ended 2.5 widths of the wanted band below lambda_1 there, and Lanczos took 91 steps
  // instead of 51.
  constexpr int kMaxFactorisations = 60;
  constexpr double kNarrow = 0.01;
  // Probes stop this close (relative) to lambda_1, the level of a count's round-off on an
  // ill-conditioned model; the wanted band of the benchmark's 10^5 spans is 4.7e-8 wide.
  constexpr double kResolution = 1e-9;
  // The margin below hi1 when lo's factor is not healthy enough to serve as the shift.
  constexpr double kClosest = 1e-7;
  // Probes placed by the band-edge estimate straddle it by this fraction of its distance to
  // hi1 (on the benchmark's 10^5 spans the estimate is within 0.2 % of that distance).
  constexpr double kStraddle = 0.02;
  auto exhausted = [&] { return counter.factorisations() > kMaxFactorisations; };

  // 1. hiN: at or above the wanted band's top, at the upper bound or one doubling of its
  //    distance from sigma. Fewer than `count` eigenvalues below sigma + 2 (upperBound -
  //    sigma) mean the wanted band is wider than lambda_1's distance from sigma (upperBound >=
  //    lambda_1), so at sigma the ratios that set Lanczos's convergence are already far from 1;
  //    the counts that would find lambda_1 cost more factorisations than they save (a plate's
  //    or a grillage's spectrum: 2 here, 8 to find the band's top).
  double hiN = upperBound;
  int atHiN = counter.below(hiN);
  const bool boundHoldsOne = atHiN >= 1;
  const int atUpperBound = atHiN;
  if (atHiN < count) {
    if (atHiN < 0 || exhausted()) return sigma;
    hiN = sigma + 2 * std::max(upperBound - sigma, 1e-6 * std::abs(upperBound));
    atHiN = counter.below(hiN);
    if (atHiN < count) return sigma;
  }
  // 2. Narrow [lo, hi1] onto lambda_1. A probe goes to the middle (bisection) or, once two
  //    counts above lambda_1 differ, just below or just above where they place a band edge,
  //    which on a long line of spans takes a few probes where bisection takes 25. A placed
  //    probe that fails to halve the bracket is followed by a bisection, so the search takes
  //    at most twice bisection's probes, and one more for the first probe (below), whatever
  //    the spectrum.
  //    The first probe goes a sixteenth of the bracket below an upper bound that is a
  //    Rayleigh quotient, not to the middle: from a start that holds every mode the quotient
  //    lies close above lambda_1 (7.7 % on the benchmark's 10^5 spans), so the probe either
  //    finds a second count above lambda_1, from which the band edge is placed, or lifts lo to
  //    within that sixteenth. Bisection spent three probes below lambda_1 there first.
  double lo = sigma;
  double hi1 = boundHoldsOne ? upperBound : hiN;
  CountAbove near{hi1, boundHoldsOne ? atUpperBound : atHiN};  // always at hi1
  CountAbove far{hi1, 0};                                      // a larger count, or none yet
  bool aimAbove = false, bisectNext = false;
  double loRcond = 0;  // of the factor at lo, once a probe has moved lo up from sigma
  constexpr double kBelowQuotient = 1.0 / 16;
  bool first = boundHoldsOne;  // the next probe is the first, below a Rayleigh quotient
  while (hi1 - lo > kNarrow * (hiN - lo) && hi1 - lo > kResolution * std::abs(hi1) &&
         !exhausted()) {
    const double before = hi1 - lo;
    double probe = first ? hi1 - kBelowQuotient * (hi1 - lo) : 0.5 * (lo + hi1);
    first = false;
    bool placed = false;
    if (!bisectNext && far.count > near.count && near.count >= 1) {
      const double edge = bandEdgeEstimate(near, far);
      const double margin =
          std::max(kStraddle * (near.at - edge), 0.4 * kResolution * std::abs(edge));
      const double at = aimAbove ? edge + margin : edge - margin;
      if (at > lo && at < hi1) {
        probe = at;
        placed = true;
      }
    }
    const int n = counter.below(probe);
    if (n < 0) break;  // the probe sits on an eigenvalue: keep the bracket we have
    if (n == 0) {
      lo = probe;
      loRcond = counter.factor().scaledRcond();
    } else {
      hi1 = probe;
      if (n >= count) hiN = probe;
      if (n < near.count) far = near;
      near = {probe, n};
    }
    if (placed) aimAbove = n == 0;  // below the edge held none: straddle it from above next
    bisectNext = placed && hi1 - lo > 0.5 * before;
  }
  // lo lies below lambda_1 (its count is 0), and its factor, positive definite, is the one
  // Lanczos will use: healthy on the scaled system, it serves however close to lambda_1 lo
  // lies. (On the benchmark's 10^5 spans lo ends 6e-9 below lambda_1, a tenth of the wanted
  // band's width, with scaled rcond 8e-6; a margin of 1e-7 below hi1 put the shift 1.5 band
  // widths down, and Lanczos took 71 steps where it takes 51 at lo.) Otherwise that margin.
  constexpr double kHealthyShift = 1e4 * kSingularRcond;
  if (lo > sigma && loRcond > kHealthyShift) return lo;
  return std::max(sigma, std::min(lo, hi1 - kClosest * std::abs(hi1)));
}

}  // namespace beamrotor
