// The shipped decks of issue 42's supports (problems/rotor_on_pedestals.yaml,
// problems/jeffcott_internal_damping.yaml): their checks against the closed forms they state,
// the variants those decks name (`--set mp=0`: the series stiffness), and a second method for
// the pedestal: a pedestal stiff enough is the ground.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

RunResult solvedDeck(const std::string& deck, std::vector<std::string> sets = {}) {
  const Study s = solveStudy(shippedDeckRequest(deck, std::move(sets)));
  REQUIRE(s.run);
  return *s.run;
}

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("rotor on pedestals: two-mass closed form, and the series stiffness without mass") {
    const RunResult withMass = solvedDeck("rotor_on_pedestals.yaml");
    REQUIRE(withMass.checks.size() == 3);
    for (const Check& c : withMass.checks) {
      CAPTURE(c.name);
      CHECK(c.pass());
      MESSAGE(c.name << ": rel. error " << c.relError());
    }
    // Massless, the shaft is what the closed forms describe: round-off (tolerance 1e-8).
    const RunResult massless = solvedDeck("rotor_on_pedestals.yaml", {"rho_s=0"});
    REQUIRE(massless.checks.size() == 3);
    for (const Check& c : massless.checks) {
      CAPTURE(c.name);
      CHECK(c.pass());
      CHECK(c.tolerance == 1e-8);
    }
    for (const char* rho : {"rho_s=0", "rho_s=10"}) {
      const RunResult series = solvedDeck("rotor_on_pedestals.yaml", {"mp=0", rho});
      REQUIRE(series.checks.size() == 1);
      CHECK(series.checks[0].pass());
      MESSAGE("series stiffness, " << rho << ": rel. error " << series.checks[0].relError());
    }
  }

  TEST_CASE("rotor on pedestals: the critical-speed map's k in series with each pedestal") {
    // The shipped deck with a map over the bearings' stiffness k, kb at its middle point: there
    // its lines are the Campbell diagram's forward critical speeds (the same rotor, shaft mass
    // and all; a second method: a real symmetric eigenproblem against the refined Campbell
    // crossings). (Not a shipped analysis: with `--set rho_s=0` the free rotor's tilt has no
    // inertia, and the map's free-free asymptote does not exist.)
    std::string text = fileContents(problemsDir() / "rotor_on_pedestals.yaml");
    text.insert(text.find("\nchecks:"),
                "\n  - {type: critical-speed-map, name: map, from_k: kb / 100, to_k: kb * 100, "
                "points: 5, critical_speeds: 3}\n");
    const Study s = solveDeckText(text, (problemsDir() / "rotor_on_pedestals.yaml").string());
    REQUIRE(s.run);
    const CampbellOutcome& c = *resultOf<CampbellOutcome>(s.run->analyses.at(0));
    const CriticalSpeedMap& map = resultOf<CriticalSpeedMapOutcome>(s.run->analyses.at(1))->map;
    REQUIRE(map.stiffness.size() == 5);
    CHECK(map.stiffness[2] == doctest::Approx(5e7).epsilon(1e-15));
    REQUIRE(c.criticalSpeeds.size() == 6);
    for (std::size_t j = 0; j < 3; ++j) {
      // The Campbell crossings are refined to 1e-10 of the speed; the map's eigenvalues carry
      // round-off (1e-12) and the middle k its own (1e-16): 1e-9.
      CAPTURE(j);
      CHECK(map.speeds[2][j] * 30 / kPi ==
            doctest::Approx(c.criticalSpeeds[2 * j].rpm).epsilon(1e-9));
      MESSAGE("map at kb against Campbell, line ", j + 1, ": ",
              map.speeds[2][j] * 30 / kPi / c.criticalSpeeds[2 * j].rpm - 1);
    }
    // An anisotropic pedestal is refused by the map (it solves one plane for both).
    const DeckError e = readingError(
        "title: t\nmodel: {dimension: lateral}\n"
        "materials: [{name: s, E: 2.1e11, nu: 0.3, rho: 7850}]\n"
        "sections: [{name: s, shape: circle, D: 50 mm}]\n"
        "segments: [{name: s, length: 1, section: s, elements: 4}]\n"
        "bearings:\n"
        "  - {name: A, at: start, kxx: 1e7, kyy: 1e7, pedestal: {m: 10, kxx: 1e7, kyy: 2e7}}\n"
        "  - {name: B, at: end, kxx: 1e7, kyy: 1e7}\n"
        "analyses: [{type: critical-speed-map, name: m, from_k: 1e6, to_k: 1e8, points: 3}]\n",
        "aniso.yaml");
    CHECK(e.message().find("bearing 'A'") != std::string::npos);
    CHECK(e.message().find("kxx") != std::string::npos);
  }

  TEST_CASE("a pedestal far stiffer than its bearing is the ground") {
    // kp = 5e13 N/m: the disk on the shaft (ks = 48 E I / L^3) and both bearings in series,
    // k1, and then 2 kp, 3e-7 stiffer than k1 alone: the critical speed 1.5e-7 below the one on
    // the ground, sqrt(k1 / m).
    const RunResult stiff = solvedDeck("rotor_on_pedestals.yaml", {"mp=0", "kp=5e13", "rho_s=0"});
    const CampbellOutcome& c = *resultOf<CampbellOutcome>(stiff.analyses.at(0));
    REQUIRE(!c.criticalSpeeds.empty());
    const double ks = 48 * 210e9 * (kPi * std::pow(0.1, 4) / 64) / std::pow(0.8, 3);
    const double k1 = ks * 2 * 5e7 / (ks + 2 * 5e7);
    const double ground = std::sqrt(k1 / 50.0) * 30 / kPi;
    CHECK(c.criticalSpeeds[0].rpm == doctest::Approx(ground).epsilon(1e-6));
    CHECK(c.criticalSpeeds[0].rpm < ground);
  }

  TEST_CASE("Jeffcott rotor with internal damping: onset and critical speed checks") {
    const RunResult run = solvedDeck("jeffcott_internal_damping.yaml");
    REQUIRE(run.checks.size() == 2);
    for (const Check& c : run.checks) {
      CAPTURE(c.name);
      CHECK(c.pass());
      MESSAGE(c.name << ": " << c.computed << " rpm, rel. error " << c.relError());
    }
  }
}
