// The factor M = G G' that puts shift-invert Lanczos in standard form: its products and solve
// against M itself, the mass matrices it declines, and eigenpairs through it against a
// closed form.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/solvers/MassFactor.hpp"
#include "fem/solvers/SymmetricEigen.hpp"
#include "problems/bench/StandardModels.hpp"
#include "tests/Helpers.hpp"
#include "tests/ThreadsSetting.hpp"
#include "tests/fem/solvers/ChainPencil.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// The consistent mass of the planar benchmark's beam (30 spans unless told), without its
/// exact zeros.
SparseMatrix beamMass(int elements = 300) {
  const PlanarBenchModel bench = planarBenchModel(elements);
  const DofMap dofs(*bench.model);
  SparseMatrix M = SparseAssembler(*bench.model, dofs).assemble(MatrixKind::mass);
  dropExactZeros(M);
  return M;
}

/// P A P' for a shuffled order: a numbering with no band.
SparseMatrix shuffled(const SparseMatrix& A) {
  std::vector<int> order(A.rows());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(
      Eigen::Map<Eigen::VectorXi>(order.data(), Eigen::Index(order.size())));
  SparseMatrix out(A.rows(), A.cols());
  out = A.twistedBy(P);
  return out;
}

/// The products and the solve of `factor` against M: G (G' x) = M x, and G'^-1 (G' x) = x,
/// both to round-off (the largest relative difference over a few vectors).
double worstMismatch(const MassFactor& factor, const SparseMatrix& M) {
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> uniform(-1, 1);
  double worst = 0;
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::VectorXd x(M.rows()), gtx(M.rows()), ggtx(M.rows());
    for (double& v : x) v = uniform(generator);
    factor.multiplyTransposed(x, gtx);
    factor.multiply(gtx, ggtx);
    const Eigen::VectorXd mx = M * x;
    worst = std::max(worst, (ggtx - mx).norm() / mx.norm());
    factor.solveTransposed(gtx);
    worst = std::max(worst, (gtx - x).norm() / x.norm());
  }
  return worst;
}

}  // namespace

