#include "fem/assembly/SymmetricBand.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "fem/assembly/ParallelParts.hpp"

namespace beamrotor {

SymmetricBand::SymmetricBand(int n, int halfBandwidth) : n_(n), kd_(halfBandwidth) {
  if (n < 0 || halfBandwidth < 0)
    throw std::invalid_argument("SymmetricBand: negative size or bandwidth");
  // Zeroed by parts, each its own columns: 134 MB for a planar line of 10^6 elements.
  lower_.resize(Eigen::Index(n) * leading());
  forEvenParts(n, [&](int first, int end) {
    std::fill(lower_.data() + place(first, first), lower_.data() + place(end, end), 0.0);
  });
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

std::vector<int> SymmetricBand::keptColumnStarts() const {
  std::vector<int> start(std::size_t(n_) + 1, 0);
  forEvenParts(n_, [&](int first, int end) {
    for (int j = first; j < end; ++j) {
      int kept = 1;  // the diagonal
      for (int i = j + 1; i <= j + kd_ && i < n_; ++i) kept += lower(i, j) != 0.0;
      start[j + 1] = kept;
    }
  });
  for (int j = 0; j < n_; ++j) start[j + 1] += start[j];
  return start;
}

long long SymmetricBand::nonZeros() const {
  return 2 * (long long)keptColumnStarts()[n_] - n_;
}

CompressedLower SymmetricBand::lowerWithoutZeros() && {
  CompressedLower out;
  out.size = n_;
  out.columnStarts = keptColumnStarts();
  const std::vector<int>& start = out.columnStarts;
  out.rows.resize(std::size_t(start[n_]));
  // Each part packs its columns to the front of its own stretch of the storage: an entry
  // never moves up, so it is read before anything is written over it, and no part writes
  // where another reads. The parts' packed runs are then moved down into place in order.
  const std::vector<int> bounds = evenRanges(n_, partsFor(std::size_t(n_)));
  runParts(int(bounds.size()) - 1, [&](int part) {
    const int first = bounds[part], end = bounds[part + 1];
    Eigen::Index packed = place(first, first);     // where this part's next value goes
    std::size_t kept = std::size_t(start[first]);  // and its row, at its final place
    for (int j = first; j < end; ++j)
      for (int i = j; i <= j + kd_ && i < n_; ++i)
        if (const double a = lower(i, j); i == j || a != 0.0) {
          out.rows[kept++] = i;
          lower_[packed++] = a;
        }
  });
  for (std::size_t part = 1; part + 1 < bounds.size(); ++part) {
    const int first = bounds[part], end = bounds[part + 1];
    double* data = lower_.data();
    std::memmove(data + start[first], data + place(first, first),
                 sizeof(double) * std::size_t(start[end] - start[first]));
  }
  lower_.conservativeResize(start[n_]);
  out.values = std::move(lower_);
  *this = SymmetricBand();
  return out;
}

SparseMatrix SymmetricBand::toSparse() const {
  // Eigen writes the full matrix column by column, each in ascending rows.
  const CompressedLower lower = SymmetricBand(*this).lowerWithoutZeros();
  return SparseMatrix(lower.view().selfadjointView<Eigen::Lower>());
}

}  // namespace beamrotor
