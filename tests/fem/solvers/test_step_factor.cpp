// StepFactor: a time step's factor, dense below kDenseLimit equations and UMFPACK's above,
// against UMFPACK's own solve (a second method) and its singularity measure.
#include <doctest/doctest.h>

#include <Eigen/Sparse>
#include <vector>

#include "fem/solvers/SparseLU.hpp"
#include "fem/solvers/StepFactor.hpp"

using namespace beamrotor;

namespace {

/// A chain of n masses on springs with a gyroscopic-like skew coupling (unsymmetric, well
/// conditioned): 2 + i/n on the diagonal, -1 and -0.5 off it.
SparseMatrix chain(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + double(i) / n);
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, -1.0);
      t.emplace_back(i + 1, i, -0.5);
    }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

}  // namespace

TEST_SUITE("linear solver") {
  TEST_CASE("a step's factor: dense when small, UMFPACK when large, the same solutions") {
    for (int n : {1, 7, int(StepFactor::kDenseLimit), int(StepFactor::kDenseLimit) + 1, 300}) {
      CAPTURE(n);
      const SparseMatrix A = chain(n);
      const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
      StepFactor step;
      REQUIRE(step.factorize(A));
      CHECK(step.factorizations() == 1);
      SparseLU umfpack;
      umfpack.compute(A);
      const Eigen::VectorXd x = step.solve(b), reference = umfpack.solve(b);
      // Both backward stable on a matrix of condition < 10: round-off of the solution.
      CHECK((x - reference).norm() <= 1e-14 * reference.norm());
      CHECK((A * x - b).norm() <= 1e-14 * b.norm());
      CHECK(step.factorEntries() > 0);
    }
  }

  TEST_CASE("a step's factor: a scaled diagonal has rcond 1, a singular matrix 0") {
    // Rows scaled by their sums make every pivot of a diagonal matrix 1, whatever its units.
    SparseMatrix D(3, 3);
    D.insert(0, 0) = 1e-9;
    D.insert(1, 1) = 1.0;
    D.insert(2, 2) = 1e9;
    StepFactor step;
    REQUIRE(step.factorize(D));
    CHECK(step.rcond() == doctest::Approx(1.0).epsilon(1e-15));  // a / a: round-off
    // A free dof with neither mass nor stiffness: an empty row and column.
    SparseMatrix S(3, 3);
    S.insert(0, 0) = 2.0;
    S.insert(2, 2) = 3.0;
    S.makeCompressed();
    CHECK_FALSE(step.factorize(S));
    CHECK(step.rcond() == 0.0);
    CHECK(step.factorizations() == 2);
    // The same matrix again keeps its factor; a changed entry is factorised afresh.
    CHECK_FALSE(step.factorize(S));
    CHECK(step.factorizations() == 2);
    S.coeffRef(1, 1) = 1.0;
    CHECK(step.factorize(S));
    CHECK(step.factorizations() == 3);
  }
}
