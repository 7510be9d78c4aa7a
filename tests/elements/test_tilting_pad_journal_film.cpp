// The tilting-pad bearing's nonlinear film with each pad's tilt a dof
// (elements/TiltingPadJournalFilm.hpp) against the bearing's own equilibrium and coefficients
// (elements/TiltingPadBearing.hpp: a second Newton on the same pads; elements/TiltingPadFilm.hpp:
// each pad's film coefficients placed on journal and tilt; the synchronous set by Lund's
// condensation), against central differences of its own forces away from equilibrium, and its
// drag against the pads' shear torques summed in closed form.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <ctime>
#include <memory>
#include <numbers>
#include <vector>

#include "elements/TiltingPadFilm.hpp"
#include "elements/TiltingPadJournalFilm.hpp"
#include "elements/TurnedBearing.hpp"
#include "tests/elements/TiltingPadTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

constexpr double kPiPadTest = std::numbers::pi;
const ReynoldsGrid kPadGrid{24, 8};

Eigen::Vector2d along(double angle) { return {std::cos(angle), std::sin(angle)}; }

Eigen::Matrix2d matrixOf(const BearingCoefficients& k, bool damping) {
  Eigen::Matrix2d m;
  if (damping)
    m << k.cyy, k.cyz, k.czy, k.czz;
  else
    m << k.kyy, k.kyz, k.kzy, k.kzz;
  return m;
}

