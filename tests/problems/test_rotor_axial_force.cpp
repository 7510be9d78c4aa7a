// A rotor shaft's axial force (segments' axial_force, lateral models) in the rotor analyses:
// a simply supported uniform shaft at rest, without rotary inertia, whose whirl frequencies
// follow f_n^2 = f_n0^2 (1 + N / P_n), P_n = n^2 pi^2 E I / L^2 (the mode shapes of vibration and
// of buckling are the same sines), in compression and in tension; and the reader's refusal in
// a planar model.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

constexpr double kShaftL = 1.5, kShaftD = 0.05, kShaftE = 210e9, kShaftRho = 7850;

double shaftEI() { return kShaftE * std::numbers::pi * std::pow(kShaftD, 4) / 64; }
double shaftRhoA() { return kShaftRho * std::numbers::pi * kShaftD * kShaftD / 4; }
/// Euler's load of mode n, pinned at both ends.
double eulerLoad(int n) { return n * n * std::numbers::pi * std::numbers::pi * shaftEI() / (kShaftL * kShaftL); }
/// Natural frequency (Hz) of mode n without axial force.
double frequencyAtRest(int n) {
  return n * n * std::numbers::pi / (2 * kShaftL * kShaftL) * std::sqrt(shaftEI() / shaftRhoA());
}

/// The shaft with axial force N and a check of whirl frequency `mode` against `reference`.
std::string shaftDeck(double N, int mode, double reference) {
  std::ostringstream d;
  d.precision(17);
  d << "model: {dimension: lateral, rotary_inertia: false}\n"
    << "materials: [{name: steel, E: " << kShaftE << ", nu: 0.3, rho: " << kShaftRho << "}]\n"
    << "sections: [{name: s, shape: circle, D: " << kShaftD << "}]\n"
    << "segments: [{name: shaft, length: " << kShaftL << ", section: s, elements: 48, axial_force: "
    << N << "}]\n"
    << "supports: [{at: start, fix: [uy, uz]}, {at: end, fix: [uy, uz]}]\n"
    << "analyses: [{type: rotor, name: rest, speed_rpm: 0, modes: 6}]\n"
    << "checks: [{name: f, quantity: frequency " << mode << ", reference: " << reference
    << ", tolerance: 2e-6}]\n";
  return d.str();
}

}  // namespace

TEST_SUITE("rotor axial force") {
  // Each whirl frequency appears twice at rest (the y and z planes), so mode 2n-1 is bending
  // mode n. Cubic elements converge at order 4 in both the frequency and the buckling load:
  // with 24 elements mode 2 is 6e-6 off, with 48 elements 2.4e-7 (measured, the largest of
  // these cases); the tolerance is 2e-6.
  TEST_CASE("compression lowers and tension raises the whirl frequencies as f^2 = f0^2 (1 + N/P)") {
    for (int n : {1, 2})
      for (double share : {-0.6, 0.0, 0.8}) {
        const double N = share * eulerLoad(1);
        const double expected = frequencyAtRest(n) * std::sqrt(1 + N / eulerLoad(n));
        CAPTURE(n);
        CAPTURE(share);
        const Study s = test::solveDeckText(shaftDeck(N, 2 * n - 1, expected), "shaft.yaml");
        CHECK(test::checkAllPass(s) == 1);
      }
  }

  TEST_CASE("axial_force belongs to lateral models") {
    std::string planar = shaftDeck(-1e3, 1, 1);
    planar.replace(planar.find("dimension: lateral, rotary_inertia: false"),
                   std::string("dimension: lateral, rotary_inertia: false").size(),
                   "dimension: planar");
    const DeckError e = test::readingError(planar, "planar.yaml");
    CHECK(e.place().field == "segments[0].axial_force");
    CHECK(e.message().find("lateral") != std::string::npos);
  }
}
