// The trends the pump rod paper states (problems/scenes/README.md section 1), asserted on the decks
// as far as they are true: reactions exactly linear in w0, monotonic in the stroke eta (but
// rational, not quadratic, in eta), the 44 % / 79 % growth of the middle reaction, and lower
// stresses once the crosshead end can turn (variant B against variant A).
#include <doctest/doctest.h>

#include <Eigen/Dense>

#include "fem/assembly/ElementExtrema.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

const std::vector<std::pair<std::string, Dof>> kReactionsA{{"left", Dof::uy},
                                                           {"left", Dof::rz},
                                                           {"middle", Dof::uy},
                                                           {"right", Dof::uy},
                                                           {"right", Dof::rz}};

const RunResult solved(const std::string& deck, double eta, double w0 = 0.001) {
  return *solveStudy(
              shippedDeckRequest(deck, {"eta=" + std::to_string(eta), "w0=" + std::to_string(w0)}))
              .run;
}

/// Largest outer-fibre stress along the rod (Pa), as the writers report it.
double peakStress(const RunResult& run) {
  for (const AnalysisOutcome& a : run.analyses)
    if (staticsOf(a))
      return largestPeak(elementPeaks({*run.model, staticsOf(a)->displacement}),
                         &ElementPeaks::stress)
          ->value;
  throw std::logic_error("no static analysis");
}

/// Largest |rotation| along the rod (rad): the Hermite rotation sampled at 1000 places per
/// element; its extreme lies where M = 0 and is flat there, so the sampling misses it by at
/// most (|V| / EI) (h / 2)^2 / 2 with h = 1/1000 of an element: 3e-8 relative on the pump rod.
double peakRotation(const RunResult& run) {
  for (const AnalysisOutcome& a : run.analyses)
    if (staticsOf(a)) {
      double peak = 0;
      for (const StaticStation& st : sampleStatics({*run.model, staticsOf(a)->displacement}, 1000))
        peak = std::max(peak, std::abs(st.displacement[dofIndex(Dof::rz)]));
      return peak;
    }
  throw std::logic_error("no static analysis");
}

}  // namespace

