// The lean path of a design study (each point's expressions from byte code remembered by an
// ExpressionMemo, problems/deck/parse/Expression.hpp) against the full path (every point's deck
// parsed and evaluated in eight systems of units): the same table and summary, bit for bit,
// and the memo's evaluator against a plain one expression by expression.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/Units.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/study/DesignPoints.hpp"
#include "problems/study/DesignStudyRun.hpp"
#include "problems/study/StudyPoint.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// Runs `request` on the lean and on the full path; checks that both write the same table and
/// the same summary (but for the path each names) and returns the lean path's outcome.
DesignStudyOutcome studyBothWays(DesignStudyRequest request, const std::filesystem::path& out) {
  request.outDir = (out / "lean").string();
  request.fullPath = false;
  DesignStudyOutcome lean = runDesignStudy(request);
  request.outDir = (out / "full").string();
  request.fullPath = true;
  const DesignStudyOutcome full = runDesignStudy(request);
  CHECK(lean.summary["path"] == "lean");
  CHECK(full.summary["path"] == "full");
  // study.csv carries 17 significant digits, which read back bit for bit: equal files are
  // equal doubles in every cell.
  CHECK(fileContents(lean.dir / "study.csv") == fileContents(full.dir / "study.csv"));
  Json leanSummary = lean.summary, fullSummary = full.summary;
  leanSummary.erase("path");
  fullSummary.erase("path");
  CHECK(leanSummary.dump() == fullSummary.dump());
  return lean;
}

/// An evaluator's values: L (a length), E (a stress), eta and w0 (lengths).
void defineLeanTestNames(ExpressionEvaluator& e, double L, double w0) {
  e.define("L", Amount{L, dim::length, false});
  e.define("E", Amount{200e9, dim::pressure, false});
  e.define("w0", Amount{w0, dim::length, false});
  e.define("n", 3.0);
}

}  // namespace

