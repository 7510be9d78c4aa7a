// The beam's geometric stiffness at element level: symmetry, rigid-body behaviour, and Euler's
// columns for the four classical end conditions (and Engesser's shear-reduced load for the
// Timoshenko element) with the observed convergence order per element formulation.
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "fem/stability/Buckling.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

enum class ColumnEnds { pinnedPinned, fixedFree, fixedPinned, fixedFixed };

/// Effective length factor K of each end condition (Pcr = pi^2 EI / (K L)^2). Fixed-pinned:
/// the lowest root of tan(kL) = kL, kL = 4.493409457909064 (Timoshenko and Gere, Theory of
/// Elastic Stability, 2nd ed., sec. 2.5), K = pi / kL.
double effectiveLengthFactor(ColumnEnds ends) {
  switch (ends) {
    case ColumnEnds::pinnedPinned:
      return 1.0;
    case ColumnEnds::fixedFree:
      return 2.0;
    case ColumnEnds::fixedPinned:
      return kPi / 4.493409457909064;
    case ColumnEnds::fixedFixed:
      return 0.5;
  }
  return 0;
}

/// The lowest buckling factor of a planar column along x of n elements under a unit
/// compressive end load (so the factor is the critical load in N).
double columnFactor(double L, std::shared_ptr<const Section> s, int n, ColumnEnds ends,
                    BeamTheory theory) {
  Model m;
  const Line line = uniformBeam(m, L, std::move(s), n, DofSet::planar(), {theory});
  const int base = line.nodes.front(), top = line.nodes.back();
  const bool baseFixed = ends != ColumnEnds::pinnedPinned;
  Support b{"base", base, {{Dof::ux, 0}, {Dof::uy, 0}}};
  if (baseFixed) b.dofs.push_back({Dof::rz, 0});
  m.addSupport(b);
  if (ends != ColumnEnds::fixedFree) {
    Support t{"top", top, {{Dof::uy, 0}}};
    if (ends == ColumnEnds::fixedFixed) t.dofs.push_back({Dof::rz, 0});
    m.addSupport(t);
  }
  m.addLoad({top, Dof::ux, -1.0});
  BucklingOptions o;
  o.count = 1;
  return solveBuckling(m, o).modes.at(0).factor;
}

struct ConvergenceRun {
  double errorCoarse = 0, errorFine = 0, order = 0;
};

/// Relative errors on 4 and 8 elements and the observed order log2(e4 / e8).
ConvergenceRun columnConvergence(ColumnEnds ends, BeamTheory theory, double L,
                                 std::shared_ptr<const Section> s, double exact) {
  ConvergenceRun r;
  r.errorCoarse = relError(columnFactor(L, s, 4, ends, theory), exact);
  r.errorFine = relError(columnFactor(L, s, 8, ends, theory), exact);
  r.order = std::log2(r.errorCoarse / r.errorFine);
  return r;
}

}  // namespace

