// Decks with standard sections: an IPE 300 beam bent about both axes (and pulled) against the
// closed form at its flange corner with the published section properties, and a `general`
// section that a run needs more from than the deck gives, refused naming the key (exit 2)
// whether the need comes from the deck or from `--formulation` on the command line.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fem/model/StandardSections.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

// IPE 300 (ArcelorMittal tables): A 53.81 cm^2, Iy 8356 cm^4 (strong; local z here), Iz
// 603.8 cm^4 (weak; local y here). The references below use these printed values, so they
// agree with the exact section to the tables' precision: at most 0.5 in the last digit,
// 9.3e-5 of A, 6.0e-5 of Iy, 8.3e-5 of Iz; a weighted sum of their reciprocals by as much.
constexpr double kTablePrecision = 1.2e-4;

// A 3D cantilever: tip loads N (x), Fy, Fz; at the root Mz = Fy L and My = Fz L, largest at
// the flange corner where all three add: sigma = |N|/A + |Fy| L (h/2)/I_strong +
// |Fz| L (b/2)/I_weak.
// A 3D model of steel, which every deck below shares, and its IPE 300.
const std::string kSteel3d = R"(
model: {dimension: 3d}
materials:
  - {name: steel, E: 210e9, nu: 0.3, rho: 7850}
)";
const std::string kIpeModel = kSteel3d + R"(
sections:
  - {name: ipe300, shape: I, h: 0.300, b: 0.150, tw: 0.0071, tf: 0.0107, r: 0.015}
)";

const std::string kCantileverDeck = kIpeModel + R"(
parameters: {L: 2, N: 150e3, Fy: -12e3, Fz: 3e3}
derived:
  A: 53.81e-4
  I_strong: 8356e-8
  I_weak: 603.8e-8
  sigma_corner: abs(N)/A + abs(Fy)*L*0.15/I_strong + abs(Fz)*L*0.075/I_weak
segments:
  - {length: L, section: ipe300, elements: 4}
supports:
  - {name: root, at: start, fix: clamped}
loads:
  - {type: point, at: end, fx: N, fy: Fy, fz: Fz}
checks:
  - {name: flange corner, quantity: stress max, reference: sigma_corner, tolerance: 1.2e-4}
)";

// Simply supported in both planes, uniform qy and qz: M = q L^2 / 8 at midspan in each, the
// middle of the middle element.
const std::string kSpanDeck = kIpeModel + R"(
parameters: {L: 3, qy: -8e3, qz: 1.5e3}
derived:
  sigma_mid: (abs(qy)*L^2/8)*0.15/8356e-8 + (abs(qz)*L^2/8)*0.075/603.8e-8
segments:
  - {length: L, section: ipe300, elements: 3}
supports:
  - {name: left, at: start, fix: [ux, uy, uz, rx]}
  - {name: right, at: end, fix: [uy, uz]}
loads:
  - {type: distributed, qy: qy, qz: qz}
checks:
  - {name: midspan corner, quantity: stress max, reference: sigma_mid, tolerance: 1.2e-4}
)";

// A general section with its depth but no shear coefficient: fine for Euler-Bernoulli.
const std::string kGeneralDeck = R"(materials:
  - {name: steel, E: 210e9, nu: 0.3, rho: 7850}
sections:
  - {name: ipe, shape: general, A: 53.81e-4, Iz: 8356e-8, Iy: 603.8e-8, depth: 0.3}
segments:
  - {length: 4, section: ipe, elements: 4}
supports:
  - {name: root, at: start, fix: clamped}
loads:
  - {type: point, at: end, fy: -1000}
)";

// One segment of each standard shape, its keys in an order unlike the constructors'.
const std::string kShapesDeck = kSteel3d + R"(
sections:
  - {name: i, shape: I, r: 0.015, tf: 0.0107, tw: 0.0071, b: 0.150, h: 0.300}
  - {name: u, shape: channel, taper: 0.08, r_toe: 0.006, r: 0.0115, tf: 0.0115, tw: 0.0085,
     b: 0.075, h: 0.2}
  - {name: l, shape: angle, r_toe: 0.006, r: 0.012, t: 0.01, b: 0.09, h: 0.15}
  - {name: box, shape: rhs, r_in: 0.008, r_out: 0.016, t: 0.008, b: 0.1, h: 0.2}
