// SymbolicReuse: a symmetric system of a pattern met before is factorised on the kept symbolic
// analysis, and its solution is the one a fresh analysis gives, bit for bit (CHOLMOD's analysis
// reads the pattern alone); a new pattern or a non-symmetric matrix is analysed anew.
#include <doctest/doctest.h>

#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/solvers/SymbolicReuse.hpp"
#include "fem/solvers/Tolerances.hpp"
#include "problems/bench/StandardModels.hpp"

using namespace beamrotor;

namespace {

SparseMatrix benchStiffness(int elements) {
  const PlanarBenchModel bench = planarBenchModel(elements);
  const DofMap dofs(*bench.model);
  return SparseAssembler(*bench.model, dofs).assemble(MatrixKind::stiffness);
}

/// The solution of A x = b by a solver analysed and factorised for A alone.
Eigen::VectorXd freshSolution(const SparseMatrix& A, const Eigen::VectorXd& b) {
  LinearSolver fresh;
  fresh.analyzePattern(A);
  fresh.factorize(A);
  return fresh.solve(b);
}

}  // namespace

TEST_SUITE("symbolic reuse") {
  TEST_CASE("one analysis serves every symmetric matrix of a pattern, bit for bit") {
    const SparseMatrix K = benchStiffness(200);
    // Other values on the same pattern, still symmetric: K scaled and its diagonal stiffened
    // (a design point with other sections and supports' springs).
    SparseMatrix K2 = 3.5 * K;
    K2.diagonal() += Eigen::VectorXd::LinSpaced(K.rows(), 1e3, 2e3);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);

    SymbolicReuse reuse;
    for (const SparseMatrix* A : std::vector<const SparseMatrix*>{&K, &K2, &K}) {
      LinearSolver& solver = reuse.analysedFor(*A);
      solver.factorize(*A);
      REQUIRE(solver.healthy(kSingularRcond));
      const Eigen::VectorXd x = solver.solve(b);
      CHECK(x == freshSolution(*A, b));  // the same operations in the same order: equal bits
      // And a solution at all: the residual at round-off (K's condition number ~1e9).
      CHECK((*A * x - b).norm() <= 1e-6 * b.norm());
    }
    CHECK(reuse.analyses() == 1);
    CHECK(reuse.reuses() == 2);

    // Another pattern (more elements): analysed anew, then kept for its own.
    const SparseMatrix K3 = benchStiffness(150);
    const Eigen::VectorXd b3 = Eigen::VectorXd::Ones(K3.rows());
    reuse.analysedFor(K3).factorize(K3);
    CHECK(reuse.analyses() == 2);
    reuse.analysedFor(K3);
    CHECK(reuse.reuses() == 3);
  }

  TEST_CASE("a non-symmetric matrix is analysed every time, by LU") {
    const SparseMatrix K = benchStiffness(40);
    // One off-diagonal pair made unequal (a cross-coupled bearing): UMFPACK's analysis reads
    // values, so it is never kept.
    SparseMatrix N = K;
    const int col = 4;
    SparseMatrix::InnerIterator it(N, col);
    while (it && it.row() == col) ++it;
    REQUIRE(it);
    it.valueRef() *= 1.5;
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(N.rows(), 1.0, 2.0);
    SymbolicReuse reuse;
    for (int pass = 0; pass < 2; ++pass) {
      LinearSolver& solver = reuse.analysedFor(N);
      CHECK_FALSE(solver.symmetric());
      solver.factorize(N);
      const Eigen::VectorXd x = solver.solve(b);
      CHECK((N * x - b).norm() <= 1e-6 * b.norm());
    }
    CHECK(reuse.analyses() == 2);
    CHECK(reuse.reuses() == 0);
    // Back to the symmetric matrix of the same pattern: analysed anew (the kept analysis was
    // LU's), then reused.
    reuse.analysedFor(K);
    reuse.analysedFor(K);
    CHECK(reuse.analyses() == 3);
    CHECK(reuse.reuses() == 1);
  }
}
