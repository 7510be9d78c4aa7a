// Timoshenko elements: the interdependent-interpolation element is exact for an end-loaded
// cantilever at every slenderness; the naive linear element with full integration locks.
#include <doctest/doctest.h>

#include "fem/static/Static.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// Tip deflection of a cantilever of length L, square section h x h, tip force P.
double tipDeflection(double L, double h, int n, BeamTheory theory) {
  Model m;
  const Line line = uniformBeam(m, L, steelRectangle(h, h), n, DofSet::planar(), {theory});
  clamp(m, "root", line.nodes.front(), DofSet::planar());
  m.addLoad({line.nodes.back(), Dof::uy, -1000.0});
  return -solveStatic(m).displacement(line.nodes.back(), 1);
}

double exactTimoshenko(double L, double h) {
  const auto s = steelRectangle(h, h);
  const double P = 1000.0;
  return P * L * L * L / (3 * s->EIz()) + P * L / (s->kappaY * s->material.G * s->A);
}

/// Saint-Venant torsion constant of an a x c rectangle (a >= c) by the exact series
/// (Timoshenko and Goodier, Theory of Elasticity, 1970, torsion of rectangular bars):
///   J = (a c^3 / 3) (1 - (192 / pi^5) (c / a) sum_{n odd} tanh(n pi a / (2 c)) / n^5).
/// The terms fall as n^-5: 50 of them leave < 1e-10 of the sum.
double rectangleTorsionSeries(double a, double c) {
  double sum = 0;
  for (int n = 1; n < 100; n += 2) sum += std::tanh(n * kPi * a / (2 * c)) / std::pow(n, 5);
  return a * c * c * c / 3 * (1 - 192 / std::pow(kPi, 5) * (c / a) * sum);
}

using Vector6 = Eigen::Matrix<double, 6, 1>;

/// Tip displacements and rotations (global) of a 3D Timoshenko cantilever of n elements along
/// `axis` (in the x-y plane, so the element's local z is global z and local y is z x axis)
/// under the tip load (fx, fy, fz, mx, my, mz).
Vector6 frameTip(std::shared_ptr<const Section> s, const Eigen::Vector3d& axis, double L, int n,
                 const Vector6& load) {
  Model m;
  LineSpec spec;
  spec.dofs = DofSet::frame3d();
  spec.direction = axis;
  spec.segments.push_back({L, std::move(s), n, 0, {BeamTheory::timoshenko}});
  spec.points = {{"root", 0}, {"tip", L}};
  buildLine(m, spec);
  clamp(m, "root", m.node("root"), DofSet::frame3d());
  for (int k = 0; k < 6; ++k) m.addLoad({m.node("tip"), kAllDofs[k], load[k]});
  return solveStatic(m).displacement.row(m.node("tip")).transpose();
}

}  // namespace

