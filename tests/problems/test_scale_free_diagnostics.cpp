// Diagnostics that do not depend on units: the over-refinement fixture (a cantilever with a
// tip force) scaled uniformly from micrometres to kilometres gives the same relative results,
// conditioning and warnings at every scale; the round-off the warning reports is measured and
// bounds the real error; a clamped cantilever refined past double precision is never called a
// mechanism; and `accuracy:` stops refining where round-off takes over, naming its field.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "problems/deck/parse/DeckError.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

std::string fileText(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The over-refinement fixture (a 1.2 m cantilever, D = 50 mm, P = 1 kN at the tip) with
/// `elements` elements, every length times `lambda` and the force times lambda^2: stresses and
/// rotations stay, deflections scale with lambda, K with lambda (translations) to lambda^3
/// (rotations). `acceptRoundOff`: the static analysis keeps a solution that leaves no digit to
/// trust (accept_round_off: true), which otherwise fails.
RunResult scaledCantilever(int elements, double lambda, bool acceptRoundOff = false) {
  std::string text = fileText(std::filesystem::path(BEAMROTOR_SOURCE_DIR) /
                              "tests/problems/over_refined/cantilever_4000.yaml");
  const std::string from = "elements: 4000";
  text.replace(text.find(from), from.size(), "elements: " + std::to_string(elements));
  const std::string analysis = "- {type: static}";
  if (acceptRoundOff)
    text.replace(text.find(analysis), analysis.size(), "- {type: static, accept_round_off: true}");
  StudyRequest request;
  request.deckPath = "cantilever_scaled.yaml";
  request.sets = {setting("L", 1.2 * lambda), setting("D", 0.05 * lambda),
                  setting("P", 1000 * lambda * lambda)};
  return *solveStudyText(text, request).run;
}

const StaticResult& staticsOf(const RunResult& run) {
  return *staticsOf(run.analyses.front());
}

double tipDeflection(const RunResult& run) {
  return staticsOf(run).displacement(run.model->node("tip"), int(Dof::uy));
}

}  // namespace

TEST_SUITE("scale-free diagnostics") {
  TEST_CASE("a cantilever from micrometres to kilometres: same results, conditioning, warnings") {
    // Before: at L = 0.12 mm (lambda = 1e-4) the 16-element cantilever got an over-refinement
    // warning, at 12 micrometres (1e-5) it was refused as singular (CHOLMOD rcond 4.9e-16).
    for (int elements : {16, 4000}) {
      const RunResult base = scaledCantilever(elements, 1);
      const StaticResult& b = staticsOf(base);
      for (double lambda : {1e-6, 1e-5, 1e-4, 1e-3, 1e3}) {
        CAPTURE(elements);
        CAPTURE(lambda);
        const RunResult run = scaledCantilever(elements, lambda);
        const StaticResult& r = staticsOf(run);
        // Relative results: the same to the round-off the solutions carry (each measured).
        const double roundOff = std::max({b.roundOff, r.roundOff, 1e-14});
        CHECK(relError(tipDeflection(run) / lambda, tipDeflection(base)) < 100 * roundOff);
        CHECK(relError(run.checks[0].computed / lambda, base.checks[0].computed) < 100 * roundOff);
        // Diagnostics: the scaled condition estimate is the same number up to its own round-off
        // (its smallest pivot, a difference of large ones, is known to ~ eps / rcond: 1e-9 at
        // 16 elements, ~1 % measured at 4000), the measured round-off of the same order, the
        // warnings the same.
        CHECK(relError(r.rcond, b.rcond) < (elements == 16 ? 1e-9 : 0.05));
        CHECK(r.roundOff < 30 * std::max(b.roundOff, 1e-15));
        CHECK(b.roundOff < 30 * std::max(r.roundOff, 1e-15));
        CHECK(run.analyses[0].warnings.size() == base.analyses[0].warnings.size());
      }
      // 16 elements: exact to round-off, no warning; 4000: warned at every scale.
      CHECK(base.analyses[0].warnings.size() == (elements == 16 ? 0u : 1u));
    }
  }
}

TEST_SUITE("scale-free diagnostics") {
  TEST_CASE("the reported round-off bounds the real error, also where no digit holds") {
    // Hermite elements are exact for a tip force, so the tip's error is round-off alone: the
    // measured estimate (residual and A's own rounding, StaticResult::roundOff) must be at
    // least that. Before: at 20 000 elements the tip was 90 % off and the warning said 1.1 %.
    for (int elements : {16, 2000}) {
      CAPTURE(elements);
      const RunResult run = scaledCantilever(elements, 1);
      const double tipError = run.checks[0].relError();
      CHECK(staticsOf(run).roundOff >= tipError);
      // And not absurdly more. The estimate takes every rounding of K and of the solve with one
      // sign, the one smooth modes amplify most; the real error sums them with their own signs.
      // While element lengths were differences of node coordinates, those carried one
      // systematic perturbation and the estimate was 15-20x the error. With exact lengths only
      // independent per-entry roundings remain, which partly cancel: measured 620x at 16
      // elements (6.8e-11 against 1.1e-13) and 1120x at 2000 (1.5e-2 against 1.3e-5). 3000x
      // leaves a factor 2.7 over the larger and still fails an estimate gone off by 10x more.
      CHECK(staticsOf(run).roundOff < 3000 * std::max(tipError, 1e-13));
    }
    // 20 000 elements: the tip is 90 % off (the double-precision limit of any direct solver on
    // this K); solved (the deck accepting such a result, which otherwise fails: see
    // test_untrusted_statics.cpp), not called a mechanism, and the warning says no digit holds.
    const RunResult fine = scaledCantilever(20000, 1, true);
    CHECK(fine.checks[0].relError() > 0.5);
    CHECK(staticsOf(fine).roundOff >= fine.checks[0].relError());
    REQUIRE(fine.analyses[0].warnings.size() == 1);
    CHECK(fine.analyses[0].warnings[0].find("no digit of the solution can be trusted") !=
          std::string::npos);
  }

  TEST_CASE("accuracy: 1e-12 stops refining where round-off takes over, naming the field") {
    // problems/cantilever.yaml's frequencies converge as h^4 until round-off stops them; before,
    // the search went on to 4096 elements per segment and ended in a false "not fully
    // supported". Its FORMAT.md promise: a failure that names the `accuracy` field.
    std::string text = fileText(problemsDir() / "cantilever.yaml");
    const int line = int(std::count(text.begin(), text.end(), '\n')) + 1;
    text += "accuracy: 1e-12\n";
    StudyRequest request;
    request.deckPath = "cantilever_1e-12.yaml";
    try {
      solveStudyText(text, request);
      FAIL("1e-12 was reached");
    } catch (const DeckSolveError& e) {
      const std::string msg = e.what();
      MESSAGE(msg);
      CHECK(e.place().line == line);
      CHECK(msg.find("accuracy") != std::string::npos);
      CHECK(msg.find("round-off") != std::string::npos);
    }
  }
}
