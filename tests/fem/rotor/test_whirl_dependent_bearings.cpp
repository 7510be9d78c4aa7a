// Bearings whose coefficients depend on the whirl frequency (fem/rotor/WhirlIteration.hpp):
// each mode found with the coefficients at its own eigenvalue, against two references.
//  - A Jeffcott rotor on a table whose stiffness is linear in the whirl frequency,
//    k(w) = k0 + k1 w, damping c: the disk's r = uy + i uz obeys m l^2 + c l + k_s + k(w) = 0
//    with w = Im l. The imaginary part gives Re l = -c / (2 m), the real part
//    m w^2 - k1 w - (k_s + k0 - c^2 / (4 m)) = 0, so
//      w = (k1 + sqrt(k1^2 + 4 m (k_s + k0 - c^2 / (4 m)))) / (2 m)
//    for both whirls (no gyroscopic moment at a point mass).
//  - A rotor on tilting pads: the eigenvalues with the pads condensed at each mode's
//    eigenvalue are the eigenvalues of the full model that keeps every pad's tilt as a degree
//    of freedom (massless pads: the tilt's equation holds no inertia, so condensing it at the
//    eigenvalue is exact there; Lund 1964, Allaire et al. 1981).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/TiltingPadFilm.hpp"
#include "elements/TiltingPadWhirl.hpp"
#include "elements/WhirlTable.hpp"
#include "fem/rotor/RotorModes.hpp"
#include "tests/elements/TiltingPadTestSupport.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// The shaft on two bearings of `point`'s pads, condensed at each mode's eigenvalue.
void condensedPads(Model& model, const TiltingPadPoint& point) {
  auto whirl = std::make_shared<TiltingPadWhirl>(std::vector<TiltingPadPoint>{point});
  for (int node : buildShaft(model))
    model.add<Bearing>(node, std::vector<double>{point.speed},
                       std::vector<BearingCoefficients>{point.synchronous})
        .setWhirlCoefficients(whirl);
}

/// The same shaft with every loaded pad's tilt kept, a node of its own (massless pads).
int fullPads(Model& model, const TiltingPadPoint& point) {
  return addPadTilts(model, buildShaft(model), point, 0.0);
}

/// The same shaft on the pads' synchronous set.
void synchronousPads(Model& model, const TiltingPadPoint& point) {
  for (int node : buildShaft(model)) model.add<Bearing>(node, point.synchronous);
}

/// The test shaft at 6000 rpm three ways: pads condensed at each mode's eigenvalue, the full
/// model with the pads' tilts, and the synchronous set.
struct PadModels {
  double speed = 6000 * std::numbers::pi / 30;
  TiltingPadPoint point = padPoint(speed);
  Model condensed, full, synchronous;
  int padFilms = 0;
  PadModels() {
    condensedPads(condensed, point);
    padFilms = fullPads(full, point);
    synchronousPads(synchronous, point);
  }
};

/// The distance from lambda to the nearest of `modes`' eigenvalues.
double nearestTo(std::complex<double> lambda, const std::vector<RotorMode>& modes) {
  double nearest = 1e300;
  for (const RotorMode& m : modes) nearest = std::min(nearest, std::abs(m.eigenvalue - lambda));
  return nearest;
}

}  // namespace

