// Tilting pads kept as degrees of freedom (elements/TiltingPadFilm.hpp): the rotor's full model
// (shaft dofs plus each loaded pad's tilt) against the pads condensed onto the journal.
//  - Any eigenvalue lambda of the full model is an eigenvalue of the shaft on bearings whose
//    coefficients are the pads condensed at lambda itself (Lund 1964, with the pad's inertia
//    I about its pivot): per pad, in pad axes (e_k, t_k), Z = K_k + lambda C_k and
//      Z' = Z - Z t t^T Z / (t^T Z t + lambda^2 I / R^2),
//    the frequency-dependent reduction K(s) = K_jj - K_jt (K_tt + s C_tt + s^2 I)^-1 K_tj.
//    With massless pads Z' is tiltingPadCoefficientsAt's, a second code path.
//  - Massless pads at whirl = spin condense to the bearing's synchronous table.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/TiltingPadFilm.hpp"
#include "fem/rotor/RotorModes.hpp"
#include "tests/elements/TiltingPadTestSupport.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

using Complex = std::complex<double>;

/// The pads of `point` condensed at lambda with pad inertia I (Lund's formula above), summed,
/// as real K and C with K + lambda C = Z'(lambda) (Im lambda > 0), bearing's axes.
BearingCoefficients condensedWithInertia(const TiltingPadPoint& point, Complex lambda,
                                         double inertia) {
  Eigen::Matrix2cd total = Eigen::Matrix2cd::Zero();
  for (const PadFilmState& p : point.pads) {
    if (p.stiffness[1][1] == 0) continue;
    Eigen::Matrix2cd z;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        z(i, j) = point.stiffnessScale * p.stiffness[i][j] +
                  lambda * point.dampingScale * p.damping[i][j];
    const Complex tzt = z(1, 1) + lambda * lambda * inertia / (point.radius * point.radius);
    const Eigen::Matrix2cd reduced = z - z.col(1) * z.row(1) / tzt;
    Eigen::Matrix2d q;  // e_k, t_k in the bearing's axes
    q << std::cos(p.pivot), -std::sin(p.pivot), std::sin(p.pivot), std::cos(p.pivot);
    total += q * reduced * q.transpose();
  }
  double k[4], c[4];
  for (int i = 0; i < 4; ++i) {
    const Complex zi = total(i / 2, i % 2);
    c[i] = zi.imag() / lambda.imag();
    k[i] = zi.real() - lambda.real() * c[i];
  }
  return {k[0], k[1], k[2], k[3], c[0], c[1], c[2], c[3]};
}

/// The shaft on two bearings of the given (frozen) coefficients: its eigenvalue nearest lambda.
/// The shift sits 1e-6 of |lambda| off it: at lambda itself K + lambda D + lambda^2 M is
/// singular to round-off (rcond ~1e-15, which the solver refuses) when lambda is an eigenvalue.
Complex frozenEigenvalue(const BearingCoefficients& k, double speed, Complex lambda) {
  Model model;
  for (int node : buildShaft(model)) model.add<Bearing>(node, k);
  const Complex shift = lambda + Complex(1e-6 * std::abs(lambda), 0);
  return solveRotorModes(model, speed, rotorOptions(1, shift)).modes.at(0).eigenvalue;
}

constexpr double kSpeed = 6000 * std::numbers::pi / 30;

}  // namespace

