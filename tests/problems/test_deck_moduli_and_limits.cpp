// A material with E and G apart (timber) in a Timoshenko cantilever against its closed form,
// and check references and study limits written in their quantity's unit.
#include <doctest/doctest.h>

#include <string>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/study/DesignStudy.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

/// A clamped timber cantilever (E 11.5 GPa, G 0.65 GPa: E / (2 G) - 1 = 7.8 is no Poisson's
/// ratio) with a tip load; `formulation` and `section` are the caller's.
std::string timberCantilever(const std::string& formulation, const std::string& section,
                             const std::string& material = "E: E, G: G") {
  return "parameters: {L: 2 m, P: 1 kN, E: 11.5 GPa, G: 0.65 GPa, b: 100 mm, h: 200 mm}\n"
         "derived: {A: b*h, I: b*h^3/12, kappa: 5/6}\n"
         "materials: [{name: timber, " +
         material +
         "}]\n"
         "sections: [{name: beam, " +
         section +
         "}]\n"
         "segments: [{length: L, section: beam, elements: 4, formulation: " +
         formulation +
         "}]\n"
         "supports: [{name: root, at: start, fix: clamped}]\n"
         "loads: [{type: point, at: end, fy: -P}]\n"
         "checks:\n"
         "  - {name: tip, quantity: displacement end uy,\n"
         "     reference: -(P*L^3/(3*E*I) + P*L/(kappa*G*A)), tolerance: 1e-9}\n";
}

const std::string kGeneral =
    "shape: general, A: A, I: I, J: 1e-5 m^4, kappa: kappa, depth: h, width: b";

}  // namespace