TEST_SUITE("pump rod trends") {
  TEST_CASE("reactions are linear in w0: R(2 w0) = 2 R(w0) to round-off") {
    for (const char* deck : {"pump_rod.yaml", "pump_rod_hinged.yaml"}) {
      CAPTURE(deck);
      const RunResult one = solved(deck, 0.2, 0.001), two = solved(deck, 0.2, 0.002);
      for (const auto& [support, dof] : kReactionsA) {
        if (std::string(deck) != "pump_rod.yaml" && support == "left" && dof == Dof::rz) continue;
        CAPTURE(support);
        // A linear solve with a scaled right-hand side: a few roundings.
        CHECK(relError(staticReaction(two, support, dof), 2 * staticReaction(one, support, dof)) <
              1e-12);
      }
    }
  }

  TEST_CASE("reactions are monotonic in eta, close to but not exactly quadratic") {
    constexpr int kPositions = 9;
    Eigen::VectorXd eta(kPositions);
    Eigen::MatrixXd reactions(kPositions, 5);
    for (int i = 0; i < kPositions; ++i) {
      eta[i] = 0.4 * i / (kPositions - 1);
      const RunResult run = solved("pump_rod.yaml", eta[i]);
      for (int k = 0; k < 5; ++k)
        reactions(i, k) = staticReaction(run, kReactionsA[k].first, kReactionsA[k].second);
    }
    // Least-squares quadratic in eta per reaction; residual relative to the reaction's range.
    Eigen::MatrixXd V(kPositions, 3);
    V << Eigen::VectorXd::Ones(kPositions), eta, eta.array().square().matrix();
    for (int k = 0; k < 5; ++k) {
      CAPTURE(k);
      const Eigen::VectorXd r = reactions.col(k);
      const Eigen::VectorXd steps = r.tail(kPositions - 1) - r.head(kPositions - 1);
      CHECK(((steps.array() > 0).all() || (steps.array() < 0).all()));  // monotonic
      const Eigen::VectorXd fit = V * V.colPivHouseholderQr().solve(r);
      const double range = r.maxCoeff() - r.minCoeff();
      const double residual = (r - fit).cwiseAbs().maxCoeff() / range;
      MESSAGE(kReactionsA[k].first << " " << dofName(kReactionsA[k].second)
                                   << ": largest deviation from the best quadratic = "
                                   << residual * 100 << " % of its range over the stroke");
      // The closed form is a ratio of polynomials in psi (Cramer's rule on cubic influence
      // integrals), not a polynomial: the paper's "quadratic" is a description. Measured: the
      // best quadratic misses by 0.9 to 2.3 % of the range over the stroke, far above the
      // round-off (1e-12) an exact quadratic would leave.
      CHECK(residual > 1e-3);
      CHECK(residual < 0.03);
    }
  }

  TEST_CASE("the middle reaction grows 44 % (of the larger) or 79 % (of the smaller)") {
    const double p0 = staticReaction(solved("pump_rod.yaml", 0), "middle", Dof::uy);
    const double p4 = staticReaction(solved("pump_rod.yaml", 0.4), "middle", Dof::uy);
    MESSAGE("P3 = " << p0 << " N at eta = 0, " << p4 << " N at eta = 0.4: +" << (p4 - p0) / p4 * 100
                    << " % of the larger, +" << (p4 - p0) / p0 * 100 << " % of the smaller");
    // The paper's percentages, printed to whole per cent: half a per cent either way.
    CHECK(std::abs((p4 - p0) / p4 * 100 - 44) <= 0.5);
    CHECK(std::abs((p4 - p0) / p0 * 100 - 79) <= 0.5);
  }

  TEST_CASE("the paper's 33 %: the largest rotations of variants A and B differ by a third of A's") {
    // The paper says variant B's largest rotation exceeds variant A's by 33 %. The models give
    // the 33 % as the difference relative to the larger value, as the paper's 44 % for the
    // middle reaction, but the larger is variant A's: its rod turns most between the step and
    // the seal (where M = 0; 1.896e-3 rad at eta = 0.4), variant B's at the pinned crosshead
    // end (1.267e-3 rad, the deck's theta0 check). So the figure is reproduced, the direction
    // stated in the paper is not.
    const double a = peakRotation(solved("pump_rod.yaml", 0.4));
    const double b = peakRotation(solved("pump_rod_hinged.yaml", 0.4));
    MESSAGE("eta = 0.4: largest rotation A " << a << " rad, B " << b << " rad: A - B = "
                                             << (a - b) / a * 100 << " % of A, "
                                             << (a - b) / b * 100 << " % of B");
    CHECK(a > b);
    // Printed to whole per cent: half a per cent either way (measured 33.18 %).
    CHECK(std::abs((a - b) / a * 100 - 33) <= 0.5);
    // Independent reference: the closed forms of both variants (initial-parameter method, as
    // in the decks' headers) evaluated apart from beamrotor: A's rotation at its zero of M,
    // x = -M0 / V0 = 0.73671 m, is 1.8962403e-3 rad; B's theta0 is 1.2669875e-3 rad. Eight
    // printed digits (3e-8) and the sampling (3e-8): 1e-7 relative.
    CHECK(std::abs(a / 1.8962403e-3 - 1) < 1e-7);
    CHECK(std::abs(b / 1.2669875e-3 - 1) < 1e-7);
  }

  TEST_CASE("variant B (pinned crosshead end) is less stressed than variant A") {
    for (double eta : {0.0, 0.2, 0.4}) {
      CAPTURE(eta);
      const double a = peakStress(solved("pump_rod.yaml", eta));
      const double b = peakStress(solved("pump_rod_hinged.yaml", eta));
      MESSAGE("eta = " << eta << ": largest stress A " << a * 1e-6 << " MPa, B " << b * 1e-6
                       << " MPa");
      CHECK(b < a);
    }
  }
}
