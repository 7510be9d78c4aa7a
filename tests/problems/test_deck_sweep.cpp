// Sweeps: the deck is re-read and re-solved for each value of one parameter, which may move
// supports; one run per value, in order.
#include <doctest/doctest.h>

#include <cmath>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/run/Study.hpp"
#include "tests/ThreadsSetting.hpp"

using namespace beamrotor;

namespace {

// A simply supported beam whose right support sits at x = s; a load P at midspan between
// the supports: reaction P/2 at each, midspan deflection P s^3 / (48 E I).
const std::string kSweepDeck = R"(
parameters:
  s: 1.0
  P: 1000
materials:
  - {name: steel, E: 200e9, nu: 0.3}
sections:
  - {name: bar, shape: rectangle, b: 0.02, h: 0.05}
segments:
  - {length: 2.0, section: bar, elements: 8}
points:
  - {name: mid, at: s/2}
  - {name: support, at: s}
supports:
  - {name: left, at: start, fix: pinned}
  - {name: right, at: support, fix: [uy]}
loads:
  - {type: point, at: mid, fy: -P}
checks:
  - {name: midspan deflection, quantity: displacement mid uy,
     reference: -P*s^3/(48*200e9*0.02*0.05^3/12), tolerance: 1e-9}
  - {name: only at s = 1, quantity: reaction right uy, reference: P/2, tolerance: 1e-9,
     when: s == 1}
SWEEP
)";

Study solve(const std::string& sweep, StudyRequest r = {}) {
  std::string text = kSweepDeck;
  text.replace(text.find("SWEEP"), 5, sweep);
  r.deckPath = "sweep.yaml";
  return solveStudyText(text, r);
}

double midDeflection(const RunResult& run) {
  return staticsOf(run.analyses[0])->displacement(run.model->node("mid"), dofIndex(Dof::uy));
}

}  // namespace

