// Stepped pump rod, variant C (problems/scenes/README.md section 1): the right end is a hinge whose
// rotation is bounded by theta_p. The active-set solve must follow the bilinear closed form: below
// w* the clamped/hinged solution, above it that solution at w* plus the clamped/clamped one for w0
// - w*. The reference is an initial-parameter (transfer-matrix) solution
// (tests/problems/PumpRodReference.hpp), independent of the finite elements.
#include <doctest/doctest.h>

#include <cmath>

#include "fem/static/Static.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/PumpRodReference.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

const PumpRod kRodC;  // the paper's data at eta = 0.4
const double a = kRodC.a, d = kRodC.d, D1 = kRodC.D1, D2 = kRodC.D2, steelE = kRodC.E;
const double psi = kRodC.psi(), l = kRodC.l();

/// theta_p of the example data, from the tilted core's width (PumpRodReference.hpp).
double thetaP() {
  return pistonTiltLimit(0.150, 0.060, 0.1501);
}

using Response = PumpRodResponse;

Response initialParameters(double w0, bool rightClamped) {
  return pumpRodInitialParameters(kRodC, w0, rightClamped);
}

/// problems/scenes/README.md section 1.3 (the paper's eq. 26): bilinear in w0 with the switch at
/// w*.
Response bilinear(double w0, double* wStar) {
  const Response unit = initialParameters(1.0, false);
  *wStar = thetaP() / std::abs(unit.rightRotation);
  if (w0 <= *wStar) return initialParameters(w0, false);
  const Response hinged = initialParameters(*wStar, false);
  const Response clamped = initialParameters(w0 - *wStar, true);
  return {hinged.leftForce + clamped.leftForce,     hinged.leftMoment + clamped.leftMoment,
          hinged.middleForce + clamped.middleForce, hinged.rightForce + clamped.rightForce,
          hinged.rightMoment + clamped.rightMoment, hinged.rightRotation};
}

struct FeResponse {
  Response r;
  bool active;
  double stopMoment;
};

FeResponse variantCElements(double w0) {
  Model model;
  auto mat = Material::fromEnu("steel", steelE, 0.3, 7850);
  LineSpec spec;
  spec.segments.push_back({a, std::make_shared<Section>(Section::circle("D1", mat, D1)), 3});
  spec.segments.push_back({d, std::make_shared<Section>(Section::circle("D2", mat, D2)), 6});
  spec.points = {{"left", 0}, {"middle", psi}, {"right", l}};
  buildLine(model, spec);
  model.addSupport({"left", model.node("left"), {{Dof::ux, 0}, {Dof::uy, -w0}, {Dof::rz, 0}}});
  model.addSupport({"middle", model.node("middle"), {{Dof::uy, 0}}});
  model.addSupport({"right", model.node("right"), {{Dof::ux, 0}, {Dof::uy, 0}}});
  model.addContact({"rotation stop", model.node("right"), Dof::rz, -thetaP(), thetaP()});
  const StaticResult s = solveStatic(model);
  REQUIRE(s.contacts.size() == 1);
  const double stop = s.contacts[0].force;
  return {{s.reaction("left", Dof::uy), s.reaction("left", Dof::rz), s.reaction("middle", Dof::uy),
           s.reaction("right", Dof::uy), stop, s.displacement(model.node("right"), 5)},
          s.contacts[0].active,
          stop};
}

// Exact elements and exact elimination of the active stop: round-off only (condition ~1e7).
constexpr double kVariantCExact = 1e-9;

}  // namespace

TEST_SUITE("pump rod") {
  TEST_CASE("variant C: rotation stop follows the bilinear closed form across w*") {
    double wStar = 0;
    bilinear(0.001, &wStar);
    MESSAGE("theta_p = " << thetaP() << " rad, w* = " << wStar * 1e3 << " mm");
    CHECK(wStar > 0);
    CHECK(wStar < 0.005);  // the switch lies inside the 0..5 mm sweep
    std::vector<double> sweep;
    for (int k = 1; k <= 20; ++k) sweep.push_back(0.005 * k / 20);
    sweep.push_back(wStar);  // the switch point itself
    sweep.push_back(wStar * (1 - 1e-7));
    sweep.push_back(wStar * (1 + 1e-7));
    for (double w0 : sweep) {
      CAPTURE(w0);
      double ws;
      const Response ref = bilinear(w0, &ws);
      const FeResponse fe = variantCElements(w0);
      CHECK(fe.active == (w0 > wStar * (1 + 1e-9)));
      CHECK(relError(fe.r.leftForce, ref.leftForce) < kVariantCExact);
      CHECK(relError(fe.r.leftMoment, ref.leftMoment) < kVariantCExact);
      CHECK(relError(fe.r.middleForce, ref.middleForce) < kVariantCExact);
      CHECK(relError(fe.r.rightForce, ref.rightForce) < kVariantCExact);
      CHECK(relError(fe.r.rightRotation, ref.rightRotation) < kVariantCExact);
      // The stop carries the clamped increment's moment once closed, nothing before. Just
      // past w* that moment is tiny (1.7e-4 N m at w* (1 + 1e-7)), so its round-off is
      // measured against the rod's moment scale, the left clamp moment.
      if (w0 > wStar)
        CHECK(std::abs(fe.r.rightMoment - ref.rightMoment) <
              kVariantCExact * std::abs(ref.leftMoment));
      else
        CHECK(fe.stopMoment == 0);
    }
  }

  TEST_CASE("initial-parameter reference agrees with the published variant A reactions") {
    // Guards the reference itself: clamped right end at eta = 0.4, w0 = 1 mm.
    const Response r = initialParameters(0.001, true);
    CHECK(std::abs(std::abs(r.leftMoment) - 7660) <= 5);
    CHECK(std::abs(std::abs(r.middleForce) - 13330) <= 5);
    CHECK(std::abs(std::abs(r.rightMoment) - 797.05) <= 0.005);
  }
}
