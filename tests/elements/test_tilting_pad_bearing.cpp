// The tilting-pad journal bearing (elements/TiltingPadBearing) against independent references:
//  1. Michell's pivoted slider: a long pad of small arc is an inclined plane slider, whose film
//     ratio K = h_in / h_out puts the centre of pressure on the pivot and whose load follows
//     in closed form (Michell 1905; Hamrock, Schmid and Jacobson, Fundamentals of Fluid Film
//     Lubrication, 2004, ch. 8: with the sliding length B, the outlet film h_o and the surface
//     speed U, W / L = 6 mu U B^2 (ln(1 + K) - 2 K / (2 + K)) / (h_o^2 K^2), the centre of
//     pressure x_cp / B = (5 K^2 + 6 K - (2 K^2 + 8 K + 6) ln(1 + K)) /
//     (2 K (2 K - (K + 2) ln(1 + K))) from the inlet);
//  2. the static stiffness as the Jacobian of the load (a second method: the equilibrium solved
//     at two loads and differenced);
//  3. the geometry of four pads with the load between two: K and C isotropic (the loaded
//     pads at +-45 deg from the load line give e e^T sums of diag(1/2, 1/2), as do the two
//     unloaded ones);
//  4. the condensation at whirl -> 0 is the static stiffness, and one pad alone condenses to
//     a scalar along its pivot line (a pad cannot carry a force across it).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "elements/TiltingPadBearing.hpp"
#include "tests/elements/TiltingPadTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

constexpr double kPiPad = std::numbers::pi;

/// Michell's centre of pressure (from the inlet, over the length) at film ratio K.
double sliderCentreOfPressure(double K) {
  const double l = std::log(1 + K);
  return (5 * K * K + 6 * K - (2 * K * K + 8 * K + 6) * l) / (2 * K * (2 * K - (K + 2) * l));
}

/// Michell's load over 6 mu U B^2 L / h_o^2.
double sliderLoad(double K) {
  return (std::log(1 + K) - 2 * K / (2 + K)) / (K * K);
}

}  // namespace

TEST_CASE("a long tilting pad of small arc is Michell's pivoted slider") {
  // Pad axes: H = 1 - s sin(phi) with no preload and the journal at rho = 0 (a plane slider to
  // O(beta^2)); infinite L/D (each axial station on its own). The pressure then is the
  // slider's on every axial station but the end one, held at 0: the nodes carry the film over
  // 1 - 1 / (2 m) of the half length (m axial cells).
  const int axial = 4;
  for (double pivot : {0.55, 0.6, 0.65}) {
    CAPTURE(pivot);
    double previous = 0;
    for (double degrees : {8.0, 4.0}) {
      TiltingPads pad;
      pad.count = 1;
      pad.arc = degrees * kPiPad / 180;
      pad.pivotOffset = pivot;
      const PadEquilibrium e =
          padEquilibrium(pad, std::numeric_limits<double>::infinity(), {400, axial}, 0.0);
      REQUIRE(e.loaded);
      const double b = pad.arc;
      const double hIn = 1 + e.s * std::sin(pivot * b), hOut = 1 - e.s * std::sin((1 - pivot) * b);
      const double K = hIn / hOut - 1;
      // The pivot on Michell's centre of pressure. The pad's curvature (sin phi for phi) and
      // the moment about the pivot through the curved film differ from the slider by O(beta^2)
      // (measured on 400 cells: 1.7e-5 to 3.7e-5 at 8 deg, 3e-6 to 5e-6 at 4 deg, 2e-7 to 5e-6
      // at 2 deg where the grid's own error takes over): 5e-5 and 1e-5.
      CHECK(std::abs(sliderCentreOfPressure(K) - pivot) < (degrees > 5 ? 5e-5 : 1e-5));
      // Its load: P = p c^2 / (mu Omega R^2) is 6 beta p_slider / H_o^2 over the arc's
      // fraction, so |Fbar| = 6 beta^2 W_slider / H_o^2 (1 - 1 / (2 m)).
      const double closed = 6 * b * b * sliderLoad(K) / (hOut * hOut) * (1 - 0.5 / axial);
      const double error = std::abs(-e.film.force[0] / closed - 1);
      // O(beta^2) again (measured: 2.3e-4 to 7.3e-4 at 8 deg, 6e-5 to 2.1e-4 at 4 deg).
      CHECK(error < (degrees > 5 ? 1e-3 : 3e-4));
      CHECK(std::abs(e.film.force[1]) < 1e-12 * std::abs(e.film.force[0]));  // through the pivot
      if (previous > 0) CHECK(error < previous / 2.5);  // the error falls with the arc
      previous = error;
    }
  }
}