TEST_SUITE("timoshenko") {
  TEST_CASE("interdependent interpolation is exact for a tip-loaded cantilever") {
    // Exact element: round-off only. The tolerance grows with slenderness because the
    // condition number of K grows like (L/h)^2.
    for (double slenderness : {2.0, 10.0, 100.0, 1000.0})
      for (int n : {1, 4, 13}) {
        CAPTURE(slenderness);
        CAPTURE(n);
        const double L = 1.0, h = L / slenderness;
        CHECK(relError(tipDeflection(L, h, n, BeamTheory::timoshenko), exactTimoshenko(L, h)) <
              1e-9);
      }
  }

  TEST_CASE("linear element with full integration locks as L/h grows; reduced does not") {
    const double L = 1.0;
    double previous = 0;
    for (double slenderness : {10.0, 100.0, 1000.0, 10000.0}) {
      CAPTURE(slenderness);
      const double h = L / slenderness, exact = exactTimoshenko(L, h);
      const double locked =
          relError(tipDeflection(L, h, 4, BeamTheory::timoshenkoLinearFullIntegration), exact);
      const double reduced =
          relError(tipDeflection(L, h, 4, BeamTheory::timoshenkoLinearReducedIntegration), exact);
      MESSAGE("L/h = " << slenderness << ": full integration error " << locked
                       << ", reduced integration error " << reduced);
      CHECK(locked > previous);  // locking worsens monotonically with slenderness
      previous = locked;
      // Reduced integration: the one-point element under-predicts a slender cantilever's tip
      // deflection by 1/(4 n^2) = 1.5625 % at n = 4 whatever L/h (no locking); shear adds a
      // part the element gets exactly, so the error departs from that by O((h/L)^2) only.
      CHECK(std::abs(reduced - 1.0 / (4 * 4 * 4)) < 2e-4);
    }
    const double h = L / 1000;
    CHECK(relError(tipDeflection(L, h, 4, BeamTheory::timoshenkoLinearFullIntegration),
                   exactTimoshenko(L, h)) > 0.5);
  }

  TEST_CASE("3D frame, b != h: each plane bends with its own EI and kappa, twists with G J") {
    // Cantilever of length L, tip force P along a principal axis of the section: the exact
    // Timoshenko tip deflection is P L^3 / (3 E I) + P L / (kappa G A) (the constant shear
    // force P strains every section by P / (kappa G A)), with I about the axis it bends about and
    // kappa for shear along the force. A rectangle b (along local z) by h (along local y) has
    // I_z = b h^3 / 12 for a force along y and I_y = h b^3 / 12 along z; Cowper's (1966)
    // kappa = 10 (1 + nu) / (12 + 11 nu). With b = 0.1, h = 0.4, L = 1 the shear part is 12 %
    // of the deflection along y and 0.8 % along z, and I_z / I_y = 16: a shear parameter built
    // with the other plane's EI or kappa moves a deflection by 10 % or more. The
    // interdependent-interpolation element is exact for this load (round-off only; the
    // condition number here is below 1e8), so 1e-9.
    const double L = 1.0, b = 0.1, h = 0.4, P = 5e4, T = 2e4;
    const double E = 210e9, nu = 0.3, G = E / (2 * (1 + nu));
    const double A = b * h, Iz = b * h * h * h / 12, Iy = h * b * b * b / 12;
    const double kappa = 10 * (1 + nu) / (12 + 11 * nu);
    struct Case {
      std::shared_ptr<const Section> section;
      double kappaY, kappaZ, J;
      double jTolerance;
    };
    // The deck's rectangle (Roark's approximation of J: 1.3e-4 from the exact series at
    // a/c = 4, so 2e-4 for the twist), and a general section with unequal kappas and J given,
    // where the element alone decides (1e-9).
    const auto general = std::make_shared<Section>(Section::general(
        "g", Material::fromEnu("steel", E, nu, 7850), A, Iy, Iz, 1e-4, 0.55, 0.8, h));
    const std::vector<Case> cases{
        {steelRectangle(b, h), kappa, kappa, rectangleTorsionSeries(h, b), 2e-4},
        {general, 0.55, 0.8, 1e-4, 1e-9}};
    for (const Case& c : cases)
      for (const Eigen::Vector3d& axis : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(3, 4, 0)})
        for (int n : {1, 5}) {
          CAPTURE(c.kappaY);
          CAPTURE(axis.transpose());
          CAPTURE(n);
          const Eigen::Vector3d ex = axis.normalized(), ez = Eigen::Vector3d::UnitZ();
          const Eigen::Vector3d ey = ez.cross(ex);
          const double wy = P * L * L * L / (3 * E * Iz) + P * L / (c.kappaY * G * A);
          const double wz = P * L * L * L / (3 * E * Iy) + P * L / (c.kappaZ * G * A);
          Vector6 load = Vector6::Zero();
          load.head<3>() = P * ey;  // a force along local y
          Vector6 u = frameTip(c.section, axis, L, n, load);
          CHECK(relError(u.head<3>().dot(ey), wy) < 1e-9);
          CHECK(std::abs(u[2]) < 1e-9 * wy);  // nothing leaks into the other plane
          // Along local z = global z.
          load.setZero();
          load[2] = P;
          u = frameTip(c.section, axis, L, n, load);
          CHECK(relError(u[2], wz) < 1e-9);
          CHECK(std::abs(u.head<3>().dot(ey)) < 1e-9 * wz);
          // A torque about the axis: T L / (G J).
          load.setZero();
          load.tail<3>() = T * ex;
          u = frameTip(c.section, axis, L, n, load);
          CHECK(relError(u.tail<3>().dot(ex), T * L / (G * c.J)) < c.jTolerance);
        }
  }
}