TEST_SUITE("design study lean path") {
  TEST_CASE("the lean path writes the full path's table and summary bit for bit") {
    const auto scratch = scratchDir("study-lean");
    // The pump rod over stroke and wear, w0 = 0 included: there every reaction, reference and
    // stress is zero, which the lean path evaluates in full (a zero fits any dimension).
    DesignStudyRequest rod;
    rod.deckPath = (problemsDir() / "pump_rod.yaml").string();
    rod.study.sweeps = {"eta=0:0.4:4", "w0=0,0.7e-3,1.5e-3"};
    rod.study.outputs = {"reaction left uy", "reaction middle uy", "reaction right rz",
                         "stress max <= 200 MPa"};
    const DesignStudyOutcome o = studyBothWays(rod, scratch / "rod");
    CHECK(o.points == 15);
    CHECK(o.failed == 0);
    // Two threads on the lean path (a memo per thread): the same table again.
    rod.outDir = (scratch / "rod_threads").string();
    rod.threads = 2;
    const DesignStudyOutcome threaded = runDesignStudy(rod);
    CHECK(fileContents(threaded.dir / "study.csv") == fileContents(o.dir / "study.csv"));

    // Sampled, with a point that fails (eta beyond the rod) and values with units.
    DesignStudyRequest sampled = rod;
    sampled.threads = 1;
    sampled.study.sweeps.clear();
    sampled.study.samples = {"eta=uniform(0,1.5)", "E=lognormal(200e9,0.05)"};
    sampled.study.count = 40;
    sampled.study.seed = 3;
    const DesignStudyOutcome s = studyBothWays(sampled, scratch / "sampled");
    CHECK(s.failed > 0);  // some of the 40 put the seal beyond the rod's end
    CHECK(s.failed < 40);

    // A frame whose lateral load goes through zero and whose column height moves the joints.
    DesignStudyRequest frame;
    frame.deckPath = (problemsDir() / "portal_frame.yaml").string();
    frame.study.sweeps = {"h=3,4.5", "H=-5e3,0,10e3"};
    studyBothWays(frame, scratch / "frame");
    std::filesystem::remove_all(scratch);
  }

  TEST_CASE("a study's static systems share one symbolic analysis while their pattern holds") {
    // A simply supported beam under a uniform load whose element count is a parameter: the
    // span changes K's values only, the element count its pattern. A rotational spring joins
    // the two ends: K is then no narrow band (a plain line would be stored as one and
    // factorised with no symbolic analysis at all, fem/assembly/BandAssembly) and goes to the
    // sparse LDL'. Its end moments are equal and opposite, so each support still carries
    // half the load.
    const std::string text = R"(title: symbolic analysis shared among points
parameters:
  n: 4
  L: 2.0
model: {dimension: planar, formulation: euler-bernoulli}
materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]
sections: [{name: bar, shape: rectangle, b: 0.04, h: 0.06}]
segments: [{length: L, section: bar, elements: n}]
supports: [{name: left, at: start, fix: [ux, uy]}, {name: right, at: end, fix: [uy]}]
springs: [{at: start, to: end, dof: rz, k: 1e4}]
loads: [{type: distributed, qy: -5000}]
analyses: [{type: static}]
)";
    const DeckSource source = parseDeckText(text, "symbolic_reuse.yaml");
    const Deck deck = readDeck(source, {});
    StudyCommandLine study;
    study.sweeps = {"n=4,6", "L=1.5,2,2.5"};
    study.outputs = {"reaction left uy"};
    const StudyPlan plan = makeStudyPlan(source.path, text, deck, {}, "",
                                         readDesignStudy(source, deck, study));
    const DesignPoints points(plan.spec);
    REQUIRE(points.size() == 6);
    const PointSolver solver(plan);
    int patternChanges = 0;
    std::vector<double> previous;
    for (long long i = 0; i < points.size(); ++i) {
      const std::vector<double> values = points.at(i);  // n, L
      if (previous.empty() || values[0] != previous[0]) ++patternChanges;
      previous = values;
      const StudyRow row = solver.solve(i, values);
      REQUIRE(row.ok());
      // Half the load at each support; the solve is exact up to round-off (K's condition
      // number here is below 1e9, and the reactions are recovered from K u - f).
      const double expected = 5000 * values[1] / 2;
      CHECK(std::abs(row.outputs[0] - expected) <= 1e-9 * expected);
    }
    // Each new element count is analysed once; every other point reuses the analysis.
    CHECK(solver.symbolicAnalyses() == patternChanges);
    CHECK(solver.symbolicReuses() == points.size() - patternChanges);
    CHECK(patternChanges < points.size());
  }

  TEST_CASE("an evaluator sharing a memo gives the plain evaluator's values and dimensions") {
    // The reference is a plain evaluator (eight parses per expression) defined with the same
    // values; the memo must give each value bit for bit and the same dimension, on the reading
    // that fills it and on later readings at other values (zero among them).
    const std::vector<std::string> texts{
        "0.715 m - L/10", "E * pi * (L/20)^4 / 64", "12 kN/m * L", "sin(30 deg) * L",
        "w0 * n",       "max(L, 2 m) - w0",       "-w0",          "E / (1 GPa) + n^2"};
    ExpressionMemo memo;
    const double readings[][2] = {{1.7, 0.0}, {2.3, 0.4e-3}, {1.1, 0.0}, {2.3, 2e-3}};
    for (const auto& [L, w0] : readings) {
      ExpressionEvaluator plain, remembering(&memo);
      defineLeanTestNames(plain, L, w0);
      defineLeanTestNames(remembering, L, w0);
      for (const std::string& text : texts) {
        CAPTURE(text);
        CAPTURE(L);
        CAPTURE(w0);
        const Amount expected = plain.amount(text), got = remembering.amount(text);
        CHECK(got.si == expected.si);  // bit for bit
        CHECK(got.anyDimension == expected.anyDimension);
        CHECK(got.dimension.exponents == expected.dimension.exponents);
      }
    }
    // The first reading evaluated all eight in full. w0 * n and -w0 were zero there, which
    // fits any dimension, so the second (w0 != 0) evaluated those two in full to learn it;
    // every other value came from byte code, zeros included.
    CHECK(memo.memoEvaluations() == 3 * 8 - 2);
    CHECK(memo.fullEvaluations() == 8 + 2);
  }
}