TEST_SUITE("mass factor") {
  TEST_CASE("G G' is M, and G'^-1 undoes G'") {
    // Cholesky is backward stable: G G' = M + E with |E| ~ n eps |G| |G'|; over these
    // 900-dof well conditioned masses 1e-13 relative leaves room for that.
    const SparseMatrix M = beamMass();
    const auto own = MassFactor::ofMass(M);
    REQUIRE(own != nullptr);
    CHECK(worstMismatch(*own, M) < 1e-13);
  }

  TEST_CASE("G's products split over three parts give the bits of one") {
    // 60 000 elements: 1.7e5 dofs, three parts of over 50 000 rows when three are allowed.
    const SparseMatrix M = beamMass(60000);
    const auto factor = MassFactor::ofMass(M);
    REQUIRE(factor != nullptr);
    Eigen::VectorXd x(M.rows());
    for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = std::cos(0.91 * double(i));
    const auto products = [&](const char* threads) {
      const ThreadsSetting setting(threads);
      Eigen::MatrixXd out(M.rows(), 2);
      factor->multiply(x, out.col(0));
      factor->multiplyTransposed(x, out.col(1));
      return out;
    };
    const Eigen::MatrixXd one = products("1"), three = products("3");
    CHECK((one.array() == three.array()).all());
    // And they are G's: G G' x against M x, to round-off.
    Eigen::VectorXd ggtx(M.rows());
    factor->multiply(three.col(1), ggtx);
    const Eigen::VectorXd mx = M * x;
    CHECK((ggtx - mx).norm() / mx.norm() < 1e-13);
  }

  TEST_CASE("masses that standard form does not suit are declined") {
    const int n = 400;
    // A massless dof (a lumped mass without rotary inertia): M singular.
    SparseMatrix lumped(n, n);
    for (int i = 0; i < n; ++i) lumped.insert(i, i) = i % 2 == 0 ? 1.0 : 0.0;
    CHECK(MassFactor::ofMass(lumped) == nullptr);
    // Indefinite.
    const ChainPencil indefinite = chainPencil(n, 1, 1, 1, 1);  // 1 + 2 cos t < 0 for some t
    CHECK(MassFactor::ofMass(indefinite.K) == nullptr);
    // Positive definite but nearly singular on the scaled system: pairs of dofs that move
    // as one, [1, 1 - e; 1 - e, 1] with e = 1e-10, whose second pivot is 2e-10. (A tiny
    // mass on a dof of its own is not: scaled, a diagonal M is the identity.)
    std::vector<Eigen::Triplet<double>> pairs;
    for (int i = 0; i < n; i += 2)
      pairs.insert(pairs.end(), {{i, i, 1.0}, {i + 1, i + 1, 1.0}, {i, i + 1, 1 - 1e-10},
                                 {i + 1, i, 1 - 1e-10}});
    SparseMatrix tied(n, n);
    tied.setFromTriplets(pairs.begin(), pairs.end());
    CHECK(MassFactor::ofMass(tied) == nullptr);
    SparseMatrix light(n, n);
    for (int i = 0; i < n; ++i) light.insert(i, i) = i == 0 ? 1e-10 : 1.0;
    CHECK(MassFactor::ofMass(light) != nullptr);
    // A 20 x 20 grid's five-point pattern (positive definite): its factor fills beyond M's
    // entries, so two products with it a step would cost more than the three with M.
    const int side = 20;
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) {
        const int k = i * side + j;
        t.emplace_back(k, k, 5.0);
        if (i + 1 < side) t.insert(t.end(), {{k, k + side, -1.0}, {k + side, k, -1.0}});
        if (j + 1 < side) t.insert(t.end(), {{k, k + 1, -1.0}, {k + 1, k, -1.0}});
      }
    SparseMatrix grid(side * side, side * side);
    grid.setFromTriplets(t.begin(), t.end());
    CHECK(MassFactor::ofMass(grid) == nullptr);
    // The same grid's diagonal alone is accepted: the rule is the fill, not the size.
    CHECK(MassFactor::ofMass(SparseMatrix(grid.diagonal().asDiagonal())) != nullptr);
    // The beam's mass numbered without a band: a fill-reducing ordering would be needed.
    CHECK(MassFactor::ofMass(beamMass()) != nullptr);
    CHECK(MassFactor::ofMass(shuffled(beamMass())) == nullptr);
  }

  TEST_CASE("eigenpairs through the factor of a chain's mass agree with the closed form") {
    // K = 2 I - T, M = (4 I + T) / 6: linear elements' stiffness and consistent mass on a
    // fixed-fixed chain; M is tridiagonal and factorises without fill, so Lanczos runs in
    // standard form on it. Its eigenvalues (2 - 2 cos t) / ((4 + 2 cos t) / 6) in closed form.
    const ChainPencil p = chainPencil(600, 2, -1, 4.0 / 6, 1.0 / 6);
    REQUIRE(MassFactor::ofMass(p.M) != nullptr);
    const int modes = 8;
    const EigenPairs pairs = symmetricEigenpairs(p.K, p.M, modes, 0.0);
    REQUIRE(pairs.values.size() == modes);
    CHECK(pairs.missedBySturmCount == 0);
    for (int k = 0; k < modes; ++k) {
      CAPTURE(k);
      // The closed form's cosines carry round-off of a few ulps of 1, over lambda_1 ~ 3e-5:
      // about 1e-11 relative; 1e-9 leaves room without hiding a wrong mode (the next
      // eigenvalue lies 20 % or more away).
      CHECK(relError(pairs.values[k], p.exact[k]) < 1e-9);
      const Eigen::VectorXd x = pairs.vectors.col(k);
      CHECK((p.K * x - pairs.values[k] * (p.M * x)).norm() / (p.K * x).norm() < 1e-9);
    }
    // M-orthonormal vectors, as the generalised form returns them.
    const Eigen::MatrixXd gram = pairs.vectors.transpose() * (p.M * pairs.vectors);
    CHECK((gram - Eigen::MatrixXd::Identity(modes, modes)).cwiseAbs().maxCoeff() < 1e-10);
  }
}
