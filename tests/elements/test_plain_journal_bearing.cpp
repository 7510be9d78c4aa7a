// The short (Ocvirk) plain journal bearing against its own definition: the film force is
// computed here from the short-bearing pressure field by quadrature, independently of the
// closed forms in elements/PlainJournalBearing.cpp; the coefficients are that force's
// derivatives by central differences.
//
// With the pressure only along the axis, Reynolds' equation d/dz(h^3 dp/dz) = 6 mu (Omega
// dh/dtheta + 2 dh/dt) with p = 0 at z = +-L/2 gives p = 3 mu g (z^2 - L^2/4) / h^3,
// g = Omega dh/dtheta + 2 dh/dt, so the pressure integrated over the length is
// -mu L^3 g / (2 h^3), positive (a film in tension carries nothing) where g < 0. For a journal
// at (y, z) moving at (y', z'), h = c - y cos(theta) - z sin(theta), theta from +y towards +z
// (the sense of rotation), and the film pushes the journal by
//   F = (mu L^3 R / 2) int_{g < 0} g / h^3 (cos theta, sin theta) d theta.
// g = a sin(theta) + b cos(theta) is negative on exactly half a turn, found in closed form, so
// the quadrature sees a smooth integrand (composite Simpson).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "elements/PlainJournalBearing.hpp"

using namespace beamrotor;

namespace {

constexpr double kPiJournal = std::numbers::pi;

/// The short-bearing film force on the journal (N) at position (y, z) and velocity (vy, vz).
std::array<double, 2> filmForce(const PlainJournal& b, double speed, double y, double z,
                                double vy, double vz) {
  const double R = b.diameter / 2, L = b.length, c = b.clearance;
  // g(theta) = speed (y sin - z cos) - 2 (vy cos + vz sin) = A sin(theta + beta)
  const double gs = speed * y - 2 * vz, gc = -speed * z - 2 * vy;
  const double beta = std::atan2(gc, gs);
  const double from = kPiJournal - beta;  // g < 0 on (pi - beta, 2 pi - beta)
  const int n = 20000;                    // Simpson intervals (even)
  const double h = kPiJournal / n;
  double fy = 0, fz = 0;
  for (int i = 0; i <= n; ++i) {
    const double t = from + i * h;
    const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    const double gap = c - y * std::cos(t) - z * std::sin(t);
    const double g = gs * std::sin(t) + gc * std::cos(t);
    const double q = w * g / (gap * gap * gap);
    fy += q * std::cos(t);
    fz += q * std::sin(t);
  }
  const double scale = b.viscosity * L * L * L * R / 2 * h / 3;
  return {scale * fy, scale * fz};
}

PlainJournal testBearing() {
  // A compressor-like bearing: D 100 mm, L 40 mm (L/D 0.4), c 75 um, ISO VG 32 at 50 C.
  return {0.1, 0.04, 75e-6, 0.018, 4000};
}

}  // namespace

