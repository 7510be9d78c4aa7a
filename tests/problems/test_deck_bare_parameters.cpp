// Parameters written without a unit take the dimension of the fields they flow into
// (problems/deck/BareParameters.hpp): a command-line value with a unit is then converted to SI
// and used exactly as the bare SI number (bit for bit), a wrong dimension or a parameter used
// in two dimensions is refused naming the uses.
#include <doctest/doctest.h>

#include <numbers>
#include <string>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/parse/UnitSyntax.hpp"
#include "problems/deck/study/Overrides.hpp"
#include "problems/deck/study/SweepOption.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

Deck readWith(const std::string& text, const std::vector<std::string>& sets) {
  std::vector<ParameterOverride> overrides;
  for (const std::string& s : sets) overrides.push_back(parseOverride(s, "bare.yaml"));
  return readDeck(parseDeckText(text, "bare.yaml"), overrides);
}

std::optional<Dimension> bareDimension(const Deck& deck, const std::string& name) {
  for (const auto& [n, unit] : deck.bareDimensions)
    if (n == name) return unit.dimension;
  return std::nullopt;
}

std::string readFailure(const std::string& text, const std::vector<std::string>& sets) {
  try {
    readWith(text, sets);
  } catch (const DeckError& e) {
    return e.what();
  }
  return "";
}

/// A bare cantilever: L flows into a length, P into a force, E into a pressure, d (the
/// section's side, through A = d^2) into a length, eta through `0.715 - eta` into a length,
/// Q into a force directly and into a mass through `mass: Q / 9.80665` (less directly), and
/// `unused` into nothing.
const std::string kBare =
    "parameters: {L: 2, P: 1000, E: 2.1e11, d: 0.05, eta: 0.4, Q: 98.0665, unused: 3}\n"
    "derived: {A: d^2, I: d^4/12, b: 0.715 - eta, mass: Q / 9.80665}\n"
    "materials: [{name: steel, E: E, nu: 0.3, rho: 7850}]\n"
    "sections: [{name: bar, shape: general, A: A, I: I, J: I, kappa: 0.85, depth: d}]\n"
    "segments: [{length: L, section: bar, elements: 4}]\n"
    "points: [{name: p, at: b}]\n"
    "supports: [{name: root, at: start, fix: clamped}]\n"
    "loads: [{type: point, at: end, fy: -P}, {type: point, at: p, fy: -Q}]\n"
    "masses: [{at: p, m: mass}]\n"
    "checks:\n"
    "  - {name: w, quantity: displacement end uy, reference: -P*L^3/(3*E*I), tolerance: 1,\n"
    "     when: eta == 0.4}\n";

/// A body on a rotational spring c l^2 preloaded by the moment c l a (the MO-10 scene of
/// problems/mo10.yaml): the preload deflection a is written as a zero with its unit.
const std::string kZeroPreload =
    "parameters: {c: 100 kN/m, l: 100 mm, a: 0 m}\n"
    "points: [{name: body}]\n"
    "masses: [{at: body, m: 0, Jd: 0.5 kg*m^2}]\n"
    "springs: [{at: body, dof: rz, k: c*l^2/rad}]\n"
    "loads: [{type: point, at: body, mz: -c*l*a}]\n";

double preloadMoment(const Deck& deck) {
  for (const auto& [dof, value] : deck.loads.at(0).components)
    if (dof == Dof::rz) return value;
  return 0;
}

/// A sweep of the bare cantilever's L (a length, as its segment tells) written `values`.
std::string sweptBare(const std::string& values) {
  return kBare + "sweep: {parameter: L, " + values + "}\n";
}

}  // namespace