TEST_CASE("a tilting-pad bearing's static stiffness is the derivative of its load") {
  // The journal's equilibrium at W (1 -+ 1e-3); with the load between two pads it moves along
  // the load line (attitude 0), so dW / d(e c) is the static kxx. Central differences: error
  // O(1e-6) relative; the Newton solves balance the load to 1e-11.
  const PlainJournal j = tiltingPadTestJournal();
  const TiltingPads pads = fourPadsBetween();
  const double speed = 3000 * kPiPad / 30, h = 1e-3;
  const ReynoldsGrid grid{24, 8};
  const TiltingPadPoint at = tiltingPadPoint(j, pads, speed, grid);
  CHECK(std::abs(at.attitude) < 1e-9);
  PlainJournal lighter = j, heavier = j;
  lighter.load *= 1 - h;
  heavier.load *= 1 + h;
  const double e1 = tiltingPadPoint(lighter, pads, speed, grid).eccentricity;
  const double e2 = tiltingPadPoint(heavier, pads, speed, grid).eccentricity;
  const double differenced = 2 * h * j.load / ((e2 - e1) * j.clearance);
  const BearingCoefficients k = tiltingPadStaticStiffness(at);
  CHECK(k.kyy == doctest::Approx(differenced).epsilon(1e-5));
  // The condensation at whirl -> 0 tends to the static stiffness (linearly in the whirl).
  const BearingCoefficients slow = tiltingPadCoefficients(at, 1e-6);
  CHECK(slow.kyy == doctest::Approx(k.kyy).epsilon(1e-8));
  CHECK(slow.kzz == doctest::Approx(k.kzz).epsilon(1e-8));
}

TEST_CASE("four pads with the load between two: isotropic coefficients") {
  const TiltingPadPoint at =
      tiltingPadPoint(tiltingPadTestJournal(), fourPadsBetween(), 3000 * kPiPad / 30, {24, 8});
  for (double whirl : {0.5, 1.0, 2.0}) {
    CAPTURE(whirl);
    const BearingCoefficients k = tiltingPadCoefficients(at, whirl);
    // Exact in the geometry; the pads' own films agree to the equilibrium's 1e-11.
    CHECK(k.kzz == doctest::Approx(k.kyy).epsilon(1e-9));
    CHECK(k.czz == doctest::Approx(k.cyy).epsilon(1e-9));
    CHECK(std::abs(k.kyz) < 1e-9 * k.kyy);
    CHECK(std::abs(k.kzy) < 1e-9 * k.kyy);
    CHECK(std::abs(k.cyz) < 1e-9 * k.cyy);
    CHECK(std::abs(k.czy) < 1e-9 * k.cyy);
  }
  // The synchronous set is the condensation at whirl = spin.
  const BearingCoefficients one = tiltingPadCoefficients(at, 1);
  CHECK(at.synchronous.kyy == one.kyy);
  CHECK(at.synchronous.cyy == one.cyy);
  // The loaded pads (pivots at 225 and 135 deg) see the journal at the same depth, so they
  // carry equal forces at the same film shape; their tilts differ by the journal's motion
  // across their pivot lines, e (t_135 - t_225) . (-1, 0) / R = sqrt(2) e / R.
  REQUIRE(at.pads.size() == 4);
  const PlainJournal j = tiltingPadTestJournal();
  CHECK(at.pads[0].force == doctest::Approx(at.pads[3].force).epsilon(1e-9));
  CHECK(at.pads[3].tilt - at.pads[0].tilt ==
        doctest::Approx(std::sqrt(2.0) * at.eccentricity * j.clearance / (j.diameter / 2))
            .epsilon(1e-9));
}

TEST_CASE("one pad condenses to a stiffness along its pivot line") {
  // A single pad under the load (load on pad): the pad turns any force across its pivot line
  // away, so the condensed impedance is (e e^T) z: kxy = kyx = kyy = 0 in the bearing's axes.
  TiltingPads pad = fourPadsBetween();
  pad.count = 1;
  pad.loadOnPad = true;
  const TiltingPadPoint at = tiltingPadPoint(tiltingPadTestJournal(), pad, 3000 * kPiPad / 30, {24, 8});
  const BearingCoefficients k = at.synchronous;
  CHECK(k.kyy > 0);
  CHECK(k.cyy > 0);
  CHECK(std::abs(k.kyz) < 1e-12 * k.kyy);
  CHECK(std::abs(k.kzy) < 1e-12 * k.kyy);
  CHECK(std::abs(k.kzz) < 1e-12 * k.kyy);
  CHECK(std::abs(k.czz) < 1e-12 * k.cyy);
  CHECK(std::abs(at.attitude) < 1e-12);
}

