// Signed fibre stresses (fem/model/SignedStress): the top and bottom fibre normal stress of a
// section against N / A -+ Mz c / Iz written out here, their larger magnitude against the
// section's largest |sigma| (maxNormalStress, a second method) for every standard shape, and
// the signed shear stress against the magnitude with the shear force's sign.
#include <doctest/doctest.h>

#include <cmath>

#include "fem/model/LineElement.hpp"
#include "fem/model/ShearStress.hpp"
#include "fem/model/SignedStress.hpp"
#include "fem/model/StandardSections.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

// A few roundings separate the two evaluations of the same formula.
constexpr double kSignedRoundOff = 1e-13;

const Material kSignedSteel = Material::fromEnu("steel", 200e9, 0.3, 7850);

}  // namespace

TEST_SUITE("signed stress") {
  TEST_CASE("circle and rectangle: N / A - Mz y / Iz at y = +c (top) and -c (bottom)") {
    const double N = 4.0e4, Mz = -1.5e3;
    SUBCASE("circle") {
      const double D = 0.07, A = kPi * D * D / 4, I = kPi * std::pow(D, 4) / 64;
      const YFibreStresses s = yFibreStresses(Section::circle("rod", kSignedSteel, D), {.N = N, .Mz = Mz});
      // Hogging (Mz < 0 with sigma = -Mz y / Iz): the top fibre is stretched beyond N / A.
      CHECK(relError(s.top, N / A - Mz * (D / 2) / I) < kSignedRoundOff);
      CHECK(relError(s.bottom, N / A + Mz * (D / 2) / I) < kSignedRoundOff);
      CHECK(s.top > N / A);
      CHECK(s.bottom < 0);
    }
    SUBCASE("rectangle, h along y") {
      const double b = 0.04, h = 0.1, A = b * h, I = b * h * h * h / 12;
      const YFibreStresses s =
          yFibreStresses(Section::rectangle("bar", kSignedSteel, b, h), {.N = N, .Mz = Mz});
      CHECK(relError(s.top, N / A - Mz * (h / 2) / I) < kSignedRoundOff);
      CHECK(relError(s.bottom, N / A + Mz * (h / 2) / I) < kSignedRoundOff);
    }
  }

  TEST_CASE("the larger of |top| and |bottom| is the section's largest |sigma| under N and Mz") {
    // A field linear in y alone reaches its extremes at the extreme y, so for every shape
    // (also the angle, whose fibres are not symmetric about the centroid) the two agree.
    const std::vector<Section> sections{
        Section::circle("circle", kSignedSteel, 0.05),
        Section::tube("tube", kSignedSteel, 0.06, 0.004),
        Section::rectangle("rectangle", kSignedSteel, 0.03, 0.08),
        iSection("ipe", kSignedSteel, 0.2, 0.1, 0.0056, 0.0085, 0.012),
        channelSection("channel", kSignedSteel, 0.16, 0.065, 0.0075, 0.0105, 0.0105, 0.0055),
        angleSection("angle", kSignedSteel, 0.1, 0.065, 0.008, 0.01, 0.005),
    };
    for (const Section& section : sections) {
      CAPTURE(section.name);
      for (const SectionForces f : {SectionForces{.N = 1e4, .Mz = 2e3},
                                    SectionForces{.N = -3e4, .Mz = -5e2},
                                    SectionForces{.Mz = 7e2}}) {
        const YFibreStresses s = yFibreStresses(section, f);
        CHECK(relError(std::max(std::abs(s.top), std::abs(s.bottom)), maxNormalStress(section, f)) <
              kSignedRoundOff);
      }
    }
  }

  TEST_CASE("signed shear: the magnitude of each component with its shear force's sign") {
    const Section rod = Section::circle("rod", kSignedSteel, 0.07);
    for (const double V : {-2500.0, 1800.0}) {
      CHECK(signedShearY(rod, {.Vy = V, .Vz = 0.3 * V}) ==
            doctest::Approx(std::copysign(maxShearStress(rod, {.Vy = V}), V)).epsilon(kSignedRoundOff));
      CHECK(signedShearZ(rod, {.Vy = 0.3 * V, .Vz = V}) ==
            doctest::Approx(std::copysign(maxShearStress(rod, {.Vz = V}), V)).epsilon(kSignedRoundOff));
    }
    CHECK(signedShearY(rod, {}) == 0);
  }
}
