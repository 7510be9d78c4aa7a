// Pencils whose dofs fall into blocks that do not couple: the blocks found, and eigenpairs
// solved block by block against closed forms.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/solvers/DecoupledBlocks.hpp"
#include "fem/solvers/SymmetricEigen.hpp"
#include "problems/bench/StandardModels.hpp"
#include "tests/Helpers.hpp"
#include "tests/fem/solvers/ChainPencil.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// The chains side by side, their dofs dealt out in turn (dof i of the whole belongs to chain
/// i mod 3 while all three last), so that no block is a contiguous range.
struct Dealt {
  SparseMatrix K, M;
  std::vector<double> exact;  // every eigenvalue of every chain, ascending
};

Dealt dealt(const std::vector<ChainPencil>& chains) {
  int n = 0;
  for (const ChainPencil& c : chains) n += int(c.K.rows());
  std::vector<std::vector<int>> position(chains.size());
  for (int next = 0; next < n;)
    for (std::size_t c = 0; c < chains.size(); ++c)
      if (position[c].size() < std::size_t(chains[c].K.rows())) position[c].push_back(next++);
  std::vector<Eigen::Triplet<double>> k, m;
  Dealt out;
  for (std::size_t c = 0; c < chains.size(); ++c) {
    for (int col = 0; col < chains[c].K.outerSize(); ++col) {
      for (SparseMatrix::InnerIterator it(chains[c].K, col); it; ++it)
        k.emplace_back(position[c][it.row()], position[c][col], it.value());
      for (SparseMatrix::InnerIterator it(chains[c].M, col); it; ++it)
        m.emplace_back(position[c][it.row()], position[c][col], it.value());
    }
    out.exact.insert(out.exact.end(), chains[c].exact.begin(), chains[c].exact.end());
  }
  out.K.resize(n, n);
  out.M.resize(n, n);
  out.K.setFromTriplets(k.begin(), k.end());
  out.M.setFromTriplets(m.begin(), m.end());
  std::sort(out.exact.begin(), out.exact.end());
  return out;
}

/// The `count` values of `all` nearest sigma, ascending.
std::vector<double> nearestValues(std::vector<double> all, int count, double sigma) {
  std::sort(all.begin(), all.end(),
            [sigma](double a, double b) { return std::abs(a - sigma) < std::abs(b - sigma); });
  all.resize(count);
  std::sort(all.begin(), all.end());
  return all;
}

}  // namespace

TEST_SUITE("decoupled blocks") {
  TEST_CASE("a straight planar line's largest block is its bending dofs; the rest are axial") {
    // 30 spans of 10 elements pinned (ux, uy) at every span end: 301 nodes, free are 270 uy
    // and 301 rz (bending) and 270 ux in 30 chains of 9, which no entry of K or M couples
    // to bending (the members lie along x: every such entry is an exact zero).
    const PlanarBenchModel bench = planarBenchModel(300);
    const DofMap dofs(*bench.model);
    const SparseAssembler assembler(*bench.model, dofs);
    const SparseMatrix K = assembler.assemble(MatrixKind::stiffness);
    const SparseMatrix M = assembler.assemble(MatrixKind::mass);
    const LargestBlock split = largestBlock(K, M);
    CHECK(split.dofs.size() == 571);
    CHECK(split.rest.size() == 270);
    CHECK(std::none_of(split.dofs.begin(), split.dofs.end(),
                       [&](int e) { return dofs.dofOf(e).dof == Dof::ux; }));
    CHECK(std::all_of(split.rest.begin(), split.rest.end(),
                      [&](int e) { return dofs.dofOf(e).dof == Dof::ux; }));
    // The block's matrix against the dense matrix's rows and columns picked by index.
    const Eigen::MatrixXd dense(K);
    CHECK((Eigen::MatrixXd(principalSubmatrix(K, split.rest)) - dense(split.rest, split.rest))
              .norm() == 0);
    CHECK((Eigen::MatrixXd(principalSubmatrix(K, split.dofs)) - dense(split.dofs, split.dofs))
              .norm() == 0);
  }

  TEST_CASE("eigenpairs solved block by block are the whole pencil's nearest the shift") {
    // Three chains with closed-form eigenvalues (ChainPencil.hpp): 400 and 250 dofs of
    // 2 - 2 cos(j pi / (n + 1)), interleaved (6.1e-5, 1.6e-4, 2.5e-4, ...), and 3 dofs whose
    // eigenvalues (1.5e-5, 2e-5, 3.1e-5) lie below both. The largest block (400) goes to
    // Lanczos; the rest splits again into the 250-dof chain and the 3-dof one. Below the
    // spectrum the lowest 12 come from all three chains; inside it (sigma = 6e-4, LU at
    // sigma) the 6 nearest from two.
    const Dealt p = dealt({chainPencil(400, 2, -1, 1, 0), chainPencil(250, 2, -1, 1, 0),
                           chainPencil(3, 2e-5, 0, 1, 0.25)});
    REQUIRE(largestBlock(p.K, p.M).dofs.size() == 400);
    for (const auto& [count, sigma] : {std::pair{12, 0.0}, std::pair{6, 6e-4}}) {
      CAPTURE(sigma);
      const EigenPairs pairs = symmetricEigenpairs(p.K, p.M, count, sigma);
      const std::vector<double> exact = nearestValues(p.exact, count, sigma);
      REQUIRE(pairs.values.size() == count);
      CHECK(pairs.missedBySturmCount == 0);
      for (int k = 0; k < count; ++k) {
        CAPTURE(k);
        // Backward stable solves of pencils with |K| <= 4, M = I (or 1 +- 0.5): absolute
        // errors of a few eps |K| ~ 1e-15, below 1e-10 of the smallest eigenvalue, 1.5e-5.
        CHECK(relError(pairs.values[k], exact[k]) < 1e-9);
        const Eigen::VectorXd x = pairs.vectors.col(k);
        CHECK((p.K * x - pairs.values[k] * (p.M * x)).norm() < 1e-12);
      }
      // M-orthonormal across blocks too (vectors of different blocks have disjoint dofs).
      const Eigen::MatrixXd X = pairs.vectors;
      CHECK((X.transpose() * (p.M * X) - Eigen::MatrixXd::Identity(count, count)).norm() < 1e-12);
    }
  }

  TEST_CASE("equal eigenvalues in two blocks are all found") {
    // Two equal chains of 300 dofs (two bending planes of a square section, in effect): every
    // eigenvalue 2 - 2 cos(j pi / 301) is double. The largest block (one chain) gives the 6
    // lowest of its own; the counts on the rest find its equal ones within reach, and they
    // displace the first chain's higher ones: each of the 3 lowest twice.
    const Dealt p = dealt({chainPencil(300, 2, -1, 1, 0), chainPencil(300, 2, -1, 1, 0)});
    const EigenPairs pairs = symmetricEigenpairs(p.K, p.M, 6, 0.0);
    REQUIRE(pairs.values.size() == 6);
    CHECK(pairs.missedBySturmCount == 0);
    for (int k = 0; k < 6; ++k) {
      CAPTURE(k);
      // As above: absolute errors ~1e-15 against the smallest eigenvalue, 1.1e-4.
      CHECK(relError(pairs.values[k], p.exact[k]) < 1e-9);
    }
    const Eigen::MatrixXd X = pairs.vectors;
    CHECK((X.transpose() * (p.M * X) - Eigen::MatrixXd::Identity(6, 6)).norm() < 1e-12);
  }
}