/// TiltingPadFilm's K or C blocks of every pad at `point` (one table speed), assembled over
/// (y, z, delta_1 .. delta_n): journal node 0, pad k's tilt the rx of node k + 1.
Eigen::MatrixXd padFilmBlocks(const TiltingPadPoint& point, double loadAngle, bool damping) {
  const auto points = std::make_shared<const std::vector<TiltingPadPoint>>(1, point);
  const int n = int(point.pads.size());
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n + 2, n + 2);
  for (int k = 0; k < n; ++k) {
    const TiltingPadFilm pad(0, k + 1, points, k, loadAngle, 0);
    const ElementMatrix m = damping ? pad.dampingAt(point.speed) : pad.stiffnessAt(point.speed);
    const int at[3] = {0, 1, k + 2};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) out(at[r], at[c]) += m(r, c);
  }
  return out;
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
  TEST_CASE("at the bearing's equilibrium: the load carried, no moment, the pads' K and C") {
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
          const Eigen::VectorXd x = film.restState(load, speed);
          REQUIRE(x.size() == 6);
          const FilmLoad f = film.loadAt(x, Eigen::VectorXd::Zero(6), speed);
          // The bearing's Newton carries the load to 1e-11 W; its tilt roots put each pad's
          // moment at 1e-13 of the tilt's bracket times the pad's tilt stiffness, measured
          // against W R (the moment a load W at the journal's radius would put).
          const double balance = (f.force.head<2>() + load).norm() / b.load;
          const double R = b.diameter / 2;
          const double moment = f.force.tail<4>().cwiseAbs().maxCoeff() / (b.load * R);
          // The film's derivatives and TiltingPadFilm's blocks: the same pad films at the same
          // places (the tilts through the rest state's rad and back: round-off).
          // A pad the journal has left (the upper two, load between pads at 3000 rpm) holds
          // nothing in either but the film's placeholder damping on its idle tilt.
          const Eigen::MatrixXd K = padFilmBlocks(p, loadAngle, false);
          Eigen::MatrixXd C = padFilmBlocks(p, loadAngle, true);
          for (std::size_t k = 0; k < p.pads.size(); ++k)
            if (p.pads[k].force == 0) {
              const Eigen::Index t = Eigen::Index(k) + 2;
              CHECK(f.damping(t, t) == doctest::Approx(1e-6 * p.dampingScale * R * R).epsilon(1e-14));
              C(t, t) = f.damping(t, t);
            }
          const double kError = (f.stiffness - K).norm() / K.norm();
          const double cError = (f.damping - C).norm() / C.norm();
          // Lund's condensation of the film's blocks at whirl = spin, the pads massless:
          // Z' = Z_jj - Z_jp Z_pp^-1 Z_pj, Z = K + i Omega C: the synchronous set.
          const Eigen::MatrixXcd Z = f.stiffness.cast<std::complex<double>>() +
                                     std::complex<double>(0, speed) *
                                         f.damping.cast<std::complex<double>>();
          const Eigen::Matrix2cd condensed =
              Z.topLeftCorner(2, 2) -
              Z.topRightCorner(2, 4) * Z.bottomRightCorner(4, 4).lu().solve(Z.bottomLeftCorner(4, 2));
          const BearingCoefficients sync = turnedCoefficients(p.synchronous, loadAngle);
          const Eigen::Matrix2d ks = matrixOf(sync, false), cs = matrixOf(sync, true);
          const double kSync = (condensed.real() - ks).norm() / ks.norm();
          const double cSync = (condensed.imag() / speed - cs).norm() / cs.norm();
          MESSAGE("on pad " << onPad << ", rpm " << rpm << ", angle " << loadAngle << ": eps "
                            << p.eccentricity << ", balance " << balance << " W, moment "
                            << moment << " W R, K " << kError << ", C " << cError
                            << "; condensed against the synchronous set: K " << kSync << ", C "
                            << cSync);
          // Measured: balance 7.8e-12, moment 8.0e-15, K 6.8e-15, C 4.0e-15, condensed K 9.9e-15
          // and C 7.1e-15: the derivatives and the condensation at round-off (1e-13 allowed).
          CHECK(balance < 2e-11);
          CHECK(moment < 1e-12);
          CHECK(kError < 1e-13);
          CHECK(cError < 1e-13);
          CHECK(kSync < 1e-13);
          CHECK(cSync < 1e-13);
          CHECK(x.head<2>().norm() / b.clearance == doctest::Approx(p.eccentricity).epsilon(1e-12));
        }
      }
    }
  }

  TEST_CASE("away from equilibrium the film's derivatives are its forces' own") {
    const PlainJournal b = tiltingPadTestJournal();
    const TiltingPadJournalFilm film(b, fourPadsBetween(), kPadGrid, 0.3);
    const double speed = 500, c = b.clearance, R = b.diameter / 2;
    Eigen::VectorXd x = film.restState(-b.load * along(0.3), speed);
    Eigen::VectorXd v(6);
    x.head<2>() += c * Eigen::Vector2d(0.08, -0.05);
    x.tail<4>() += c / R * Eigen::Vector4d(0.03, -0.02, 0.05, 0.01);
    v << 0.03 * c * speed, -0.02 * c * speed, 0.02 * c / R * speed, -0.01 * c / R * speed,
        0.015 * c / R * speed, 0.0;
    const FilmLoad f = film.loadAt(x, v, speed);
    // Central differences at h = 1e-5 of each dof's scale (c, c / R; times Omega for rates):
    // their truncation error is h^2 / 6 of the third derivative (some 1e-10 of K here); the
    // discrete film's force has kinks where its cavity's edge crosses a node, which a difference
    // across one would show as an O(1) jump in a column. Measured below 1e-7 of the largest
    // entry.
    Eigen::MatrixXd K(6, 6), C(6, 6);
    for (int j = 0; j < 6; ++j) {
      const double scale = j < 2 ? c : c / R;
      Eigen::VectorXd dx = Eigen::VectorXd::Zero(6), dv = Eigen::VectorXd::Zero(6);
      dx[j] = 1e-5 * scale;
      dv[j] = 1e-5 * scale * speed;
      K.col(j) = -(film.loadAt(x + dx, v, speed).force - film.loadAt(x - dx, v, speed).force) /
                 (2 * dx[j]);
      C.col(j) = -(film.loadAt(x, v + dv, speed).force - film.loadAt(x, v - dv, speed).force) /
                 (2 * dv[j]);
    }
    // Each row and column in its own units: the entries weighed by the dofs' scales.
    Eigen::VectorXd w(6);
    w << 1, 1, R, R, R, R;
    const Eigen::MatrixXd scaleRows = w.cwiseInverse().asDiagonal();
    const auto relative = [&](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
      const Eigen::MatrixXd d = scaleRows * (a - b) * scaleRows, m = scaleRows * b * scaleRows;
      return d.cwiseAbs().maxCoeff() / m.cwiseAbs().maxCoeff();
    };
    const double kError = relative(K, f.stiffness), cError = relative(C, f.damping);
    MESSAGE("central differences: K " << kError << ", C " << cError);
    CHECK(kError < 1e-6);
    CHECK(cError < 1e-6);
    // Cost of a call as a Newton iteration of a run-up makes it (the state moved a little):
    // reported, not asserted.
    const int calls = 200;
    const std::clock_t start = std::clock();
    for (int i = 0; i < calls; ++i) {
      Eigen::VectorXd y = x;
      y.head<2>() += 1e-4 * c * along(0.1 * i);
      film.loadAt(y, v, speed);
    }
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
      const Eigen::VectorXd x = film.restState({-b.load, 0}, speed);
      const FilmLoad f = film.loadAt(x, Eigen::VectorXd::Zero(6), speed);
      // Each pad from the bearing's equilibrium: rho and s from the journal's place and the
      // pad's tilt, Couette's shear over the arc in closed form, the pressure flow's half the
      // moment of the pad's force about its centre of curvature, c_p (m + rho, s) x (F, 0).
      double expected = 0, couette = 0;
      for (std::size_t k = 0; k < p.pads.size(); ++k) {
        const PadFilmState& pad = p.pads[k];
        const Eigen::Vector2d u = x.head<2>() / cp;
        const double rho = u.dot(along(pad.pivot));
        const double s = u.dot(along(pad.pivot + kPiPadTest / 2)) - x[Eigen::Index(k) + 2] * R / cp;
        const double half = pads.arc / 2;
        const double shear = b.viscosity * speed * R * R * R * b.length / cp *
                             couetteClosedForm(pads.preload + rho, s, -half, half);
        couette += shear;
        expected += shear - cp * s * pad.force / 2;
      }
      const double drag = film.dragTorqueAt(x, f.force, speed);
      const double couetteOnly = film.dragTorqueAt(x, Eigen::VectorXd::Zero(6), speed);
      // The same pads at the same place: the pads' forces along t_k vanish to the roots'
      // tolerance, the Gauss rule is at round-off on an analytic integrand.
      MESSAGE("rpm " << rpm << ": drag " << drag << " N m (Couette " << couetteOnly
                     << "), expected " << expected << " (" << couette << ")");
      CHECK(drag == doctest::Approx(expected).epsilon(1e-10));
      CHECK(couetteOnly == doctest::Approx(couette).epsilon(1e-12));
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
    // The journal away from the pad's pivot past the preload (m + rho < 0), the pad where its
    // film stops converging (restState's unloaded tilt: the load 0 there, the journal centred,
    // then moved): nothing, and the idle pad's placeholder damping on its tilt alone.
    Eigen::VectorXd x(3);
    const double trailing = (1 - one.pivotOffset) * one.arc, cp = c / (1 - one.preload);
    const double a = one.preload - 0.5 * c / cp;
    x << -0.5 * c * along(pivot), -a * std::tan(trailing) * cp / (b.diameter / 2);
    const FilmLoad away = film.loadAt(x, Eigen::VectorXd::Zero(3), speed);
    CHECK(away.force.norm() == 0);
    CHECK(away.stiffness.norm() == 0);
    CHECK(away.damping(2, 2) > 0);
    CHECK(away.damping.norm() == away.damping(2, 2));
    // Moving away fast from a loaded place: the squeeze opens the film.
    Eigen::VectorXd y = Eigen::VectorXd::Zero(3), v = Eigen::VectorXd::Zero(3);
    y.head<2>() = 0.2 * c * along(pivot);
    v.head<2>() = -5.0 * c * speed * along(pivot);
    const FilmLoad receding = film.loadAt(y, v, speed);
    CHECK(std::isfinite(receding.force.norm()));
    CHECK(std::isfinite(receding.stiffness.norm() + receding.damping.norm()));
    // Past the pad's pivot (m + rho > 1): a JournalLeftClearance, never a NaN.
    y.head<2>() = 1.01 * c * along(pivot);
    CHECK_THROWS_AS(film.loadAt(y, Eigen::VectorXd::Zero(3), speed), JournalLeftClearance);
  }
}
