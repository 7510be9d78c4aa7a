// Design studies of the shipped decks end to end (problems/study/DesignStudyRun): the pump
// rod's stroke-and-wear grid against the initial-parameter solution at every point, threads
// against the serial table bit for bit, sample moments and an exceedance probability against
// the input distribution's closed forms, a failing point recorded in its row, and a rotor
// study over bearing stiffness keeping its critical speeds and checks.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/study/DesignStudyRun.hpp"
#include "problems/study/Sampling.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/PumpRodReference.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

DesignStudyRequest pumpRodStudy(const std::filesystem::path& out) {
  DesignStudyRequest r;
  r.deckPath = (problemsDir() / "pump_rod.yaml").string();
  r.outDir = out.string();
  return r;
}

}  // namespace

TEST_SUITE("design studies") {
  TEST_CASE("a stroke-and-wear grid gives every reaction of the closed form at every point") {
    const auto scratch = scratchDir("study-grid");
    DesignStudyRequest r = pumpRodStudy(scratch / "serial");
    r.study.sweeps = {"eta=0:0.4:4", "w0=0.5e-3:1.5e-3:2"};
    const DesignStudyOutcome serial = runDesignStudy(r);
    CHECK(serial.points == 15);
    CHECK(serial.failed == 0);
    const auto rows = csvCells(serial.dir / "study.csv");
    REQUIRE(rows.size() == 16);
    const auto& h = rows[0];
    const int eta = csvColumn(h, "eta"), w0 = csvColumn(h, "w0");
    for (std::size_t i = 1; i < rows.size(); ++i) {
      PumpRod rod;
      rod.eta = std::stod(rows[i][eta]);
      const PumpRodResponse ref = pumpRodInitialParameters(rod, std::stod(rows[i][w0]), true);
      // Hermite elements reproduce the cubic exactly: round-off only (the deck's 1e-9).
      CHECK(std::stod(rows[i][csvColumn(h, "reaction left uy")]) ==
            doctest::Approx(ref.leftForce).epsilon(1e-9));
      CHECK(std::stod(rows[i][csvColumn(h, "reaction left rz")]) ==
            doctest::Approx(ref.leftMoment).epsilon(1e-9));
      CHECK(std::stod(rows[i][csvColumn(h, "reaction middle uy")]) ==
            doctest::Approx(ref.middleForce).epsilon(1e-9));
      CHECK(std::stod(rows[i][csvColumn(h, "reaction right uy")]) ==
            doctest::Approx(ref.rightForce).epsilon(1e-9));
      CHECK(std::stod(rows[i][csvColumn(h, "reaction right rz")]) ==
            doctest::Approx(ref.rightMoment).epsilon(1e-9));
      CHECK(rows[i].back() == "ok");
    }
    // The closed-form checks pass wherever they apply (psi > a: all these points).
    for (const auto& check : serial.summary["checks"])
      if (check["applicable"].get<long long>() > 0) {
        CAPTURE(check["name"].get<std::string>());
        CHECK(check["passed"] == check["applicable"]);
      }
    CHECK(std::filesystem::exists(serial.dir / "worst" / "results.json"));
    CHECK(std::filesystem::exists(serial.dir / "summary.json"));

    // Two threads: the same table and summary, byte for byte.
    r.outDir = (scratch / "threads").string();
    r.threads = 2;
    const DesignStudyOutcome threaded = runDesignStudy(r);
    CHECK(fileContents(threaded.dir / "study.csv") == fileContents(serial.dir / "study.csv"));
    CHECK(fileContents(threaded.dir / "summary.json") ==
          fileContents(serial.dir / "summary.json"));
    std::filesystem::remove_all(scratch);
  }

  TEST_CASE("sampled wear: the mean and variance of a reaction linear in w0") {
    // The middle force is c w0 (linear statics, w0 the only load). With w0 uniform on
    // [a, b]: mean c (a + b) / 2, variance c^2 (b - a)^2 / 12. Tolerance: 5 standard errors
    // of each estimate for n random points: sd / sqrt(n) for the mean, and
    // sqrt((mu4 - sigma^4) / n) with mu4 = (b - a)^4 / 80 for the variance.
    const auto scratch = scratchDir("study-moments");
    DesignStudyRequest r = pumpRodStudy(scratch / "moments");
    r.study.samples = {"w0=uniform(0.5e-3,1.5e-3)"};
    r.study.count = 400;
    r.study.seed = 11;
    r.study.outputs = {"reaction middle uy"};
    const DesignStudyOutcome o = runDesignStudy(r);
    REQUIRE(o.failed == 0);
    PumpRod rod;  // eta = 0.4, the deck's
    const double c = pumpRodInitialParameters(rod, 1.0, true).middleForce;
    const double a = 0.5e-3, b = 1.5e-3, n = 400;
    const double mean = c * (a + b) / 2, variance = c * c * (b - a) * (b - a) / 12;
    const double mu4 = std::pow(c * (b - a), 4) / 80;
    const auto& out = o.summary["outputs"][0];
    const double sampleMean = out["mean"].get<double>();
    const double sampleVariance = std::pow(out["sd"].get<double>(), 2);
    CHECK(std::abs(sampleMean - mean) < 5 * std::sqrt(variance / n));
    CHECK(std::abs(sampleVariance - variance) < 5 * std::sqrt((mu4 - variance * variance) / n));
    // The estimates are not trivially exact either: the sample varies.
    CHECK(sampleMean != mean);
    std::filesystem::remove_all(scratch);
  }

  TEST_CASE("the probability of exceeding a stress limit with normal wear is a normal tail") {
    // The largest stress is k w0 (linear statics): P(k w0 > L) = 1 - Phi((L / k - mu) / sd).
    // k from a deterministic point (w0 = 1 mm); L where the exact probability is 0.2.
    // Tolerance: 5 binomial standard errors sqrt(p (1 - p) / n).
    const auto scratch = scratchDir("study-tail");
    DesignStudyRequest once = pumpRodStudy(scratch / "once");
    once.study.sweeps = {"w0=1e-3"};
    once.study.outputs = {"stress max"};
    const double k = runDesignStudy(once).summary["outputs"][0]["mean"].get<double>() / 1e-3;
    const double mu = 1e-3, sd = 0.2e-3, p = 0.2;
    const double limit = k * (mu + sd * normalQuantile(1 - p));
    DesignStudyRequest r = pumpRodStudy(scratch / "tail");
    r.study.samples = {"w0=normal(1e-3,0.2e-3)"};
    r.study.count = 1000;
    r.study.seed = 5;
    char output[96];
    std::snprintf(output, sizeof output, "stress max <= %.17g", limit);
    r.study.outputs = {output};
    const DesignStudyOutcome o = runDesignStudy(r);
    const auto& exceedance = o.summary["outputs"][0]["exceedance"];
    const double estimate = exceedance["probability"].get<double>();
    CHECK(std::abs(estimate - p) < 5 * std::sqrt(p * (1 - p) / 1000));
    CHECK(exceedance["wilson95"][0].get<double>() < estimate);
    CHECK(exceedance["wilson95"][1].get<double>() > estimate);
    std::filesystem::remove_all(scratch);
  }

  TEST_CASE("a point that fails is recorded in its row and the study goes on") {
    const auto scratch = scratchDir("study-failure");
    DesignStudyRequest r = pumpRodStudy(scratch / "fail");
    // eta = 2 puts the seal beyond the rod's end: that point cannot be built.
    r.study.sweeps = {"eta=0.2,2,0.4"};
    const DesignStudyOutcome o = runDesignStudy(r);
    CHECK(o.points == 3);
    CHECK(o.failed == 1);
    const auto rows = csvCells(o.dir / "study.csv");
    CHECK(rows[1].back() == "ok");
    CHECK(rows[2].back() != "ok");
    CHECK(rows[2][csvColumn(rows[0], "reaction left uy")].empty());
    CHECK(rows[3].back() == "ok");
    std::filesystem::remove_all(scratch);
  }

  TEST_CASE("a rotor study over bearing stiffness keeps critical speeds and checks per point") {
    // The forme shaft in its rigid limit (E = 2e17): the deck's checks are the two-dof closed
    // forms, so each must pass at every stiffness; the bounce critical speed goes with
    // sqrt(C1) (both bearings scale with C1), a ratio of 2 from C1 to 4 C1 (both within the
    // Campbell range, where every critical speed the checks ask for is found).
    const auto scratch = scratchDir("study-rotor");
    DesignStudyRequest r;
    r.deckPath = (problemsDir() / "forme_shaft_rotor.yaml").string();
    r.outDir = (scratch / "rotor").string();
    r.sets = {"E=2e17"};
    r.study.sweeps = {"C1=0.5e8,2e8"};
    const DesignStudyOutcome o = runDesignStudy(r);
    REQUIRE(o.failed == 0);
    for (const auto& check : o.summary["checks"]) {
      CAPTURE(check["name"].get<std::string>());
      CHECK(check["passed"] == check["applicable"]);
    }
    const auto rows = csvCells(o.dir / "study.csv");
    const int critical = csvColumn(rows[0], "critical_speed 1");
    CHECK(std::stod(rows[2][critical]) / std::stod(rows[1][critical]) ==
          doctest::Approx(2.0).epsilon(1e-6));
    std::filesystem::remove_all(scratch);
  }
}

