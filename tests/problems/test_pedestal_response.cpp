// The housings of bearings on pedestals in an unbalance response: a symmetric rigid rotor (a
// stiff, nearly massless shaft with a 100 kg disk at its middle) on two isotropic bearings kb,
// each on a pedestal mp, kp, driven by m e at the disk. Its cylindrical whirl is the
// two-mass chain, undamped (Den Hartog's two-dof forced response):
//   (2 kb - m w^2) x - 2 kb xp = m e w^2,   -2 kb x + (2 kb + 2 kp - 2 mp w^2) xp = 0,
// whose housing amplitude is xp = 2 kb m e w^2 / det.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

TEST_SUITE("rotor decks") {
  TEST_CASE("pedestal housings answer in the unbalance response") {
    const char* deck = R"(
title: rigid rotor on two bearings on pedestals
model: {dimension: lateral}
materials: [{name: stiff, E: 2.1e15, nu: 0.3, rho: 1e-3}]
sections: [{name: shaft, shape: circle, D: 100 mm}]
segments: [{name: shaft, length: 0.2, section: shaft, elements: 2}]
points: [{name: mid, at: 0.1}]
masses: [{name: disk, at: mid, m: 100 kg}]
bearings:
  - {name: A, at: start, kxx: 1e7, kyy: 1e7, pedestal: {m: 20 kg, k: 5e6 N/m}}
  - {name: B, at: end, kxx: 1e7, kyy: 1e7, pedestal: {m: 20 kg, k: 5e6 N/m}}
analyses:
  - {type: unbalance, name: response, from_rpm: 600, to_rpm: 6000, steps: 9,
     unbalance: [{at: mid, me: 1e-3}], response: [mid]}
)";
    const Study s = solveDeckText(deck, "pedestals.yaml");
    REQUIRE(s.run);
    const UnbalanceOutcome& u = *resultOf<UnbalanceOutcome>(s.run->analyses.at(0));
    REQUIRE(u.responsePoints.size() == 3);
    CHECK(u.responsePoints[1] == "A_pedestal");
    CHECK(u.responsePoints[2] == "B_pedestal");
    const double m = 100, mp = 20, kb = 1e7, kp = 5e6, me = 1e-3;
    for (std::size_t i = 0; i < u.unbalance.speeds.size(); ++i) {
      const double w = u.unbalance.speeds[i];
      const double a = 2 * kb - m * w * w, b = -2 * kb, d = 2 * kb + 2 * kp - 2 * mp * w * w;
      const double det = a * d - b * b;
      const double x = me * w * w * d / det, xp = -b * me * w * w / det;
      CAPTURE(w);
      // The shaft's bending (kb / (48 E I / L^3) ~ 2e-7) and its mass (1.6e-5 kg against 100)
      // set the agreement: 1e-5 relative.
      CHECK(u.unbalance.orbits[0][i].major() == doctest::Approx(std::abs(x)).epsilon(1e-5));
      CHECK(u.unbalance.orbits[1][i].major() == doctest::Approx(std::abs(xp)).epsilon(1e-5));
      CHECK(u.unbalance.orbits[2][i].major() == doctest::Approx(std::abs(xp)).epsilon(1e-5));
    }
    // The housings carry no API 684 reading of their own.
    CHECK(u.peaks.empty());
  }
}
