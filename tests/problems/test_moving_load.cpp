// `type: moving-load` from the deck: a two-span continuous frame crossed along a path named
// backwards (from its far end), planar and as a 3d frame under an oblique wheel, against the
// Mueller-Breslau closed forms' extremes; a cantilever's resultants at its wall (statics);
// the shipped crane girder's files; and bad input named at its file, line and field. The
// lines are exact (consistent nodal loads, closed-form clamped shares), the extremes found in
// closed form: every tolerance is round-off (1e-9).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>
#include <filesystem>
#include <string>

#include "problems/deck/DeckReader.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/TwoSpanFrame.hpp"

using namespace beamrotor;

namespace moving_load {

// Two equal spans L = 6 m on pins A, B, C as a frame, 4 elements per span, one wheel of 1 N.
// Closed forms (Mueller-Breslau, two equal spans, a unit load at xi L from the outer support):
// R_B = xi (3 - xi^2) / 2, largest 1 with the load on B; the moment at B, -L xi (1 - xi^2) / 4,
// least -L / (6 sqrt 3) at xi = 1/sqrt 3 (inside an element: an extreme found, not sampled);
// at mid-span of span 1, largest 0.203125 L with the load there.
const std::string kTwoSpans = "\n" + test::twoSpanFrame(4) + R"(analyses:
  - type: moving-load
    name: wheel
    path: [span2, span1]
    wheels: [{force: 1 N}]
    quantities: [reaction B uy, resultant Mz at B, resultant Mz at m1]
checks:
  - {name: RB, quantity: moving max reaction B uy, reference: 1 N, tolerance: 1e-9}
  - {name: MB, quantity: moving min resultant Mz at B, reference: -(1 N) * L / (6 * sqrt(3)),
     tolerance: 1e-9}
  - {name: Mmid, quantity: moving max resultant Mz at m1, reference: 0.203125 * (1 N) * L,
     tolerance: 1e-9}
)";

// The same two spans as a 3d frame, the wheel pushing along [0, -1, -1]: by superposition its
// parts along -y and -z each carry 1/sqrt 2 of the closed forms, in the two bending planes.
const std::string kObliqueThreeD = R"(parameters: {L: 6 m}
model: {dimension: 3d}
materials: [{name: steel, E: 210 GPa, nu: 0.3, rho: 7850 kg/m^3}]
sections: [{name: s, shape: general, A: 53.8 cm^2, Iy: 8356 cm^4, Iz: 604 cm^4, J: 20 cm^4, depth: 300 mm, width: 150 mm}]
nodes:
  - {name: A, at: [0, 0, 0]}
  - {name: B, at: [L, 0, 0]}
  - {name: C, at: [2 * L, 0, 0]}
members:
  - {name: span1, from: A, to: B, section: s, elements: 4}
  - {name: span2, from: B, to: C, section: s, elements: 4}
points: [{name: m1, member: span1, at: 0.5}]
supports:
  - {name: A, at: A, fix: [ux, uy, uz, rx]}
  - {name: B, at: B, fix: [uy, uz]}
  - {name: C, at: C, fix: [uy, uz]}
analyses:
  - type: moving-load
    name: wheel
    path: [span2, span1]
    direction: [0, -1, -1]
    wheels: [{force: 1 N}]
    quantities: [reaction B uy, reaction B uz, resultant My at B, resultant Mz at B, resultant My at m1]
checks:
  - {name: RBy, quantity: moving max reaction B uy, reference: (1 N) / sqrt(2), tolerance: 1e-9}
  - {name: RBz, quantity: moving max reaction B uz, reference: (1 N) / sqrt(2), tolerance: 1e-9}
  - {name: MBy, quantity: moving max resultant My at B, reference: (1 N) * L / (6 * sqrt(6)), tolerance: 1e-9}
  - {name: MBz, quantity: moving min resultant Mz at B, reference: -(1 N) * L / (6 * sqrt(6)), tolerance: 1e-9}
  - {name: Mmid, quantity: moving min resultant My at m1, reference: -0.203125 * (1 N) * L / sqrt(2), tolerance: 1e-9}
)";

// A cantilever clamped at its end, the wheel pushing along [1, -1, 0] (parts 1/sqrt 2 across
// and towards the wall): the resultants at the wall are read at the end of the last element,
// so a load inside it adds the clamped share at that end. Statics: Mz = -(L - x) / sqrt 2
// (hogging), Vy = 1 / sqrt 2 and N = -1 / sqrt 2 wherever the load stands.
const std::string kCantilever = R"(parameters: {L: 3 m}
model: {dimension: planar}
materials: [{name: steel, E: 210 GPa, nu: 0.3, rho: 7850 kg/m^3}]
sections: [{name: s, shape: general, A: 53.8 cm^2, I: 8356 cm^4, depth: 300 mm, width: 150 mm}]
segments: [{length: L, section: s, elements: 3}]
supports: [{name: wall, at: end, fix: clamped}]
analyses:
  - type: moving-load
    direction: [1, -1, 0]
    wheels: [{force: 1 N}]
    quantities: [resultant Mz at end, resultant Vy at end, resultant N at end]
checks:
  - {name: M, quantity: moving min resultant Mz at end, reference: -(1 N) * L / sqrt(2), tolerance: 1e-9}
  - {name: V max, quantity: moving max resultant Vy at end, reference: (1 N) / sqrt(2), tolerance: 1e-9}
  - {name: V min, quantity: moving min resultant Vy at end, reference: (1 N) / sqrt(2), tolerance: 1e-9}
  - {name: N max, quantity: moving max resultant N at end, reference: -(1 N) / sqrt(2), tolerance: 1e-9}
  - {name: N min, quantity: moving min resultant N at end, reference: -(1 N) / sqrt(2), tolerance: 1e-9}
)";

}  // namespace moving_load

