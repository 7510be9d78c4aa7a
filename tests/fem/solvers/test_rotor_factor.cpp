// RepeatedFactor (fem/solvers/RotorFactor.hpp): one symbolic analysis per pattern, one numeric
// factorisation per distinct matrix; a matrix equal to the last one keeps its factor, and its
// solutions are those of a fresh factorisation, bit for bit. Reference: a dense LU of the
// same matrix (a second method).
#include <doctest/doctest.h>

#include <vector>

#include "fem/solvers/RotorFactor.hpp"
#include "fem/solvers/Tolerances.hpp"

using namespace beamrotor;

namespace {

/// A non-symmetric tridiagonal matrix of order 8 (diagonal 4, sub-diagonal -1, super-diagonal
/// -2, so diagonally dominant), with `corner` added at (0, 0).
SparseMatrixOf<double> repeatedFactorSample(double corner) {
  std::vector<Eigen::Triplet<double>> entries;
  const int n = 8;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, i == 0 ? 4 + corner : 4);
    if (i > 0) entries.emplace_back(i, i - 1, -1);
    if (i + 1 < n) entries.emplace_back(i, i + 1, -2);
  }
  SparseMatrixOf<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

/// Largest entry of x minus the dense LU solution of A x = b, relative to that solution.
double repeatedFactorError(const SparseMatrixOf<double>& A, const Eigen::VectorXd& b,
                           const Eigen::VectorXd& x) {
  const Eigen::VectorXd dense = Eigen::MatrixXd(A).partialPivLu().solve(b);
  return (x - dense).cwiseAbs().maxCoeff() / dense.cwiseAbs().maxCoeff();
}

}  // namespace

TEST_SUITE("repeated factor") {
  TEST_CASE("a repeated matrix keeps its factor; other values on the pattern are refactorised") {
    const SparseMatrixOf<double> A = repeatedFactorSample(0), B = repeatedFactorSample(3);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(8, -1.0, 2.0);
    RepeatedFactor<double> factor(false);

    REQUIRE(factor.factorize(A));
    const Eigen::VectorXd x = factor.solve(b);
    // Condition number of A below 10: a few roundings of numbers of size 1.
    CHECK(repeatedFactorError(A, b, x) < 1e-14);

    REQUIRE(factor.factorize(A));  // the same entries: nothing redone
    CHECK(factor.factorizations() == 1);
    CHECK(Eigen::VectorXd(factor.solve(b)) == x);

    REQUIRE(factor.factorize(B));  // one entry changed: a new numeric factorisation
    CHECK(factor.factorizations() == 2);
    CHECK(repeatedFactorError(B, b, factor.solve(b)) < 1e-14);

    REQUIRE(factor.factorize(A));  // A again after B: refactorised, the same bits as the first
    CHECK(factor.factorizations() == 3);
    CHECK(Eigen::VectorXd(factor.solve(b)) == x);
    CHECK(factor.analyses() == 1);
  }

  TEST_CASE("a singular matrix stays reported singular when it repeats") {
    // Rows 0 and 1 equal: singular, UMFPACK's rcond (min |U_ii| / max |U_ii|) is 0.
    SparseMatrixOf<double> S = repeatedFactorSample(0);
    S.coeffRef(1, 0) = 4;
    S.coeffRef(1, 1) = -2;
    S.coeffRef(1, 2) = 0;
    RepeatedFactor<double> factor(false);
    CHECK_FALSE(factor.factorize(S));
    CHECK_FALSE(factor.factorize(S));
    CHECK(factor.factorizations() == 1);
    CHECK(factor.rcond() <= kSingularRcond);
  }
}
