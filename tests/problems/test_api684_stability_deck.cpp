// The stability half of the API 684 verdict through the deck path: a Jeffcott rotor whose
// bearing's cross-coupled stiffness grows with speed has its onset of instability in closed
// form, and an operating range across it fails the verdict with that onset named.
//
// A mass m at mid-span of a massless shaft (stiffness k = 48 E I / L^3 there) on a bearing with
// direct damping c and cross-coupled stiffness Q = q Omega (kxy = q Omega, kyx = -q Omega,
// linear between the table's rows). With r = y + i z: m r'' + c r' + (k - i Q) r = 0, whose
// forward whirl loses its damping when Q = c sqrt(k / m) (Childs, Turbomachinery
// Rotordynamics, 1993, ch. 3), i.e. at Omega* = c sqrt(k / m) / q. Below it the forward mode's
// log decrement is -2 pi Re(lambda) / |Im(lambda)| of the root of
// m lambda^2 + c lambda + k - i q Omega = 0 with the larger real part.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>
#include <string>

#include "problems/cli/RotorSummary.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;

namespace {

struct CrossCoupledDeckRotor {
  double L = 0.8, D = 0.025, m = 8, E = 2.1e11, c = 50, q = 50, top = 400;  // top: rad/s
  double k() const { return 48 * E * (std::numbers::pi * std::pow(D, 4) / 64) / std::pow(L, 3); }
  double onset() const { return c * std::sqrt(k() / m) / q; }  // 217 rad/s, 2074 rpm
  double logDecrement(double w) const {
    const std::complex<double> root =
        (-c + std::sqrt(std::complex<double>(c * c - 4 * m * k(), 4 * m * q * w))) / (2 * m);
    return -2 * std::numbers::pi * root.real() / std::abs(root.imag());
  }

  /// The deck, with the operating range in rpm and the `operating:` map's extra entries.
  std::string deck(double minRpm, double maxRpm, const std::string& extra = "") const {
    std::ostringstream d;
    d.precision(17);
    const double rpm = 30 / std::numbers::pi, qTop = q * top;
    d << "title: cross-coupled Jeffcott rotor\n"
         "model: {dimension: lateral, rotary_inertia: false}\n"
         "materials: [{name: massless, E: " << E << ", nu: 0.3, rho: 7850e-12}]\n"
         "sections: [{name: shaft, shape: circle, D: " << D << "}]\n"
         "segments: [{length: " << L << ", section: shaft, elements: 2}]\n"
         "points: [{name: disk, at: " << L / 2 << "}]\n"
         "supports:\n"
         "  - {name: left, at: start, fix: [uy, uz]}\n"
         "  - {name: right, at: end, fix: [uy, uz]}\n"
         "masses: [{name: disk, at: disk, m: " << m << "}]\n"
         "bearings:\n"
         "  - name: seal\n"
         "    at: disk\n"
         "    table:\n"
         "      - {speed_rpm: 0, cxx: " << c << ", cyy: " << c << "}\n"
         "      - {speed_rpm: " << top * rpm << ", kxy: " << qTop << ", kyx: " << -qTop
      << ", cxx: " << c << ", cyy: " << c << "}\n"
         "analyses:\n"
         "  - {type: unbalance, name: response, from_rpm: 100, to_rpm: 3500, steps: 68,\n"
         "     unbalance: {at: disk, me: 1e-5}, response: [disk],\n"
         "     operating: {min_rpm: " << minRpm << ", max_rpm: " << maxRpm << extra << "}}\n";
    return d.str();
  }
};

const AnalysisOutcome& solvedResponse(const std::string& text, RunResult& keep) {
  StudyRequest request;
  request.deckPath = "cross_coupled.yaml";
  const Study s = solveStudyText(text, request);
  REQUIRE(s.run);
  keep = *s.run;
  REQUIRE(keep.analyses.size() == 1);
  REQUIRE(keep.analyses[0].rotor);
  REQUIRE(keep.analyses[0].rotor->stability);
  return keep.analyses[0];
}

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("API 684 verdict: an operating range across the onset fails, the onset named") {
    const CrossCoupledDeckRotor j;
    const double rpm = 30 / std::numbers::pi, onsetRpm = j.onset() * rpm;
    RunResult run;
    const AnalysisOutcome& a = solvedResponse(j.deck(1800, 2400), run);
    const OperatingStability& s = *a.rotor->stability;
    CHECK_FALSE(s.pass);
    REQUIRE(s.onset.has_value());
    // Refined on the speed to 1e-10 (fem/rotor/RotorStability.hpp); the shaft's 4e-13 mass
    // and the eigensolver's round-off move the root far less. 1e-8 leaves room for both.
    CHECK(s.onset->rpm == doctest::Approx(onsetRpm).epsilon(1e-8));
    // The least stable point is the range's top: the decrement falls steadily with speed.
    CHECK(s.speed * rpm == doctest::Approx(2400).epsilon(1e-12));
    CHECK(s.smallest == doctest::Approx(j.logDecrement(2400 / rpm)).epsilon(1e-8));
    // The summary fails the API 684 reading, naming the onset.
    std::ostringstream summary;
    cli::printRotor(summary, a);
    CAPTURE(summary.str());
    CHECK(summary.str().find("API 684: FAIL (unstable above 2074") != std::string::npos);
  }

  TEST_CASE("API 684 verdict: below the onset it passes, unless the deck asks more decrement") {
    const CrossCoupledDeckRotor j;
    const double rpm = 30 / std::numbers::pi;
    const double top = j.logDecrement(1800 / rpm);  // 0.0120 at the range's top
    RunResult run;
    const OperatingStability& s = *solvedResponse(j.deck(1200, 1800), run).rotor->stability;
    CHECK(s.pass);
    CHECK_FALSE(s.onset.has_value());
    CHECK(s.smallest == doctest::Approx(top).epsilon(1e-8));
    RunResult strict;
    const AnalysisOutcome& a = solvedResponse(
        j.deck(1200, 1800, ", min_log_decrement: " + std::to_string(top + 0.01)), strict);
    CHECK_FALSE(a.rotor->stability->pass);
    // The deck carries the limit with 6 decimals (std::to_string): 1e-4 of it.
    CHECK(a.rotor->stability->required == doctest::Approx(top + 0.01).epsilon(1e-4));
  }
}
