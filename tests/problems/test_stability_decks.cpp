// Buckling, second-order statics and prestressed modes from decks: a column deck against
// Euler's load, bad input refused with the field named, a load past the critical one refused
// with the factor named, and the pump rod under the piston force (problems/
// pump_rod_piston_force.yaml) against the first-order deck at zero pressure and in both strokes.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "problems/deck/parse/DeckError.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// A pinned steel column (circle 50 mm, 2 m, 16 elements) pressed by P at its top and pushed
/// sideways by 100 kN at midspan, with the analyses given; Pe = pi^2 EI / L^2 = 150.8 kN.
/// The lateral load is large (the theory is linear in it) so that the deflection (0.27 m
/// first-order) outweighs the axial shortening P L / EA (2.5e-4 m at 50 kN) by 10^3: the
/// amplification of the largest translation magnitude is then the deflections' to (1e-3)^2 / 2.
std::string columnDeck(double P, const std::string& analyses, const std::string& extra = "") {
  return "parameters: {P: " + std::to_string(P) +
         "}\n"
         "model: {dimension: planar}\n"
         "materials: [{name: steel, E: 200e9, nu: 0.3, rho: 7850}]\n"
         "sections: [{name: c, shape: circle, D: 0.05}]\n"
         "segments: [{length: 2, section: c, elements: 16}]\n"
         "points: [{name: mid, at: 1}]\n"
         "supports:\n"
         "  - {name: base, at: start, fix: [ux, uy]}\n"
         "  - {name: top, at: end, fix: [uy]}\n"
         "loads: [{type: point, at: end, fx: -P}, {type: point, at: mid, fy: -100e3}]\n"
         "analyses:\n" +
         analyses + extra;
}

double eulerLoad() {
  const double I = kPi * std::pow(0.05, 4) / 64;
  return kPi * kPi * 200e9 * I / 4.0;
}

const AnalysisOutcome& outcomeNamed(const RunResult& run, const std::string& name) {
  for (const AnalysisOutcome& a : run.analyses)
    if (a.name == name) return a;
  FAIL("no analysis " << name);
  return run.analyses.front();
}

}  // namespace

