// The static solve of a line stored as a band (LAPACK's Cholesky) against closed forms, and
// against the sparse path's solution of the same K: a spring of zero stiffness between far
// nodes widens the band past what suits it and leaves every entry of K as it was.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "elements/Spring.hpp"
#include "fem/assembly/Assembly.hpp"
#include "fem/static/LinearStatics.hpp"
#include "fem/static/Static.hpp"
#include "problems/bench/StandardModels.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

bool startsWith(const std::string& text, const std::string& head) {
  return text.rfind(head, 0) == 0;
}

}  // namespace

TEST_SUITE("band statics") {
  TEST_CASE("a cantilever line is solved on its band: exact tip deflection, sizes reported") {
    // Hermite cubics give the end-loaded cantilever's deflection exactly: round-off remains
    // (K's condition number ~1e6 here).
    const double L = 2.0, P = 1500.0;
    const auto sec = steelCircle(0.05);
    Model m;
    const Line line = uniformBeam(m, L, sec, 7);
    clamp(m, "root", line.nodes.front(), DofSet::planar());
    m.addLoad({line.nodes.back(), Dof::uy, -P});
    const StaticResult r = solveStatic(m);
    CHECK(r.solver == "LAPACK band Cholesky, half-bandwidth 5");
    CHECK(relError(r.displacement(line.nodes.back(), 1), -P * L * L * L / (3 * sec->EIz())) <
          1e-10);
    CHECK(relError(r.reaction("root", Dof::rz), P * L) < 1e-10);
    // Sizes as the sparse path reports them: K's entries without exact zeros.
    const DofMap dofs(m);
    SparseMatrix K = SparseAssembler(m, dofs).assemble(MatrixKind::stiffness);
    dropExactZeros(K);
    CHECK(r.size.nonzeros == K.nonZeros());
    // L: K's lower triangle and one fill a node after the first: a node's uy and rz do not
    // couple in K (the two elements' terms cancel exactly) but do once uy of the node before
    // is eliminated. 52 + 5 here; CHOLMOD's LDL' has the same (next test).
    CHECK(r.size.factorEntries == (K.nonZeros() + K.rows()) / 2 + 5);
  }

  TEST_CASE("matrices freed after the last solve: reactions and diagnostics stay") {
    const double L = 2.0, P = 1500.0;
    Model m;
    const Line line = uniformBeam(m, L, steelCircle(0.05), 7);
    clamp(m, "root", line.nodes.front(), DofSet::planar());
    m.addLoad({line.nodes.back(), Dof::uy, -P});
    LinearStatics system(m);
    const Eigen::VectorXd u = system.solve({}, 1e-14);
    const std::string solver = system.solverName();
    const long long entries = system.stiffnessEntries();
    const double factorEntries = system.factorEntries(), roundOff = system.roundOff();
    const Eigen::VectorXd reactions = system.reactions(u);
    system.releaseMatrices();
    CHECK(system.solverName() == solver);
    CHECK(system.stiffnessEntries() == entries);
    CHECK(system.factorEntries() == factorEntries);
    CHECK(system.roundOff() == roundOff);
    CHECK(system.reactions(u) == reactions);
    // The root's moment reaction: P L (statics).
    const int rz = system.dofs().equation({line.nodes.front(), Dof::rz});
    CHECK(relError(reactions[rz - system.dofs().freeCount()], P * L) < 1e-10);
    CHECK_THROWS_AS(system.solve({}, 1e-14), std::logic_error);
  }

  TEST_CASE("the band and the sparse path solve the same K alike") {
    PlanarBenchModel bench = planarBenchModel(400);
    const StaticResult band = solveStatic(*bench.model);
    bench.model->addElement(
        std::make_unique<Spring>(NodeDof{2, Dof::uy}, NodeDof{395, Dof::uy}, 0.0));
    const StaticResult sparse = solveStatic(*bench.model);
    REQUIRE(startsWith(band.solver, "LAPACK band Cholesky"));
    REQUIRE(startsWith(sparse.solver, "CHOLMOD LDL'"));
    CHECK(band.size.nonzeros == sparse.size.nonzeros);
    CHECK(band.size.factorEntries == sparse.size.factorEntries);
    CHECK(band.rcond == doctest::Approx(sparse.rcond).epsilon(1e-12));
    // Each solution within its measured round-off of the other, and the midspan deflection
    // of the middle span at the closed form q s^4 / (384 E I) of a span between two
    // neighbours alike (the discrete model is exact at the nodes).
    const double scale = sparse.displacement.cwiseAbs().maxCoeff();
    CHECK((band.displacement - sparse.displacement).cwiseAbs().maxCoeff() <=
          (band.roundOff + sparse.roundOff) * scale);
    CHECK(relError(band.displacement(bench.midspanNode, 1), bench.exactMidspanW) < 1e-10);
  }

  TEST_CASE("a pivot lost to round-off hands K to the sparse LDL', which gives its answer") {
    // A spring of k = 2^86 N/m (7.7e25) between two nodes of a soft cantilever: eliminating
    // one of its dofs leaves k + a - k^2 / (k + b) for the other, in which a and b (~1e6) are
    // lost to round-off (half an ulp of k is 8.6e9). With k a power of two every step of the
    // elimination is exact (k + a and k + b round to k, sqrt(k) = 2^43, k / sqrt(k) = 2^43),
    // so the pivot is k - k less the other columns' squares: not positive, whatever order or
    // kernel the LAPACK build sums in (with 1e26 the rounded square root left a pivot of
    // either sign, one BLAS build's positive). The structure is held (no mechanism), so the
    // sparse LDL' takes K, as the sparse path would have from the start: the same answer to
    // the last bit, and its measured round-off says no digit of it holds.
    const auto build = [](bool wide) {
      auto m = std::make_unique<Model>();
      const Line line = uniformBeam(*m, 2.0, steelCircle(0.05), 4);
      clamp(*m, "root", line.nodes.front(), DofSet::planar());
      m->addElement(std::make_unique<Spring>(NodeDof{line.nodes[2], Dof::uy},
                                             NodeDof{line.nodes[3], Dof::uy}, std::ldexp(1.0, 86)));
      // No stiffness, but it couples node 1 with the tip: too wide for a band.
      if (wide)
        m->addElement(std::make_unique<Spring>(NodeDof{line.nodes[1], Dof::uy},
                                               NodeDof{line.nodes[4], Dof::uy}, 0.0, 1.0));
      m->addLoad({line.nodes.back(), Dof::uy, -1000});
      return m;
    };
    const StaticResult fallback = solveStatic(*build(false));
    const StaticResult sparse = solveStatic(*build(true));
    CHECK(startsWith(fallback.solver, "CHOLMOD LDL'"));
    CHECK(startsWith(sparse.solver, "CHOLMOD LDL'"));
    CHECK(fallback.displacement == sparse.displacement);
    CHECK(fallback.rcond == sparse.rcond);
    CHECK(fallback.roundOff > 1);
  }
}
