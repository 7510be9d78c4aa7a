#include "fem/solvers/DecoupledBlocks.hpp"

#include <numeric>

namespace beamrotor {

namespace {

/// Disjoint sets of dofs, joined pair by pair (union by size, path halving).
class DofSets {
 public:
  explicit DofSets(int n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int root(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(int a, int b) {
    a = root(a);
    b = root(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }
  int size(int i) { return size_[root(i)]; }

 private:
  std::vector<int> parent_, size_;
};

/// Joins the dofs of every nonzero entry of A, or of every stored one (`stored`).
void joinCoupled(const SparseMatrix& A, DofSets& sets, bool stored = false) {
  for (int col = 0; col < int(A.outerSize()); ++col)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it)
      if (stored || it.value() != 0) sets.join(int(it.row()), col);
}

/// The largest of the sets and the rest, each ascending.
LargestBlock largestOf(DofSets& sets, int n) {
  LargestBlock out;
  int largest = 0;
  for (int i = 1; i < n; ++i)
    if (sets.size(i) > sets.size(largest)) largest = i;
  const int root = sets.root(largest);
  out.dofs.reserve(sets.size(root));
  out.rest.reserve(n - sets.size(root));
  for (int i = 0; i < n; ++i) (sets.root(i) == root ? out.dofs : out.rest).push_back(i);
  return out;
}

}  // namespace

LargestBlock largestBlock(const SparseMatrix& K, const SparseMatrix& M) {
  const int n = int(K.rows());
  if (n == 0) return {};
  DofSets sets(n);
  joinCoupled(K, sets);
  joinCoupled(M, sets);
  return largestOf(sets, n);
}

LargestBlock largestBlockOfPattern(const SparseMatrix& A) {
  const int n = int(A.rows());
  if (n == 0) return {};
  DofSets sets(n);
  joinCoupled(A, sets, true);
  return largestOf(sets, n);
}

std::vector<int> entriesAt(std::span<const int> values, const std::vector<int>& rows) {
  std::vector<int> out;
  if (values.empty()) return out;
  out.reserve(rows.size());
  for (const int row : rows) out.push_back(values[std::size_t(row)]);
  return out;
}

SparseMatrix principalSubmatrix(const SparseMatrix& A, const std::vector<int>& dofs) {
  std::vector<int> position(A.rows(), -1);
  for (int k = 0; k < int(dofs.size()); ++k) position[dofs[k]] = k;
  const int m = int(dofs.size());
  // Two passes: count each kept column's kept rows, then write them (rows stay ascending: the
  // positions keep the dofs' order).
  SparseMatrix out(m, m);
  long long entries = 0;
  for (const int col : dofs)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it) entries += position[it.row()] >= 0;
  out.resizeNonZeros(Eigen::Index(entries));
  int *start = out.outerIndexPtr(), *row = out.innerIndexPtr();
  double* value = out.valuePtr();
  int next = 0;
  for (int k = 0; k < m; ++k) {
    start[k] = next;
    for (SparseMatrix::InnerIterator it(A, dofs[k]); it; ++it)
      if (const int r = position[it.row()]; r >= 0) {
        row[next] = r;
        value[next++] = it.value();
      }
  }
  start[m] = next;
  return out;
}

}  // namespace beamrotor
