// The direct solver chosen from the matrix: CHOLMOD LDL' for symmetric matrices, UMFPACK LU
// otherwise. Each is checked against the other (a second method) and against exact algebra.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>

#include "elements/Bearing.hpp"
#include "fem/assembly/Assembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/solvers/LinearSolver.hpp"
#include "fem/solvers/NodeOrdering.hpp"
#include "fem/static/Static.hpp"
#include "problems/bench/StandardModels.hpp"
#include "tests/Helpers.hpp"
#include "tests/ThreadsSetting.hpp"

using namespace beamrotor;

namespace {

SparseMatrix fromDense(const Eigen::MatrixXd& D) {
  return D.sparseView();
}

/// The stiffness of the planar bench beam with `elements` elements (all beams).
SparseMatrix planarBenchStiffness(int elements) {
  const PlanarBenchModel bench = planarBenchModel(elements);
  const DofMap dofs(*bench.model);
  return SparseAssembler(*bench.model, dofs).assemble(MatrixKind::stiffness);
}

/// The stiffness of the bench grillage with `bays` bays, without its exact zeros, and the node
/// of each of its equations.
struct Grillage {
  SparseMatrix K;
  std::vector<int> nodes;
};
Grillage grillageStiffness(int bays) {
  const GridBenchModel grid = gridBenchModel(bays);
  const DofMap dofs(*grid.model);
  Grillage out{SparseAssembler(*grid.model, dofs).assemble(MatrixKind::stiffness),
               dofs.freeNodes()};
  dropExactZeros(out.K);
  return out;
}

}  // namespace

