// CHOLMOD's supernodal Cholesky on a 3D frame's stiffness against the simplicial LDL' in the
// same order (a second method): the same solution to round-off, each with a small residual,
// the same pivots, and a matrix that is not positive definite reported, not factorised.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/solvers/LinearSolver.hpp"
#include "fem/solvers/SupernodalCholesky.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/run/ModelBuilder.hpp"

using namespace beamrotor;

namespace {

std::string jointName(int i, int j, int k) {
  std::string out = "n";
  out += std::to_string(i);
  out += '_';
  out += std::to_string(j);
  out += '_';
  out += std::to_string(k);
  return out;
}

/// A building of n x n bays and n storeys (4 m, 5 m, 3.5 m), `elements` Timoshenko elements
/// per member, tube columns and rectangular beams, bases clamped.
std::string buildingDeck(int n, int elements) {
  std::ostringstream d;
  d << "title: supernodal test building\nmodel: {dimension: 3d, formulation: timoshenko}\n"
    << "materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]\n"
    << "sections:\n  - {name: column, shape: tube, D: 0.3, t: 0.012}\n"
    << "  - {name: beam, shape: rectangle, b: 0.2, h: 0.4}\nnodes:\n";
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        d << "  - {name: " << jointName(i, j, k) << ", at: [" << 4 * i << ", " << 3.5 * k << ", "
          << 5 * j << "]}\n";
  d << "members:\n";
  int m = 0;
  const auto member = [&](const std::string& a, const std::string& b, const char* section) {
    d << "  - {name: m" << m++ << ", from: " << a << ", to: " << b << ", section: " << section
      << ", elements: " << elements << "}\n";
  };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        if (k < n) member(jointName(i, j, k), jointName(i, j, k + 1), "column");
        if (k == 0) continue;
        if (i < n) member(jointName(i, j, k), jointName(i + 1, j, k), "beam");
        if (j < n) member(jointName(i, j, k), jointName(i, j + 1, k), "beam");
      }
  d << "supports:\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      d << "  - {name: s" << i << "_" << j << ", at: " << jointName(i, j, 0)
        << ", fix: clamped}\n";
  d << "loads: [{type: self-weight, g: 9.81}]\nanalyses: [{type: static}]\n";
  return d.str();
}

/// The free stiffness of the building (without its exact zeros, as statics factorises it),
/// the node of each equation and its self-weight load vector.
struct Building {
  SparseMatrix K;
  std::vector<int> nodes;
  Eigen::VectorXd f;
};
Building building(int n, int elements) {
  const Deck deck = readDeck(parseDeckText(buildingDeck(n, elements), "building.yaml"));
  const std::shared_ptr<Model> model = buildModel(deck);
  const DofMap dofs(*model);
  Building out{SparseAssembler(*model, dofs).assemble(MatrixKind::stiffness), dofs.freeNodes(),
               loadVector(*model, dofs)};
  out.f.conservativeResize(out.K.rows());  // the free dofs come first (DofMap)
  dropExactZeros(out.K);
  return out;
}

/// ||K x - f|| / (||K||_1 ||x|| + ||f||): the normwise backward error of a solution.
double backwardError(const SparseMatrix& K, const Eigen::VectorXd& x, const Eigen::VectorXd& f) {
  const SparseMatrix full = K.selfadjointView<Eigen::Upper>();
  double norm1 = 0;
  for (Eigen::Index c = 0; c < full.outerSize(); ++c) {
    double column = 0;
    for (SparseMatrix::InnerIterator it(full, c); it; ++it) column += std::abs(it.value());
    norm1 = std::max(norm1, column);
  }
  return (full * x - f).norm() / (norm1 * x.norm() + f.norm());
}

}  // namespace