segments:
  - {length: 1, section: i, elements: 1}
  - {length: 1, section: u, elements: 1}
  - {length: 1, section: l, elements: 1}
  - {length: 1, section: box, elements: 1}
supports:
  - {name: root, at: start, fix: clamped}
loads:
  - {type: point, at: end, fy: -1000, fz: 500}
)";

}  // namespace

TEST_SUITE("section decks") {
  TEST_CASE("every standard shape read from a deck is the section its constructor makes") {
    const Study study = test::solveDeckText(kShapesDeck, "shapes.yaml");
    REQUIRE(study.deck.segments.size() == 4);
    const Material steel = Material::fromEnu("steel", 210e9, 0.3, 7850);
    const std::vector<Section> expected{
        iSection("i", steel, 0.3, 0.15, 0.0071, 0.0107, 0.015),
        channelSection("u", steel, 0.2, 0.075, 0.0085, 0.0115, 0.0115, 0.006, 0.08),
        angleSection("l", steel, 0.15, 0.09, 0.01, 0.012, 0.006),
        hollowRectangleSection("box", steel, 0.2, 0.1, 0.008, 0.016, 0.008)};
    for (std::size_t k = 0; k < expected.size(); ++k) {
      const Section& read = *study.deck.segments[k].section;
      CAPTURE(read.name);
      // The same computation on the same numbers: equal to the last bit.
      CHECK(read.A == expected[k].A);
      CHECK(read.Iy == expected[k].Iy);
      CHECK(read.Iz == expected[k].Iz);
      CHECK(read.J == expected[k].J);
      CHECK(read.kappaY == expected[k].kappaY);
      CHECK(read.fibres.size() == expected[k].fibres.size());
    }
    REQUIRE(study.run);
  }

  TEST_CASE("IPE 300 bent about both axes: the flange corner's stress") {
    for (const auto& [text, reference] :
         {std::pair{kCantileverDeck, 150e3 / 53.81e-4 + 12e3 * 2 * 0.15 / 8356e-8 +
                                         3e3 * 2 * 0.075 / 603.8e-8},
          std::pair{kSpanDeck,
                    (8e3 * 9 / 8) * 0.15 / 8356e-8 + (1.5e3 * 9 / 8) * 0.075 / 603.8e-8}}) {
      const Study study = test::solveDeckText(text, "ipe300.yaml");
      REQUIRE(study.run);
      REQUIRE(study.run->checks.size() == 1);
      const Check& c = study.run->checks.front();
      CHECK(c.pass());
      CHECK(test::relError(c.computed, reference) < kTablePrecision);
    }
  }

  TEST_CASE("a general section without kappa under --formulation timoshenko: exit 2 naming it") {
    const auto dir = test::scratchDir("general_kappa");
    const auto deck = dir / "general.yaml";
    std::ofstream(deck) << kGeneralDeck;
    const test::ProcessResult plain =
        test::runBeamrotor({"check", deck.string()});
    CHECK(plain.exitCode == 0);
    const test::ProcessResult timoshenko =
        test::runBeamrotor({"check", deck.string(), "--formulation", "timoshenko"});
    CAPTURE(timoshenko.err);
    CHECK(timoshenko.exitCode == 2);
    CHECK(timoshenko.err.find(deck.string() + ":4:5: sections[0].kappa: missing field 'kappa'") !=
          std::string::npos);
    // `converge` runs the Timoshenko elements too: they stop with the same reason, the
    // Euler-Bernoulli one goes on.
    const test::ProcessResult converge = test::runBeamrotor(
        {"converge", deck.string(), "--levels", "3", "--out", (dir / "converge").string()});
    CAPTURE(converge.err);
    REQUIRE(converge.exitCode == 0);
    const nlohmann::json study =
        nlohmann::json::parse(test::fileContents(dir / "converge" / "convergence.json"));
    for (const nlohmann::json& method : study["methods"]) {
      CAPTURE(method["name"].get<std::string>());
      const bool timoshenkoElement = method["name"].get<std::string>().rfind("timoshenko", 0) == 0;
      CHECK(method["levels"].empty() == timoshenkoElement);
      if (timoshenkoElement)
        CHECK(method["failure"].get<std::string>().find("sections[0].kappa") != std::string::npos);
    }
    std::filesystem::remove_all(dir);
  }
}
