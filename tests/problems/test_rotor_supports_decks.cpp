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
