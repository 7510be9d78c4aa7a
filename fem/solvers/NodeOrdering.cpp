#include "fem/solvers/NodeOrdering.hpp"

#include <amd.h>

#include <algorithm>
#include <stdexcept>

namespace beamrotor {

std::vector<int> nodeByNodeOrdering(const SparseMatrix& A, std::span<const int> nodeOfRow) {
  const int n = int(A.rows());
  if (int(nodeOfRow.size()) != n || A.cols() != n)
    throw std::invalid_argument("nodeByNodeOrdering: one node per row of a square matrix");
  // The groups: runs of rows with the same node.
  std::vector<int> groupStart, groupOfRow(n);
  for (int i = 0; i < n; ++i) {
    if (i == 0 || nodeOfRow[i] != nodeOfRow[i - 1]) groupStart.push_back(i);
    groupOfRow[i] = int(groupStart.size()) - 1;
  }
  const int groups = int(groupStart.size());
  groupStart.push_back(n);

  // The graph of groups, column by column, each neighbour once (stamped with its column).
  std::vector<int> columnStart(groups + 1, 0), neighbours, stamp(groups, -1);
  neighbours.reserve(std::size_t(A.nonZeros() / 4) + groups);
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  for (int g = 0; g < groups; ++g) {
    const std::size_t first = neighbours.size();
    stamp[g] = g;  // no self loops
    for (int col = groupStart[g]; col < groupStart[g + 1]; ++col)
      for (int k = outer[col]; k < outer[col + 1]; ++k) {
        const int other = groupOfRow[inner[k]];
        if (stamp[other] == g) continue;
        stamp[other] = g;
        neighbours.push_back(other);
      }
    std::sort(neighbours.begin() + std::ptrdiff_t(first), neighbours.end());
    columnStart[g + 1] = int(neighbours.size());
  }

  // AMD forms the symmetric pattern itself when only one triangle of A was stored.
  std::vector<int> groupOrder(groups);
  if (amd_order(groups, columnStart.data(), neighbours.data(), groupOrder.data(), nullptr,
                nullptr) < AMD_OK)
    throw std::runtime_error("AMD failed to order the graph of nodes");

  std::vector<int> order;
  order.reserve(std::size_t(n));
  for (const int g : groupOrder)
    for (int row = groupStart[g]; row < groupStart[g + 1]; ++row) order.push_back(row);
  return order;
}

}  // namespace beamrotor