TEST_SUITE("deck sweep") {
  TEST_CASE("from/to/steps gives steps + 1 runs and moves the support") {
    const Study st = solve("sweep: {parameter: s, from: 1, to: 2, steps: 4}");
    REQUIRE(st.sweep);
    CHECK_FALSE(st.run);
    REQUIRE(st.sweep->runs.size() == 5);
    CHECK(st.sweep->values == std::vector<double>{1, 1.25, 1.5, 1.75, 2});
    for (std::size_t i = 0; i < 5; ++i) {
      const double s = st.sweep->values[i];
      const RunResult& run = st.sweep->runs[i];
      CAPTURE(s);
      // Each run carries its own parameter value ...
      CHECK(run.parameters[0] == std::pair<std::string, double>{"s", s});
      // ... and its own model: the right support moved to x = s.
      CHECK(run.model->nodes()[run.model->node("support")].x() == doctest::Approx(s));
      // Exact Euler-Bernoulli result, round-off only.
      const double EI = 200e9 * 0.02 * std::pow(0.05, 3) / 12;
      CHECK(midDeflection(run) == doctest::Approx(-1000 * s * s * s / (48 * EI)).epsilon(1e-9));
      for (const Check& c : run.checks) CHECK(c.pass());
      // The `when: s == 1` check runs at the first value only.
      CHECK(run.checks.size() == (i == 0 ? 2u : 1u));
      CHECK(run.skippedChecks.size() == (i == 0 ? 0u : 1u));
    }
  }

  TEST_CASE("an explicit list of values, and --set of the swept parameter runs once") {
    const Study st = solve("sweep: {parameter: s, values: [1.2, 1.6]}");
    REQUIRE(st.sweep);
    CHECK(st.sweep->values == std::vector<double>{1.2, 1.6});
    StudyRequest r;
    r.sets = {"s=1.5"};
    const Study single = solve("sweep: {parameter: s, values: [1.2, 1.6]}", r);
    REQUIRE(single.run);
    CHECK_FALSE(single.sweep);
    CHECK(single.run->parameters[0].second == 1.5);
  }

  TEST_CASE("a parameter written with a unit labels its sweep with its SI unit") {
    // The load in kN (the deck's checks, in bare numbers, are left out), swept over P.
    std::string text = kSweepDeck;
    text.replace(text.find("  P: 1000"), 9, "  P: 1 kN");
    text.erase(text.find("checks:"));
    text += "sweep: {parameter: P, values: [1000, 1500]}\n";
    StudyRequest r;
    r.deckPath = "sweep.yaml";
    const Study withUnit = solveStudyText(text, r);
    REQUIRE(withUnit.sweep);
    CHECK(withUnit.sweep->unit == "N");
    // A bare number takes the dimension of the field it flows into (s places a support: a
    // length), in SI: its values are metres.
    const Study bare = solve("sweep: {parameter: s, values: [1, 1.5]}");
    CHECK(bare.sweep->unit == "m");
  }

  TEST_CASE("sweep values take units of the swept parameter's dimension") {
    // s is a length (the support's place): values in m and mm are its SI values, bit for bit
    // (1.5 = 1500 x 0.001 exactly in binary), whether the deck writes s bare or with its unit,
    // and each run solves the same model.
    const Study bare = solve("sweep: {parameter: s, values: [1, 1.5]}");
    const Study units = solve("sweep: {parameter: s, values: [1 m, 1500 mm]}");
    std::string text = kSweepDeck;  // its checks, in bare numbers, left out
    text.replace(text.find("  s: 1.0"), 8, "  s: 1000 mm");
    text.erase(text.find("checks:"));
    text += "sweep: {parameter: s, from: 1 m, to: 1500 mm, steps: 1}\n";
    StudyRequest r;
    r.deckPath = "sweep.yaml";
    const Study stated = solveStudyText(text, r);
    REQUIRE(bare.sweep);
    REQUIRE(units.sweep);
    REQUIRE(stated.sweep);
    CHECK(bare.sweep->values == std::vector<double>{1, 1.5});
    CHECK(units.sweep->values == bare.sweep->values);
    CHECK(stated.sweep->values == bare.sweep->values);
    for (std::size_t i = 0; i < 2; ++i) {
      CHECK(midDeflection(units.sweep->runs[i]) == midDeflection(bare.sweep->runs[i]));
      CHECK(midDeflection(stated.sweep->runs[i]) == midDeflection(bare.sweep->runs[i]));
    }
    // A unit of another dimension is refused at its line and column, naming the field.
    CHECK_THROWS_WITH_AS(solve("sweep: {parameter: s, values: [1 m, 1.5 kg]}"),
                         "sweep.yaml:24:37: sweep.values[1]: values[1] expects a length (m), got "
                         "a mass (kg)",
                         DeckError);
    CHECK_THROWS_WITH_AS(solve("sweep: {parameter: P, from: 100 N, to: 2 m, steps: 2}"),
                         "sweep.yaml:24:40: sweep.to: to expects a force (N), got a length (m)",
                         DeckError);
  }

  TEST_CASE("a sweep from the command line replaces the deck's") {
    StudyRequest r;
    r.sweep = "s=1:2:2";
    const Study st = solve("", r);
    REQUIRE(st.sweep);
    CHECK(st.sweep->values == std::vector<double>{1, 1.5, 2});
    r.sweep = "P=100,200,300";
    CHECK(solve("", r).sweep->runs.size() == 3);
    r.sweep = "q=1:2:2";
    CHECK_THROWS_AS(solve("", r), DeckError);
  }

  TEST_CASE("values run side by side: the first value that breaks the deck is named") {
    // s = 2.5 and s = 3 both put the support beyond the 2 m line; one value after another the
    // run stops at 2.5, and so it does on two threads.
    const test::ThreadsSetting twoThreads("2");
    try {
      solve("sweep: {parameter: s, values: [1, 1.5, 2.5, 3, 1.2, 1.8]}");
      FAIL("no error raised");
    } catch (const DeckError& e) {
      CHECK(std::string(e.what()).find("with s = 2.5 (sweep)") != std::string::npos);
    }
  }

  TEST_CASE("a value that breaks the deck is named in the error") {
    // s = 2.5 puts the support beyond the 2 m line.
    try {
      solve("sweep: {parameter: s, values: [1, 2.5]}");
      FAIL("no error raised");
    } catch (const DeckError& e) {
      const std::string what = e.what();
      CHECK(what.find("with s = 2.5 (sweep)") != std::string::npos);
      CHECK(what.find("points[1].at") != std::string::npos);
    }
  }
}