TEST_SUITE("rotor") {
  TEST_CASE("tilting pads as dofs: each eigenvalue a root of the pads condensed at it") {
    const TiltingPadPoint point = padPoint(kSpeed);
    // Massless pads and pads of 0.02 kg m^2 about their pivots (a heavy pad: its inertia
    // shifts the bounce pair by ~1e-4 relative, the pads' relaxation modes more).
    for (double inertia : {0.0, 0.02}) {
      CAPTURE(inertia);
      Model full;
      const int films = addPadTilts(full, buildShaft(full), point, inertia);
      CHECK(films == 8);  // every pad carries a film at this load and speed
      const RotorModesResult r = solveRotorModes(full, kSpeed, rotorOptions(8));
      REQUIRE(r.modes.size() == 8);
      int checked = 0;
      for (const RotorMode& mode : r.modes) {
        const Complex lambda = mode.eigenvalue;
        if (!(lambda.imag() > 0)) continue;
        CAPTURE(lambda);
        const BearingCoefficients lund = condensedWithInertia(point, lambda, inertia);
        if (inertia == 0) {
          // Lund's formula against the library's condensation (TiltingPadBearing.cpp), the
          // same Schur complement written twice: round-off (1e-12 of the largest term).
          const BearingCoefficients lib = tiltingPadCoefficientsAt(point, lambda);
          CHECK(std::abs(lib.kyy - lund.kyy) <= 1e-10 * std::abs(lund.kyy));
          CHECK(std::abs(lib.kzy - lund.kzy) <= 1e-10 * std::abs(lund.kyy));
          CHECK(std::abs(lib.czz - lund.czz) <= 1e-10 * std::abs(lund.czz));
        }
        // lambda is an eigenvalue of the frozen reduced model: the two eigen-solutions'
        // round-off (1e-12 relative measured) and the frozen K, C's (Im lambda divides) stay
        // below 1e-9.
        CHECK(std::abs(frozenEigenvalue(lund, kSpeed, lambda) - lambda) <=
              1e-9 * std::abs(lambda));
        ++checked;
      }
      CHECK(checked >= 6);
    }
  }

  TEST_CASE("tilting pads as dofs: massless pads at whirl = spin give the synchronous table") {
    const TiltingPadPoint point = padPoint(kSpeed);
    Model full;
    const std::array<int, 2> journals = buildShaft(full);
    addPadTilts(full, journals, point, 0.0);
    BearingCoefficients sum{0, 0, 0, 0, 0, 0, 0, 0};
    for (const auto& e : full.elements())
      if (const auto* f = dynamic_cast<const TiltingPadFilm*>(e.get());
          f && f->journal() == journals[0]) {
        const BearingCoefficients c = f->synchronousAt(kSpeed);
        sum = {sum.kyy + c.kyy, sum.kyz + c.kyz, sum.kzy + c.kzy, sum.kzz + c.kzz,
               sum.cyy + c.cyy, sum.cyz + c.cyz, sum.czy + c.czy, sum.czz + c.czz};
      }
    const BearingCoefficients& s = point.synchronous;
    // The same condensation from the element's 3 x 3 matrices: round-off of the largest term.
    const double k = std::abs(s.kyy), c = std::abs(s.cyy);
    CHECK(std::abs(sum.kyy - s.kyy) <= 1e-12 * k);
    CHECK(std::abs(sum.kyz - s.kyz) <= 1e-12 * k);
    CHECK(std::abs(sum.kzy - s.kzy) <= 1e-12 * k);
    CHECK(std::abs(sum.kzz - s.kzz) <= 1e-12 * k);
    CHECK(std::abs(sum.cyy - s.cyy) <= 1e-12 * c);
    CHECK(std::abs(sum.czz - s.czz) <= 1e-12 * c);
  }

  TEST_CASE("tilting pads as dofs: the pads' own modes reported apart") {
    const TiltingPadPoint point = padPoint(kSpeed);
    Model full;
    addPadTilts(full, buildShaft(full), point, 0.0);
    const RotorModesResult r = solveRotorModes(full, kSpeed, rotorOptions(6));
    // The rotor's modes as asked; the modes whose energy lies mostly in the tilts apart.
    CHECK(r.modes.size() == 6);
    REQUIRE_FALSE(r.bearingModes.empty());
    for (const RotorMode& m : r.modes) CHECK(m.bearingEnergy <= 0.5);
    for (const RotorMode& m : r.bearingModes) {
      CAPTURE(m.eigenvalue);
      CHECK(m.bearingEnergy > 0.5);
      CHECK(m.eigenvalue.real() < 0);
    }
  }

  TEST_CASE("tilting pads as dofs: a larger preload stiffens the pads") {
    // Preload narrows each pad's converging film at the pivot: every pad's film stiffer, the
    // bounce pair (~57 Hz) higher. Measured below.
    auto bounce = [](double preload) {
      TiltingPads pads = fourPadsBetween();
      pads.preload = preload;
      const TiltingPadPoint point = padPoint(kSpeed, pads);
      Model full;
      addPadTilts(full, buildShaft(full), point, 0.0);
      return solveRotorModes(full, kSpeed, rotorOptions(1, Complex(0, 350))).modes.at(0);
    };
    const RotorMode low = bounce(0.2), high = bounce(0.5);
    CAPTURE(low.eigenvalue);
    CAPTURE(high.eigenvalue);
    CHECK(high.dampedFrequency > low.dampedFrequency);
  }

  TEST_CASE("tilting pads as dofs: a sweep's candidates hold every rotor mode solved for") {
    // At 6000 rpm two of the pads' real relaxations (-198.8 /s, a double eigenvalue, and
    // -199.8 /s) carry only 37 % of their energy in the tilts, so they count with the rotor's
    // modes: two modes asked for are those two, and the bounce pair (-10.3 + 357.9i /s) the
    // solution holds as well is left out. everyRotorMode (a Campbell sweep's candidates)
    // reports it.
    const TiltingPadPoint point = padPoint(kSpeed);
    Model full;
    addPadTilts(full, buildShaft(full), point, 0.0);
    RotorOptions options = rotorOptions(2);
    const RotorModesResult asked = solveRotorModes(full, kSpeed, options);
    options.everyRotorMode = true;
    const RotorModesResult every = solveRotorModes(full, kSpeed, options);
    REQUIRE(asked.modes.size() == 2);
    REQUIRE(every.modes.size() > asked.modes.size());
    // The same eigen-solution: the nearest modes first, to the bit, and the pads' own alike.
    for (std::size_t m = 0; m < asked.modes.size(); ++m)
      CHECK(every.modes[m].eigenvalue == asked.modes[m].eigenvalue);
    REQUIRE(every.bearingModes.size() == asked.bearingModes.size());
    for (std::size_t m = 0; m < asked.bearingModes.size(); ++m)
      CHECK(every.bearingModes[m].eigenvalue == asked.bearingModes[m].eigenvalue);
    for (const RotorMode& m : every.modes) CHECK(m.bearingEnergy <= 0.5);
    // Against the dense eigensolver of the same model (a second method): the modes reported,
    // the rotor's and the pads', are every mode of the model out to the farthest of them from
    // the shift (0), one per conjugate pair, each to 1e-9 of |lambda| (the two solvers'
    // round-off: measured 2e-14 at most).
    RotorOptions dense = rotorOptions(40, 0, {}, EigenMethod::dense);
    dense.everyRotorMode = true;
    const RotorModesResult reference = solveRotorModes(full, kSpeed, dense);
    std::vector<RotorMode> reported = every.modes, all = reference.modes;
    reported.insert(reported.end(), every.bearingModes.begin(), every.bearingModes.end());
    all.insert(all.end(), reference.bearingModes.begin(), reference.bearingModes.end());
    double farthest = 0;
    for (const RotorMode& m : reported) {
      CAPTURE(m.eigenvalue);
      farthest = std::max(farthest, std::abs(m.eigenvalue));
      double nearest = 1e300;
      for (const RotorMode& r : all) nearest = std::min(nearest, std::abs(r.eigenvalue - m.eigenvalue));
      CHECK(nearest <= 1e-9 * std::abs(m.eigenvalue));
    }
    std::size_t within = 0;
    for (const RotorMode& r : all) within += std::abs(r.eigenvalue) <= farthest * (1 + 1e-9);
    CHECK(within == reported.size());
    // The bounce pair among the candidates: a lightly damped pair near 358 rad/s.
    CHECK(std::any_of(every.modes.begin(), every.modes.end(), [](const RotorMode& m) {
      return std::abs(m.eigenvalue.imag() - 357.9) < 0.1 && m.dampingRatio < 0.05;
    }));
  }
}