TEST_SUITE("deck units") {
  TEST_CASE("a timber cantilever (E and G apart) deflects as P L^3/(3 E I) + P L/(kappa G A)") {
    // The interdependent Timoshenko element is exact at the nodes for a tip load, so the
    // bending plus shear closed form holds to round-off (1e-9 allows it many times over).
    const Study s = test::solveDeckText(timberCantilever("timoshenko", kGeneral), "timber.yaml");
    CHECK(test::checkAllPass(s) == 1);
    REQUIRE(s.run);
    const double bending = 1000.0 * 8 / (3 * 11.5e9 * (0.1 * 0.008 / 12));
    const double shear = 1000.0 * 2 / (5.0 / 6 * 0.65e9 * 0.02);
    CHECK(s.run->checks[0].computed == doctest::Approx(-(bending + shear)).epsilon(1e-9));
    // The shear term (5 % of the tip deflection) comes from the G given, not from E and nu.
    CHECK(shear / bending > 0.05);
    const Deck deck = readDeck(parseDeckText(timberCantilever("timoshenko", kGeneral), "t.yaml"));
    REQUIRE(deck.segments.size() == 1);
    CHECK(deck.segments[0].section->material.G == 0.65e9);
    CHECK(deck.segments[0].section->material.E == 11.5e9);
  }

  TEST_CASE("E, G and nu: G as given, nu for the shear coefficient; a rectangle needs nu") {
    // Without nu a rectangle's Cowper coefficient 10 (1 + nu) / (12 + 11 nu) has no nu.
    const DeckError e = test::readingError(
        timberCantilever("timoshenko", "shape: rectangle, b: b, h: h"), "timber.yaml");
    CHECK(std::string(e.what()).find("needs Poisson's ratio") != std::string::npos);
    CHECK(std::string(e.what()).find("give the material nu") != std::string::npos);
    const Deck deck =
        readDeck(parseDeckText(timberCantilever("timoshenko", "shape: rectangle, b: b, h: h",
                                                "E: E, G: G, nu: 0.4"),
                               "t.yaml"));
    const Section& s = *deck.segments[0].section;
    CHECK(s.material.G == 0.65e9);
    CHECK(s.kappaY == doctest::Approx(10 * 1.4 / (12 + 11 * 0.4)).epsilon(1e-15));
    // An isotropic material given E and G keeps nu = E / (2 G) - 1, as before.
    const Deck steel = readDeck(parseDeckText(
        timberCantilever("timoshenko", kGeneral, "E: 200 GPa, G: 80 GPa"), "s.yaml"));
    CHECK(steel.segments[0].section->material.nu == doctest::Approx(0.25).epsilon(1e-15));
  }

  TEST_CASE("check references and study limits take their quantity's unit") {
    // A planar cantilever member (2 m, tip load 1 kN): |Mz| max = P L = 2 kN m, and the largest
    // translation is the tip's P L^3 / (3 E I) = 17.6367 mm (I = 0.04 * 0.06^3 / 12), both
    // exact at the nodes of the Hermite element; 1e-5 covers the 6 digits written.
    const std::string model =
        "model: {dimension: planar}\n"
        "parameters: {P: 1 kN}\n"
        "materials: [{name: steel, E: 210 GPa, nu: 0.3}]\n"
        "sections: [{name: bar, shape: rectangle, b: 40 mm, h: 60 mm}]\n"
        "nodes: [{name: A, at: [0, 0]}, {name: B, at: [2000 mm, 0]}]\n"
        "members: [{name: m, from: A, to: B, section: bar, elements: 4}]\n"
        "supports: [{name: root, at: A, fix: clamped}]\n"
        "loads: [{type: point, at: B, fy: -P}]\n";
    const std::string frame =
        model +
        "checks:\n"
        "  - {name: M, quantity: member m Mz maxabs, reference: 2 kN m, tolerance: 1e-9}\n"
        "  - {name: w, quantity: displacement max, reference: 17.6367 mm, tolerance: 1e-5}\n";
    CHECK(1000.0 * 8 / (3 * 210e9 * (0.04 * 0.000216 / 12)) ==
          doctest::Approx(0.0176367).epsilon(1e-5));
    const Study solved = test::solveDeckText(frame, "frame.yaml");
    CHECK(test::checkAllPass(solved) == 2);
    REQUIRE(solved.run);
    CHECK(solved.run->checks[0].reference == 2000);

    // Every member resultant and the member deflection, read in their units.
    const std::string more =
        "  - {name: N, quantity: member m N max, reference: 1.5 kN, tolerance: 1}\n"
        "  - {name: V, quantity: member m Vy min, reference: -1 kN, tolerance: 1}\n"
        "  - {name: T, quantity: member m T max, reference: 0.5 kN m, tolerance: 1}\n"
        "  - {name: d, quantity: member m deflection max, reference: 3 mm, tolerance: 1}\n";
    const Deck deck = readDeck(parseDeckText(frame + more, "frame.yaml"));
    REQUIRE(deck.checks.size() == 6);
    CHECK(deck.checks[2].reference == 1500);
    CHECK(deck.checks[3].reference == -1000);
    CHECK(deck.checks[4].reference == 500);
    CHECK(deck.checks[5].reference == doctest::Approx(0.003).epsilon(1e-15));
    const DeckError e = test::readingError(
        model + "checks: [{name: w, quantity: displacement max, reference: 1 kN, "
                "tolerance: 1e-9}]\n",
        "frame.yaml");
    CHECK(std::string(e.what()).find("reference expects a length (m), got a force (N)") !=
          std::string::npos);

    // Study limits: in the block, and after <= on the command line.
    const std::string studied = frame +
                                "study:\n"
                                "  parameters: {P: {values: [1 kN, 2 kN]}}\n"
                                "  outputs:\n"
                                "    - {quantity: displacement max, limit: 10 mm}\n"
                                "    - {quantity: member m Mz maxabs, limit: 1.5 kN*m}\n";
    const DeckSource source = parseDeckText(studied, "study.yaml");
    const Deck studyDeck = readDeck(source);
    const DesignStudySpec spec = readDesignStudy(source, studyDeck, {});
    REQUIRE(spec.outputs.size() == 2);
    CHECK(spec.outputs[0].limit == doctest::Approx(0.01).epsilon(1e-15));
    CHECK(spec.outputs[1].limit == 1500);
    StudyCommandLine line;
    line.outputs = {"member m deflection max <= 4 mm", "member m Mz maxabs <= 2 kN m"};
    const DesignStudySpec typed = readDesignStudy(source, studyDeck, line);
    REQUIRE(typed.outputs.size() == 2);
    CHECK(typed.outputs[0].limit == doctest::Approx(0.004).epsilon(1e-15));
    CHECK(typed.outputs[1].limit == 2000);
    line.outputs = {"displacement max <= 2 kN"};
    CHECK_THROWS_WITH_AS(readDesignStudy(source, studyDeck, line),
                         doctest::Contains("expects a length (m), got a force (N)"), DeckError);
  }
}
