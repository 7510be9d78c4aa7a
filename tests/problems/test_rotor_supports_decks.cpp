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
    const RunResult series = solvedDeck("rotor_on_pedestals.yaml", {"mp=0"});
    REQUIRE(series.checks.size() == 1);
    CHECK(series.checks[0].pass());
    MESSAGE("series stiffness: rel. error " << series.checks[0].relError());
    // By hand: 2 (5e7 2e7 / 7e7) / 50 = 571428.57 1/s^2, 755.93 rad/s, 7218.6 rpm.
    CHECK(series.checks[0].computed == doctest::Approx(7218.6).epsilon(1e-4));
  }

  TEST_CASE("a pedestal far stiffer than its bearing is the ground") {
    // kp 1e6 times kb: the series stiffness is kb (1 - 1e-6), the critical speed 5e-7 lower
    // than on the ground, sqrt(2 kb / m) = 1414.2 rad/s; the pedestal's own modes lie far
    // above the sweep.
    const RunResult stiff = solvedDeck("rotor_on_pedestals.yaml", {"mp=0", "kp=5e13"});
    const CampbellOutcome& c = *resultOf<CampbellOutcome>(stiff.analyses.at(0));
    REQUIRE(!c.criticalSpeeds.empty());
    const double ground = std::sqrt(2 * 5e7 / 50.0) * 30 / kPi;
    CHECK(c.criticalSpeeds[0].rpm == doctest::Approx(ground).epsilon(2e-6));
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
