// The crank-slider analysis (problems/scenes/README.md section 3) through a deck: the shipped
// SNT-32 deck's figures and its paper figures with their reasons, the motion table against a
// second method (finite differences, brute-force peaks), the two-term approximation against its
// truncation bound, the balance of three cranks, and bad input.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "problems/deck/Quantity.hpp"
#include "problems/run/RunCrankSlider.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

constexpr double kPiDrive = std::numbers::pi;

const CrankSliderOutcome& driveOutcome(const RunResult& run, const std::string& name) {
  for (const AnalysisOutcome& a : run.analyses)
    if (a.name == name && resultOf<CrankSliderOutcome>(a)) return *resultOf<CrankSliderOutcome>(a);
  FAIL("no crank-slider analysis " << name);
  return *resultOf<CrankSliderOutcome>(run.analyses.front());
}

const Check& driveCheck(const RunResult& run, const std::string& name) {
  for (const Check& c : run.checks)
    if (c.name == name) return c;
  FAIL("no check " << name);
  return run.checks.front();
}

/// A small crank-slider deck with `extra` appended to its analysis entry.
std::string crankDeck(const std::string& analysisExtra, const std::string& checks = "") {
  return "analyses:\n  - {type: crank-slider, r: 0.05, l: 0.2, speed_rpm: 300" + analysisExtra +
         "}\n" + checks;
}

}  // namespace

