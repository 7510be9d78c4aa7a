// Bearings whose load acts at any angle (elements/TurnedBearing.hpp), and the unloaded
// journal of a vertical rotor (elements/ConcentricJournal.hpp), each against a second method.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "elements/ConcentricJournal.hpp"
#include "elements/TurnedBearing.hpp"

using namespace beamrotor;

namespace {

Eigen::Matrix2d stiffnessOf(const BearingCoefficients& k) {
  Eigen::Matrix2d K;
  K << k.kyy, k.kyz, k.kzy, k.kzz;
  return K;
}

Eigen::Matrix2d dampingOf(const BearingCoefficients& k) {
  Eigen::Matrix2d C;
  C << k.cyy, k.cyz, k.czy, k.czz;
  return C;
}

/// A cross-coupled, anisotropic bearing (N/m, N s/m).
const BearingCoefficients kSample{3e8, 1.1e8, -2.3e8, 1.4e8, 4e5, 6e4, 7e4, 2.5e5};

}  // namespace

TEST_SUITE("turned and concentric bearings") {
  TEST_CASE("a quarter turn swaps the axes: kyy' = kzz, kyz' = -kzy, kzy' = -kyz, kzz' = kyy") {
    // The bearing's x_b along global z, y_b along -y: read off the definition, not T K T^T.
    const BearingCoefficients q = turnedCoefficients(kSample, std::numbers::pi / 2);
    const double k = 1e8 * 1e-15, c = 1e5 * 1e-15;  // round-off of cos(pi/2) = 6e-17
    CHECK(q.kyy == doctest::Approx(kSample.kzz).epsilon(k));
    CHECK(q.kyz == doctest::Approx(-kSample.kzy).epsilon(k));
    CHECK(q.kzy == doctest::Approx(-kSample.kyz).epsilon(k));
    CHECK(q.kzz == doctest::Approx(kSample.kyy).epsilon(k));
    CHECK(q.cyy == doctest::Approx(kSample.czz).epsilon(c));
    CHECK(q.cyz == doctest::Approx(-kSample.czy).epsilon(c));
    CHECK(q.czy == doctest::Approx(-kSample.cyz).epsilon(c));
    CHECK(q.czz == doctest::Approx(kSample.cyy).epsilon(c));
    // Angle 0 is the same numbers, bit for bit (decks without load_angle keep their answers).
    const BearingCoefficients same = turnedCoefficients(kSample, 0);
    CHECK(same.kyz == kSample.kyz);
    CHECK(same.czy == kSample.czy);
  }

  TEST_CASE("turning by theta turns the force: F(T u) = T F(u), and keeps the invariants") {
    for (double theta : {0.3, 1.9, -2.4}) {
      CAPTURE(theta);
      const BearingCoefficients t = turnedCoefficients(kSample, theta);
      Eigen::Matrix2d T;
      T << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
      const Eigen::Vector2d u(1.3e-5, -0.4e-5);
      const Eigen::Vector2d f0 = stiffnessOf(kSample) * u, f1 = stiffnessOf(t) * (T * u);
      CHECK((f1 - T * f0).norm() < 1e-14 * f0.norm());
      // Rotation keeps the trace, the determinant and the skew part (kyz - kzy) of each matrix.
      for (auto of : {&stiffnessOf, &dampingOf}) {
        const Eigen::Matrix2d A = of(kSample), B = of(t);
        CHECK(B.trace() == doctest::Approx(A.trace()).epsilon(1e-14));
        CHECK(B.determinant() == doctest::Approx(A.determinant()).epsilon(1e-13));
        CHECK(B(0, 1) - B(1, 0) == doctest::Approx(A(0, 1) - A(1, 0)).epsilon(1e-14));
      }
      // And turning back gives the bearing's own coefficients.
      const BearingCoefficients back = turnedCoefficients(t, -theta);
      CHECK(back.kzy == doctest::Approx(kSample.kzy).epsilon(1e-14));
      CHECK(back.cyz == doctest::Approx(kSample.cyz).epsilon(1e-13));
    }
  }

  TEST_CASE("the centred journal is the short bearing's limit of vanishing load") {
    // The short-bearing coefficients at a load so small that eps ~ 3e-5: the direct
    // stiffnesses are O(eps) of the cross-coupled one, the rest agree to O(eps^2) (the
    // expansions of S_s and h0 in eps are even), ~1e-9.
    PlainJournal j;
    j.diameter = 0.1;
    j.length = 0.05;
    j.clearance = 1e-4;
    j.viscosity = 0.02;
    const double speed = 600;  // rad/s
    const BearingCoefficients centred = concentricJournalCoefficients(j, speed);
    j.load = 0.01;  // N
    const double eps = eccentricityRatio(j, speed);
    REQUIRE(eps < 1e-4);
    const BearingCoefficients light = shortBearingCoefficients(j, speed);
    const double tol = 10 * eps * eps + 1e-12;
    CHECK(light.kyz == doctest::Approx(centred.kyz).epsilon(tol));
    CHECK(light.kzy == doctest::Approx(centred.kzy).epsilon(tol));
    CHECK(light.cyy == doctest::Approx(centred.cyy).epsilon(tol));
    CHECK(light.czz == doctest::Approx(centred.czz).epsilon(tol));
    CHECK(std::abs(light.kyy) < 3 * eps * centred.kyz);
    CHECK(std::abs(light.kzz) < 3 * eps * centred.kyz);
    CHECK(std::abs(light.cyz) < 3 * eps * centred.cyy);
    // The half-frequency whirl ratio: cross-coupling = Omega / 2 times the damping.
    CHECK(centred.kyz == doctest::Approx(speed * centred.cyy / 2).epsilon(1e-15));
    // pi mu R L^3 / (2 c^3) by hand: 0.02 * 0.05 * 1.25e-4 / (2e-12) pi = 6.25e4 pi N s/m.
    CHECK(centred.cyy == doctest::Approx(6.25e4 * std::numbers::pi).epsilon(1e-14));
  }
}
