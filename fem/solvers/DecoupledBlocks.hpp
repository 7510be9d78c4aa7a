// A pencil (K, M) whose dofs fall into blocks that neither matrix couples, and each block on its
// own. The blocks are the connected components of the graph whose edges are the nonzeros of K
// and M off the diagonal (exact zeros are no edges: dropExactZeros). A straight line's axial
// dofs never meet its bending ones, nor a flat grillage's in-plane dofs its out-of-plane ones,
// nor one bending plane of a straight 3D member the other: the pencil's eigenpairs are those of
// the blocks, each eigenvector zero outside its block.
#pragma once

#include <span>
#include <vector>

#include "fem/assembly/Assembly.hpp"

namespace beamrotor {

/// The dofs of the largest block and of all the others, each ascending.
struct LargestBlock {
  std::vector<int> dofs;
  std::vector<int> rest;
};

/// K, M square, of the same size, compressed by columns.
LargestBlock largestBlock(const SparseMatrix& K, const SparseMatrix& M);

/// The same for one matrix's pattern: every stored entry couples, whatever its value, so the
/// blocks hold for every matrix of that pattern (a held dof's cleared row and column too).
LargestBlock largestBlockOfPattern(const SparseMatrix& A);

/// values[row] for each of `rows`: a block's share of a list kept per row (the node of each
/// equation); empty when `values` is. Ascending rows keep a node's rows consecutive.
std::vector<int> entriesAt(std::span<const int> values, const std::vector<int>& rows);

/// A(dofs, dofs) for ascending dofs: the rows and columns kept, in their order.
SparseMatrix principalSubmatrix(const SparseMatrix& A, const std::vector<int>& dofs);

}  // namespace beamrotor
