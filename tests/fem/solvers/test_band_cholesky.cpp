// LAPACK's banded Cholesky: solutions against a closed-form inverse, the conditioning
// estimate and fill against CHOLMOD's LDL' of the same matrix, and a matrix that is not
// positive definite refused.
#include <doctest/doctest.h>

#include "fem/assembly/BandAssembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/solvers/BandCholesky.hpp"
#include "fem/solvers/LinearSolver.hpp"
#include "problems/bench/StandardModels.hpp"

using namespace beamrotor;

TEST_SUITE("band Cholesky") {
  TEST_CASE("the second-difference matrix: its inverse in closed form") {
    // A = tridiag(-1, 2, -1) of order n has (A^-1)_ij = i (n + 1 - j) / (n + 1) for i <= j
    // (1-based). Its condition number is about 4 n^2 / pi^2 = 1e3 here: round-off ~1e-13.
    const int n = 50;
    SymmetricBand A(n, 2);  // one more place than needed: zeros in the band are harmless
    for (int j = 0; j < n; ++j) {
      A.lower(j, j) = 2;
      if (j + 1 < n) A.lower(j + 1, j) = -1;
    }
    BandCholesky factor;
    REQUIRE(factor.factorize(A));
    for (int k : {0, 17, n - 1}) {
      const Eigen::VectorXd x = factor.solve(Eigen::VectorXd::Unit(n, k));
      for (int i = 0; i < n; ++i) {
        const int lo = std::min(i, k) + 1, hi = std::max(i, k) + 1;
        CHECK(x[i] == doctest::Approx(double(lo) * (n + 1 - hi) / (n + 1)).epsilon(1e-13));
      }
    }
    // The kept factor holds no zeros of the band: n diagonal entries and n - 1 below it.
    CHECK(factor.factorEntries() == 2 * n - 1);
    // Pivots L_jj^2 / A_jj = (j + 2) / (2 (j + 1)): from 1 down to (n + 1) / (2 n).
    CHECK(factor.scaledRcond() == doctest::Approx((n + 1.0) / (2.0 * n)).epsilon(1e-14));
  }

  TEST_CASE("the planar line: rcond and fill equal CHOLMOD's LDL' of the same K") {
    const PlanarBenchModel bench = planarBenchModel(500);
    const DofMap dofs(*bench.model);
    const SymmetricBand K =
        assembleBand(*bench.model, dofs, MatrixKind::stiffness, *stiffnessBand(*bench.model, dofs));
    BandCholesky band;
    REQUIRE(band.factorize(K));
    LinearSolver sparse;
    const SparseMatrix Ks = K.toSparse();
    sparse.analyzePattern(Ks);
    sparse.factorize(Ks);
    REQUIRE(sparse.healthy(0));
    // The same elimination in the same order (no fill either way): pivots L_jj^2 against
    // D_jj, equal to round-off (K's condition number is about 1e9, the pivots' is not).
    CHECK(band.scaledRcond() == doctest::Approx(sparse.rcond()).epsilon(1e-12));
    CHECK(band.factorEntries() == sparse.factorEntries());
    // Both solutions solve K x = b to the round-off the condition number allows.
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(Ks.rows(), -1.0, 2.0);
    const Eigen::VectorXd x = band.solve(b), xs = sparse.solve(b);
    CHECK((x - xs).norm() <= 1e-6 * xs.norm());
    CHECK((Ks * x - b).norm() <= 1e-9 * b.norm());
  }

  TEST_CASE("not positive definite: refused, nothing to solve") {
    SymmetricBand A(3, 1);
    A.lower(0, 0) = 1;
    A.lower(1, 0) = 2;  // [[1, 2], [2, 1]] has eigenvalues 3 and -1
    A.lower(1, 1) = 1;
    A.lower(2, 2) = 1;
    BandCholesky factor;
    CHECK_FALSE(factor.factorize(A));
    CHECK_FALSE(factor.factorized());
    CHECK(factor.scaledRcond() == 0);
    CHECK_THROWS(factor.solve(Eigen::VectorXd::Ones(3)));
  }
}
