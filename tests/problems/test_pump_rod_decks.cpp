// The pump rod decks of variants B (pinned crosshead end) and C (rotation stop at the piston):
// their closed-form checks hold for any eta and w0, variant C's across the switch at w*, and
// a short sweep draws the three stroke positions on one chart with the worst section reported.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "problems/output/files/CsvTable.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/PumpRodReference.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

const ContactState& pistonStop(const RunResult& run) {
  for (const AnalysisOutcome& a : run.analyses)
    if (staticsOf(a) && staticsOf(a)->contacts.size() == 1) return staticsOf(a)->contacts[0];
  throw std::logic_error("no contact in the run");
}

/// Variant C's switch point at stroke position eta with the example core and bore, from the
/// independent references of tests/problems/PumpRodReference.hpp: w* = theta_p / |theta_R|,
/// theta_R the piston-end rotation per unit w0 of the hinged solution.
double referenceWStar(double eta) {
  PumpRod rod;
  rod.eta = eta;
  return pistonTiltLimit(0.150, 0.060, 0.1501) /
         std::abs(pumpRodInitialParameters(rod, 1.0, false).rightRotation);
}

}  // namespace

TEST_SUITE("pump rod decks") {
  TEST_CASE("variant B deck: closed form to 1e-9 for any eta and w0") {
    for (const char* eta : {"0", "0.13", "0.4"})
      for (const char* w0 : {"0.001", "0.0037"}) {
        CAPTURE(eta);
        CAPTURE(w0);
        const Study s = solveStudy(shippedDeckRequest(
            "pump_rod_hinged.yaml", {std::string("eta=") + eta, std::string("w0=") + w0}));
        // Reactions, the left rotation and both stress peaks: 7 checks per run.
        CHECK(checkAllPass(s) == 7);
      }
  }

  TEST_CASE("variant C deck: bilinear closed form across w*, through the deck") {
    const Study base = solveStudy(shippedDeckRequest("pump_rod_limited_rotation.yaml"));
    const double wStar = deckValue(base.deck, "wstar");
    const double thetaP = deckValue(base.deck, "theta_p");
    // Both are the deck's `report:`, shown with the results.
    REQUIRE(base.run->reported.size() == 2);
    CHECK(base.run->reported[0] == std::pair<std::string, double>{"theta_p", thetaP});
    CHECK(base.run->reported[1] == std::pair<std::string, double>{"wstar", wStar});
    MESSAGE("theta_p = " << thetaP << " rad, w* = " << wStar * 1e3 << " mm");
    // Against independent references (tests/problems/PumpRodReference.hpp): theta_p from the
    // tilted core's width, Dp cos + lp sin = Dc, solved by bisection (the deck's arccos form
    // takes the difference of two angles of 0.38 rad, so its round-off is ~200 ulp of
    // theta_p: 1e-12); w* = theta_p / |theta_R| with the piston-end rotation per unit w0 of
    // the hinged solution by the numerically marched transfer matrix (the deck solves the
    // same conditions by Cramer's rule; condition ~1e7, so 1e-9 as for the reactions).
    const double thetaRef = pistonTiltLimit(0.150, 0.060, 0.1501), wStarRef = referenceWStar(0.4);
    CHECK(relError(thetaP, thetaRef) < 1e-12);
    CHECK(relError(wStar, wStarRef) < 1e-9);
    // The figures problems/scenes/README.md quotes (1.670e-3 rad, 2.157 mm) to their 4 digits.
    CHECK(std::abs(thetaRef - 1.670e-3) <= 0.0005e-3);
    CHECK(std::abs(wStarRef - 2.157e-3) <= 0.0005e-3);
    // A w0 sweep across w*, with the switch itself and values a hair either side.
    std::string values;
    for (int k = 1; k <= 10; ++k) values += exactDecimal(0.0005 * k) + ",";
    for (double f : {1 - 1e-7, 1.0, 1 + 1e-7}) values += exactDecimal(wStar * f) + ",";
    values.pop_back();
    StudyRequest r = shippedDeckRequest("pump_rod_limited_rotation.yaml");
    r.noSweep = false;
    r.sweep = "w0=" + values;
    const Study s = solveStudy(r);
    REQUIRE(s.sweep);
    // Five closed-form checks everywhere, the 4-digit regression pin at every value (eta = 0.4).
    CHECK(checkAllPass(s) == 6 * int(s.sweep->values.size()));
    for (std::size_t i = 0; i < s.sweep->values.size(); ++i) {
      const double w0 = s.sweep->values[i];
      CAPTURE(w0);
      // The stop closes only past w* (round-off decides at w* itself).
      if (std::abs(w0 - wStar) > 1e-9 * wStar)
        CHECK(pistonStop(s.sweep->runs[i]).active == (w0 > wStar));
    }
  }

  TEST_CASE("variant C deck as shipped: w* falls along the stroke, the stop closes past it") {
    StudyRequest r = shippedDeckRequest("pump_rod_limited_rotation.yaml");
    r.noSweep = false;
    const Study s = solveStudy(r);
    REQUIRE(s.sweep);
    REQUIRE(s.sweep->values == std::vector<double>{0, 0.2, 0.4});
    double previous = INFINITY;
    for (std::size_t i = 0; i < s.sweep->runs.size(); ++i) {
      const RunResult& run = s.sweep->runs[i];
      const double w0 = 0.004, wStar = run.reported.at(1).second;
      CAPTURE(wStar);
      // The independent reference at this eta, as in the case above (1e-9).
      CHECK(relError(wStar, referenceWStar(s.sweep->values[i])) < 1e-9);
      // The seal lies further from the piston as eta grows (c = 0.415 + eta): the piston end
      // turns more per unit w0, so the stop closes earlier.
      CHECK(wStar < previous);
      CHECK(pistonStop(run).active == (w0 > wStar));
      previous = wStar;
    }
    // At w0 = 4 mm: open at eta = 0 (w* = 5.35 mm), closed at 0.2 (3.19 mm) and 0.4.
    CHECK_FALSE(pistonStop(s.sweep->runs[0]).active);
    CHECK(pistonStop(s.sweep->runs[2]).active);
  }

  TEST_CASE("variant A: worst section on the thin side of the step, stress jumping there") {
    const SolvedDeck solved = solveShippedDeckToScratch("pump_rod.yaml", "pump-rod-a");
    const auto doc = solved.json("results.json");
    const auto& bending = doc["analyses"][0];
    // M(x) = M0 + V0 x on [0, psi] from the left reactions (moment -M0, force V0); outer-fibre
    // stress 32 |M| / (pi D^3) with the local diameter (problems/scenes/README.md section 1).
    const double a = 0.575, D1 = 0.120, D2 = 0.070, pi = std::numbers::pi;
    const double M0 = -bending["reactions"]["left"]["mz"].get<double>();
    const double V0 = bending["reactions"]["left"]["fy"].get<double>();
    const double Ma = M0 + V0 * a;
    const auto& top = bending["max_stress"];
    CHECK(relError(top["value"].get<double>(), 32 * std::abs(Ma) / (pi * D2 * D2 * D2)) < 1e-9);
    CHECK(std::abs(top["x"].get<double>() - a) < 1e-12);
    CHECK(top["section"] == "rod");
    // The jump at the step is the diameter ratio cubed, (D1 / D2)^3 = 5.04, read off the CSV
    // the charts draw: the last station of the extension and the first of the rod.
    std::istringstream csv(solved.text("bending_fields.csv"));
    std::string line;
    std::vector<double> atStep;
    while (std::getline(csv, line)) {
      if (line.rfind("0.575,", 0) != 0) continue;
      const auto comma = [&](int n) {
        std::size_t p = 0;
        for (int k = 0; k < n; ++k) p = line.find(',', p) + 1;
        return std::stod(line.substr(p));
      };
      atStep.push_back(comma(13));  // column 14: stress [Pa]
    }
    REQUIRE(atStep.size() == 2);
    CHECK(relError(atStep[1] / atStep[0], std::pow(D1 / D2, 3)) < 1e-9);
    // The summary prints the peak to 6 digits: the closed form's, from the independent
    // transfer-matrix reactions (M(a) = M0 + V0 a, 49.9381 MPa; FE and closed form agree to
    // 1e-9, far inside the printed digit).
    const PumpRodResponse ref = pumpRodInitialParameters(PumpRod{}, 0.001, true);
    const double peak = 32 * std::abs(-ref.leftMoment + ref.leftForce * a) / (pi * D2 * D2 * D2);
    char expected[96];
    std::snprintf(expected, sizeof expected, "largest normal stress %.6g MPa at x = 0.575 m (rod)",
                  peak * 1e-6);
    CAPTURE(expected);
    CHECK(solved.process.out.find(expected) != std::string::npos);
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("a three-value sweep overlays the diagrams and reports the worst section") {
    const SolvedDeck solved = solveShippedDeckToScratch("pump_rod_hinged.yaml", "pump-rod-hinged");
    // One chart script reads the three values' field tables, one line each.
    const std::string script = solved.text("bending_diagrams.gp");
    for (const char* v : {"bending_fields_value_000.csv", "bending_fields_value_001.csv",
                          "bending_fields_value_002.csv", "eta = 0.2", "shear stress"})
      CHECK(script.find(v) != std::string::npos);
    // The worst normal stress over the sweep is the largest of the runs' closed-form peaks
    // (their `largest stress closed form` references), and lies on the thin rod.
    const auto doc = solved.json("sweep.json");
    double closedForm = 0, at = -1;
    for (const auto& run : doc["runs"])
      for (const auto& c : run["checks"])
        if (c["name"] == "largest stress closed form" && c["reference"].get<double>() > closedForm)
          closedForm = c["reference"].get<double>(), at = run["value"].get<double>();
    const auto& worst = doc["worst"]["bending"]["max_stress"];
    CHECK(relError(worst["value"].get<double>(), closedForm) < 1e-9);
    CHECK(worst["at"]["eta"].get<double>() == at);
    CHECK(worst["section"] == "rod");
    CHECK(doc["worst"]["bending"].contains("max_shear"));
    // And the summary names it.
    CHECK(solved.process.out.find("largest normal stress") != std::string::npos);
    CHECK(solved.process.out.find("(rod) at eta = ") != std::string::npos);
    std::filesystem::remove_all(solved.dir.parent_path());
  }
}
