#include "fem/assembly/SymmetricBand.hpp"

#include <stdexcept>
#include <utility>

#include "fem/assembly/ParallelParts.hpp"

namespace beamrotor {

SymmetricBand::SymmetricBand(int n, int halfBandwidth)
    : n_(n), kd_(halfBandwidth), lower_(std::size_t(n) * std::size_t(halfBandwidth + 1), 0.0) {
  if (n < 0 || halfBandwidth < 0)
    throw std::invalid_argument("SymmetricBand: negative size or bandwidth");
}

double SymmetricBand::operator()(int i, int j) const {
  if (i < j) std::swap(i, j);
  return i - j <= kd_ ? lower(i, j) : 0.0;
}

Eigen::VectorXd SymmetricBand::diagonal() const {
  Eigen::VectorXd d(n_);
  for (int j = 0; j < n_; ++j) d[j] = lower(j, j);
  return d;
}

Eigen::VectorXd SymmetricBand::operator*(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y(n_);
  forEvenParts(n_, [&](int first, int end) {
    for (int i = first; i < end; ++i) {
      double sum = 0;
      forRow(i, [&](int j, double a) { sum += a * x[j]; });
      y[i] = sum;
    }
  });
  return y;
}

long long SymmetricBand::nonZeros() const {
  long long count = n_;
  for (int j = 0; j < n_; ++j)
    for (int i = j + 1; i <= j + kd_ && i < n_; ++i) count += lower(i, j) != 0.0 ? 2 : 0;
  return count;
}

SparseMatrix SymmetricBand::toSparse() const {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(nonZeros()));
  for (int j = 0; j < n_; ++j) {
    entries.emplace_back(j, j, lower(j, j));
    for (int i = j + 1; i <= j + kd_ && i < n_; ++i)
      if (lower(i, j) != 0.0) {
        entries.emplace_back(i, j, lower(i, j));
        entries.emplace_back(j, i, lower(i, j));
      }
  }
  SparseMatrix A(n_, n_);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

}  // namespace beamrotor