TEST_SUITE("linear solver") {
  TEST_CASE("a symmetric stiffness matrix goes to LDL', which agrees with LU to round-off") {
    const PlanarBenchModel bench = planarBenchModel(200);
    const DofMap dofs(*bench.model);
    const SparseMatrix K = SparseAssembler(*bench.model, dofs).assemble(MatrixKind::stiffness);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);

    LinearSolver chosen;
    chosen.analyzePattern(K);
    chosen.factorize(K);
    REQUIRE(chosen.symmetric());
    CHECK(chosen.methodName() == "CHOLMOD LDL'");
    REQUIRE(chosen.healthy(kSingularRcond));

    SparseLU lu;
    lu.compute(K);
    REQUIRE(lu.info() == Eigen::Success);
    const Eigen::VectorXd x1 = chosen.solve(b), x2 = lu.solve(b);
    // Both are backward stable; K's condition number here is ~1e9 (E I / h^3 against E A / h),
    // so the two solutions may differ by cond * eps ~ 1e-7 relative at worst; observed ~1e-12.
    CHECK((x1 - x2).norm() / x2.norm() < 1e-9);
    CHECK((K * x1 - b).norm() / b.norm() < 1e-12);
    // The graph of a line of beams is chordal, so a fill-free elimination order exists and
    // CHOLMOD's ordering finds it: L has exactly the pattern of K's lower triangle.
    const SparseMatrix lower = K.triangularView<Eigen::Lower>();
    CHECK(chosen.factorEntries() == doctest::Approx(double(lower.nonZeros())));
    CHECK(chosen.orderingName() == "natural");  // the line's own order is fill-free
  }

  TEST_CASE("a grillage fills: the analysis orders it (AMD) and names the ordering") {
    // A 2D grid has no fill-free order; its node-by-node envelope is ~7 n nodes wide, far
    // above the 1.2 x K's lower triangle that keeps the natural order, so AMD is used.
    const GridBenchModel grid = gridBenchModel(6);
    const DofMap dofs(*grid.model);
    const SparseMatrix K = SparseAssembler(*grid.model, dofs).assemble(MatrixKind::stiffness);
    LinearSolver chosen;
    chosen.analyzePattern(K);
    chosen.factorize(K);
    REQUIRE(chosen.symmetric());
    CHECK(chosen.orderingName() == "AMD");
    const SparseMatrix lower = K.triangularView<Eigen::Lower>();
    CHECK(chosen.factorEntries() > 1.2 * double(lower.nonZeros()));  // it does fill
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);
    CHECK((K * chosen.solve(b) - b).norm() / b.norm() < 1e-10);
  }

  TEST_CASE("exact zeros dropped: a line keeps its own order, a grillage splits in two") {
    // A straight line along x never couples its axial dofs with its bending ones, and equal
    // spans cancel each interior node's own bending-rotation entry: 4 of every 9 lower
    // entries per node are exact zeros. Without them the pattern is no longer one band, so
    // its envelope says "fill", but the analysis in its own order counts the true fill (the
    // cancelled entries come back, one per node) and keeps that order.
    SparseMatrix K = planarBenchStiffness(200);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);
    LinearSolver full;
    full.analyzePattern(K);
    full.factorize(K);
    const Eigen::VectorXd xFull = full.solve(b);
    const double fullEntries = full.factorEntries();
    const Eigen::Index before = K.nonZeros();
    dropExactZeros(K);
    CHECK(K.nonZeros() < before);
    LinearSolver pruned;
    pruned.analyzePattern(K);
    pruned.factorize(K);
    CHECK(pruned.orderingName() == "natural");
    // The full pattern is fill-free in its order (L holds K's lower triangle exactly); the
    // pruned one fills back at most the one cancelled entry a node (rows / 3 bounds the node
    // count), and saves 4 of the 9 lower entries of each node's blocks: measured 0.59 of
    // the full factor.
    const SparseMatrix lower = K.triangularView<Eigen::Lower>();
    CHECK(pruned.factorEntries() >= double(lower.nonZeros()));
    CHECK(pruned.factorEntries() <= double(lower.nonZeros()) + double(K.rows()) / 3);
    CHECK(pruned.factorEntries() < 0.62 * fullEntries);
    // The same matrix: the solutions agree to the solves' round-off (cond ~1e9, observed
    // 1e-15).
    CHECK((pruned.solve(b) - xFull).norm() / xFull.norm() < 1e-12);

    // A flat grillage loaded across its plane: the in-plane dofs (ux, uy, rz) never couple
    // with the out-of-plane ones (uz, rx, ry), so K is two independent systems of half the
    // size; each fills like the whole did, at a quarter of its factor.
    const GridBenchModel grid = gridBenchModel(8);
    const DofMap dofs(*grid.model);
    SparseMatrix G = SparseAssembler(*grid.model, dofs).assemble(MatrixKind::stiffness);
    LinearSolver grillage;
    grillage.analyzePattern(G);
    grillage.factorize(G);
    const Eigen::VectorXd g = Eigen::VectorXd::LinSpaced(G.rows(), -1.0, 2.0);
    const Eigen::VectorXd yFull = grillage.solve(g);
    const double grillageEntries = grillage.factorEntries();
    dropExactZeros(G);
    LinearSolver halves;
    halves.analyzePattern(G);
    halves.factorize(G);
    // Measured 0.47 of the full factor at 8 bays (0.47 at 154 bays, 1.48e7 of 3.17e7).
    CHECK(halves.factorEntries() < 0.6 * grillageEntries);
    CHECK((halves.solve(g) - yFull).norm() / yFull.norm() < 1e-10);
  }

  TEST_CASE("a grillage ordered node by node: a node's equations together, a smaller factor") {
    // Without exact zeros a node's equations no longer share their neighbours (a member along x
    // couples torsion with torsion only), so AMD on equations orders each apart; on the graph
    // of nodes it eliminates them together.
    const Grillage grillage = grillageStiffness(20);
    const SparseMatrix& K = grillage.K;
    const std::vector<int>& nodes = grillage.nodes;
    const std::vector<int> order = nodeByNodeOrdering(K, nodes);
    REQUIRE(order.size() == std::size_t(K.rows()));
    std::vector<int> seen(order.size(), 0);
    for (const int row : order) ++seen[std::size_t(row)];
    CHECK(std::count(seen.begin(), seen.end(), 1) == K.rows());  // a permutation
    // Each node's rows come as one run, in their own order: as many runs as nodes.
    int runs = 1;
    for (std::size_t k = 1; k < order.size(); ++k) {
      if (nodes[order[k]] != nodes[order[k - 1]])
        ++runs;
      else
        CHECK(order[k] == order[k - 1] + 1);
    }
    CHECK(runs == std::set<int>(nodes.begin(), nodes.end()).size());

    LinearSolver byEquation, byNode;
    byEquation.analyzePattern(K, MatrixSymmetry::byConstruction);
    byNode.analyzePattern(K, MatrixSymmetry::byConstruction, nodes);
    CHECK(byEquation.orderingName() == "AMD");
    CHECK(byNode.orderingName() == "AMD by node");
    byEquation.factorize(K);
    byNode.factorize(K);
    REQUIRE(byNode.healthy(kSingularRcond));
    // Measured 0.98 of the factor on equations here, 0.90 at 154 bays (1.34e7 of 1.48e7).
    CHECK(byNode.factorEntries() <= byEquation.factorEntries());
    // The same system: the solutions agree to the solves' round-off.
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);
    const Eigen::VectorXd x = byEquation.solve(b);
    CHECK((byNode.solve(b) - x).norm() / x.norm() < 1e-9);
  }

  TEST_CASE("a flexible grillage's reactions balance its load to round-off (refined solution)") {
    // Global equilibrium: the supports' vertical reactions sum to the load. Each reaction is
    // K_cf u, so the balance holds to the residual of the free equations; the 30-bay grillage
    // (37806 equations, deflections of metres under 1 kN a node) leaves a residual of
    // eps |L| |D| |L'| |u| that unbalances it by 5.9e-10 after the solve alone, and by 5.4e-14
    // after one step of refinement (both measured).
    const GridBenchModel grid = gridBenchModel(30);
    const StaticResult s = solveStatic(*grid.model);
    double vertical = 0;
    for (const ReactionComponent& r : s.reactions)
      if (r.dof == Dof::uz) vertical += r.value;
    CHECK(std::abs(vertical / grid.totalLoad - 1) < 1e-12);
    CHECK(s.solver.find("AMD by node") != std::string::npos);
  }

  TEST_CASE("a grillage whose pattern splits in two is factorised as two blocks, same answers") {
    // 40 bays: 67206 equations, in-plane and out-of-plane halves that no entry couples.
    const Grillage grillage = grillageStiffness(40);
    const SparseMatrix& K = grillage.K;
    const std::vector<int>& nodes = grillage.nodes;
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);
    // A second method: one factor of the whole matrix.
    SparseLDLT whole;
    whole.analyzePattern(K, nodes);
    whole.factorize(K);
    Eigen::VectorXd x;
    whole.solveInto(b, x);

    const auto splitSolution = [&](const SparseMatrix& A, const std::string& threads) {
      const test::ThreadsSetting setting(threads);
      LinearSolver split;
      split.analyzePattern(A, MatrixSymmetry::byConstruction, nodes);
      split.factorize(A);
      CHECK(split.methodName() == "CHOLMOD LDL' of 2 decoupled blocks");
      CHECK(split.orderingName() == "AMD by node");
      REQUIRE(split.healthy(kSingularRcond));
      // The two halves are alike, so each block is ordered as the whole was and the entries
      // add up to the whole factor's (measured: equal).
      CHECK(split.factorEntries() == doctest::Approx(whole.factorEntries()).epsilon(0.01));
      CHECK(split.rcond() == doctest::Approx(whole.scaledRcond()).epsilon(1e-6));
      return split.solve(b);
    };
    const Eigen::VectorXd onTwo = splitSolution(K, "2");
    CHECK((onTwo - x).norm() / x.norm() < 1e-9);
    // The blocks are done one after the other on one core, to the same bits.
    CHECK(splitSolution(K, "1") == onTwo);

    // The blocks come from the pattern, not the values: a later matrix of the same pattern
    // with a dof held (its row and column cleared, as contacts do) is still solved right.
    SparseMatrix held = K;
    const int dof = int(K.rows()) / 2;
    for (int col = 0; col < held.outerSize(); ++col)
      for (SparseMatrix::InnerIterator it(held, col); it; ++it)
        if ((col == dof || it.row() == dof) && it.row() != col) it.valueRef() = 0;
    LinearSolver split;
    split.analyzePattern(held, MatrixSymmetry::byConstruction, nodes);
    split.factorize(K);
    CHECK((split.solve(b) - x).norm() / x.norm() < 1e-9);
    split.factorize(held);
    SparseLDLT wholeHeld;
    wholeHeld.analyzePattern(held, nodes);
    wholeHeld.factorize(held);
    Eigen::VectorXd y;
    wholeHeld.solveInto(b, y);
    CHECK((split.solve(b) - y).norm() / y.norm() < 1e-9);
  }

  TEST_CASE("an unsymmetric matrix goes to LU and is solved exactly") {
    Eigen::MatrixXd D(3, 3);
    D << 4, 1, 0,  //
        2, 5, 1,   //
        0, 1, 3;
    const SparseMatrix A = fromDense(D);
    CHECK_FALSE(isNumericallySymmetric(A));
    LinearSolver s;
    s.analyzePattern(A);
    s.factorize(A);
    CHECK_FALSE(s.symmetric());
    CHECK(s.methodName() == "UMFPACK LU");
    const Eigen::Vector3d x(1, -2, 3);
    CHECK((s.solve(D * x) - x).norm() < 1e-14);
  }

  TEST_CASE("symmetry is judged relative to the largest entry") {
    Eigen::MatrixXd D(2, 2);
    D << 1e12, 1.0,  //
        1.0 + 1e-3, 1e12;
    // The off-diagonal mismatch is 1e-15 of the largest entry: symmetric to working precision.
    CHECK(isNumericallySymmetric(fromDense(D)));
    D(1, 0) = 1.0 + 1e3;  // 1e-9 of the largest entry: a real asymmetry
    CHECK_FALSE(isNumericallySymmetric(fromDense(D)));
  }

  TEST_CASE("solveInto: Eigen's triangular solves on CHOLMOD's factor, as CHOLMOD's solve") {
    const SparseMatrix K = planarBenchStiffness(200);
    SparseLDLT ldlt;
    ldlt.analyzePattern(K);
    ldlt.factorize(K);
    REQUIRE(ldlt.info() == Eigen::Success);
    SparseLU lu;  // a second method
    lu.compute(K);
    Eigen::VectorXd x;
    for (const Eigen::VectorXd& b : {Eigen::VectorXd(Eigen::VectorXd::LinSpaced(K.rows(), -1, 2)),
                                     Eigen::VectorXd(Eigen::VectorXd::Ones(K.rows()))}) {
      ldlt.solveInto(b, x);  // the second call reuses the first one's storage
      // The same factor applied as cholmod_solve applies it (Eigen's solve()), the sums in
      // another order: equal to a few eps of the solution (measured 6.1e-16 and 6.3e-16).
      const Eigen::VectorXd z = ldlt.solve(b);
      CHECK((x - z).norm() / z.norm() < 1e-14);
      // Against LU within cond(K) eps, as in the first test case; the residual at round-off.
      const Eigen::VectorXd y = lu.solve(b);
      CHECK((x - y).norm() / y.norm() < 1e-9);
      CHECK((K * x - b).norm() / b.norm() < 1e-12);
    }
  }

  TEST_CASE("symmetric by construction: beams say so, a cross-coupled bearing does not") {
    // The planar bench beam: every element a beam, so the assembler vouches for K and the
    // solver takes LDL' without reading the values; the answer is the one the value scan
    // leads to (the same factorisation, bitwise).
    const PlanarBenchModel bench = planarBenchModel(200);
    const DofMap dofs(*bench.model);
    const SparseAssembler assembler(*bench.model, dofs);
    CHECK(assembler.stiffnessSymmetric());
    const SparseMatrix K = assembler.assemble(MatrixKind::stiffness);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);
    LinearSolver vouched, scanned;
    vouched.analyzePattern(K, MatrixSymmetry::byConstruction);
    scanned.analyzePattern(K);
    vouched.factorize(K);
    scanned.factorize(K);
    CHECK(vouched.methodName() == "CHOLMOD LDL'");
    CHECK((vouched.solve(b) - scanned.solve(b)).cwiseAbs().maxCoeff() == 0.0);

    // A shaft on a bearing with k_yz != k_zy: the assembler does not vouch, and the scan finds
    // the asymmetry, so the solver takes LU.
    Model shaft;
    const Line line = test::uniformBeam(shaft, 1.0, test::steelCircle(0.05), 4, DofSet::frame3d());
    test::clamp(shaft, "left", line.nodes.front(), DofSet::frame3d());
    BearingCoefficients c = BearingCoefficients::isotropic(1e7);
    c.kyz = 2e6;
    c.kzy = -2e6;
    shaft.add<Bearing>(line.nodes.back(), c);
    const DofMap shaftDofs(shaft);
    const SparseAssembler shaftAssembler(shaft, shaftDofs);
    CHECK_FALSE(shaftAssembler.stiffnessSymmetric());
    const SparseMatrix Kb = shaftAssembler.assemble(MatrixKind::stiffness);
    CHECK_FALSE(isNumericallySymmetric(Kb));
    LinearSolver chosen;
    chosen.analyzePattern(Kb);
    CHECK(chosen.methodName() == "UMFPACK LU");
  }

  TEST_CASE("a singular symmetric matrix reports rcond 0, not a solution") {
    Eigen::MatrixXd D(3, 3);
    D << 1, -1, 0,  //
        -1, 2, -1,  //
        0, -1, 1;   // a free-free chain of two springs: one rigid-body mode
    const SparseMatrix A = fromDense(D);
    LinearSolver s;
    s.analyzePattern(A);
    s.factorize(A);
    REQUIRE(s.symmetric());
    CHECK(s.rcond() < kSingularRcond);
    CHECK_FALSE(s.healthy(kSingularRcond));
  }
}