TEST_SUITE("geometric stiffness") {
  TEST_CASE("symmetric, free of rigid translation, and N L theta^2 for a rigid rotation") {
    // A 3D beam in a general direction, Timoshenko and Euler-Bernoulli, axial force varying
    // along it: KG must be symmetric, vanish on rigid translations and give the work of the
    // axial force through a rigid rotation, theta^T KG theta = mean N L theta^2 for a rotation
    // about an axis across the beam (exact: the slope is theta everywhere) and zero about the
    // beam's own axis (no slope). Round-off tolerance: the entries are O(N L).
    for (BeamTheory theory : {BeamTheory::eulerBernoulli, BeamTheory::timoshenko}) {
      const Eigen::Vector3d x1(0.1, 0.2, 0.3), x2(1.3, -0.4, 1.1);
      Beam beam(0, x1, 1, x2, steelCircle(0.05), DofSet::frame3d(), {theory});
      const double N0 = -1500, N1 = -900, L = (x2 - x1).norm();
      const Beam::Matrix12 KG = beam.localGeometricStiffness(N0, N1);
      CHECK((KG - KG.transpose()).norm() <= 1e-14 * KG.norm());
      for (int d = 0; d < 3; ++d) {
        Beam::Vector12 t = Beam::Vector12::Zero();
        t[d] = t[6 + d] = 1;
        CHECK((KG * t).norm() <= 1e-13 * KG.norm());
      }
      // Rigid rotation theta about local z: v = theta x, rz = theta; about local y: w = -theta
      // x, ry = theta; about local x: rx = theta.
      const double theta = 1e-3, meanN = (N0 + N1) / 2;
      Beam::Vector12 rz = Beam::Vector12::Zero(), ry = Beam::Vector12::Zero(),
                     rx = Beam::Vector12::Zero();
      rz[5] = rz[11] = theta;
      rz[7] = theta * L;
      ry[4] = ry[10] = theta;
      ry[8] = -theta * L;
      rx[3] = rx[9] = theta;
      const double expected = meanN * L * theta * theta;
      CHECK(relError(rz.dot(KG * rz), expected) < 1e-12);
      CHECK(relError(ry.dot(KG * ry), expected) < 1e-12);
      CHECK(std::abs(rx.dot(KG * rx)) <= 1e-14 * std::abs(expected));
    }
  }

  TEST_CASE("the global matrix is the local one rotated, and tension stiffens") {
    // Planar beam at 30 degrees: its KG from a displacement state that stretches it by
    // delta carries N = EA delta / L; compare with T^T KG_local T built here.
    const double c = std::cos(kPi / 6), s = std::sin(kPi / 6), L = 2.0, delta = 1e-4;
    auto sec = steelCircle(0.04);
    Beam beam(0, Eigen::Vector3d::Zero(), 1, Eigen::Vector3d(c * L, s * L, 0), sec,
              DofSet::planar());
    ElementVector u = ElementVector::Zero(6);  // ux uy rz at each end
    u[3] = c * delta;
    u[4] = s * delta;
    const double N = sec->EA() * delta / L;
    const ElementMatrix KG = beam.geometricStiffness(u);
    const Beam::Matrix12 local = beam.localGeometricStiffness(N, N);
    Eigen::Matrix<double, 6, 6> T = Eigen::Matrix<double, 6, 6>::Zero();
    for (int e = 0; e < 2; ++e) {
      T.block<2, 2>(3 * e, 3 * e) << c, s, -s, c;
      T(3 * e + 2, 3 * e + 2) = 1;
    }
    Eigen::Matrix<double, 6, 6> Kl;
    const std::array<int, 6> planar{0, 1, 5, 6, 7, 11};
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) Kl(a, b) = local(planar[a], planar[b]);
    const Eigen::Matrix<double, 6, 6> expected = T.transpose() * Kl * T;
    CHECK((KG - expected).norm() <= 1e-12 * expected.norm());
    // Tension: the transverse diagonal terms are positive (6/5 N / L for Euler-Bernoulli).
    CHECK(Kl(1, 1) == doctest::Approx(1.2 * N / L).epsilon(1e-12));
  }

  TEST_CASE("Euler columns, four end conditions: the closed form and the observed order") {
    // Steel circle 50 mm, L = 2 m (slender: L/D = 40). Pcr = pi^2 EI / (K L)^2.
    // Measured (Euler-Bernoulli, consistent KG, 4 -> 8 elements): the error falls as h^4 for
    // every end condition (the eigenvalue error of cubic Hermite elements is O(h^(2(p+1-m))) =
    // O(h^4), Strang and Fix, An Analysis of the Finite Element Method, ch. 6); observed orders
    // 3.88 - 3.99. Measured errors on 8 elements: 3.3e-5 (pinned-pinned), 2.1e-6 (fixed-free),
    // 1.4e-4 (fixed-pinned), 5.1e-4 (fixed-fixed); tolerance 6e-4.
    const double L = 2.0;
    auto sec = steelCircle(0.05);
    for (ColumnEnds ends : {ColumnEnds::pinnedPinned, ColumnEnds::fixedFree,
                            ColumnEnds::fixedPinned, ColumnEnds::fixedFixed}) {
      const double K = effectiveLengthFactor(ends);
      const double exact = kPi * kPi * sec->EIz() / (K * L * K * L);
      const ConvergenceRun r =
          columnConvergence(ends, BeamTheory::eulerBernoulli, L, sec, exact);
      MESSAGE("K = " << K << ": errors " << r.errorCoarse << " (4), " << r.errorFine
                     << " (8), order " << r.order);
      CHECK(r.errorFine < 6e-4);
      CHECK(r.order > 3.8);
      CHECK(r.order < 4.3);
    }
  }

  TEST_CASE("a stocky Timoshenko column buckles at Engesser's load") {
    // Engesser: Pcr = Pe / (1 + Pe / (kappa G A)) for the energy with the axial force acting
    // on the total slope (Timoshenko and Gere, sec. 2.17). Circle 100 mm, L = 0.6 m, pinned:
    // Pe / (kappa G A) = 0.066, so shear lowers the load by 6 %, which the Euler-Bernoulli
    // element misses entirely. Measured: the interdependent element converges to Engesser's
    // value as h^2 (errors 2.8e-3, 6.1e-4, 1.5e-4, 3.7e-5 on 4, 8, 16, 32 elements: its
    // shapes are exact for the static beam without axial force, not for the buckled one, and
    // the shear part of the slope is constant per element), the linear element with reduced
    // integration also as h^2 with a 40 times larger constant.
    const double L = 0.6;
    auto sec = steelCircle(0.1);
    const double Pe = kPi * kPi * sec->EIz() / (L * L);
    const double kGA = sec->kappaY * sec->material.G * sec->A;
    const double engesser = Pe / (1 + Pe / kGA);
    CHECK(Pe / engesser - 1 > 0.05);  // the shear effect is far above the tolerances below
    std::array<double, 4> errors{};
    for (int level = 0; level < 4; ++level)
      errors[level] = relError(
          columnFactor(L, sec, 4 << level, ColumnEnds::pinnedPinned, BeamTheory::timoshenko),
          engesser);
    MESSAGE("interdependent: " << errors[0] << ", " << errors[1] << ", " << errors[2] << ", "
                               << errors[3]);
    CHECK(errors[3] < 5e-5);
    for (int level = 1; level < 4; ++level) {
      CHECK(std::log2(errors[level - 1] / errors[level]) > 1.9);
      CHECK(std::log2(errors[level - 1] / errors[level]) < 2.4);
    }
    const ConvergenceRun lin = columnConvergence(
        ColumnEnds::pinnedPinned, BeamTheory::timoshenkoLinearReducedIntegration, L, sec,
        engesser);
    MESSAGE("linear reduced: " << lin.errorCoarse << ", " << lin.errorFine << ", order "
                               << lin.order);
    CHECK(lin.order > 1.8);
    CHECK(lin.order < 2.3);
    // Euler-Bernoulli gives Pe: its error against Engesser is the neglected shear.
    CHECK(relError(columnFactor(L, sec, 8, ColumnEnds::pinnedPinned, BeamTheory::eulerBernoulli),
                   Pe) < 2e-4);
  }

  TEST_CASE("3D: torsional buckling of a column at G J A / Ip (the twist term)") {
    // A doubly symmetric column whose torsion constant is small against its bending stiffness
    // buckles by twisting at P_T = G J A / Ip (no warping; Timoshenko and Gere, sec. 5.3, with
    // the warping constant zero). Twist is interpolated linearly in the element and its
    // stiffness G J / L and geometric term N Ip / (A L) have the same shape, so every mesh gives
    // P_T to round-off. Ends held against twist and lateral motion, one end axially.
    const auto steel = Material::fromEnu("steel", 200e9, 0.3, 7850);
    const double A = 1e-3, I = 1e-5, J = 1e-9, L = 2.0;
    auto sec = std::make_shared<Section>(Section::general("thin", steel, A, I, I, J, 0, 0, 0.1));
    Model m;
    const Line line = uniformBeam(m, L, sec, 8, DofSet::frame3d());
    m.addSupport({"base", line.nodes.front(),
                  {{Dof::ux, 0}, {Dof::uy, 0}, {Dof::uz, 0}, {Dof::rx, 0}}});
    m.addSupport({"top", line.nodes.back(), {{Dof::uy, 0}, {Dof::uz, 0}, {Dof::rx, 0}}});
    m.addLoad({line.nodes.back(), Dof::ux, -1.0});
    const BucklingResult r = solveBuckling(m);
    const double torsional = steel.G * J * A / (2 * I);
    CHECK(torsional < kPi * kPi * steel.E * I / (L * L) / 100);  // far below flexural buckling
    REQUIRE(!r.modes.empty());
    CHECK(relError(r.modes[0].factor, torsional) < 1e-10);
    // The mode is a twist: largest rotation about x scaled to 1, no lateral translation.
    CHECK(r.modes[0].shape.col(3).cwiseAbs().maxCoeff() == doctest::Approx(1).epsilon(1e-12));
    CHECK(r.modes[0].shape.leftCols(3).cwiseAbs().maxCoeff() < 1e-9);
  }
}
