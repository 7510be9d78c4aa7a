// Bearing tables by speed and whirl frequency through a deck (FORMAT.md, "Coefficients by
// whirl frequency"): the shipped problems/jeffcott_whirl_table.yaml against its closed form
// (its checks), which coefficients its outputs say were used, and bad tables named at their
// row.
#include <doctest/doctest.h>

#include <string>

#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/TiltingPadShaftDeck.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

TEST_SUITE("rotor decks") {
  TEST_CASE("whirl table deck: the shipped Jeffcott rotor against its closed form") {
    const Study s = solveShippedDeck("jeffcott_whirl_table.yaml");
    // Both whirls' frequencies and the critical speed against w (the deck's checks, 1e-9).
    CHECK(checkAllPass(s) == 3);
    const RotorModesResult& r = *resultOf<RotorModesResult>(s.run->analyses.at(0));
    CHECK(r.coefficients.atOwnWhirl);
    CHECK(r.coefficients.unsettled.empty());
    CHECK(r.modes.at(0).whirlIterations >= 2);
    const CampbellOutcome& c = *resultOf<CampbellOutcome>(s.run->analyses.at(1));
    CHECK(c.campbell.coefficients.atOwnWhirl);
  }

  TEST_CASE("whirl table deck: bad tables are named at their row") {
    auto deckWith = [](const std::string& rows) {
      return std::string(R"(title: a whirl table
model: {dimension: lateral}
materials: [{name: steel, E: 2.1e11, nu: 0.3, rho: 7850}]
sections: [{name: shaft, shape: circle, D: 100 mm}]
segments: [{name: shaft, length: 0.2, section: shaft, elements: 2}]
bearings:
  - name: A
    at: start
    table:
)") + rows + "  - {name: B, at: end, kxx: 1e8, kyy: 1e8}\n";
    };
    auto lineOf = [&](const std::string& rows, const std::string& words) {
      const DeckError e = readingError(deckWith(rows), "whirl.yaml");
      CAPTURE(e.message());
      CHECK(e.message().find(words) != std::string::npos);
      return e.place().line;
    };
    const std::string a0 = "      - {speed_rpm: 0, whirl_hz: 0, kxx: 1e8, kyy: 1e8}\n";
    const std::string a1 = "      - {speed_rpm: 0, whirl_hz: 50, kxx: 1e8, kyy: 1e8}\n";
    const std::string b0 = "      - {speed_rpm: 3000, whirl_hz: 0, kxx: 1e8, kyy: 1e8}\n";
    const std::string b1 = "      - {speed_rpm: 3000, whirl_hz: 50, kxx: 1e8, kyy: 1e8}\n";
    const std::string b2 = "      - {speed_rpm: 3000, whirl_hz: 60, kxx: 1e8, kyy: 1e8}\n";
    // A second speed on other whirl frequencies, or on fewer of them.
    CHECK(lineOf(a0 + a1 + b0 + b2, "same whirl frequencies") == 13);
    CHECK(lineOf(a0 + a1 + b0, "same whirl frequencies") == 12);
    // Whirl frequencies that do not ascend; a speed that goes back.
    CHECK(lineOf(a1 + a0, "strictly ascending") == 11);
    CHECK(lineOf(b0 + b1 + a0 + a1, "strictly ascending") == 12);
    // A whirl frequency is a frequency: rpm is refused, Hz and bare numbers read.
    CHECK(lineOf("      - {speed_rpm: 0, whirl_hz: 3000 rpm, kxx: 1e8, kyy: 1e8}\n", "") == 10);
    // A row without a whirl frequency in a whirl table.
    CHECK(lineOf(a0 + "      - {speed_rpm: 0, kxx: 1e8, kyy: 1e8}\n", "whirl_hz") == 11);
    // A good one reads and runs, each mode at its own whirl.
    const Study s = solveDeckText(deckWith(a0 + a1 + b0 + b1) +
                                      "analyses: [{type: rotor, name: r, speed_rpm: 1000, "
                                      "modes: 2}]\n",
                                  "whirl.yaml");
    REQUIRE(s.run);
    CHECK(resultOf<RotorModesResult>(s.run->analyses.at(0))->coefficients.atOwnWhirl);
  }

  TEST_CASE("whirl table deck: tilting pads at each mode's eigenvalue on request") {
    auto deckWith = [](const std::string& choice) {
      return tiltingPadShaftDeck("tilting pads by whirl", choice) +
             "analyses: [{type: rotor, name: r, speed_rpm: 4500, modes: 2}]\n";
    };
    const Study synchronous = solveDeckText(deckWith(""), "pads.yaml");
    const Study each = solveDeckText(deckWith(", whirl_coefficients: each-mode"), "pads.yaml");
    const RotorModesResult& a = *resultOf<RotorModesResult>(synchronous.run->analyses.at(0));
    const RotorModesResult& b = *resultOf<RotorModesResult>(each.run->analyses.at(0));
    CHECK_FALSE(a.coefficients.atOwnWhirl);
    CHECK(b.coefficients.atOwnWhirl);
    CHECK(b.coefficients.mostIterations >= 2);
    const DeckError e = readingError(deckWith(", whirl_coefficients: each"), "pads.yaml");
    CHECK(e.place().line == 10);
    CHECK(e.message().find("each-mode") != std::string::npos);
  }
}