TEST_SUITE("rotor") {
  TEST_CASE("whirl table linear in the whirl frequency: the Jeffcott rotor's closed form") {
    const double L = 0.7, D = 0.03, m = 20, E = 2.1e11;
    const double k0 = 1e6, k1 = 500, c = 200;  // N/m, N/m per rad/s, N s/m
    const double ks = 48 * E * (std::numbers::pi * std::pow(D, 4) / 64) / std::pow(L, 3);
    // Two speeds and two whirl frequencies bracket the mode (its whirl ~ 330 rad/s): the
    // bilinear table is then exactly linear in the whirl frequency.
    std::vector<BearingCoefficients> rows;
    for (int speedRow = 0; speedRow < 2; ++speedRow)
      for (double w : {0.0, 2000.0}) rows.push_back(BearingCoefficients::isotropic(k0 + k1 * w, c));
    auto table = std::make_shared<WhirlTable>(std::vector<double>{0, 2000},
                                              std::vector<double>{0, 2000}, rows);
    Model model;
    const int disk = buildJeffcottRotor(model, L, D, m, E);
    const double speed = 500;
    model.add<Bearing>(disk, std::vector<double>{0, 2000}, table->synchronous())
        .setWhirlCoefficients(table);
    const RotorModesResult r = solveRotorModes(model, speed, rotorOptions(2));
    const double sigma = -c / (2 * m);
    const double w = (k1 + std::sqrt(k1 * k1 + 4 * m * (ks + k0 - c * c / (4 * m)))) / (2 * m);
    CHECK(r.coefficients.atOwnWhirl);
    CHECK(r.coefficients.unsettled.empty());
    REQUIRE(r.modes.size() == 2);
    for (const RotorMode& mode : r.modes) {
      // The iteration stops at 1e-10 (relative) and contracts by k1 / (2 m w) = 0.04 a step,
      // so it lies within 1e-11 of its fixed point; the shaft's mass (4e-13 of the disk's)
      // and round-off of the eigen-solution add less. 1e-9 keeps a margin of 10.
      CHECK(mode.eigenvalue.real() == doctest::Approx(sigma).epsilon(1e-9));
      CHECK(mode.eigenvalue.imag() == doctest::Approx(w).epsilon(1e-9));
      CHECK(mode.whirlIterations >= 2);
    }
    // The synchronous set (k at whirl = spin, 500 rad/s) gives another frequency: the
    // iteration moved it.
    const double wSync = std::sqrt((ks + k0 + k1 * speed) / m - sigma * sigma);
    CHECK(std::abs(w - wSync) > 1e-3 * w);
  }

  TEST_CASE("whirl table constant in the whirl frequency: the synchronous modes") {
    // Coefficients that do not change with the whirl: the fixed point is the synchronous
    // eigenvalue itself, reached at the first re-solve (to the eigensolver's round-off).
    Model a, b;
    const BearingCoefficients k{2e6, 3e5, -3e5, 2.5e6, 400, 20, 20, 500};
    buildJeffcottRotor(a, 0.7, 0.03, 20, 2.1e11, k);
    const int db = buildJeffcottRotor(b, 0.7, 0.03, 20, 2.1e11);
    auto table = std::make_shared<WhirlTable>(std::vector<double>{0}, std::vector<double>{0, 1e4},
                                              std::vector<BearingCoefficients>{k, k});
    b.add<Bearing>(db, std::vector<double>{0}, table->synchronous()).setWhirlCoefficients(table);
    const RotorModesResult ra = solveRotorModes(a, 300, rotorOptions(2));
    const RotorModesResult rb = solveRotorModes(b, 300, rotorOptions(2));
    CHECK_FALSE(ra.coefficients.atOwnWhirl);
    CHECK(ra.modes[0].whirlIterations == 0);
    REQUIRE(rb.modes.size() == ra.modes.size());
    for (std::size_t i = 0; i < ra.modes.size(); ++i) {
      CHECK(std::abs(rb.modes[i].eigenvalue - ra.modes[i].eigenvalue) <=
            1e-11 * std::abs(ra.modes[i].eigenvalue));
      CHECK(rb.modes[i].whirlIterations <= 2);
    }
  }

  TEST_CASE("tilting pads at each mode's eigenvalue: the full model with the pads' tilts") {
    const PadModels p;
    const double speed = p.speed;
    CHECK(p.padFilms >= 6);
    // The bounce pair around 350 rad/s.
    const Complex around(0, 350);
    const RotorModesResult rc = solveRotorModes(p.condensed, speed, rotorOptions(2, around));
    // The full model has one eigenvalue more per pad (the tilt's relaxation), which it asks
    // for itself and reports apart (bearingModes).
    const RotorModesResult rf = solveRotorModes(p.full, speed, rotorOptions(2, around));
    const RotorModesResult sync = solveRotorModes(p.synchronous, speed, rotorOptions(2, around));
    CHECK(rc.coefficients.atOwnWhirl);
    CHECK(rc.coefficients.unsettled.empty());
    CHECK_FALSE(rf.coefficients.atOwnWhirl);
    REQUIRE(rc.modes.size() == 2);
    // The pair: one forward, one backward whirl.
    CHECK(rc.modes[0].whirl != rc.modes[1].whirl);
    for (const RotorMode& mode : rc.modes) {
      const std::complex<double> lambda = mode.eigenvalue;
      CAPTURE(lambda);
      // The iteration stops at 1e-10 of |lambda|; the two eigen-solutions' round-off is below
      // 1e-12. 1e-8 keeps a margin.
      CHECK(nearestTo(lambda, rf.modes) <= 1e-8 * std::abs(lambda));
      // The synchronous set differs from the eigenvalue's by several per cent (whirl well
      // below the spin for these modes): the test tells the two apart.
      CHECK(nearestTo(lambda, sync.modes) > 1e-4 * std::abs(lambda));
    }
  }

  TEST_CASE("tilting pads at each mode's eigenvalue: every mode found, or named") {
    // The eight modes nearest 0: the bounce pair, two bending modes and a high one settle on
    // eigenvalues of the full model; the synchronous set's conical mode (-613 + 21i /s) and
    // its overdamped pair (-702 /s) have no counterpart near them (the full model has
    // -467 + 488i, -490 + 478i, -520 + 519i twice and its pads' real modes near -199 /s: the
    // pads' lag changes those heavily damped modes altogether), and the iteration from them
    // lands on the bounce pair or leaves the real axis' candidates. Those three are named
    // (coefficients.unsettled) and keep their synchronous eigenvalues: none is reported at
    // another mode's eigenvalue (docs/whirl-dependent-bearings.md).
    const PadModels p;
    const double speed = p.speed;
    const RotorModesResult rc = solveRotorModes(p.condensed, speed, rotorOptions(8));
    // Twelve of the full model's: its heavily damped modes and the pads' lie among the eight
    // nearest 0 as well.
    const RotorModesResult rf = solveRotorModes(p.full, speed, rotorOptions(12));
    std::vector<RotorMode> everyFull = rf.modes;  // the rotor's modes and the pads'
    everyFull.insert(everyFull.end(), rf.bearingModes.begin(), rf.bearingModes.end());
    const RotorModesResult sync = solveRotorModes(p.synchronous, speed, rotorOptions(8));
    REQUIRE(rc.modes.size() == 8);
    REQUIRE(sync.modes.size() == 8);
    CHECK(rc.coefficients.unsettled.size() == 3);
    int found = 0, named = 0;
    for (std::size_t i = 0; i < rc.modes.size(); ++i) {
      const std::complex<double> lambda = rc.modes[i].eigenvalue;
      CAPTURE(lambda);
      if (std::abs(lambda - sync.modes[i].eigenvalue) <= 1e-12 * std::abs(lambda)) {
        // Named: the synchronous eigenvalue, at least 30 % of |lambda| from any of the full
        // model's (measured: 68 % and 72 %), so the name is deserved.
        ++named;
        CHECK(nearestTo(lambda, everyFull) > 0.3 * std::abs(lambda));
        CHECK(rc.modes[i].whirlIterations >= 1);
      } else {
        // Found: as in the bounce pair's case above, 1e-8 keeps a margin over the iteration's
        // 1e-10.
        ++found;
        CHECK(nearestTo(lambda, everyFull) <= 1e-8 * std::abs(lambda));
      }
    }
    CHECK(found == 5);
    CHECK(named == 3);
  }
}
