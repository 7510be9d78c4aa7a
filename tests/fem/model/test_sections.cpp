// Section properties (fem/model/Section) against formulas written out here: the hollow circle's
// shear coefficient against Cowper (1966) and its two published limits, the solid circle and the
// thin-walled round tube; areas and second moments of the tube and the rectangle.
#include <doctest/doctest.h>

#include <cmath>

#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

// One closed form evaluated two ways: a few roundings apart.
constexpr double kSectionRoundOff = 1e-14;

/// Cowper, "The shear coefficient in Timoshenko's beam theory", J. Appl. Mech. 33 (1966),
/// table 1, hollow circle of outer radius a and inner radius b, m = b / a:
///   kappa = 6 (1 + nu) (1 + m^2)^2 / ((7 + 6 nu) (1 + m^2)^2 + (20 + 12 nu) m^2).
double cowperHollowCircle(double a, double b, double nu) {
  const double m2 = (b / a) * (b / a), s = (1 + m2) * (1 + m2);
  return 6 * (1 + nu) * s / ((7 + 6 * nu) * s + (20 + 12 * nu) * m2);
}

}  // namespace

TEST_SUITE("sections") {
  TEST_CASE("tube shear coefficient: Cowper's hollow circle, for any wall and Poisson ratio") {
    const double D = 0.2;
    for (double nu : {0.0, 0.3, 0.45})
      for (double t : {0.002, 0.02, 0.05, 0.08, 0.1}) {
        CAPTURE(nu);
        CAPTURE(t);
        const Section s = Section::tube("t", Material::fromEnu("m", 200e9, nu, 7850), D, t);
        const double kappa = cowperHollowCircle(D / 2, D / 2 - t, nu);
        CHECK(relError(s.kappaY, kappa) < kSectionRoundOff);
        CHECK(relError(s.kappaZ, kappa) < kSectionRoundOff);
      }
  }

  TEST_CASE("tube shear coefficient: the solid circle and the thin-walled tube as limits") {
    for (double nu : {0.0, 0.3, 0.45}) {
      CAPTURE(nu);
      const Material m = Material::fromEnu("m", 200e9, nu, 7850);
      // Wall D / 2: no bore, Cowper's solid circle 6 (1 + nu) / (7 + 6 nu), as Section::circle.
      const double solid = 6 * (1 + nu) / (7 + 6 * nu);
      CHECK(relError(Section::tube("t", m, 0.1, 0.05).kappaY, solid) < kSectionRoundOff);
      CHECK(relError(Section::circle("c", m, 0.1).kappaY, solid) < kSectionRoundOff);
      // Cowper's thin-walled round tube, 2 (1 + nu) / (4 + 3 nu), is the limit m -> 1; the
      // hollow-circle formula departs from it as (t / D)^2: measured 1.67e-6 (nu = 0) to
      // 1.59e-6 (nu = 0.45) at t / D = 1e-3, a hundred times less at 1e-4.
      const double thin = 2 * (1 + nu) / (4 + 3 * nu);
      const double e3 = relError(Section::tube("t", m, 1.0, 1e-3).kappaY, thin);
      const double e4 = relError(Section::tube("t", m, 1.0, 1e-4).kappaY, thin);
      CHECK(e3 < 2e-6);
      CHECK(e4 < 2e-8);
      CHECK(e3 / e4 == doctest::Approx(100).epsilon(0.01));
    }
  }

  TEST_CASE("tube and rectangle: area, second moments, torsion constant of the tube") {
    const Material steel = Material::fromEnu("steel", 200e9, 0.3, 7850);
    const double D = 0.2, t = 0.03, d = D - 2 * t;
    const Section tube = Section::tube("t", steel, D, t);
    CHECK(relError(tube.A, kPi * (D * D - d * d) / 4) < kSectionRoundOff);
    const double I = kPi * (std::pow(D, 4) - std::pow(d, 4)) / 64;
    CHECK(relError(tube.Iy, I) < kSectionRoundOff);
    CHECK(relError(tube.Iz, I) < kSectionRoundOff);
    CHECK(relError(tube.J, 2 * I) < kSectionRoundOff);  // polar moment of a ring
    // Rectangle b (along local z) by h (along local y): bending about z uses h^3.
    const double b = 0.05, h = 0.3;
    const Section r = Section::rectangle("r", steel, b, h);
    CHECK(relError(r.A, b * h) < kSectionRoundOff);
    CHECK(relError(r.Iz, b * h * h * h / 12) < kSectionRoundOff);
    CHECK(relError(r.Iy, h * b * b * b / 12) < kSectionRoundOff);
    CHECK(r.outerY == h / 2);
    CHECK(r.outerZ == b / 2);
  }
}