TEST_SUITE("crank-slider analysis") {
  TEST_CASE("SNT-32 deck: printed figures reproduced, the others carried with their reasons") {
    const Study s = solveStudy(shippedDeckRequest("snt32_drive.yaml"));
    REQUIRE(s.run);
    const RunResult& run = *s.run;
    CHECK(checkAllPass(s) == 28);
    CHECK(run.model->nodeCount() == 0);  // a mechanism: no model
    // Independent numbers from the paper's data (r = 0.0188, l = 0.288, omega = 62):
    const double r = 0.0188, l = 0.288, w = 62, lam = r / l;
    const double mRot = 24.1 * 0.00762 / r + 18.0 * 0.248 / l;
    const double mRec = 15.29 + 18.0 * 0.040 / l;
    const CrankSliderOutcome& c = driveOutcome(run, "drive");
    // a_max at the outer dead centre, r omega^2 (1 + lambda): the golden-section search lands
    // on a flat maximum, to round-off.
    CHECK(std::abs(c.aMax / (r * w * w * (1 + lam)) - 1) < 1e-13);
    // The paper's 74.75 is K_lambda r n^2 with its Table 2 K_lambda = 0.0115 at 588 rpm:
    const Check& aMax = driveCheck(run, "largest slider acceleration");
    REQUIRE(aMax.paper);
    CHECK(std::abs(0.0115 * r * 588 * 588 - *aMax.paper) < 0.005);  // the print's half unit
    CHECK(aMax.reason.find("K_lambda") != std::string::npos);
    // The paper's 202 N second-order total is the reciprocating 84 N plus the rotating mass'
    // force times the printed lambda 0.065: the term with no second harmonic.
    const Check& second = driveCheck(run, "second order one crank");
    REQUIRE(second.paper);
    CHECK(std::abs(second.computed + mRot * r * w * w * 0.065 - *second.paper) < 1.0);
    CHECK(std::abs(second.computed - 84) < 0.5);
    // The delivery's 105.4 L/min: 3.14 for pi reproduces it to its print, pi does not.
    const Check& q = driveCheck(run, "theoretical delivery");
    CHECK(std::abs(3 * 3.14 / 4 * 0.045 * 0.045 * 2 * r * 588 * 1e3 - 105.4) < 0.05);
    CHECK(std::abs(q.computed * 60e3 - 105.4) > 0.05);
    // Masses and harmonics against the lever rule written out here.
    REQUIRE(c.reduced);
    CHECK(std::abs(c.reduced->rotating - mRot) < 1e-12 * mRot);
    CHECK(std::abs(c.harmonics[0] - mRec * r * w * w) < 1e-12 * c.harmonics[0]);
    int withPaper = 0;
    for (const Check& k : run.checks) withPaper += k.paper.has_value();
    CHECK(withPaper == 15);
    // Table 2's rows above 0.2 and Tables 4 and 5 at 45 deg: the paper's figures are what the
    // reasons say, recomputed here from their formulas.
    const Check& v05 = driveCheck(run, "Table 2 v_max over v_mean at 0.5");
    CHECK(std::abs(v05.computed - 1.7643) < 5e-5);  // brute force in the table test below
    const Check& rate = driveCheck(run, "Table 4 rod angular velocity at 45 deg");
    CHECK(std::abs(w * 0.065 * std::cos(kPiDrive / 4) - *rate.paper) < 0.005);
    const Check& accel = driveCheck(run, "Table 4 rod angular acceleration at 45 deg");
    CHECK(std::abs(w * w * 0.065 * std::sin(kPiDrive / 4) - *accel.paper) < 0.005);
    const Check& couple = driveCheck(run, "Table 5 rod inertia moment at 45 deg");
    CHECK(std::abs(0.93 * w * w * 0.065 * std::sin(kPiDrive / 4) - *couple.paper) < 0.005);
    // The first-order total 3107 N: the reduced masses' sum rounded to 43 kg.
    const Check& first = driveCheck(run, "first order one crank");
    CHECK(std::abs(43 * r * w * w - *first.paper) < 0.5);
    CHECK(std::abs(first.computed - 3111.7) < 0.05);
  }

  TEST_CASE("quantities at a crank angle against finite differences of x and beta") {
    const Study s = solveStudy(shippedDeckRequest("snt32_drive.yaml"));
    const CrankSliderOutcome& c = driveOutcome(*s.run, "drive");
    const double r = 0.0188, l = 0.288, w = 62, lam = r / l, jRes = 0.93;
    const double mRec = 15.29 + 18.0 * 0.040 / l;
    const auto beta = [&](double phi) { return std::asin(lam * std::sin(phi)); };
    const auto x = [&](double phi) {
      return r * (1 - std::cos(phi)) + l * (1 - std::cos(beta(phi)));
    };
    const auto measureAt = [&](const std::string& property, int deg) {
      return measureCrank(parseQuantity("crank " + property + " at " + std::to_string(deg) + " deg"),
                          c);
    };
    // Central differences in phi with h = 1e-3 rad: truncation h^2 / 6 (first) and h^2 / 12
    // (second) times the next derivative, ~2e-7 relative here; round-off eps / h^2 ~ 2e-10.
    const double h = 1e-3;
    const auto d1 = [&](auto f, double phi) { return (f(phi + h) - f(phi - h)) / (2 * h); };
    const auto d2 = [&](auto f, double phi) {
      return (f(phi + h) - 2 * f(phi) + f(phi - h)) / (h * h);
    };
    for (const int deg : {0, 45, 100, 250}) {
      CAPTURE(deg);
      const double phi = deg * kPiDrive / 180;
      CHECK(std::abs(measureAt("x", deg) - x(phi)) < 1e-15);
      CHECK(std::abs(measureAt("v", deg) - w * d1(x, phi)) < 1e-6 * r * w);
      CHECK(std::abs(measureAt("a", deg) - w * w * d2(x, phi)) < 1e-6 * r * w * w);
      CHECK(std::abs(measureAt("beta", deg) - beta(phi)) < 1e-15);
      CHECK(std::abs(measureAt("beta_dot", deg) - w * d1(beta, phi)) < 1e-6 * lam * w);
      CHECK(std::abs(measureAt("beta_ddot", deg) - w * w * d2(beta, phi)) < 1e-6 * lam * w * w);
      CHECK(std::abs(measureAt("moment", deg) + jRes * w * w * d2(beta, phi)) <
            1e-6 * jRes * lam * w * w);
      CHECK(std::abs(measureAt("force", deg) + mRec * w * w * d2(x, phi)) < 1e-6 * mRec * r * w * w);
      double sum = 0;
      for (const double theta : {0.0, 2 * kPiDrive / 3, 4 * kPiDrive / 3})
        sum += -mRec * w * w * d2(x, phi + theta);
      CHECK(std::abs(measureAt("cranks_force", deg) - sum) < 3e-6 * mRec * r * w * w);
    }
    // Bad input names what is allowed.
    const DeckError bad = readingError(
        crankDeck("", "checks:\n  - {name: b, quantity: crank beta_dt at 45 deg, reference: 1, "
                      "tolerance: 1}\n"),
        "angle.yaml");
    CHECK(bad.message().find("beta_dot") != std::string::npos);
    const DeckError noMass = readingError(
        crankDeck("", "checks:\n  - {name: m, quantity: crank moment at 45 deg, reference: 1, "
                      "tolerance: 1}\n"),
        "angle_mass.yaml");
    CHECK(noMass.message().find("masses") != std::string::npos);
  }

  TEST_CASE("motion table: rates by finite differences, two-term error within its bound") {
    const Study s = solveStudy(shippedDeckRequest("snt32_drive.yaml"));
    const CrankSliderOutcome& c = driveOutcome(*s.run, "drive");
    const double r = 0.0188, w = 62, lam = r / 0.288;
    const std::size_t n = c.samples.size();
    REQUIRE(n == 361);
    const double h = 2 * kPiDrive / 360 / w;  // time step between samples (s)
    double worstV = 0, worstA = 0, worstApprox = 0;
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const crank::State& m = c.samples[i - 1].exact;
      const crank::State& p = c.samples[i + 1].exact;
      worstV = std::max(worstV, std::abs((p.x - m.x) / (2 * h) - c.samples[i].exact.v));
      worstA = std::max(worstA, std::abs((p.v - m.v) / (2 * h) - c.samples[i].exact.a));
      worstApprox =
          std::max(worstApprox, std::abs(c.samples[i].exact.a - c.samples[i].approximate.a));
    }
    // Central differences err by h^2/6 |x'''| <= h^2/6 r omega^3 (1 + 2 lambda): 2.7e-5 m/s
    // here; and h^2/6 |x''''| for a.
    CHECK(worstV <= h * h / 6 * r * w * w * w * (1 + 2 * lam));
    CHECK(worstA <= h * h / 6 * r * w * w * w * w * (1 + 4 * lam));
    // The two-term acceleration drops A2 - lambda, A4 and A6 and the lambda^7 rest:
    // r omega^2 (lambda^3/4 + lambda^3/4 + O(lambda^5)) = 0.0152 m/s^2 here. Measured 0.0150.
    CHECK(worstApprox <= r * w * w * (lam * lam * lam / 2) * 1.01);
    CHECK(worstApprox >= r * w * w * (lam * lam * lam / 2) * 0.9);  // and it is that term
    // Three cranks: the exact sum of their inertia forces is the order-6 remainder, 3 m_rec r
    // omega^2 A6 at most (0.2 N here) plus the lambda^7 residual; one crank's is ~1300 N.
    const double mRec = c.reduced->reciprocating;
    for (const CrankSample& sample : c.samples)
      CHECK(std::abs(sample.cranksForce) <=
            3 * mRec * r * w * w * (c.series.A6 + 0.33 * std::pow(lam, 7)));
  }

  TEST_CASE("harmonic table: v_max / v_mean by brute force, K_lambda = (pi/30)^2 (1 + lambda)") {
    const Study s = solveStudy(shippedDeckRequest("snt32_drive.yaml"));
    const CrankSliderOutcome& c = driveOutcome(*s.run, "drive");
    REQUIRE(c.table.size() == 10);
    for (const CrankLambdaRow& row : c.table) {
      // Second method: the largest |dx/dphi| over 200000 samples, r = 1; the sampled maximum
      // is below the true one by at most |v''| dphi^2 / 8 ~ 1e-10.
      double best = 0;
      for (int i = 0; i <= 200000; ++i) {
        const double phi = kPiDrive * i / 200000;
        const double beta = std::asin(row.lambda * std::sin(phi));
        best = std::max(best, std::sin(phi + beta) / std::cos(beta));
      }
      CAPTURE(row.lambda);
      CHECK(std::abs(row.vRatio - best * kPiDrive / 2) < 1e-9);
      const double k = kPiDrive / 30;
      CHECK(std::abs(row.kLambda / (k * k * (1 + row.lambda)) - 1) < 1e-13);
    }
  }

  TEST_CASE("a crank-slider needs no model, and bad input names its field") {
    // One crank: the single-crank sums equal the crank's own harmonics.
    const Study one = solveDeckText(
        crankDeck(", masses: {slider: 10, rod: 4, rod_com_to_crank_pin: 0.05, "
                  "rod_com_to_slider_pin: 0.15}",
                  "checks:\n  - {name: F1, quantity: crank cranks_F1, reference: 10 * 0.05 * "
                  "(10*pi)^2 + 4 * 0.05 / 0.2 * 0.05 * (10*pi)^2, tolerance: 1e-12}\n"),
        "one_crank.yaml");
    CHECK(checkAllPass(one) == 1);
    const DeckError shortRod = readingError(
        "analyses:\n  - {type: crank-slider, r: 0.2, l: 0.1, speed_rpm: 300}\n", "short_rod.yaml");
    CHECK(shortRod.place().field.find(".l") != std::string::npos);
    CHECK(shortRod.place().line == 2);
    const DeckError com =
        readingError(crankDeck(", masses: {slider: 10, rod: 4, rod_com_to_crank_pin: 0.05, "
                               "rod_com_to_slider_pin: 0.2}"),
                     "com.yaml");
    CHECK(com.message().find("add up to l") != std::string::npos);
    const DeckError noMasses = readingError(
        crankDeck("", "checks:\n  - {name: F, quantity: crank F1, reference: 1, tolerance: 1}\n"),
        "no_masses.yaml");
    CHECK(noMasses.message().find("masses") != std::string::npos);
    const DeckError row =
        readingError(crankDeck(", lambdas: [0.1, 0.2]",
                               "checks:\n  - {name: A, quantity: crank A2 at 0.3, reference: 1, "
                               "tolerance: 1}\n"),
                     "row.yaml");
    CHECK(row.message().find("0.1, 0.2") != std::string::npos);
    const DeckError paperAlone = readingError(
        crankDeck("",
                  "checks:\n  - {name: v, quantity: crank v_max, reference: 1, tolerance: "
                  "1, paper: 2}\n"),
        "paper.yaml");
    CHECK(paperAlone.message().find("reason") != std::string::npos);
    const DeckError unordered = readingError(crankDeck(", lambdas: [0.2, 0.1]"), "order.yaml");
    CHECK(unordered.message().find("ascending") != std::string::npos);
  }

  TEST_CASE("solve writes the tables, the two charts and the paper lines") {
    const SolvedDeck d = solveShippedDeckToScratch("snt32_drive.yaml", "snt32_solve");
    CHECK(d.process.out.find("paper prints 74.75") != std::string::npos);
    CHECK(d.process.out.find("1st harmonic cancels, 2nd cancels") != std::string::npos);
    CHECK(d.process.out.find("model: none") != std::string::npos);
    const nlohmann::json doc = d.json("results.json");
    const nlohmann::json& drive = doc["analyses"][0];
    CHECK(drive["type"] == "crank-slider");
    CHECK(std::abs(drive["inertia"]["F1"].get<double>() - 1285.63) < 0.01);
    bool found = false;
    for (const auto& c : doc["checks"])
      if (c["name"] == "theoretical delivery") {
        found = true;
        CHECK(c["reason"].get<std::string>().find("3.14") != std::string::npos);
      }
    CHECK(found);
    const std::string motion = d.text("drive_motion.csv");
    CHECK(motion.rfind("phi,x,x_approx", 0) == 0);
    CHECK(motion.find("\n# units: deg,m,m") != std::string::npos);
    CHECK(!d.text("drive_harmonics.csv").empty());
    CHECK(!d.text("drive_lambda_table.csv").empty());
    std::filesystem::remove_all(d.dir.parent_path());
  }
}