TEST_SUITE("linear solver") {
  TEST_CASE("a 3D frame: supernodal LL' and simplicial LDL' give the same answer to round-off") {
    const Building b = building(4, 3);  // 260 members, 780 beams, a factor of 45,851 entries
    SparseLDLT ldlt;
    ldlt.analyzePattern(b.K, b.nodes);
    ldlt.factorize(b.K);
    Eigen::VectorXd x1;
    ldlt.solveInto(b.f, x1);

    SupernodalCholesky cholesky;
    cholesky.analyse(b.K, ldlt.order());
    REQUIRE(cholesky.factorize(b.K));
    Eigen::VectorXd x2;
    cholesky.solveInto(b.f, x2);

    // Both are backward stable (Higham, Accuracy and Stability, ch. 10): the residual is a
    // modest multiple of the round-off eps = 2.2e-16 times ||K|| ||x|| (measured 1.1e-17 and
    // 8.5e-18 here, 1.5e-17 and 5.7e-17 on the large frame below).
    const double eps = std::numeric_limits<double>::epsilon();
    CHECK(backwardError(b.K, x1, b.f) < 10 * eps);
    CHECK(backwardError(b.K, x2, b.f) < 10 * eps);
    // The two solutions differ by at most the forward error bound, the backward error times
    // the condition number; on the symmetrically scaled system that is 1 / scaled rcond
    // (7.4e-4 here: the bound is 3e-11, the difference measured 8e-15).
    const double rcond = ldlt.scaledRcond();
    REQUIRE(rcond > 0);
    CHECK((x1 - x2).norm() / x1.norm() < 100 * eps / rcond);
    // The same elimination (CHOLMOD's postorder of the elimination tree is an equivalent
    // order), so the same pivots: L_jj^2 = D_jj to round-off, the smallest and the largest.
    const auto [low1, high1] = ldlt.scaledPivotRange();
    const auto [low2, high2] = cholesky.scaledPivotRange();
    CHECK(low2 == doctest::Approx(low1).epsilon(1e-10));
    CHECK(high2 == doctest::Approx(high1).epsilon(1e-10));
    // The same fill: L's entries counted by each analysis.
    CHECK(cholesky.factorEntries() == doctest::Approx(ldlt.predictedFactorEntries()));
  }

  TEST_CASE("a matrix that is not positive definite is reported by the supernodal factor") {
    const Building b = building(2, 2);
    SparseLDLT ldlt;
    ldlt.analyzePattern(b.K, b.nodes);
    SupernodalCholesky cholesky;
    cholesky.analyse(b.K, ldlt.order());
    SparseMatrix negative = -b.K;
    CHECK_FALSE(cholesky.factorize(negative));
    CHECK_FALSE(cholesky.factorised());
    CHECK(cholesky.scaledPivotRange() == std::pair{0.0, 0.0});
    // The LinearSolver falls back to the LDL', which factorises -K (indefinite is fine) and
    // solves it: -K x = -f gives K's own solution.
    LinearSolver solver;
    solver.analyzePattern(negative, MatrixSymmetry::byConstruction, b.nodes,
                          Definiteness::positiveExpected);
    solver.factorize(negative);
    CHECK(solver.methodName() == "CHOLMOD LDL'");
    const Eigen::VectorXd x = solver.solve(-b.f);
    CHECK(backwardError(b.K, x, b.f) < 10 * std::numeric_limits<double>::epsilon());
  }

  TEST_CASE("a large frame's stiffness goes to the supernodal factor, same answer as LDL'") {
    const Building b = building(12, 1);  // 5772 members; a factor of 3.2e6 entries
    LinearSolver chosen;
    chosen.analyzePattern(b.K, MatrixSymmetry::byConstruction, b.nodes,
                          Definiteness::positiveExpected);
    chosen.factorize(b.K);
    REQUIRE(chosen.methodName() == "CHOLMOD supernodal LL'");
    const Eigen::VectorXd x2 = chosen.solve(b.f);

    LinearSolver plain;  // no definiteness promised: the LDL'
    plain.analyzePattern(b.K, MatrixSymmetry::byConstruction, b.nodes);
    plain.factorize(b.K);
    REQUIRE(plain.methodName() == "CHOLMOD LDL'");
    const Eigen::VectorXd x1 = plain.solve(b.f);

    const double eps = std::numeric_limits<double>::epsilon();
    CHECK(backwardError(b.K, x2, b.f) < 10 * eps);
    CHECK(backwardError(b.K, x1, b.f) < 10 * eps);
    CHECK((x1 - x2).norm() / x1.norm() < 100 * eps / plain.rcond());
    CHECK(chosen.factorEntries() == doctest::Approx(plain.factorEntries()));
    CHECK(plain.factorEntries() >= kSupernodalFrom);
  }
}
