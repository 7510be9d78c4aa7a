// Largest transverse shear stress per section shape (fem/model/ShearStress) against the textbook
// formulas written out here: the elasticity distribution over a circle (problems/scenes/README.md
// section 1) and Jourawski's V Q / (I b) at the neutral axis for the tube and the rectangle.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "fem/model/ShearStress.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

// Closed forms evaluated two ways: a few roundings apart.
constexpr double kShearRoundOff = 1e-13;

const Material kSteel = Material::fromEnu("steel", 200e9, 0.3, 7850);

}  // namespace

TEST_SUITE("shear stress") {
  TEST_CASE("solid circle: the elasticity distribution at the centre (Timoshenko-Goodier)") {
    const double D = 0.07, R = D / 2, V = 1234.5, nu = kSteel.nu;
    const Section s = Section::circle("rod", kSteel, D);
    // tau(z) = (3 + 2 nu) / (8 (1 + nu)) V / I (R^2 - (1 - 2 nu) / (3 + 2 nu) z^2), largest at
    // z = 0, with I = pi R^4 / 4.
    const double I = kPi * std::pow(R, 4) / 4;
    const double tau0 = (3 + 2 * nu) / (8 * (1 + nu)) * V / I * R * R;
    CHECK(relError(maxShearStress(s, {0, V, 0, 0, 0, 0}), tau0) < kShearRoundOff);
    // The resultant of two components acts like one force of its size (axisymmetry).
    CHECK(relError(maxShearStress(s, {0, 0.6 * V, -0.8 * V, 0, 0, 0}), tau0) < kShearRoundOff);
    // 1/26 = 3.8 % above the elementary 4/3 for nu = 0.3: the Poisson effect across the width.
    CHECK(relError(shearStressFactor(s) / (4.0 / 3), 27.0 / 26) < kShearRoundOff);
  }

  TEST_CASE("tube and rectangle: Jourawski's V Q / (I b) at the neutral axis") {
    const double V = -800.0;
    SUBCASE("tube") {
      const double D = 0.1, t = 0.01, R = D / 2, r = R - t;
      const Section s = Section::tube("pipe", kSteel, D, t);
      const double Q = 2.0 / 3 * (R * R * R - r * r * r);  // first moment of the upper half
      const double I = kPi / 4 * (std::pow(R, 4) - std::pow(r, 4)), b = 2 * (R - r);
      CHECK(relError(maxShearStress(s, {0, V, 0, 0, 0, 0}), std::abs(V) * Q / (I * b)) <
            kShearRoundOff);
      // A thin wall tends to twice the mean shear stress.
      const Section thin = Section::tube("thin", kSteel, 1.0, 1e-5);
      CHECK(shearStressFactor(thin) == doctest::Approx(2.0).epsilon(1e-4));
    }
    SUBCASE("rectangle") {
      const double b = 0.02, h = 0.05;
      const Section s = Section::rectangle("bar", kSteel, b, h);
      const double Q = b * h * h / 8, I = b * h * h * h / 12;
      CHECK(relError(maxShearStress(s, {0, V, 0, 0, 0, 0}), std::abs(V) * Q / (I * b)) <
            kShearRoundOff);
    }
    SUBCASE("general section: the mean shear stress V / A") {
      const Section s = Section::general("any", kSteel, 1e-3, 2e-6, 2e-6, 4e-6, 0.85, 0.85, 0.05);
      CHECK(relError(maxShearStress(s, {0, V, 0, 0, 0, 0}), std::abs(V) / 1e-3) < kShearRoundOff);
    }
  }
}