TEST_SUITE("deck units") {
  TEST_CASE("a parameter written as a zero with a unit keeps the unit's dimension") {
    // 0 m is 0 in every system of units, so evaluation alone cannot tell it from 0 kg; the
    // preload c l a must still be a moment, and a value set for a a length.
    CHECK(zerosAsOnes("0 m") == "1 m");
    CHECK(zerosAsOnes("0.0e3 kN/m + t0*0 - 10 mm + .0 mm") == "1 kN/m + t0*1 - 10 mm + 1 mm");
    const Deck deck = readWith(kZeroPreload, {});
    CHECK(deck.dimensions.back() == std::pair<std::string, Dimension>{"a", dim::length});
    CHECK(preloadMoment(deck) == 0);
    // 100 kN/m x 0.1 m x 2 mm = 20 N m, bare SI or with a unit alike.
    for (const char* set : {"a=0.002", "a=2 mm"})
      CHECK(preloadMoment(readWith(kZeroPreload, {set})) == doctest::Approx(-20).epsilon(1e-15));
    CHECK(readFailure(kZeroPreload, {"a=2 kg"}).find("a expects a length (m), got a mass (kg)") !=
          std::string::npos);
    // A bare zero stays bare, and units of two dimensions leave the zero fitting any: only
    // c and l have a dimension then.
    for (const char* zero : {"a: 0", "a: 0 m + 0 kg"}) {
      std::string text = kZeroPreload;
      text.replace(text.find("a: 0 m"), 6, zero);
      CAPTURE(zero);
      CHECK(readWith(text, {}).dimensions.size() == 2);
    }
  }

  TEST_CASE("a deck's sweep of a bare parameter takes units of the dimension its fields tell") {
    // L is a length (segments[0].length): values with units are its SI values, bit for bit.
    const Deck si = readWith(sweptBare("values: [4, 6]"), {});
    const Deck units = readWith(sweptBare("values: [4 m, 6000 mm]"), {});
    REQUIRE(si.sweep);
    REQUIRE(units.sweep);
    CHECK(si.sweep->values == std::vector<double>{4, 6});
    CHECK(units.sweep->values == si.sweep->values);
    CHECK(readWith(sweptBare("from: 4000 mm, to: 6 m, steps: 2"), {}).sweep->values ==
          std::vector<double>{4, 5, 6});
    // Another dimension is refused at its line and column, naming the field.
    CHECK(readFailure(sweptBare("values: [4 m, 6 s]"), {}) ==
          "bare.yaml:13:37: sweep.values[1]: values[1] expects a length (m), got a time (s)");
    CHECK(readFailure(sweptBare("from: 4 m, to: 6 kg, steps: 2"), {}) ==
          "bare.yaml:13:38: sweep.to: to expects a length (m), got a mass (kg)");
    // A parameter no field tells the dimension of takes no unit, as on the command line.
    CHECK(readFailure(kBare + "sweep: {parameter: unused, values: [1, 2 mm]}\n", {})
              .find("bare.yaml:13:40: sweep.values[1]: unused expects a dimensionless number, "
                    "got a length (m) (the deck gives unused without a unit") == 0);
  }

  TEST_CASE("a bare parameter takes its dimension from the fields it flows into") {
    const Deck deck = readWith(kBare, {});
    CHECK(bareDimension(deck, "L") == dim::length);
    CHECK(bareDimension(deck, "P") == dim::force);
    CHECK(bareDimension(deck, "E") == dim::pressure);
    CHECK(bareDimension(deck, "d") == dim::length);  // A: d^2 is an area, depth: d a length
    CHECK(bareDimension(deck, "eta") == dim::length);  // `eta == 0.4` says nothing
    CHECK(bareDimension(deck, "Q") == dim::force);  // fy: -Q decides over Q / 9.80665
    CHECK(!bareDimension(deck, "unused"));
  }

  TEST_CASE("--set with a unit on a bare parameter is its SI value, bit for bit") {
    const Deck si = readWith(kBare, {"L=1.2", "E=2.1e11", "eta=0.2", "d=0.04"});
    const Deck units = readWith(kBare, {"L=1200mm", "E=210 GPa", "eta=200 mm", "d=4 cm"});
    CHECK(test::deckValue(units, "L") == test::deckValue(si, "L"));
    CHECK(test::deckValue(units, "E") == test::deckValue(si, "E"));
    CHECK(test::deckValue(units, "b") == test::deckValue(si, "b"));
    CHECK(test::deckValue(units, "I") == test::deckValue(si, "I"));
    CHECK(units.segments[0].length == si.segments[0].length);
    // On a shipped deck, through the whole solve: the same reactions to the last bit.
    const Study a =
        solveStudy(test::shippedDeckRequest("cantilever.yaml", {"L=1200mm", "E=210GPa"}));
    const Study b =
        solveStudy(test::shippedDeckRequest("cantilever.yaml", {"L=1.2", "E=210e9"}));
    REQUIRE(a.run);
    REQUIRE(b.run);
    CHECK(test::staticReaction(*a.run, "root", Dof::rz) ==
          test::staticReaction(*b.run, "root", Dof::rz));
    REQUIRE(a.run->checks.size() == b.run->checks.size());
    for (std::size_t k = 0; k < a.run->checks.size(); ++k)
      CHECK(a.run->checks[k].computed == b.run->checks[k].computed);
  }

  TEST_CASE("--sweep with units on a bare parameter, converted to SI") {
    const Deck deck = readWith(kBare, {});
    const DeckSweep s = parseSweepOption("L=4m:8m:4", deck);
    REQUIRE(s.values.size() == 5);
    CHECK(s.values[0] == 4);
    CHECK(s.values[4] == 8);
    CHECK(parseSweepOption("L=4000mm,5", deck).values == std::vector<double>{4, 5});
    CHECK_THROWS_WITH_AS(parseSweepOption("L=4 s,5 s", deck),
                         doctest::Contains("L expects a length (m), got a time (s)"), DeckError);
  }

  TEST_CASE("a wrong dimension, two dimensions and an untold one are refused naming the uses") {
    CHECK(readFailure(kBare, {"L=3 kg"}) ==
          "bare.yaml: --set L=3 kg: L is a length (m), as its use at bare.yaml:5 "
          "(segments[0].length) tells; got a mass (kg)");
    const std::string twice = kBare + "  - {name: r, quantity: reaction root uy, reference: L,\n"
                                      "     tolerance: 1}\n";
    const std::string why = readFailure(twice, {});
    CHECK(why.find("parameter 'L' has no unit and is used as a length (m) at bare.yaml:5 "
                   "(segments[0].length) and as a force (N) at bare.yaml:13 "
                   "(checks[1].reference)") != std::string::npos);
    CHECK(readFailure(kBare, {"unused=3 mm"}).find(
              "the deck gives unused without a unit, and no field whose value holds it alone "
              "tells its dimension") != std::string::npos);
    // A bare value stays SI, whatever the field.
    CHECK(test::deckValue(readWith(kBare, {"L=3"}), "L") == 3);
  }

  TEST_CASE("a bare parameter read in rpm takes bare numbers only, never an SI value as rpm") {
    // n flows into speed_rpm, whose bare numbers are rpm: 3000 rpm typed with its unit would
    // be 314.16 rad/s in SI and then read as 314.16 rpm, a tenth of what was asked. Bare
    // numbers stay rpm; a value with a unit is refused wherever it is given.
    const std::string rotor =
        "parameters: {n: 3000}\n"
        "model: {dimension: lateral}\n"
        "materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]\n"
        "sections: [{name: shaft, shape: circle, D: 0.05}]\n"
        "segments: [{length: 1, section: shaft, elements: 4}]\n"
        "supports: [{name: a, at: start, fix: [uy, uz]}, {name: b, at: end, fix: [uy, uz]}]\n"
        "analyses: [{type: rotor, name: spin, speed_rpm: n, modes: 2}]\n";
    const Deck bare = readWith(rotor, {"n=1500"});
    CHECK(bare.analyses.at(0).as<RotorSpec>()->rotor.speed ==
          doctest::Approx(1500 * 2 * std::numbers::pi / 60).epsilon(1e-15));
    CHECK(readFailure(rotor, {"n=1500 rpm"}).find(
              "n has no unit in the deck and flows into a field that reads bare numbers in rpm") !=
          std::string::npos);
    CHECK_THROWS_WITH_AS(parseSweepOption("n=1000 rpm:2000 rpm:2", bare),
                         doctest::Contains("reads bare numbers in rpm"), DeckError);
    const std::string swept = rotor + "sweep: {parameter: n, values: [1000, 2000 rpm]}\n";
    const std::string why = readFailure(swept, {});
    CHECK(why.find("bare.yaml:8") != std::string::npos);
    CHECK(why.find("reads bare numbers in rpm") != std::string::npos);
    CHECK(readWith(rotor + "sweep: {parameter: n, values: [1000, 2000]}\n", {}).sweep->values ==
          std::vector<double>{1000, 2000});
  }
}
