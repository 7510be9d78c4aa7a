#include "fem/solvers/BandCholesky.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

extern "C" {
// LAPACK (Debian's OpenBLAS or reference LAPACK, 32-bit integers).
void dpbtrf_(const char* uplo, const int* n, const int* kd, double* ab, const int* ldab, int* info);
}

namespace beamrotor {

bool BandCholesky::factorize(const SymmetricBand& A) {
  factorized_ = false;
  L_ = CompressedLower();
  SymmetricBand band = A;
  const int n = band.size(), kd = band.halfBandwidth(), ld = band.leading();
  int info = 0;
  if (n > 0) dpbtrf_("L", &n, &kd, band.data(), &ld, &info);
  if (info < 0) throw std::logic_error("dpbtrf: argument " + std::to_string(-info) + " is wrong");
  if (info > 0) return false;
  pivots_.resize(n);
  for (int j = 0; j < n; ++j) {
    const double l = band.lower(j, j);
    pivots_[j] = l * l / A.lower(j, j);
  }
  L_ = std::move(band).lowerWithoutZeros();
  factorized_ = true;
  return true;
}

Eigen::VectorXd BandCholesky::solve(Eigen::VectorXd b) const {
  solveInPlace(b);
  return b;
}

void BandCholesky::solveInPlace(Eigen::Ref<Eigen::VectorXd> x) const {
  if (!factorized_) throw std::logic_error("BandCholesky::solve: no factorisation");
  const Eigen::Map<const SparseMatrix> L = L_.view();
  L.triangularView<Eigen::Lower>().solveInPlace(x);
  L.transpose().triangularView<Eigen::Upper>().solveInPlace(x);
}

double BandCholesky::scaledRcond() const {
  if (!factorized_) return 0;
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for (Eigen::Index j = 0; j < pivots_.size(); ++j) {
    const double pivot = pivots_[j];
    // A diagonal entry that is not positive, or infinite entries, leave no finite positive
    // pivot: nothing about such a matrix is well conditioned.
    if (!(pivot > 0) || !std::isfinite(pivot)) return 0;
    smallest = std::min(smallest, pivot);
    largest = std::max(largest, pivot);
  }
  return largest > 0 ? smallest / largest : 0;
}

double BandCholesky::factorEntries() const { return double(L_.nonZeros()); }

}  // namespace beamrotor
