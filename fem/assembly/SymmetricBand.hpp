// A symmetric matrix whose entries all lie within a few places of the diagonal: what a line of
// beams, a shaft or a rod gives when its free equations are numbered node by node. Stored as
// LAPACK's lower band (the storage of dpbtrf and dsbmv), so that a factorisation reads it as
// it is, and with no index per entry.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "fem/assembly/Assembly.hpp"

namespace beamrotor {

/// A lower triangle compressed by columns, in Eigen's layout, owning its arrays.
struct CompressedLower {
  int size = 0;
  std::vector<int> columnStarts;  ///< size + 1 entries
  std::vector<int> rows;
  Eigen::VectorXd values;
  long long nonZeros() const { return columnStarts.empty() ? 0 : columnStarts.back(); }
  Eigen::Map<const SparseMatrix> view() const {
    return {size, size, columnStarts.back(), columnStarts.data(), rows.data(), values.data()};
  }
};

class SymmetricBand {
 public:
  SymmetricBand() = default;
  /// An n x n zero matrix with `halfBandwidth` places below (and above) the diagonal.
  SymmetricBand(int n, int halfBandwidth);

  int size() const { return n_; }
  int halfBandwidth() const { return kd_; }
  /// Rows of the storage: column j holds A(j, j), ..., A(j + kd, j) at
  /// data()[j * leading()], ..., data()[j * leading() + kd].
  int leading() const { return kd_ + 1; }
  double* data() { return lower_.data(); }
  const double* data() const { return lower_.data(); }

  /// A(row, column) for column <= row <= column + halfBandwidth().
  double& lower(int row, int column) { return lower_[place(row, column)]; }
  double lower(int row, int column) const { return lower_[place(row, column)]; }
  /// A(i, j) for any i, j (zero outside the band).
  double operator()(int i, int j) const;
  Eigen::VectorXd diagonal() const;

  /// Calls visit(j, A(i, j)) for each j of row i's band in ascending order.
  template <class Visit>
  void forRow(int i, Visit&& visit) const {
    const int first = i > kd_ ? i - kd_ : 0, last = i + kd_ < n_ ? i + kd_ : n_ - 1;
    for (int j = first; j < i; ++j) visit(j, lower(i, j));
    for (int j = i; j <= last; ++j) visit(j, lower(j, i));
  }

  /// A x, row range by row range (each entry one sum in ascending column order, so the same
  /// bits on any number of cores).
  Eigen::VectorXd operator*(const Eigen::VectorXd& x) const;
  /// The lower triangle compressed by columns, without the exact zeros below the diagonal
  /// (the diagonal always kept), made in place: the band's storage becomes the values and is
  /// then shortened where it lies (realloc), so no second array of the band's size is ever
  /// held and what the zeros took is free for what comes next (the band is left empty).
  CompressedLower lowerWithoutZeros() &&;
  /// Both triangles, compressed, without the exact zeros off the diagonal (the pattern
  /// dropExactZeros leaves): the matrix for the sparse methods (mechanism search, LDL').
  SparseMatrix toSparse() const;
  /// Its stored entries that dropExactZeros would keep, counted in both triangles.
  long long nonZeros() const;

 private:
  /// Start of each column of lowerWithoutZeros() (n + 1 entries).
  std::vector<int> keptColumnStarts() const;
  Eigen::Index place(int row, int column) const {
    return Eigen::Index(column) * (kd_ + 1) + (row - column);
  }
  int n_ = 0, kd_ = 0;
  Eigen::VectorXd lower_;
};

}  // namespace beamrotor
