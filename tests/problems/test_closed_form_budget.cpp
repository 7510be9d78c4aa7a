// The closed-form functions' cost is bounded (problems/deck/parse/SceneFunctions.hpp): 200
// derived values each calling mo10_phi_max(100000, ...) kept the reader busy past 60 s with no
// output; now the value that would take the reading past its budget is refused at its line,
// naming the limit. The shipped MO-10 decks stay far inside it.
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "problems/deck/parse/SceneFunctions.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// A small deck whose derived values x1 .. xN each call mo10_phi_max over `cycles` cycles;
/// the value x1 stands on line `kFirstValueLine`.
constexpr int kFirstValueLine = 4;
std::string costlyDeck(int values, int cycles) {
  std::string text = "parameters:\n  J: 0.5\nderived:\n";
  for (int i = 1; i <= values; ++i)
    text += "  x" + std::to_string(i) + ": mo10_phi_max(" + std::to_string(cycles) +
            ", J, 1e5, 0.1, 0, 200, 37.18)\n";
  text += R"(materials:
  - {name: steel, E: 200e9, nu: 0.3, rho: 7850}
sections:
  - {name: bar, shape: circle, D: 0.05}
segments:
  - {name: a, length: 1, section: bar, elements: 4}
supports:
  - {name: root, at: start, fix: clamped}
analyses:
  - {type: static}
)";
  return text;
}

}  // namespace

TEST_SUITE("closed-form budget") {
  TEST_CASE("200 costly derived values: the one past the budget is refused at its line") {
    const auto dir = scratchDir("closed-form-budget");
    std::ofstream(dir / "deck.yaml") << costlyDeck(200, 100000);
    const ProcessResult p = runBeamrotor({"check", (dir / "deck.yaml").string()});
    CAPTURE(p.err);
    CHECK(p.exitCode == 2);
    // Each value is evaluated in 9 systems of units: 9 x 100000 cycles already pass the
    // budget, so the first value is refused, naming the limit and the cycles asked.
    CHECK(p.err.find("deck.yaml:" + std::to_string(kFirstValueLine) + ":") != std::string::npos);
    CHECK(p.err.find("x1") != std::string::npos);
    CHECK(p.err.find("at most " + std::to_string(kMostClosedFormCycles) + " MO-10 cycles") !=
          std::string::npos);
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("the budget counts every call of a reading: the value that passes it is named") {
    const auto dir = scratchDir("closed-form-budget-sum");
    // 9 evaluations x 10000 cycles = 90000 per value (Expression.cpp's kScalings): two fit in
    // 250000, the third does not.
    REQUIRE(kMostClosedFormCycles == 250000);
    std::ofstream(dir / "deck.yaml") << costlyDeck(10, 10000);
    const ProcessResult p = runBeamrotor({"check", (dir / "deck.yaml").string()});
    CAPTURE(p.err);
    CHECK(p.exitCode == 2);
    CHECK(p.err.find("deck.yaml:" + std::to_string(kFirstValueLine + 2) + ":") !=
          std::string::npos);
    CHECK(p.err.find("this call of 10000 cycles would take them past it, 250000 being "
                     "computed already") != std::string::npos);
    // Two such values read (and a fresh budget per reading: a second run reads them again).
    std::ofstream(dir / "two.yaml") << costlyDeck(2, 10000);
    CHECK(runBeamrotor({"check", (dir / "two.yaml").string()}).exitCode == 0);
    std::filesystem::remove_all(dir);
  }
}
