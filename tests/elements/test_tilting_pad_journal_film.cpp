// The tilting-pad bearing's nonlinear film (elements/TiltingPadJournalFilm.hpp) against the
// bearing's own equilibrium and coefficients (elements/TiltingPadBearing.hpp: a second Newton
// on the same pads, and the condensation of each pad's film coefficients), against central
// differences of its own force away from equilibrium, and its drag against the pads' shear
// torques summed in closed form.
#include <doctest/doctest.h>

#include <ctime>
#include <cmath>
#include <numbers>

#include "elements/TiltingPadJournalFilm.hpp"
#include "elements/TurnedBearing.hpp"
#include "tests/elements/TiltingPadTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

constexpr double kPiPadTest = std::numbers::pi;
const ReynoldsGrid kPadGrid{24, 8};

Eigen::Vector2d along(double angle) { return {std::cos(angle), std::sin(angle)}; }

/// The journal's place at `point` in global axes (the bearing's turned by `loadAngle`).
Eigen::Vector2d journalAt(const TiltingPadPoint& point, double clearance, double loadAngle) {
  return point.eccentricity * clearance * along(point.attitude + kPiPadTest + loadAngle);
}

Eigen::Matrix2d matrixOf(const BearingCoefficients& k, bool damping) {
  Eigen::Matrix2d m;
  if (damping)
    m << k.cyy, k.cyz, k.czy, k.czz;
  else
    m << k.kyy, k.kyz, k.kzy, k.kzz;
  return m;
}

/// int dphi / (1 - a cos(phi) - s sin(phi)) from phi1 to phi2 in closed form: with
/// a cos + s sin = eps cos(phi - psi), psi = atan(s / a) in (-pi/2, pi/2) (eps signed), the
/// antiderivative of 1 / (1 - eps cos x) is 2 / sqrt(1 - eps^2) atan(sqrt((1 + eps) / (1 - eps))
/// tan(x / 2)) on (-pi, pi), where x = phi - psi stays for a pad's arc.
double couetteClosedForm(double a, double s, double phi1, double phi2) {
  const double psi = a != 0 ? std::atan(s / a) : std::copysign(kPiPadTest / 2, s);
  const double eps = a != 0 ? a / std::cos(psi) : s;
  const double r = std::sqrt((1 + eps) / (1 - eps)), k = 2 / std::sqrt(1 - eps * eps);
  auto F = [&](double x) { return k * std::atan(r * std::tan(x / 2)); };
  return F(phi2 - psi) - F(phi1 - psi);
}

}  // namespace

