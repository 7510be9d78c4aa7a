// The sparsity pattern of a compressed matrix, kept to tell whether a later matrix has the
// same one (column starts and row indices compared exactly): what decides whether a symbolic
// analysis, which reads the pattern, can serve again.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace beamrotor {

class KeptPattern {
 public:
  /// Keeps A's pattern (A compressed), replacing the one kept before.
  template <class Matrix>
  void keep(const Matrix& A) {
    starts_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
    rows_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  }
  /// True when A is compressed with the kept pattern; false when none is kept.
  template <class Matrix>
  bool matches(const Matrix& A) const {
    return A.isCompressed() && starts_.size() == std::size_t(A.outerSize()) + 1 &&
           rows_.size() == std::size_t(A.nonZeros()) &&
           std::equal(starts_.begin(), starts_.end(), A.outerIndexPtr()) &&
           std::equal(rows_.begin(), rows_.end(), A.innerIndexPtr());
  }

 private:
  std::vector<int> starts_, rows_;
};

/// True when A and B are compressed with the same pattern and the same values, entry for entry:
/// a factor of one serves the other.
template <class Matrix>
bool sameEntries(const Matrix& A, const Matrix& B) {
  return A.isCompressed() && B.isCompressed() && A.rows() == B.rows() && A.cols() == B.cols() &&
         A.nonZeros() == B.nonZeros() &&
         std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1,
                    B.outerIndexPtr()) &&
         std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), B.innerIndexPtr()) &&
         std::equal(A.valuePtr(), A.valuePtr() + A.nonZeros(), B.valuePtr());
}

}  // namespace beamrotor
