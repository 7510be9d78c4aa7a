// API 684 Level I screening with tilting pads kept as degrees of freedom (the full model,
// elements/TiltingPadFilm.hpp), against a closed form and against the pads condensed.
//
// A Jeffcott-like rotor: a disk of mass m on a massless shaft of stiffness k_s (simply
// supported, the disk at mid-span), the test bearing's four pads (massless) acting on the disk,
// and the cross-coupling Q added there (k_yz = Q, k_zy = -Q). Massless pads condensed at a
// motion e^{lambda t} give the exact impedance Z(lambda) (Lund 1964; tiltingPadCoefficientsAt),
// so on the stability boundary, lambda = i w, the disk obeys
//   det(Z(i w) + (k_s - m w^2) I + Q J) = 0,   J = [0 1; -1 0],
// one complex equation in the real unknowns a = k_s - m w^2 and Q. With T = Z11 + Z22,
// D = det Z, S = Z12 - Z21 it reads a^2 + a T + D + Q S + Q^2 = 0: its imaginary part is linear,
// a = alpha + beta Q (alpha = -Im D / Im T, beta = -Im S / Im T), and its real part then the
// quadratic (1 + beta^2) Q^2 + (2 alpha beta + beta Re T + Re S) Q + alpha^2 + alpha Re T +
// Re D = 0. (An isotropic support K + i w C, no cross-coupling, gives the closed form of
// test_level_one_stability.cpp: Q = w C at m w^2 = k_s + K.) Given w = Omega, the pads'
// synchronous table is Z(i Omega) exactly; the mass m = (k_s - a) / Omega^2 then puts the
// threshold whirl at the spin speed, where the condensed model is exact as well.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/TiltingPadFilm.hpp"
#include "fem/rotor/LevelOneStability.hpp"
#include "tests/elements/TiltingPadTestSupport.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

constexpr double kPadTableSpeed = 6000 * std::numbers::pi / 30;  // rad/s, the pads' table speed
constexpr double kPadShaftL = 0.8, kPadShaftD = 0.04, kPadShaftE = 2.1e11;       // the shaft: m, m, Pa

double padShaftStiffness() {
  return 48 * kPadShaftE * (std::numbers::pi * std::pow(kPadShaftD, 4) / 64) / std::pow(kPadShaftL, 3);
}

/// The closed form above at w = Omega: the disk's mass and Q0.
struct PadThreshold {
  double mass = 0, q0 = 0;
};

PadThreshold padThresholdAtSpin(const BearingCoefficients& s, double omega) {
  using C = std::complex<double>;
  const C i(0, omega);
  const C z11 = s.kyy + i * s.cyy, z12 = s.kyz + i * s.cyz, z21 = s.kzy + i * s.czy,
          z22 = s.kzz + i * s.czz;
  const C T = z11 + z22, D = z11 * z22 - z12 * z21, S = z12 - z21;
  const double alpha = -D.imag() / T.imag(), beta = -S.imag() / T.imag();
  const double qa = 1 + beta * beta, qb = 2 * alpha * beta + beta * T.real() + S.real(),
               qc = alpha * alpha + alpha * T.real() + D.real();
  const double root = std::sqrt(qb * qb - 4 * qa * qc);
  // The forward whirl's boundary: the smallest Q > 0.
  double q = (-qb - root) / (2 * qa);
  if (!(q > 0)) q = (-qb + root) / (2 * qa);
  return {(padShaftStiffness() - (alpha + beta * q)) / (omega * omega), q};
}

/// The Jeffcott-like rotor of mass m with the pads at the disk: kept as dofs (inertia >= 0),
/// or condensed into one Bearing element of coefficients `condensed`. Returns the disk's node.
int buildPadJeffcott(Model& model, double m, const TiltingPadPoint& point, double inertia,
               const BearingCoefficients* condensed = nullptr) {
  const int disk = buildJeffcottRotor(model, kPadShaftL, kPadShaftD, m, kPadShaftE);
  if (condensed) {
    model.add<Bearing>(disk, *condensed);
    return disk;
  }
  auto points = std::make_shared<const std::vector<TiltingPadPoint>>(1, point);
  for (int pad = 0; pad < int(point.pads.size()); ++pad) {
    if (!padEverLoaded(*points, pad)) continue;
    const int node = model.addNode(model.nodes()[disk]);
    model.add<TiltingPadFilm>(disk, node, points, pad, 0.0, inertia);
  }
  return disk;
}

CriticalSpeedRatioPoint padTestRegionA() { return criticalSpeedRatioPoint(1, 1, 0); }

}  // namespace

TEST_SUITE("rotor") {
  TEST_CASE("level one with pad tilts as dofs: Q0 against the closed form and the condensed pads") {
    const TiltingPadPoint point = padPoint(kPadTableSpeed);
    const PadThreshold t = padThresholdAtSpin(point.synchronous, kPadTableSpeed);
    CAPTURE(t.mass);
    CAPTURE(t.q0);
    REQUIRE(t.mass > 0);
    // The full model: shaft and the four pads' tilts, nothing condensed.
    Model full;
    const int disk = buildPadJeffcott(full, t.mass, point, 0.0);
    const LevelOneResult r =
        levelOneStability(full, rotorOptions(2), disk, kPadTableSpeed, t.q0 / 3, padTestRegionA());
    REQUIRE(r.found);
    // The root is narrowed to 1e-10 of Q0 (kSpeedTolerance); the eigenvalues' round-off on a
    // massless shaft (RotorModes.cpp) ~1e-12 and the closed form's a handful of operations on
    // the table's coefficients. Measured 6.6e-15 (Q0) and 3.6e-15 (the whirl), the condensed
    // model's Q0 the same bits.
    CHECK(r.zeroDecrement == doctest::Approx(t.q0).epsilon(1e-9));
    CHECK(r.frequencyHzAtQ0 == doctest::Approx(kPadTableSpeed / (2 * std::numbers::pi)).epsilon(1e-8));
    CHECK(r.whirlAtQ0 == Whirl::forward);
    CHECK_FALSE(r.bearingModeAtQ0);  // the pads' relaxations decay; the disk's whirl decides
    CHECK_FALSE(r.bearingModeAtQa);
    // The pads condensed at whirl = spin: exact where the threshold whirls at the spin speed,
    // so the same Q0 to the two roots' tolerance.
    Model condensed;
    buildPadJeffcott(condensed, t.mass, point, 0.0, &point.synchronous);
    const LevelOneResult c =
        levelOneStability(condensed, rotorOptions(2), disk, kPadTableSpeed, t.q0 / 3, padTestRegionA());
    REQUIRE(c.found);
    CHECK(c.zeroDecrement == doctest::Approx(r.zeroDecrement).epsilon(1e-9));
    MESSAGE("Q0 full ", r.zeroDecrement, " closed ", t.q0, " condensed ", c.zeroDecrement,
            " rel ", r.zeroDecrement / t.q0 - 1, " ", c.zeroDecrement / r.zeroDecrement - 1,
            " f ", r.frequencyHzAtQ0 / (kPadTableSpeed / (2 * std::numbers::pi)) - 1);
  }
}
