// Bearing loads at any angle and unloaded journals (FORMAT.md, "Load direction and vertical
// rotors"), each against a second method or a closed form, through the deck.
//
// 1. A flexible rotor on two plain journals whose load turns by theta: the round shaft, the
//    disk and the gyroscopic matrix are invariant under the turn, and the bearings turn with
//    the load, so the whole system is the one at theta = 0 seen in turned axes: the same
//    eigenvalues, critical speeds and onset of instability at every angle.
// 2. A vertical rotor: a rigid, light shaft with a disk (m, Jd, no Jp) centred between two
//    unloaded (centred) journals, k_c = Omega c / 2 cross-coupled and c direct each. For the
//    forward whirl r = uy + i uz the bounce and the tilt each obey a scalar equation:
//      m lambda^2 + 2 c (lambda - i Omega / 2) = 0,   Jd lambda^2 + 2 c l^2 (lambda - i Omega / 2) = 0,
//    whose roots near i Omega / 2 are the forward whirl modes.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

const char* kTurnedJournals = R"(
title: flexible rotor on plain journals loaded at an angle
parameters: {angle: 0 deg}
model: {dimension: lateral, rotary_inertia: true}
materials: [{name: steel, E: 2.1e11, nu: 0.3, rho: 7850}]
sections: [{name: shaft, shape: circle, D: 40 mm}]
segments: [{name: shaft, length: 0.8, section: shaft, elements: 8}]
points: [{name: disk, at: 0.5}]
masses: [{name: disk, at: disk, m: 40, Jp: 0.3, Jd: 0.2}]
bearings:
  - {name: A, at: start, type: plain-journal, D: 50 mm, L: 20 mm, c: 60 um, mu: 0.02,
     load: 230 N, load_angle: angle, from_rpm: 200, to_rpm: 15000, steps: 100}
  - {name: B, at: end, type: plain-journal, D: 50 mm, L: 20 mm, c: 60 um, mu: 0.02,
     load: 190 N, load_angle: angle, from_rpm: 200, to_rpm: 15000, steps: 100}
analyses:
  - {type: campbell, name: campbell, modes: 4, from_rpm: 500, to_rpm: 15000, steps: 30}
)";

const CampbellOutcome& campbellAt(const std::string& angle, RunResult& keep) {
  StudyRequest request;
  request.deckPath = "turned_journals.yaml";
  request.sets = {"angle=" + angle};
  const Study s = solveStudyText(kTurnedJournals, request);
  REQUIRE(s.run);
  keep = *s.run;
  return *resultOf<CampbellOutcome>(keep.analyses.at(0));
}

const char* kVerticalRotor = R"(
title: vertical rotor on unloaded plain journals
model: {dimension: lateral, formulation: euler-bernoulli, rotary_inertia: false}
materials: [{name: light, E: 2e17, nu: 0.3, rho: 7850e-12}]
sections: [{name: shaft, shape: circle, D: 60 mm}]
segments: [{name: shaft, length: 0.6, section: shaft, elements: 6}]
points: [{name: disk, at: 0.3}]
masses: [{name: disk, at: disk, m: 25, Jp: 0, Jd: 0.4}]
bearings:
  - {name: A, at: start, type: plain-journal, D: 50 mm, L: 20 mm, c: 60 um, mu: 0.02, load: 0,
     from_rpm: 200, to_rpm: 15000, steps: 100}
  - {name: B, at: end, type: plain-journal, D: 50 mm, L: 20 mm, c: 60 um, mu: 0.02, load: 0,
     from_rpm: 200, to_rpm: 15000, steps: 100}
analyses:
  - {type: rotor, name: running, speed_rpm: 3000, modes: 2}
)";

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("journals loaded at any angle: the critical speeds and the onset do not change") {
    RunResult r0, r1, r2;
    const CampbellOutcome& zero = campbellAt("0", r0);
    REQUIRE(zero.onset.has_value());
    REQUIRE(!zero.criticalSpeeds.empty());
    for (const char* angle : {"37 deg", "200 deg"}) {
      CAPTURE(angle);
      RunResult& keep = std::string(angle) == "37 deg" ? r1 : r2;
      const CampbellOutcome& turned = campbellAt(angle, keep);
      // Equal eigenvalues up to the eigensolver's round-off (~1e-13); the refinements stop
      // within 1e-10 of the speed, each on its own side: 1e-8 leaves room for both.
      REQUIRE(turned.onset.has_value());
      CHECK(turned.onset->rpm == doctest::Approx(zero.onset->rpm).epsilon(1e-8));
      CHECK(turned.onset->frequencyHz == doctest::Approx(zero.onset->frequencyHz).epsilon(1e-8));
      REQUIRE(turned.criticalSpeeds.size() == zero.criticalSpeeds.size());
      for (std::size_t k = 0; k < zero.criticalSpeeds.size(); ++k)
        CHECK(turned.criticalSpeeds[k].rpm ==
              doctest::Approx(zero.criticalSpeeds[k].rpm).epsilon(1e-8));
      // The modes at each sweep speed too, to the eigensolver's round-off.
      for (std::size_t l = 0; l < zero.campbell.lines.size(); ++l)
        for (std::size_t s = 0; s < zero.campbell.speeds.size(); ++s) {
          const auto a = zero.campbell.lines[l][s].eigenvalue,
                     b = turned.campbell.lines[l][s].eigenvalue;
          CHECK(std::abs(a - b) < 1e-10 * std::abs(a));
        }
    }
    MESSAGE("turned journals: onset " << zero.onset->rpm << " rpm");
  }

  TEST_CASE("a vertical rotor on unloaded journals: the forward whirl modes' closed form") {
    StudyRequest request;
    request.deckPath = "vertical_rotor.yaml";
    const Study s = solveStudyText(kVerticalRotor, request);
    REQUIRE(s.run);
    const auto& modes = resultOf<RotorModesResult>(s.run->analyses.at(0))->modes;
    REQUIRE(modes.size() == 2);
    // The centred journal's damping pi mu R L^3 / (2 c^3), and the data of the deck.
    const double mu = 0.02, R = 0.025, Lj = 0.02, c = 60e-6;
    const double cd = std::numbers::pi * mu * R * Lj * Lj * Lj / (2 * c * c * c);
    const double m = 25, Jd = 0.4, l = 0.3, w = 3000 * std::numbers::pi / 30;
    // Roots of a x^2 + b (x - i w / 2) = 0 near i w / 2.
    auto forward = [&](double a, double b) {
      const std::complex<double> disc = std::sqrt(std::complex<double>(b * b, 2 * a * b * w));
      return (-b + disc) / (2 * a);
    };
    for (const std::complex<double> want : {forward(m, 2 * cd), forward(Jd, 2 * cd * l * l)}) {
      CAPTURE(want);
      double best = 1e300;
      for (const auto& mode : modes) best = std::min(best, std::abs(mode.eigenvalue - want));
      // The stiff shaft's compliance (its bending stiffness is 1e5 times the film's
      // cross-coupling) and 1e-12 of steel's density: 1e-6 of |lambda|.
      CHECK(best < 1e-6 * std::abs(want));
    }
  }
}