TEST_SUITE("moving load") {
  TEST_CASE("a two-span frame crossed backwards: envelopes of one wheel against Mueller-Breslau") {
    const Study study = test::solveDeckText(moving_load::kTwoSpans, "two_spans.yaml");
    CHECK(test::checkAllPass(study) == 3);
    for (const Check& c : study.run->checks)
      MESSAGE(c.name << ": " << c.computed << " against " << c.reference << " (relative error "
                     << c.relError() << ")");
    // The path starts at C: the mid-span moment of span 1 peaks with the load 9 m along it.
    const auto& m = std::get<MovingLoadOutcome>(study.run->analyses.front().result);
    CHECK(m.length == doctest::Approx(12));
    CHECK(m.quantity("resultant Mz at m1").envelope.max.lead == doctest::Approx(9).epsilon(1e-9));
  }

  TEST_CASE("a 3d frame under an oblique wheel: both bending planes against Mueller-Breslau") {
    const Study study = test::solveDeckText(moving_load::kObliqueThreeD, "oblique.yaml");
    CHECK(test::checkAllPass(study) == 5);
  }

  TEST_CASE("a cantilever's resultants at its wall: the clamped share at an element's end") {
    const Study study = test::solveDeckText(moving_load::kCantilever, "cantilever.yaml");
    CHECK(test::checkAllPass(study) == 5);
  }

  TEST_CASE("the shipped crane girder writes its tables, chart and results.json") {
    const test::SolvedDeck solved = test::solveShippedDeckToScratch("crane_girder.yaml", "moving_crane");
    const nlohmann::json doc = solved.json("results.json");
    const nlohmann::json& a = doc.at("analyses").at(0);
    CHECK(a.at("type") == "moving-load");
    CHECK(a.at("quantities").size() == 3);
    const nlohmann::json& moment = a.at("quantities").at(0);
    // P (L/2 - a/4)^2 * 2 / L with P = 60 kN, L = 8 m, a = 2.5 m, the second wheel at 3.375 m.
    CHECK(moment.at("max").at("value").get<double>() == doctest::Approx(170859.375).epsilon(1e-9));
    CHECK(moment.at("max").at("first_wheel_at").get<double>() ==
          doctest::Approx(3.375 + 2.5).epsilon(1e-9));
    CHECK(moment.at("influence").at("pieces").size() == 16);  // one cubic per element
    for (const char* file : {"trolley_influence.csv", "trolley_envelopes.csv"})
      CHECK(std::filesystem::exists(solved.dir / file));
    CHECK(solved.process.out.find("resultant Mz at under: max") != std::string::npos);
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("bad moving-load input names the file, line and field") {
    // Each: replacements of the deck above, words the message holds, and the text that starts
    // the line it must name.
    const auto refused = [](const std::vector<std::pair<std::string, std::string>>& edits,
                            const std::string& words, const std::string& lineStart) {
      std::string text = moving_load::kTwoSpans;
      for (const auto& [from, to] : edits) {
        const auto at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
      }
      const auto at = text.find(lineStart);
      REQUIRE(at != std::string::npos);
      const int line = int(std::count(text.begin(), text.begin() + long(at), '\n')) + 1;
      const DeckError e = test::readingError(text, "two_spans.yaml");
      const std::string message = e.what();
      CAPTURE(message);
      CHECK(message.find("two_spans.yaml") != std::string::npos);
      CHECK(message.find(words) != std::string::npos);
      CHECK(e.place().line == line);
    };
    // A path whose members do not join: span3 leaves A, the path has reached B or C.
    refused({{"  - {name: C, at: [2 * L, 0]}\n",
              "  - {name: C, at: [2 * L, 0]}\n  - {name: D, at: [0, 3]}\n"},
             {"  - {name: span2, from: B, to: C, section: s, elements: 4}\n",
              "  - {name: span2, from: B, to: C, section: s, elements: 4}\n"
              "  - {name: span3, from: A, to: D, section: s, elements: 1}\n"},
             {"path: [span2, span1]", "path: [span2, span3]"}},
            "does not join", "    path:");
    refused({{"path: [span2, span1]", "path: [span2, span1, span2]"}}, "twice", "    path:");
    // A hinge on the path, at a station along it or at a joint its members share (read-time:
    // the runner would refuse the released ends only once meshed).
    refused({{"analyses:\n", "hinges: [{at: m1}]\nanalyses:\n"}}, "the hinge at 'm1'", "    path:");
    refused({{"analyses:\n", "hinges: [{at: B}]\nanalyses:\n"}}, "the hinge at 'B'", "    path:");
    // A wheel whose offset leaves it off the path while the first wheel is on it.
    refused({{"wheels: [{force: 1 N}]", "wheels: [{force: 1 N}, {force: 1 N, offset: 13 m}]"}},
            "never on the path", "    wheels:");
    // A quantity that is not linear in the load.
    refused({{"quantities: [reaction B uy,", "quantities: [moment max, reaction B uy,"}},
            "not linear", "    quantities:");
    // Whether the deck's loads stand is a boolean.
    refused({{"    wheels: [{force: 1 N}]", "    deck_loads: maybe\n    wheels: [{force: 1 N}]"}},
            "expected true or false", "    deck_loads:");
    // An envelope of a quantity the analysis does not list.
    refused({{"moving max reaction B uy", "moving max reaction C uy"}},
            "add it to its quantities", "  - {name: RB");
  }
}
