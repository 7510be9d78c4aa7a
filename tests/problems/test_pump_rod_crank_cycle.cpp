// The pump rod driven by its crank (problems/pump_rod_crank_cycle.yaml): the deck's stroke
// position eta(phi), computed by the deck function crank_position, against the crank-slider
// kinematics written out here and against problems/scenes/CrankSlider; the reactions at the
// dead centres against pump_rod.yaml at eta = 0 and 0.4 (plumbing: two decks of one model; the
// published reactions the deck checks at the dead centres are the independent reference); and
// the function's domain errors.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/scenes/CrankSlider.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// Slider displacement from the dead centre at phi = 0: x = r (1 - cos phi) + L (1 - cos beta),
/// sin beta = (r / L) sin phi (e.g. Shigley & Uicker, Theory of Machines and Mechanisms).
double sliderPosition(double r, double L, double phi) {
  const double beta = std::asin(r / L * std::sin(phi));
  return r * (1 - std::cos(phi)) + L * (1 - std::cos(beta));
}

}  // namespace

TEST_SUITE("pump rod crank cycle") {
  TEST_CASE("the deck's eta(phi) is the crank-slider's slider position") {
    for (double phiDeg : {0.0, 30.0, 90.0, 137.5, 180.0, 270.0, 345.0}) {
      CAPTURE(phiDeg);
      const Study s = solveStudy(shippedDeckRequest("pump_rod_crank_cycle.yaml",
                                                    {"phi=" + std::to_string(phiDeg) + "deg"}));
      const double r = deckValue(s.deck, "r"), L = deckValue(s.deck, "L");
      const double eta = deckValue(s.deck, "eta"), phi = phiDeg * kPi / 180;
      // The formula above and the scene model differ in how they avoid cancellation near the
      // dead centres: a few roundings of the 0.4 m stroke.
      CHECK(std::abs(eta - sliderPosition(r, L, phi)) < 1e-14);
      CHECK(std::abs(eta - crank::exactInPhi(crank::makeGeometry(r, L), phi).x) < 1e-15);
      CHECK(eta >= 0);
      CHECK(eta <= 2 * r + 1e-15);
    }
  }

  TEST_CASE("at the dead centres the reactions are pump_rod.yaml's at eta = 0 and 0.4") {
    for (const auto& [phi, eta] :
         {std::pair{"0", "0"}, std::pair{"180", "0.4"}, std::pair{"360", "0"}}) {
      CAPTURE(phi);
      const RunResult crank = *solveStudy(shippedDeckRequest("pump_rod_crank_cycle.yaml",
                                                             {std::string("phi=") + phi + "deg"}))
                                   .run;
      const RunResult rod =
          *solveStudy(shippedDeckRequest("pump_rod.yaml", {std::string("eta=") + eta})).run;
      // Plumbing, not a second method: the same model up to the middle support's position,
      // off by at most a rounding of eta (sin pi is 1.2e-16, not 0), so round-off. It shows
      // crank_position puts the rod where pump_rod.yaml does.
      for (const auto& [support, dof] :
           std::vector<std::pair<std::string, Dof>>{{"left", Dof::uy},
                                                    {"left", Dof::rz},
                                                    {"middle", Dof::uy},
                                                    {"right", Dof::uy},
                                                    {"right", Dof::rz}}) {
        CAPTURE(support);
        CHECK(relError(staticReaction(crank, support, dof), staticReaction(rod, support, dof)) <
              1e-9);
      }
      // The published dead-centre checks apply here (and pass: the deck test runs them).
      CHECK(!crank.checks.empty());
    }
  }

  TEST_CASE("the whole revolution: published checks at both dead centres, none elsewhere") {
    StudyRequest r = shippedDeckRequest("pump_rod_crank_cycle.yaml");
    r.noSweep = false;
    const Study s = solveStudy(r);
    REQUIRE(s.sweep);
    REQUIRE(s.sweep->values.size() == 25);  // 0:360 deg:24, every 15 deg, in rad
    for (std::size_t i = 0; i < s.sweep->values.size(); ++i) {
      const double phi = s.sweep->values[i];
      CAPTURE(phi);
      // 180 deg and 360 deg are pi and 2 pi exactly (180 x (pi / 180) rounds to pi).
      const std::size_t expected = phi == kPi ? 5 : phi == 0 || phi == 2 * kPi ? 1 : 0;
      CHECK(s.sweep->runs[i].checks.size() == expected);
      for (const Check& c : s.sweep->runs[i].checks) CHECK(c.pass());
    }
  }

  TEST_CASE("solve: eta reported per crank angle in sweep.json and sweep.csv, worst at 180 deg") {
    const SolvedDeck solved = solveShippedDeckToScratch("pump_rod_crank_cycle.yaml", "crank-cycle");
    const auto doc = solved.json("sweep.json");
    REQUIRE(doc["runs"].size() == 25);
    for (const auto& run : doc["runs"]) {
      const double phi = run["value"].get<double>();  // in rad: the deck's 15 deg steps in SI
      CHECK(std::abs(run["reported"]["eta"].get<double>() - sliderPosition(0.2, 1.2, phi)) < 1e-14);
    }
    // The rod is worst at the outer dead centre (eta = 0.4), on the thin rod at the step.
    const auto& worst = doc["worst"]["bending"]["max_stress"];
    CHECK(worst["at"]["phi"].get<double>() == kPi);
    CHECK(worst["section"] == "rod");
    CHECK(std::abs(worst["x"].get<double>() - 0.575) < 1e-12);
    const std::string csv = solved.text("sweep.csv");
    CHECK(csv.substr(0, csv.find('\n')).find(",eta,") != std::string::npos);
    // The summary's table: back at the dead centre (phi = 2 pi) eta is exactly 0 and the
    // crank-slider's r (1 - cos 2 pi) leaves 1e-33 m of round-off, shown as 0 beside the
    // column's 0.4 m.
    const std::string& out = solved.process.out;
    const std::size_t last = out.find("  6.28319 ");
    REQUIRE(last != std::string::npos);
    std::istringstream row(out.substr(last, out.find('\n', last) - last));
    std::string phi, eta;
    row >> phi >> eta;
    CHECK(eta == "0");
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("crank_position outside its domain names the function") {
    ExpressionEvaluator ev;
    CHECK(ev.evaluate("crank_position(0.2, 1.2, pi)") == doctest::Approx(0.4).epsilon(1e-15));
    CHECK(ev.evaluate("crank_rod_angle(0.2, 1.2, pi/2)") ==
          doctest::Approx(std::asin(0.2 / 1.2)).epsilon(1e-15));
    try {
      ev.evaluate("crank_position(1.2, 0.2, 0)");
      FAIL("no error");
    } catch (const ExpressionError& e) {
      CHECK(std::string(e.what()).find("crank_position(r, l, phi):") != std::string::npos);
    }
    // Function names are reserved: a deck cannot define a parameter called crank_position.
    CHECK_THROWS_AS(ev.define("crank_position", 1), ExpressionError);
  }

  TEST_CASE("a compiled expression of t (a time load) can call crank_position too") {
    // A crank turning at 1 rad/s: the slider has run the whole stroke 2 r at t = pi, and
    // equals the kinematics above in between.
    const ExpressionEvaluator ev;
    const CompiledExpression x = ev.compile("crank_position(0.2, 1.2, t)", {"t"});
    CHECK(x({kPi}) == doctest::Approx(0.4).epsilon(1e-15));
    CHECK(std::abs(x({1.0}) - sliderPosition(0.2, 1.2, 1.0)) < 1e-15);
  }
}
