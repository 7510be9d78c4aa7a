// The forme shaft's rigid two-dof model from the paper's own inputs (problems/scenes/README.md
// section 2; problems/forme_shaft_two_dof.yaml): against a second method (the 2 x 2 generalised
// eigenproblem solved by Eigen), the paper's mode names, and the decoupled case b = 0 with its
// limit.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

const RigidBodyOutcome& givenBodyOutcome(const RunResult& run) {
  REQUIRE(run.analyses.size() == 1);
  REQUIRE(resultOf<RigidBodyOutcome>(run.analyses[0]));
  return *resultOf<RigidBodyOutcome>(run.analyses[0]);
}

/// Frequencies (rad/s, ascending) and z/phi ratios of M x'' + K x = 0, x = (z, phi).
struct TwoDofEigen {
  Eigen::Vector2d k;
  Eigen::Vector2d ratio;
};

TwoDofEigen twoDofByEigen(double m, double rho, double l1, double l2, double C1, double C2) {
  Eigen::Matrix2d K, M;
  K << C1 + C2, C2 * l2 - C1 * l1, C2 * l2 - C1 * l1, C1 * l1 * l1 + C2 * l2 * l2;
  M << m, 0, 0, m * rho * rho;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(K, M);
  TwoDofEigen out;
  for (int i = 0; i < 2; ++i) {
    out.k(i) = std::sqrt(solver.eigenvalues()(i));
    out.ratio(i) = solver.eigenvectors()(0, i) / solver.eigenvectors()(1, i);
  }
  return out;
}

}  // namespace

TEST_SUITE("forme shaft two-dof deck") {
  TEST_CASE("the paper's inputs: frequencies and ratios against the 2 x 2 eigenproblem") {
    const Study s = solveStudy(shippedDeckRequest("forme_shaft_two_dof.yaml"));
    REQUIRE(s.run);
    CHECK(checkAllPass(s) == 12);
    CHECK(s.run->skippedChecks.size() == 2);  // the decoupled ones
    const RigidBodyOutcome& r = givenBodyOutcome(*s.run);
    const double m = 4000 / 9.80665;
    const TwoDofEigen e = twoDofByEigen(m, 0.33, 0.62, 0.50, 2e8, 2e8);
    // Two methods in double precision on a 2 x 2 problem: agreement to ~1e-14, allowed 1e-12.
    for (int i = 0; i < 2; ++i) {
      CAPTURE(i);
      CHECK(std::abs(r.modes[i].k / e.k(i) - 1) < 1e-12);
      CHECK(std::abs(r.modes[i].n / e.ratio(i) - 1) < 1e-10);
      // The dynamic loads balance the inertia: F_A + F_B = m k^2 z (a conservation check).
      CHECK(std::abs(r.modes[i].FA + r.modes[i].FB + r.modes[i].inertiaForce) <
            1e-9 * std::abs(r.modes[i].FA));
    }
    CHECK(r.modes[0].k < r.modes[1].k);
    CHECK(paperModeName(1) == "k1 ('+' root)");  // our mode 2, the higher, is the paper's k1
  }

  TEST_CASE("b = 0: pure bounce and pure rocking, named, with no NaN anywhere") {
    // C1 = C2 and l1 = l2 = 0.56: C1 l1 = C2 l2. Bounce k^2 = 2 C / m; rocking
    // k^2 = 2 C l^2 / (m rho^2): the bounce is the lower (0.56 > 0.33).
    const Study s =
        solveStudy(shippedDeckRequest("forme_shaft_two_dof.yaml", {"l1=0.56", "l2=0.56"}));
    REQUIRE(s.run);
    CHECK(checkAllPass(s) == 7);  // the 5 general checks and the 2 decoupled ones
    const RigidBodyOutcome& r = givenBodyOutcome(*s.run);
    const double m = 4000 / 9.80665;
    CHECK(r.modes[0].kind == FormeModeKind::bounce);
    CHECK(r.modes[1].kind == FormeModeKind::rocking);
    CHECK(std::abs(r.modes[0].k / std::sqrt(4e8 / m) - 1) < 1e-14);
    CHECK(std::abs(r.modes[1].k / std::sqrt(4e8 * 0.56 * 0.56 / (m * 0.33 * 0.33)) - 1) < 1e-14);
    CHECK(r.modes[0].phi == 0);
    CHECK(r.modes[1].z == 0);
    CHECK(r.modes[1].n == 0);
    // The limit: with b small but not zero the coupled ratios tend to the decoupled ones
    // (n of the bounce-like mode grows as 1/b, the rocking-like one's falls as b).
    const TwoDofEigen near = twoDofByEigen(m, 0.33, 0.56, 0.56 * (1 + 1e-6), 2e8, 2e8);
    CHECK(std::abs(near.k(0) / r.modes[0].k - 1) < 1e-9);
    CHECK(std::abs(near.ratio(1)) < 1e-5);
    CHECK(std::abs(near.ratio(0)) > 1e4);
    // What a reader sees: the words, and no NaN in the summary or results.json.
    const ProcessResult p =
        runBeamrotor({"solve", "problems/forme_shaft_two_dof.yaml", "--set", "l1=0.56", "--set",
                      "l2=0.56", "--out", (scratchDir("two_dof_words") / "out").string()});
    CHECK(p.exitCode == 0);
    CHECK(p.out.find("pure bounce") != std::string::npos);
    CHECK(p.out.find("pure rocking") != std::string::npos);
    CHECK(p.out.find("the paper's k1 ('+' root)") != std::string::npos);
    CHECK(p.out.find("nan") == std::string::npos);
    std::filesystem::remove_all(scratchDir("two_dof_words"));
  }

  TEST_CASE("the body's inputs are checked") {
    const std::string head = "analyses:\n  - type: rigid-body\n    body: ";
    const DeckError both = readingError(
        head +
            "{weight: 4000, mass: 400, radius_of_gyration: 0.3, l1: 0.5, l2: 0.5, C1: 1e8, "
            "C2: 1e8}\n",
        "both.yaml");
    CHECK(both.message().find("not both") != std::string::npos);
    const DeckError negative = readingError(
        head + "{mass: 400, radius_of_gyration: 0.3, l1: 0.5, l2: 0.5, C1: -1e8, C2: 1e8}\n",
        "negative.yaml");
    CHECK(negative.place().field.find("C1") != std::string::npos);
    const DeckError withBearings = readingError(
        head +
            "{mass: 400, radius_of_gyration: 0.3, l1: 0.5, l2: 0.5, C1: 1e8, C2: 1e8}\n"
            "    bearings: [A, B]\n",
        "bearings.yaml");
    CHECK(withBearings.message().find("not both") != std::string::npos);
  }
}
