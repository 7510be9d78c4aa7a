// The stability half of the API 684 verdict through the deck path, on the shipped compressor
// deck: its plain journal bearings drive an oil whip whose onset (6276 rpm) lies below the
// 7000-9000 rpm operating range, so the verdict must fail, naming the onset. The reference is
// a second method on the same model: the deck's own campbell analysis, which brackets and
// refines the onset on its 59-speed grid, while the verdict brackets it on its own grid (30
// speeds from 500 rpm to the range, 11 over it). The closed-form check of the verdict (a
// cross-coupled Jeffcott rotor) is in tests/fem/rotor/test_rotor_stability.cpp.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "problems/cli/RotorSummary.hpp"
#include "problems/run/Study.hpp"
#include "tests/ThreadsSetting.hpp"

using namespace beamrotor;

namespace {

const AnalysisOutcome& compressorAnalysis(const RunResult& run, const std::string& name) {
  for (const AnalysisOutcome& a : run.analyses)
    if (a.name == name) return a;
  FAIL("no analysis " << name);
  return run.analyses.front();
}

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("API 684 verdict of the compressor deck: oil whip below the range fails it") {
    StudyRequest request;
    request.deckPath = BEAMROTOR_SOURCE_DIR "/problems/compressor_rotor.yaml";
    const Study study = solveStudy(request);
    REQUIRE(study.run);
    const RunResult& run = *study.run;
    const CampbellOutcome& campbell =
        *resultOf<CampbellOutcome>(compressorAnalysis(run, "campbell"));
    const AnalysisOutcome& response = compressorAnalysis(run, "response");
    REQUIRE(campbell.onset.has_value());
    REQUIRE(resultOf<UnbalanceOutcome>(response)->stability.has_value());
    const OperatingStability& s = *resultOf<UnbalanceOutcome>(response)->stability;
    CHECK_FALSE(s.pass);
    REQUIRE(s.onset.has_value());
    // Both refine the same root to 1e-10 of the speed from different brackets: they agree to
    // that, 1e-8 leaving room for the eigensolver's round-off.
    CHECK(s.onset->rpm == doctest::Approx(campbell.onset->rpm).epsilon(1e-8));
    CHECK(s.onset->rpm < 7000);
    // Unstable over the range: its smallest decrement is negative, a forward whirl.
    CHECK(s.smallest < 0);
    CHECK(s.whirl == Whirl::forward);
    std::ostringstream summary;
    cli::printRotor(summary, response, *resultOf<UnbalanceOutcome>(response));
    CAPTURE(summary.str());
    CHECK(summary.str().find("API 684: FAIL (unstable above 6276") != std::string::npos);
  }

  TEST_CASE("API 684 verdict: the response and the stability check side by side, as in turn") {
    // With two cores the unbalance response and the stability check run at the same time:
    // each is its own computation, so the outcome is the one-core run's to the bit.
    auto solved = [](const std::string& threads) {
      const test::ThreadsSetting setting(threads);
      StudyRequest request;
      request.deckPath = BEAMROTOR_SOURCE_DIR "/problems/compressor_rotor.yaml";
      return solveStudy(request);
    };
    const Study one = solved("1"), two = solved("2");
    REQUIRE(one.run);
    REQUIRE(two.run);
    const UnbalanceOutcome& a = *resultOf<UnbalanceOutcome>(compressorAnalysis(*one.run, "response"));
    const UnbalanceOutcome& b = *resultOf<UnbalanceOutcome>(compressorAnalysis(*two.run, "response"));
    REQUIRE(a.unbalance.orbits.size() == b.unbalance.orbits.size());
    for (std::size_t k = 0; k < a.unbalance.orbits.size(); ++k) {
      REQUIRE(a.unbalance.orbits[k].size() == b.unbalance.orbits[k].size());
      for (std::size_t i = 0; i < a.unbalance.orbits[k].size(); ++i) {
        CHECK(a.unbalance.orbits[k][i].uy == b.unbalance.orbits[k][i].uy);
        CHECK(a.unbalance.orbits[k][i].uz == b.unbalance.orbits[k][i].uz);
      }
    }
    REQUIRE(a.stability.has_value());
    REQUIRE(b.stability.has_value());
    CHECK(a.stability->smallest == b.stability->smallest);
    CHECK(a.stability->speed == b.stability->speed);
    CHECK(a.stability->frequencyHz == b.stability->frequencyHz);
    REQUIRE(a.stability->onset.has_value());
    REQUIRE(b.stability->onset.has_value());
    CHECK(a.stability->onset->speed == b.stability->onset->speed);
  }
}
