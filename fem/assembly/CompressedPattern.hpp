// A compressed sparse pattern written column by column from a visitor that lists each column's
// rows: one pass counts the entries, a second writes them in place, so nothing is reallocated
// however large the matrix (the assembler's pattern, the union of two patterns).
#pragma once

#include <algorithm>

#include "fem/assembly/Assembly.hpp"

namespace beamrotor {

/// A rows x cols pattern, values zero. forEachRow(col, visit) must call visit(row) once for
/// each row of column col, in ascending order, and the same way on both passes.
template <class ForEachRow>
SparseMatrix compressedPattern(int rows, int cols, ForEachRow&& forEachRow) {
  long long entries = 0;
  for (int col = 0; col < cols; ++col) forEachRow(col, [&](int) { ++entries; });
  SparseMatrix A(rows, cols);
  A.resizeNonZeros(Eigen::Index(entries));
  int* colStart = A.outerIndexPtr();
  int* rowOf = A.innerIndexPtr();
  int next = 0;
  for (int col = 0; col < cols; ++col) {
    colStart[col] = next;
    forEachRow(col, [&](int row) { rowOf[next++] = row; });
  }
  colStart[cols] = next;
  std::fill_n(A.valuePtr(), entries, 0.0);
  return A;
}

}  // namespace beamrotor
