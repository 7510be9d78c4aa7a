// Stepped pump rod, variant A (problems/scenes/README.md section 1): reactions by the finite
// elements against the published values and against an independent force-method solution written
// here.
#include <doctest/doctest.h>

#include <Eigen/Dense>

#include "fem/static/Static.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

struct Rod {
  double a = 0.575, d = 1.130, D1 = 0.120, D2 = 0.070, E = 200e9;
  double eta = 0.4, w0 = 0.001;
  double l() const { return a + d; }
  double psi() const { return a + 0.715 - eta; }
};

/// VariantAReactions on the rod (global frame: forces +y, moments counter-clockwise +z).
struct VariantAReactions {
  double leftForce, leftMoment, middleForce, rightForce, rightMoment;
};

/// Force method: primary structure the cantilever clamped at x = l; redundants X1 (force at
/// x = 0), X2 (moment at x = 0), X3 (force at psi). With the sagging-positive bending moment
/// of the part left of a section, unit loads give m1 = x, m2 = -1, m3 = <x - psi>, and the
/// Maxwell-Mohr flexibilities are delta_ij = integral m_i m_j / EI dx. Compatibility:
/// w(0) = -w0, w'(0) = 0, w(psi) = 0.
VariantAReactions forceMethod(const Rod& r) {
  const double EI1 = r.E * std::numbers::pi * std::pow(r.D1, 4) / 64;
  const double EI2 = r.E * std::numbers::pi * std::pow(r.D2, 4) / 64;
  auto m = [&](int i, double x) {
    if (i == 0) return x;
    if (i == 1) return -1.0;
    return x > r.psi() ? x - r.psi() : 0.0;
  };
  // Simpson's rule is exact for the quadratic integrands on each piece between kinks/steps.
  std::vector<double> cuts{0, r.a, r.psi(), r.l()};
  std::sort(cuts.begin(), cuts.end());
  Eigen::Matrix3d delta = Eigen::Matrix3d::Zero();
  for (int p = 0; p + 1 < 4; ++p) {
    const double x0 = cuts[p], x1 = cuts[p + 1], xm = (x0 + x1) / 2;
    if (x1 <= x0) continue;
    const double EI = xm < r.a ? EI1 : EI2;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        delta(i, j) += (x1 - x0) / 6 *
                       (m(i, x0) * m(j, x0) + 4 * m(i, xm) * m(j, xm) + m(i, x1) * m(j, x1)) / EI;
  }
  const Eigen::Vector3d X = delta.lu().solve(Eigen::Vector3d(-r.w0, 0, 0));
  // Equilibrium of the whole rod gives the right-end reactions.
  const double right = -(X[0] + X[2]);
  const double rightMoment = X[0] * r.l() + X[2] * (r.l() - r.psi()) - X[1];
  return {X[0], X[1], X[2], right, rightMoment};
}

VariantAReactions variantAElements(const Rod& r, int elementsPerPiece) {
  Model model;
  auto mat = Material::fromEnu("steel", r.E, 0.3, 7850);
  LineSpec spec;
  spec.segments.push_back(
      {r.a, std::make_shared<Section>(Section::circle("D1", mat, r.D1)), elementsPerPiece});
  spec.segments.push_back(
      {r.d, std::make_shared<Section>(Section::circle("D2", mat, r.D2)), 2 * elementsPerPiece});
  spec.points = {{"left", 0}, {"step", r.a}, {"middle", r.psi()}, {"right", r.l()}};
  buildLine(model, spec);
  model.addSupport({"left", model.node("left"), {{Dof::ux, 0}, {Dof::uy, -r.w0}, {Dof::rz, 0}}});
  model.addSupport({"middle", model.node("middle"), {{Dof::uy, 0}}});
  model.addSupport({"right", model.node("right"), {{Dof::ux, 0}, {Dof::uy, 0}, {Dof::rz, 0}}});
  const StaticResult s = solveStatic(model);
  return {s.reaction("left", Dof::uy), s.reaction("left", Dof::rz), s.reaction("middle", Dof::uy),
          s.reaction("right", Dof::uy), s.reaction("right", Dof::rz)};
}

// Hermite elements are exact without distributed load: agreement to round-off (the
// condition number of these models is ~1e7).
constexpr double kVariantAExact = 1e-9;

}  // namespace

TEST_SUITE("pump rod") {
  TEST_CASE("variant A at eta = 0.4, w0 = 1 mm: published reactions to printed precision") {
    const VariantAReactions fe = variantAElements(Rod{}, 4);
    MESSAGE("M1 = " << fe.leftMoment << " N m, P2 = " << fe.leftForce
                    << " N, P3 = " << fe.middleForce << " N, P4 = " << fe.rightForce
                    << " N, M4 = " << fe.rightMoment << " N m");
    // Half a unit of the last printed digit.
    CHECK(std::abs(std::abs(fe.leftMoment) - 7660) <= 5);
    CHECK(std::abs(std::abs(fe.leftForce) - 10400) <= 50);
    CHECK(std::abs(std::abs(fe.middleForce) - 13330) <= 5);
    CHECK(std::abs(std::abs(fe.rightForce) - 2930) <= 5);
    CHECK(std::abs(std::abs(fe.rightMoment) - 797.05) <= 0.005);
    // P3 opposes P2 and P4, and balances them.
    CHECK(fe.middleForce * fe.leftForce < 0);
    CHECK(fe.middleForce * fe.rightForce < 0);
  }

  TEST_CASE("variant A: finite elements equal the force method over the stroke") {
    for (double eta : {0.0, 0.1, 0.2, 0.3, 0.4})
      for (int n : {1, 3}) {
        CAPTURE(eta);
        CAPTURE(n);
        Rod rod;
        rod.eta = eta;
        const VariantAReactions fe = variantAElements(rod, n), fm = forceMethod(rod);
        CHECK(relError(fe.leftForce, fm.leftForce) < kVariantAExact);
        CHECK(relError(fe.leftMoment, fm.leftMoment) < kVariantAExact);
        CHECK(relError(fe.middleForce, fm.middleForce) < kVariantAExact);
        CHECK(relError(fe.rightForce, fm.rightForce) < kVariantAExact);
        CHECK(relError(fe.rightMoment, fm.rightMoment) < kVariantAExact);
      }
  }
}
