// A flexible Jeffcott rotor on two plain journal bearings (issue 42, defect B): its bending
// mode whips above an onset near twice its frequency, while the bearings' heavily damped
// whirl modes, lower at low speed, rise with it and stay stable. Asked for two lines, the
// diagram follows those whirl modes only; it once reported a wrong onset (or none) without a
// word. Now it says that a mode no line follows grows, and where; with enough lines it finds
// the onset, which a second method confirms: more lines on another grid.
#include <doctest/doctest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "problems/output/Output.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

const char* kJournalJeffcott = R"(
title: flexible Jeffcott rotor on plain journal bearings
parameters: {modes: 2, steps: 30}
model: {dimension: lateral, rotary_inertia: true}
materials: [{name: steel, E: 2.1e11, nu: 0.3, rho: 7850}]
sections: [{name: shaft, shape: circle, D: 40 mm}]
segments: [{name: shaft, length: 0.8, section: shaft, elements: 8}]
points: [{name: disk, at: 0.4}]
masses: [{name: disk, at: disk, m: 40}]
bearings:
  - {name: A, at: start, type: plain-journal, D: 50 mm, L: 20 mm, c: 60 um, mu: 0.02,
     load: gravity, from_rpm: 200, to_rpm: 15000, steps: 100}
  - {name: B, at: end, type: plain-journal, D: 50 mm, L: 20 mm, c: 60 um, mu: 0.02,
     load: gravity, from_rpm: 200, to_rpm: 15000, steps: 100}
analyses:
  - {type: campbell, name: campbell, modes: modes, from_rpm: 500, to_rpm: 15000, steps: steps}
)";

RunResult solvedJournalJeffcott(int modes, int steps) {
  StudyRequest request;
  request.deckPath = "journal_jeffcott.yaml";
  request.sets = {"modes=" + std::to_string(modes), "steps=" + std::to_string(steps)};
  const Study s = solveStudyText(kJournalJeffcott, request);
  REQUIRE(s.run);
  return *s.run;
}

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("journal-bearing Jeffcott rotor: a growing mode outside two lines is named") {
    const RunResult two = solvedJournalJeffcott(2, 30);
    const RunResult four = solvedJournalJeffcott(4, 30);
    const RunResult six = solvedJournalJeffcott(6, 37);  // the second method: another grid
    const CampbellOutcome& few = *resultOf<CampbellOutcome>(two.analyses.at(0));
    const CampbellOutcome& enough = *resultOf<CampbellOutcome>(four.analyses.at(0));
    const CampbellOutcome& more = *resultOf<CampbellOutcome>(six.analyses.at(0));
    // With enough lines the onset; the same root from other brackets and more lines, to the
    // refinement's 1e-10 and the eigensolver's round-off (1e-8).
    REQUIRE(enough.onset.has_value());
    REQUIRE(more.onset.has_value());
    CHECK(enough.onset->rpm == doctest::Approx(more.onset->rpm).epsilon(1e-8));
    CHECK_FALSE(enough.onset->atSweepSpeed);
    CHECK(enough.onset->whirl == Whirl::forward);
    CHECK(four.analyses.at(0).warnings.empty());
    MESSAGE("journal Jeffcott: onset " << enough.onset->rpm << " rpm at "
                                       << enough.onset->frequencyHz << " Hz");
    // Two lines follow the bearings' whirl modes, which stay stable: no onset on them, but
    // the growing bending mode among the candidates is reported at the first sweep speed
    // past the onset, at its frequency there (the whip frequency drifts by a few per cent
    // with speed: 5 % allowed).
    CHECK_FALSE(few.onset.has_value());
    REQUIRE(few.campbell.untracked.has_value());
    const double firstPast = few.campbell.speeds[few.campbell.untracked->speed] * 30 / kPi;
    const double before = few.campbell.speeds[few.campbell.untracked->speed - 1] * 30 / kPi;
    CHECK(firstPast > enough.onset->rpm);
    CHECK(before < enough.onset->rpm);
    CHECK(relError(few.campbell.untracked->frequencyHz, enough.onset->frequencyHz) < 0.05);
    CHECK(few.campbell.untracked->logDecrement < 0);
    REQUIRE(two.analyses.at(0).warnings.size() == 1);
    const std::string& warning = two.analyses.at(0).warnings.front();
    CAPTURE(warning);
    CHECK(warning.find("a mode no line follows grows") != std::string::npos);
    CHECK(warning.find("ask for more modes") != std::string::npos);

    // The warning reaches results.json (and so Python, which reads it).
    const std::filesystem::path dir = scratchDir("journal_jeffcott");
    writeRunOutputs(two, dir);
    std::ifstream in(dir / "results.json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    REQUIRE(doc.at("analyses").at(0).contains("warnings"));
    CHECK(doc.at("analyses").at(0).at("warnings").at(0).get<std::string>() == warning);
    std::filesystem::remove_all(dir);
  }
}
