// The level1-stability analysis through the deck path, on the shipped Jeffcott compressor deck
// (problems/level1_stability.yaml): Q0 = c omega_n (the closed form the deck derives) reaches
// the summary, results.json and the CSV; bad input is refused naming the field.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

// The deck's closed forms (its header): c sqrt(48 E I / L^3 / m) and API's metric Qa.
double deckQ0() {
  const double I = std::numbers::pi * std::pow(0.03, 4) / 64;
  return 2000 * std::sqrt(48 * 210e9 * I / std::pow(0.7, 3) / 20);
}
constexpr double kDeckQa = 3 * (60 / (2 * std::numbers::pi)) * 40 / (300.0 * 15 * 3000) * 2 * 1e9;

const char* const kBadDeck = R"(model: {dimension: lateral}
materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]
sections: [{name: rod, shape: circle, D: 0.03}]
segments: [{length: 0.7, section: rod, elements: 4}]
supports: [{name: a, at: start, fix: [uy, uz]}, {name: b, at: end, fix: [uy, uz]}]
analyses:
  - type: level1-stability
    speed_rpm: 3000
    stages:
      - {power: 40 kW, diameter: 300 mm, tip_width: 15 m s, discharge_density: 2, suction_density: 1}
)";

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("level1-stability deck: Q0, Qa and the verdict in every output") {
    const test::SolvedDeck solved =
        test::solveShippedDeckToScratch("level1_stability.yaml", "level1-deck");
    const nlohmann::json results = solved.json("results.json");
    const nlohmann::json level = test::analysisOfType(results, "level1-stability");
    REQUIRE(level.is_object());
    // Root to 1e-10 of Q (FORMAT.md); 1e-8 leaves room for the eigenvalues' round-off.
    CHECK(level["q0"].get<double>() == doctest::Approx(deckQ0()).epsilon(1e-8));
    CHECK(level["qa"].get<double>() == doctest::Approx(kDeckQa).epsilon(1e-12));
    CHECK(level["q0_over_qa"].get<double>() == doctest::Approx(deckQ0() / kDeckQa).epsilon(1e-8));
    CHECK(level["pass"] == true);
    CHECK(level["map_decides"] == true);  // Q0/Qa = 2.85
    CHECK(level["whirl_at_q0"] == "forward");
    CHECK(level["least_damped_at_q0"] == "rotor");  // no pads kept: always the rotor's
    CHECK(solved.process.out.find("API 684 Level I: pass") != std::string::npos);
    const auto cells = test::csvCells(solved.dir / "level1_level1.csv");
    REQUIRE(cells.size() == 42);  // header and 41 samples
    CHECK(std::stod(cells[1][test::csvColumn(cells[0], "log_decrement")]) > 0);
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("level1-stability: a stage field of the wrong dimension is refused with its line") {
    const DeckError e = test::readingError(kBadDeck, "level1.yaml");
    CAPTURE(e.message());
    CHECK(e.place().line == 10);
    CHECK(e.message().find("tip_width") != std::string::npos);
  }
}