TEST_SUITE("tilting-pad journal film") {
  TEST_CASE("at the bearing's equilibrium the film carries the load with the static stiffness") {
    const PlainJournal b = tiltingPadTestJournal();
    for (bool onPad : {false, true}) {
      TiltingPads pads = fourPadsBetween();
      pads.loadOnPad = onPad;
      for (double rpm : {3000.0, 8000.0}) {
        for (double loadAngle : {0.0, 0.6}) {
          CAPTURE(onPad);
          CAPTURE(rpm);
          CAPTURE(loadAngle);
          const double speed = rpm * kPiPadTest / 30;
          const TiltingPadJournalFilm film(b, pads, kPadGrid, loadAngle);
          const TiltingPadPoint p = tiltingPadPoint(b, pads, speed, kPadGrid);
          const Eigen::Vector2d load = -b.load * along(loadAngle);
          // The film's own Newton and the bearing's: both to 1e-11 W or better, so the journal's
          // places differ by that over the stiffness (some 1e8 N/m here: 1e-15 m = 1e-11 c).
          const Eigen::Vector2d x0 = film.equilibrium(load, speed);
          const Eigen::Vector2d xb = journalAt(p, b.clearance, loadAngle);
          const double placeError = (x0 - xb).norm() / b.clearance;
          // At the bearing's own equilibrium (not the film's) the film carries the load to the
          // bearing's Newton tolerance, 1e-11 W.
          const FilmForce f = film.at(xb, Eigen::Vector2d::Zero(), speed);
          const double balance = (f.force + load).norm() / b.load;
          // Stiffness: each pad's film condensed on its tilt root, by the implicit-function
          // theorem here and by Z' at whirl 0 there: the same film at the same place, round-off.
          const Eigen::Matrix2d ks =
              matrixOf(turnedCoefficients(tiltingPadStaticStiffness(p), loadAngle), false);
          const double kError = (f.stiffness - ks).norm() / ks.norm();
          // Damping: each pad's D_ee - K_et D_te / K_tt along e_k e_k^T from the bearing's own
          // pad coefficients (an independent sum).
          Eigen::Matrix2d cf = Eigen::Matrix2d::Zero();
          for (const PadFilmState& pad : p.pads) {
            if (pad.stiffness[1][1] == 0) continue;
            const double c = pad.damping[0][0] -
                             pad.stiffness[0][1] * pad.damping[1][0] / pad.stiffness[1][1];
            const Eigen::Vector2d e = along(pad.pivot + loadAngle);
            cf += p.dampingScale * c * e * e.transpose();
          }
          const double cError = (f.damping - cf).norm() / cf.norm();
          // For the record: how far the pads' following damping and the static stiffness lie
          // from the synchronous set (the pads' lag at whirl = spin, which the condensed film
          // leaves out).
          const BearingCoefficients sync = turnedCoefficients(p.synchronous, loadAngle);
          const double kSync = (ks - matrixOf(sync, false)).norm() / matrixOf(sync, false).norm();
          const double cSync = (cf - matrixOf(sync, true)).norm() / matrixOf(sync, true).norm();
          MESSAGE("on pad " << onPad << ", rpm " << rpm << ", angle " << loadAngle << ": eps "
                            << p.eccentricity << ", place " << placeError << " c, balance "
                            << balance << " W, K " << kError << ", C " << cError
                            << "; from the synchronous set: K " << kSync << ", C " << cSync);
          CHECK(placeError < 1e-9);
          CHECK(balance < 2e-11);
          CHECK(kError < 1e-9);
          CHECK(cError < 1e-9);
          CHECK(x0.norm() / b.clearance == doctest::Approx(p.eccentricity).epsilon(1e-9));
        }
      }
    }
  }

  TEST_CASE("away from equilibrium the film's derivatives are its force's own") {
    const PlainJournal b = tiltingPadTestJournal();
    const TiltingPadJournalFilm film(b, fourPadsBetween(), kPadGrid, 0.3);
    const double speed = 500, c = b.clearance;
    const Eigen::Vector2d x = film.equilibrium(-b.load * along(0.3), speed) +
                              c * Eigen::Vector2d(0.08, -0.05);
    const Eigen::Vector2d v = c * speed * Eigen::Vector2d(0.03, -0.02);
    const FilmForce f = film.at(x, v, speed);
    // Central differences at h = 1e-5 c: their truncation error is h^2 / 6 of the third
    // derivative (some 1e-10 of K here); the discrete film's force has kinks where its cavity's
    // edge crosses a node, which a difference across one would show as an O(1) jump in a
    // column. Measured below 1e-7 of the largest entry.
    const double h = 1e-5 * c, hv = 1e-5 * c * speed;
    Eigen::Matrix2d K, C;
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d dx = Eigen::Vector2d::Zero(), dv = Eigen::Vector2d::Zero();
      dx[j] = h;
      dv[j] = hv;
      K.col(j) = -(film.at(x + dx, v, speed).force - film.at(x - dx, v, speed).force) / (2 * h);
      C.col(j) = -(film.at(x, v + dv, speed).force - film.at(x, v - dv, speed).force) / (2 * hv);
    }
    const double kError = (K - f.stiffness).cwiseAbs().maxCoeff() / f.stiffness.cwiseAbs().maxCoeff();
    const double cError = (C - f.damping).cwiseAbs().maxCoeff() / f.damping.cwiseAbs().maxCoeff();
    MESSAGE("central differences: K " << kError << ", C " << cError << " (K "
                                      << f.stiffness.cwiseAbs().maxCoeff() << " N/m)");
    CHECK(kError < 1e-6);
    CHECK(cError < 1e-6);
    // Cost of a call as a Newton iteration of a run-up makes it (the journal moved a little, the
    // pads' roots started from the last ones): reported, not asserted.
    const int calls = 200;
    const std::clock_t start = std::clock();
    for (int i = 0; i < calls; ++i) film.at(x + 1e-4 * c * along(0.1 * i), v, speed);
    const double each = double(std::clock() - start) / CLOCKS_PER_SEC / calls;
    MESSAGE("a call on four 24 x 8 pads: " << each * 1e6 << " us of CPU");
  }

  TEST_CASE("the pads' drag is the sum of their shear torques") {
    const PlainJournal b = tiltingPadTestJournal();
    const TiltingPads pads = fourPadsBetween();
    const double R = b.diameter / 2, cp = b.clearance / (1 - pads.preload);
    for (double rpm : {3000.0, 8000.0}) {
      const double speed = rpm * kPiPadTest / 30;
      const TiltingPadJournalFilm film(b, pads, kPadGrid, 0.0);
      const TiltingPadPoint p = tiltingPadPoint(b, pads, speed, kPadGrid);
      const Eigen::Vector2d x = journalAt(p, b.clearance, 0);
      const FilmForce f = film.at(x, Eigen::Vector2d::Zero(), speed);
      // Each pad from the bearing's equilibrium: rho and s from the journal's place and the
      // pad's tilt, Couette's shear over the arc in closed form, the pressure flow's half the
      // moment of the pad's force about its centre of curvature, c_p (m + rho, s) x (F, 0).
      double expected = 0, couette = 0;
      for (const PadFilmState& pad : p.pads) {
        const Eigen::Vector2d u = x / cp;
        const double rho = u.dot(along(pad.pivot));
        const double s = pad.force != 0
                             ? u.dot(along(pad.pivot + kPiPadTest / 2)) - pad.tilt * R / cp
                             : 0.0;
        const double half = pads.arc / 2;
        const double shear = b.viscosity * speed * R * R * R * b.length / cp *
                             couetteClosedForm(pads.preload + rho, s, -half, half);
        couette += shear;
        expected += shear - cp * s * pad.force / 2;
      }
      const double drag = film.dragTorque(x, f.force, speed);
      const double couetteOnly = film.dragTorque(x, Eigen::Vector2d::Zero(), speed);
      // The same pads at the same place: the tilts agree to the roots' tolerance (1e-13 of
      // their bracket), the Gauss rule is at round-off on an analytic integrand.
      MESSAGE("rpm " << rpm << ": drag " << drag << " N m (Couette " << couetteOnly
                     << "), expected " << expected << " (" << couette << ")");
      CHECK(drag == doctest::Approx(expected).epsilon(1e-10));
      CHECK(couetteOnly == doctest::Approx(couette).epsilon(1e-12));
      // The power the drag takes, T Omega, exceeds Petroff's of the pads' arcs at the
      // concentric film (a sanity bound: the film is thinner than c_p somewhere on each pad).
      CHECK(drag > 0);
    }
  }

  TEST_CASE("a pad the journal leaves carries nothing, without NaN") {
    PlainJournal b = tiltingPadTestJournal();
    TiltingPads one = fourPadsBetween();
    one.count = 1;
    const TiltingPadJournalFilm film(b, one, kPadGrid, 0.0);
    const double speed = 400, c = b.clearance;
    const double pivot = kPiPadTest + kPiPadTest;  // load between pads: pi + pi / 1
    // Journal moved away from the pad's pivot past the preload (m + rho < 0).
    const FilmForce away = film.at(-0.5 * c * along(pivot), Eigen::Vector2d::Zero(), speed);
    CHECK(away.force.norm() == 0);
    CHECK(away.stiffness.norm() == 0);
    // Moving away fast from a loaded place: the squeeze opens the film.
    const FilmForce receding =
        film.at(0.2 * c * along(pivot), -5.0 * c * speed * along(pivot), speed);
    CHECK(std::isfinite(receding.force.norm()));
    CHECK(std::isfinite(receding.stiffness.norm() + receding.damping.norm()));
    // Past the pad's pivot (m + rho > 1): a JournalLeftClearance, never a NaN.
    CHECK_THROWS_AS(film.at(1.01 * c * along(pivot), Eigen::Vector2d::Zero(), speed),
                    JournalLeftClearance);
  }
}