TEST_CASE("a tilting-pad equilibrium started from a nearby speed's is the one from the centre") {
  // Newton stops within 1e-11 of the load from either start; the journal and coefficients
  // then agree to about that (1e-10 keeps a margin).
  const ReynoldsGrid grid{24, 8};
  const double speed = 3000 * kPiPad / 30;
  const TiltingPadPoint cold =
      tiltingPadPoint(tiltingPadTestJournal(), fourPadsBetween(), speed, grid);
  const TiltingPadPoint before =
      tiltingPadPoint(tiltingPadTestJournal(), fourPadsBetween(), 0.8 * speed, grid);
  const TiltingPadPoint warm =
      tiltingPadPoint(tiltingPadTestJournal(), fourPadsBetween(), speed, grid, &before);
  CHECK(warm.eccentricity == doctest::Approx(cold.eccentricity).epsilon(1e-10));
  CHECK(warm.synchronous.kyy == doctest::Approx(cold.synchronous.kyy).epsilon(1e-10));
  CHECK(warm.synchronous.czz == doctest::Approx(cold.synchronous.czz).epsilon(1e-10));
  CHECK(before.eccentricity > 1.01 * cold.eccentricity);  // a start that is not the answer
}

TEST_CASE("pads taken as left during a warm-started Newton are the ones the search leaves") {
  // Newton skips the tilt search of a pad already found left at a rho no nearer its pivot,
  // and searches it again at the converged journal. Against the cold start (every pad searched
  // at every step): the same equilibrium to Newton's 1e-11 of the load (1e-10 keeps a margin),
  // each pad's force included; each pad left at the end is left by padEquilibrium on its own
  // (the direct search at its rho), and the others carry a film. From 2000 to 3000 rpm the two
  // upper pads stay left; at 10000 rpm they carry some 470 N each (the journal nearer the
  // centre), so from 3000 rpm they load again, and from 10000 rpm they are left again at 3000.
  // (Below some 500 rpm the upper pads find roots carrying 1e-16 N, round-off of a film
  // with no pressure: no case here.)
  const ReynoldsGrid grid{24, 8};
  const PlainJournal journal = tiltingPadTestJournal();
  const TiltingPads pads = fourPadsBetween();
  const double cp = journal.clearance / (1 - pads.preload);
  struct Case {
    double fromRpm, rpm;
    int leftBefore, left;
  };
  for (const Case c : {Case{2000, 3000, 2, 2}, Case{3000, 10000, 2, 0}, Case{10000, 3000, 0, 2}}) {
    CAPTURE(c.rpm);
    const TiltingPadPoint before = tiltingPadPoint(journal, pads, c.fromRpm * kPiPad / 30, grid);
    const TiltingPadPoint cold = tiltingPadPoint(journal, pads, c.rpm * kPiPad / 30, grid);
    const TiltingPadPoint warm =
        tiltingPadPoint(journal, pads, c.rpm * kPiPad / 30, grid, &before);
    CHECK(warm.eccentricity == doctest::Approx(cold.eccentricity).epsilon(1e-10));
    CHECK(warm.attitude == doctest::Approx(cold.attitude).epsilon(1e-10));
    CHECK(warm.synchronous.kyy == doctest::Approx(cold.synchronous.kyy).epsilon(1e-10));
    CHECK(warm.synchronous.czz == doctest::Approx(cold.synchronous.czz).epsilon(1e-10));
    int leftBefore = 0, left = 0;
    for (const PadFilmState& p : before.pads) leftBefore += p.force == 0;
    const double towards = warm.attitude + kPiPad;  // the journal's centre, from the load line
    const double u = warm.eccentricity * journal.clearance / cp;
    for (std::size_t k = 0; k < warm.pads.size(); ++k) {
      const PadFilmState& p = warm.pads[k];
      CHECK(p.force == doctest::Approx(cold.pads[k].force).epsilon(1e-10));
      const double rho = u * std::cos(towards - p.pivot);
      CHECK(padEquilibrium(pads, journal.length / journal.diameter, grid, rho).loaded ==
            (p.force != 0));
      left += p.force == 0;
    }
    CHECK(leftBefore == c.leftBefore);
    CHECK(left == c.left);
  }
}