TEST_SUITE("design studies") {
  TEST_CASE("a study's ranges in mm are the study in m; a unit of another dimension is refused") {
    // The pump rod's stroke eta and wear w0 are lengths: a grid written in mm gives the values
    // written in m bit for bit (0.2 = 200 x 0.001 exactly in binary), so the two tables agree
    // byte for byte.
    const auto scratch = scratchDir("study-units");
    const std::string rod = fileContents(problemsDir() / "pump_rod.yaml");
    auto studyOf = [&](const std::string& name, const std::string& parameters) {
      const auto path = scratch / (name + ".yaml");
      std::ofstream(path) << rod + "\nstudy:\n  parameters:\n" + parameters +
                                 "  outputs: [reaction middle uy, stress max]\n";
      DesignStudyRequest r;
      r.deckPath = path.string();
      r.outDir = (scratch / name).string();
      return r;
    };
    const DesignStudyOutcome metres = runDesignStudy(studyOf(
        "metres", "    eta: {from: 0, to: 0.4, steps: 2}\n    w0: {values: [0.5e-3, 1.5e-3]}\n"));
    const DesignStudyOutcome millimetres = runDesignStudy(
        studyOf("millimetres",
                "    eta: {from: 0, to: 400 mm, steps: 2}\n    w0: {values: [0.5 mm, 1.5 mm]}\n"));
    CHECK(metres.points == 6);
    CHECK(fileContents(millimetres.dir / "study.csv") == fileContents(metres.dir / "study.csv"));

    // A distribution's numbers take the unit too (sigma of a lognormal is a pure number).
    auto sampled = [&](const std::string& w0) {
      const std::string text =
          rod + "\nstudy:\n  parameters:\n    w0: " + w0 + "\n  sampling: random\n  samples: 4\n";
      const DeckSource source = parseDeckText(text, "rod.yaml");
      return readDesignStudy(source, readDeck(source), {}).parameters.at(0).distribution.value();
    };
    const StudyDistribution si =
        sampled("{distribution: normal, mean: 1e-3, sd: 0.2e-3, lower: 0}");
    const StudyDistribution mm =
        sampled("{distribution: normal, mean: 1 mm, sd: 0.2 mm, lower: 0 m}");
    CHECK(mm.first == si.first);
    CHECK(mm.second == si.second);
    CHECK(mm.lower == si.lower);

    // Another dimension is refused at the line and column of the value, naming the field.
    try {
      runDesignStudy(studyOf("wrong", "    eta: {from: 0, to: 400 kg, steps: 2}\n"));
      FAIL("a mass was taken for the stroke");
    } catch (const DeckError& e) {
      const std::string what = e.what();
      const std::string line = std::to_string(std::count(rod.begin(), rod.end(), '\n') + 4);
      CHECK(what.find("wrong.yaml:" + line +
                      ":24: study.parameters.eta.to: to expects a length "
                      "(m), got a mass (kg)") != std::string::npos);
    }
    std::filesystem::remove_all(scratch);
  }

  TEST_CASE("a deck's study: block samples by Latin hypercube; its mistakes name their line") {
    // The Latin hypercube's sample mean of a linear output is far closer to the exact mean
    // than random sampling's: each of the n strata of w0 holds one point, uniform inside its
    // stratum of width h = (b - a) / n, so the mean of w0 has the standard deviation
    // h / sqrt(12 n) = 1.1e-3 relative for n = 40 (random sampling: (b - a) / sqrt(12 n) =
    // 4.6e-2 relative). Tolerance: 5 of the former, still 8 times below the latter.
    const auto scratch = scratchDir("study-block");
    const std::string deck = fileContents(problemsDir() / "pump_rod.yaml") +
                             "\nstudy:\n"
                             "  parameters:\n"
                             "    w0: {distribution: uniform, low: 0.5e-3, high: 1.5e-3}\n"
                             "  sampling: latin-hypercube\n"
                             "  samples: 40\n"
                             "  outputs: [reaction middle uy]\n";
    const auto path = scratch / "pump_rod_study.yaml";
    std::ofstream(path) << deck;
    DesignStudyRequest r;
    r.deckPath = path.string();
    r.outDir = (scratch / "out").string();
    const DesignStudyOutcome o = runDesignStudy(r);
    CHECK(o.summary["sampling"] == "latin-hypercube");
    CHECK(o.points == 40);
    PumpRod rod;
    const double mean = pumpRodInitialParameters(rod, 1e-3, true).middleForce;
    CHECK(o.summary["outputs"][0]["mean"].get<double>() == doctest::Approx(mean).epsilon(5.7e-3));

    std::ofstream(path) << fileContents(problemsDir() / "pump_rod.yaml") +
                               "\nstudy:\n  parameters:\n    w0: {distribution: normal, mean: 1, "
                               "sdev: 0.1}\n  samples: 4\n";
    try {
      runDesignStudy(r);
      FAIL("a misspelt key was accepted");
    } catch (const DeckError& e) {
      CHECK(std::string(e.what()).find("study.parameters.w0") != std::string::npos);
      CHECK(std::string(e.what()).find("unknown key in a normal distribution (allowed: distribution, mean, sd") != std::string::npos);
    }
    std::filesystem::remove_all(scratch);
  }
}