TEST_SUITE("stability decks") {
  TEST_CASE("a column deck: buckling factors, second order and prestressed modes") {
    // 16 Hermite elements: measured errors 2.1e-6 for the first buckling factor, 3.3e-5 for
    // the second (h^4, as in the element tests), 1.0e-6 for f^2 about the loaded state; the
    // deck's own check reads the first through `buckling_factor 1`.
    const double P = 50e3, Pe = eulerLoad();
    const Study s = solveDeckText(
        columnDeck(P,
                   "  - {type: buckling, name: stability, modes: 2}\n"
                   "  - {type: static, name: bending, second_order: true}\n"
                   "  - {type: modal, name: loaded, modes: 1, prestressed: true}\n"
                   "  - {type: modal, name: free, modes: 1}\n",
                   "checks:\n"
                   "  - {name: Euler, quantity: buckling_factor 1, analysis: stability,\n"
                   "     reference: pi^2 * 200e9 * pi * 0.05^4 / 64 / 4 / P, tolerance: 5e-6}\n"),
        "column.yaml");
    REQUIRE(s.run);
    CHECK(checkAllPass(s) == 1);
    const RunResult& run = *s.run;
    const AnalysisOutcome& b = outcomeNamed(run, "stability");
    REQUIRE(resultOf<BucklingResult>(b));
    REQUIRE(resultOf<BucklingResult>(b)->modes.size() == 2);
    CHECK(relError(resultOf<BucklingResult>(b)->modes[1].factor, 4 * Pe / P) <
          5e-5);  // mode 2: 4 Pe
    const AnalysisOutcome& so = outcomeNamed(run, "bending");
    REQUIRE(resultOf<SecondOrderResult>(so));
    CHECK(relError(resultOf<SecondOrderResult>(so)->criticalFactor, Pe / P) < 5e-6);
    // Central load: amplification (tan u - u) / (u^3 / 3), u = (pi / 2) sqrt(P / Pe).
    const double u = kPi / 2 * std::sqrt(P / Pe);
    CHECK(relError(resultOf<SecondOrderResult>(so)->displacementAmplification,
                   (std::tan(u) - u) / (u * u * u / 3)) < 1e-5);
    // Frequencies: f^2 = f0^2 (1 - P / Pe).
    const double f0 = resultOf<ModalResult>(outcomeNamed(run, "free"))->modes.at(0).frequencyHz;
    const double f = resultOf<ModalResult>(outcomeNamed(run, "loaded"))->modes.at(0).frequencyHz;
    CHECK(relError(f * f, f0 * f0 * (1 - P / Pe)) < 5e-6);
  }

  TEST_CASE("bad options are refused naming the field") {
    const std::string bad[] = {"  - {type: buckling, modes: 0}\n",
                               "  - {type: buckling, reversed: maybe}\n",
                               "  - {type: buckling, shift: 1}\n",
                               "  - {type: static, second_order: 2}\n",
                               "  - {type: modal, prestressed: sometimes}\n"};
    for (const std::string& analyses : bad) {
      CAPTURE(analyses);
      try {
        solveDeckText(columnDeck(1e3, analyses), "bad.yaml");
        FAIL("accepted");
      } catch (const DeckError& e) {
        CHECK(std::string(e.what()).find("bad.yaml:") != std::string::npos);
      }
    }
  }

  TEST_CASE("second order past the critical load: an error naming the buckling factor") {
    try {
      solveDeckText(columnDeck(1.2 * eulerLoad(), "  - {type: static, second_order: true}\n"),
                    "past.yaml");
      FAIL("accepted");
    } catch (const DeckSolveError& e) {
      const std::string msg = e.what();
      CHECK(msg.find("past.yaml:") != std::string::npos);
      CHECK(msg.find("past the critical load") != std::string::npos);
      CHECK(msg.find("buckling factor of its first-order state is 0.83333") != std::string::npos);
    }
  }

  TEST_CASE("pump rod under the piston force: zero pressure is the first-order deck") {
    const Study plain = solveStudy(shippedDeckRequest("pump_rod.yaml"));
    const Study zero = solveStudy(shippedDeckRequest("pump_rod_piston_force.yaml", {"p=0"}));
    REQUIRE(plain.run);
    REQUIRE(zero.run);
    // Its closed-form checks apply and pass (round-off), and the reactions equal the
    // first-order deck's (a different mesh, both exact: round-off, measured about 1e-13).
    CHECK(checkAllPass(zero) == 5);
    for (const char* support : {"left", "middle", "right"})
      for (Dof d : {Dof::uy, Dof::rz}) {
        CAPTURE(support);
        const double a = staticReaction(*plain.run, support, d);
        CHECK(std::abs(staticReaction(*zero.run, support, d) - a) <= 1e-9 * std::abs(a));
      }
  }

  TEST_CASE("pump rod under the piston force: compression amplifies, tension relieves") {
    const Study push = solveStudy(shippedDeckRequest("pump_rod_piston_force.yaml"));
    const Study pull =
        solveStudy(shippedDeckRequest("pump_rod_piston_force.yaml", {"pushing=0"}));
    const Study zero = solveStudy(shippedDeckRequest("pump_rod_piston_force.yaml", {"p=0"}));
    REQUIRE(push.run);
    REQUIRE(pull.run);
    CHECK(checkAllPass(push) == 1);
    CHECK(checkAllPass(pull) == 1);
    const auto& pushed = *resultOf<SecondOrderResult>(outcomeNamed(*push.run, "bending"));
    const auto& pulled = *resultOf<SecondOrderResult>(outcomeNamed(*pull.run, "bending"));
    // The crosshead end is displaced by w0, not loaded: the force that takes is the stiffness
    // of the rod against that displacement (a Schur complement of K + KG), which compression
    // lowers and tension raises (KG is negative, resp. positive, semi-definite when every
    // element is compressed, resp. tensioned). So |P2| falls when pushing and rises when
    // pulling.
    const double p0 = std::abs(staticReaction(*zero.run, "left", Dof::uy));
    const double pPush = std::abs(staticReaction(*push.run, "left", Dof::uy));
    const double pPull = std::abs(staticReaction(*pull.run, "left", Dof::uy));
    const auto& buckling = *resultOf<BucklingResult>(outcomeNamed(*push.run, "stability"));
    REQUIRE(!buckling.modes.empty());
    const double lambda = buckling.modes[0].factor;
    MESSAGE("pump rod, p = 10 MPa, Dp = 160 mm: buckling factor " << lambda << "; P2 " << p0
            << " (p = 0), " << pPush << " (pushing), " << pPull << " (pulling); moment "
            << "amplification " << pushed.momentAmplification << " / "
            << pulled.momentAmplification << ", stress amplification "
            << pushed.stressAmplification << " / " << pulled.stressAmplification);
    CHECK(relError(pushed.criticalFactor, lambda) < 1e-9);  // the same eigenproblem
    CHECK(pPush < p0);
    CHECK(pPull > p0);
    // The tension stroke cannot buckle the rod: no positive factor, and a warning says so.
    const auto& pullBuckling = *resultOf<BucklingResult>(outcomeNamed(*pull.run, "stability"));
    CHECK(pullBuckling.modes.empty());
    CHECK(!pullBuckling.warnings.empty());
  }
}