TEST_SUITE("plain journal bearing") {
  TEST_CASE("the load the film carries at the computed eccentricity is the static load") {
    const PlainJournal b = testBearing();
    for (double rpm : {500.0, 2000.0, 6000.0, 15000.0, 60000.0}) {
      const double speed = rpm * kPiJournal / 30;
      const double eps = eccentricityRatio(b, speed);
      CAPTURE(rpm);
      CAPTURE(eps);
      REQUIRE(eps > 0);
      REQUIRE(eps < 1);
      // The journal centre sits a quarter-turn-ish behind -y: at angle pi + phi from +y.
      const double phi = attitudeAngle(eps);
      const double y = -eps * b.clearance * std::cos(phi), z = -eps * b.clearance * std::sin(phi);
      const auto f = filmForce(b, speed, y, z, 0, 0);
      // Simpson with 20000 intervals on a smooth integrand: the quadrature error is far below
      // 1e-8 even at eps 0.9, where 1/h^3 peaks at 1000 times its concentric value.
      CHECK(f[0] == doctest::Approx(b.load).epsilon(1e-8));
      CHECK(std::abs(f[1]) < 1e-8 * b.load);
    }
  }

  TEST_CASE("eccentricity from the Sommerfeld number: limits and monotony") {
    const PlainJournal b = testBearing();
    double last = 1;
    for (double rpm : {100.0, 1000.0, 10000.0, 100000.0}) {
      const double eps = eccentricityRatio(b, rpm * kPiJournal / 30);
      CHECK(eps < last);  // faster: the wedge lifts the journal towards the centre
      last = eps;
      // The root solves the closed form it inverts, to round-off.
      CHECK(shortBearingSommerfeld(eps) ==
            doctest::Approx(b.sommerfeld(rpm * kPiJournal / 30)).epsilon(1e-12));
    }
    // Light load: S_s = (1 / (pi eps)) (1 - 2.31 eps^2 + O(eps^4)) (series of the closed form),
    // so eps = 1 / (pi S_s) within 2.31 eps^2 = 4e-4 relative at this load (eps 0.012).
    PlainJournal light = b;
    light.load = 0.1;
    const double speed = 1000;
    const double s = light.sommerfeld(speed);
    CHECK(eccentricityRatio(light, speed) == doctest::Approx(1 / (kPiJournal * s)).epsilon(1e-3));
  }

  TEST_CASE("the eight coefficients are the film force's derivatives") {
    const PlainJournal b = testBearing();
    for (double rpm : {300.0, 1500.0, 3000.0, 8000.0, 30000.0}) {
      const double speed = rpm * kPiJournal / 30;
      const double eps = eccentricityRatio(b, speed);
      CAPTURE(rpm);
      CAPTURE(eps);
      const double phi = attitudeAngle(eps);
      const double y0 = -eps * b.clearance * std::cos(phi);
      const double z0 = -eps * b.clearance * std::sin(phi);
      // Steps of 1e-5 c (and 1e-5 c Omega): central differences err by ~(1e-5)^2 relative;
      // round-off adds ~1e-16 / 1e-5 = 1e-11. Compared to 1e-6 of the coefficient scale W/c.
      const double d = 1e-5 * b.clearance, v = d * speed;
      auto diff = [&](double dy, double dz, double dvy, double dvz) {
        const auto p = filmForce(b, speed, y0 + dy, z0 + dz, dvy, dvz);
        const auto m = filmForce(b, speed, y0 - dy, z0 - dz, -dvy, -dvz);
        return std::array<double, 2>{-(p[0] - m[0]) / 2, -(p[1] - m[1]) / 2};
      };
      const auto ky = diff(d, 0, 0, 0), kz = diff(0, d, 0, 0);
      const auto cy = diff(0, 0, v, 0), cz = diff(0, 0, 0, v);
      const BearingCoefficients k = shortBearingCoefficients(b, speed);
      const double ks = b.load / b.clearance, cs = ks / speed;
      const double tol = 1e-6;
      CHECK(k.kyy / ks == doctest::Approx(ky[0] / d / ks).epsilon(tol));
      CHECK(k.kzy / ks == doctest::Approx(ky[1] / d / ks).epsilon(tol));
      CHECK(k.kyz / ks == doctest::Approx(kz[0] / d / ks).epsilon(tol));
      CHECK(k.kzz / ks == doctest::Approx(kz[1] / d / ks).epsilon(tol));
      CHECK(k.cyy / cs == doctest::Approx(cy[0] / v / cs).epsilon(tol));
      CHECK(k.czy / cs == doctest::Approx(cy[1] / v / cs).epsilon(tol));
      CHECK(k.cyz / cs == doctest::Approx(cz[0] / v / cs).epsilon(tol));
      CHECK(k.czz / cs == doctest::Approx(cz[1] / v / cs).epsilon(tol));
    }
  }
}
