// Tension-only members in a deck (acts:): the shipped X-braced panel passes its closed-form
// checks, reversing its load swaps the slack brace, results.json reports the states, and the
// analyses and load cases that cannot honour a slack member are refused at their line.
#include <doctest/doctest.h>

#include <cmath>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/run/RunResult.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

const StaticResult& firstStatics(const RunResult& run) {
  const StaticResult* r = staticsOf(run.analyses.front());
  REQUIRE(r);
  return *r;
}

const OneWayMemberState& stateOf(const StaticResult& r, const std::string& name) {
  for (const OneWayMemberState& m : r.oneWayMembers)
    if (m.name == name) return m;
  FAIL("no one-way member " << name);
  throw;
}

// The shipped deck's frame with an extra block (`analyses:` or `load_cases:`) in place of
// its own analyses.
const char* kPanel =
    "model: {dimension: planar}\n"
    "materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]\n"
    "sections: [{name: s, shape: general, A: 1e-3, I: 1e-6, depth: 0.2}]\n"
    "nodes: [{name: A, at: [0, 0]}, {name: B, at: [4, 0]}, {name: C, at: [0, 3]},\n"
    "        {name: D, at: [4, 3]}]\n"
    "members:\n"
    "  - {name: left, from: A, to: C, section: s, elements: 1}\n"
    "  - {name: right, from: B, to: D, section: s, elements: 1}\n"
    "  - {name: beam, from: C, to: D, section: s, elements: 1}\n"
    "  - {name: AD, from: A, to: D, section: s, elements: 1, acts: tension-only}\n"
    "supports: [{name: A, at: A, fix: pinned}, {name: B, at: B, fix: pinned}]\n"
    "loads: [{type: point, at: C, fx: 1000}]\n";

}  // namespace

TEST_SUITE("one-way members in decks") {
  TEST_CASE("braced panel: the compressed brace is slack, reversing H swaps the braces") {
    // Determinate once a brace is slack: N = H / cos(theta), cos(theta) = 4 / 5; the deck's
    // checks hold to 1e-9 (round-off).
    for (const double H : {10e3, -10e3}) {
      CAPTURE(H);
      const Study s = solveStudyText(
          test::fileContents(test::problemsDir() / "braced_panel.yaml"),
          test::shippedDeckRequest("braced_panel.yaml", {test::setting("H", H)}));
      const RunResult& run = *test::runsOf(s).front();
      const StaticResult& r = firstStatics(run);
      const OneWayMemberState &ad = stateOf(r, "AD"), &bc = stateOf(r, "BC");
      const OneWayMemberState& taut = H > 0 ? ad : bc;
      const OneWayMemberState& slack = H > 0 ? bc : ad;
      CHECK_FALSE(taut.slack);
      CHECK(slack.slack);
      CHECK(slack.force == 0);
      CHECK(slack.elongation < 0);
      const double error = std::abs(taut.force - std::abs(H) / 0.8) / (std::abs(H) / 0.8);
      MESSAGE("brace force error: ", error);
      CHECK(error < 1e-9);
      if (H > 0) CHECK(test::checkAllPass(s) == 3);
    }
  }

  TEST_CASE("modes and load cases are refused with the reason") {
    const DeckError modal = test::readingError(
        std::string(kPanel) + "analyses: [{type: static}, {type: modal, modes: 2}]\n",
        "panel.yaml");
    CHECK(modal.place().line == 13);
    CHECK(std::string(modal.what()).find("solves linear static analyses only") !=
          std::string::npos);
    const DeckError second = test::readingError(
        std::string(kPanel) + "analyses: [{type: static, second_order: true}]\n", "panel.yaml");
    CHECK(std::string(second.what()).find("acts:") != std::string::npos);
    const DeckError cases = test::readingError(
        std::string(kPanel) +
            "load_cases: [{name: wind, loads: [{type: point, at: D, fx: 500}]}]\n"
            "analyses: [{type: static}]\n",
        "panel.yaml");
    CHECK(std::string(cases.what()).find("are not linear") != std::string::npos);
  }

  TEST_CASE("a one-way member of several elements is refused at its acts:") {
    std::string text = kPanel;
    text.replace(text.find("elements: 1, acts"), 11, "elements: 3");
    const DeckError e = test::readingError(text + "analyses: [{type: static}]\n", "panel.yaml");
    CHECK(std::string(e.what()).find("give it elements: 1") != std::string::npos);
  }
}
