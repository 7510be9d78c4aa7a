// Stepped pump rod, variant C (problems/scenes/README.md section 1): the right end is a hinge whose
// rotation is bounded by theta_p. The active-set solve must follow the bilinear closed form: below
// w* the clamped/hinged solution, above it that solution at w* plus the clamped/clamped one for w0
// - w*. The reference is an initial-parameter (transfer-matrix) solution written here, independent
// of the finite elements.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "fem/static/Static.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

constexpr double a = 0.575, d = 1.130, D1 = 0.120, D2 = 0.070, youngRod = 200e9;
constexpr double eta = 0.4, psi = a + 0.715 - eta, l = a + d;

double thetaP() {
  const double Dp = 0.150, lp = 0.060, Dc = 0.1501, diag = std::hypot(Dp, lp);
  return std::acos(Dp / diag) - std::acos(Dc / diag);
}

struct Response {
  double leftForce, leftMoment, middleForce, rightForce, rightMoment, rightRotation;
};

/// Initial-parameter method: state (w, theta, M, V) with w' = theta, theta' = M/EI, M' = V
/// (M sagging-positive, V the sum of upward forces left of the section), carried across
/// prismatic pieces exactly; the middle support adds its force to V. Unknowns M(0), V(0),
/// the middle force; conditions w(psi) = 0 and, at the right end, w = 0 with theta = 0
/// (clamped) or M = 0 (hinged). Left end: w = -w0, theta = 0.
Response initialParameters(double w0, bool rightClamped) {
  const double EI1 = youngRod * std::numbers::pi * std::pow(D1, 4) / 64;
  const double EI2 = youngRod * std::numbers::pi * std::pow(D2, 4) / 64;
  auto carry = [](Eigen::Vector4d s, double h, double EI) {
    return Eigen::Vector4d(s[0] + s[1] * h + s[2] * h * h / (2 * EI) + s[3] * h * h * h / (6 * EI),
                           s[1] + s[2] * h / EI + s[3] * h * h / (2 * EI), s[2] + s[3] * h, s[3]);
  };
  // Returns (w(psi-), state at the right end) for given unknowns.
  auto march = [&](double w, double M0, double V0, double P3) {
    Eigen::Vector4d s(-w, 0, M0, V0);
    s = carry(s, a, EI1);
    s = carry(s, psi - a, EI2);
    const double wMiddle = s[0];
    s[3] += P3;
    s = carry(s, l - psi, EI2);
    return std::make_pair(wMiddle, s);
  };
  auto conditions = [&](double w, const Eigen::Vector3d& x) {
    const auto [wm, s] = march(w, x[0], x[1], x[2]);
    return Eigen::Vector3d(wm, s[0], rightClamped ? s[1] : s[2]);
  };
  // The conditions are linear in (w0, unknowns): one column per unknown, then solve.
  Eigen::Matrix3d A;
  for (int j = 0; j < 3; ++j) A.col(j) = conditions(0, Eigen::Vector3d::Unit(j));
  const Eigen::Vector3d x = A.lu().solve(-conditions(w0, Eigen::Vector3d::Zero()));
  const auto [wm, s] = march(w0, x[0], x[1], x[2]);
  // Reactions on the rod (+y forces, counter-clockwise moments): left force V(0), left moment
  // -M(0), middle force P3, right force -V(l), right moment M(l).
  return {x[1], -x[0], x[2], -s[3], s[2], s[1]};
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
  auto mat = Material::fromEnu("steel", youngRod, 0.3, 7850);
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
