// Element properties that hold for every element kind, whatever the geometry: symmetric
// matrices, positive semi-definite stiffness and mass, no strain energy under rigid motion.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <functional>

#include "elements/Beam.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

// Element matrices are formed by a few hundred flops on O(1) data scaled by stiffness S:
// asymmetry and negative eigenvalues must stay at round-off, i.e. 1e-12 relative to S.
constexpr double kElementRoundOff = 1e-12;

/// Nodal displacement of a rigid-body motion (translation t, small rotation w about the
/// origin) at point x, for one dof kind.
double rigidMotion(Dof d, const Eigen::Vector3d& x, const Eigen::Vector3d& t,
                   const Eigen::Vector3d& w) {
  const Eigen::Vector3d u = t + w.cross(x);
  return isRotation(d) ? w[dofIndex(d) - 3] : u[dofIndex(d)];
}

void checkSymmetricPsd(const ElementMatrix& A, const char* what) {
  CAPTURE(what);
  if (A.size() == 0) return;
  const double scale = A.cwiseAbs().maxCoeff();
  REQUIRE(scale > 0);
  CHECK((A - A.transpose()).cwiseAbs().maxCoeff() <= kElementRoundOff * scale);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(A) * 0.5 +
                                                    Eigen::MatrixXd(A.transpose()) * 0.5);
  CHECK(es.eigenvalues().minCoeff() >= -kElementRoundOff * scale);
}

/// Rigid motions must produce no nodal forces: K u_rigid = 0.
void checkRigidMotionFree(const Element& e, const std::vector<Eigen::Vector3d>& nodes,
                          DofSet carried) {
  const ElementMatrix K = e.stiffness();
  const double scale = K.cwiseAbs().maxCoeff();
  const auto dofs = e.dofs();
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> motions;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d unit = Eigen::Vector3d::Unit(k);
    if (carried.contains(kAllDofs[k])) motions.push_back({unit, Eigen::Vector3d::Zero()});
    if (carried.contains(kAllDofs[k + 3])) motions.push_back({Eigen::Vector3d::Zero(), unit});
  }
  for (const auto& [t, w] : motions) {
    ElementVector u(dofs.size());
    for (int a = 0; a < int(dofs.size()); ++a)
      u[a] = rigidMotion(dofs[a].dof, nodes[dofs[a].node], t, w);
    // Length scales: rotations about the origin move nodes by ~|x| ~ 1 m.
    CHECK((K * u).cwiseAbs().maxCoeff() <= 1e-9 * scale);
  }
}

}  // namespace

TEST_SUITE("element properties") {
  TEST_CASE("beams: every theory, dof set, orientation and release") {
    const auto circle = steelCircle(0.08);
    const auto rect = steelRectangle(0.04, 0.1);
    const std::vector<BeamTheory> theories{BeamTheory::eulerBernoulli, BeamTheory::timoshenko,
                                           BeamTheory::timoshenkoLinearFullIntegration,
                                           BeamTheory::timoshenkoLinearReducedIntegration};
    struct Geometry {
      DofSet dofs;
      Eigen::Vector3d a, b;
    };
    const std::vector<Geometry> geometries{
        {DofSet::planar(), {0.1, 0.2, 0}, {0.9, -0.4, 0}},
        {DofSet::frame3d(), {0.1, 0.2, 0.3}, {0.7, -0.5, 1.1}},
        {DofSet::frame3d(), {0, 0, 0}, {0, 0, 1.5}},  // along z: the default hint changes
        {DofSet::lateral(), {0.2, 0, 0}, {0.8, 0, 0}}};
    for (const auto& section : {circle, rect})
      for (BeamTheory theory : theories)
        for (MassModel massModel : {MassModel::consistent, MassModel::lumped})
          for (const Geometry& g : geometries)
            for (int released = 0; released < 2; ++released) {
              CAPTURE(int(theory));
              CAPTURE(int(massModel));
              CAPTURE(released);
              Beam beam(0, g.a, 1, g.b, section, g.dofs, {theory, massModel, true});
              if (released) beam.release(1, g.dofs.contains(Dof::rz) ? Dof::rz : Dof::ry);
              checkSymmetricPsd(beam.stiffness(), "stiffness");
              checkSymmetricPsd(beam.mass(), "mass");
              checkRigidMotionFree(beam, {g.a, g.b}, g.dofs);
              // The mass matrix carries the element's mass in every rigid translation.
              const auto dofs = beam.dofs();
              for (int k = 0; k < 3; ++k) {
                if (!g.dofs.contains(kAllDofs[k])) continue;
                ElementVector u(dofs.size());
                for (int a = 0; a < int(dofs.size()); ++a)
                  u[a] = rigidMotion(dofs[a].dof, Eigen::Vector3d::Zero(), Eigen::Vector3d::Unit(k),
                                     Eigen::Vector3d::Zero());
                const double mass = u.dot(beam.mass() * u);
                CHECK(relError(mass, section->rhoA() * beam.length()) < kElementRoundOff * 10);
              }
            }
  }

  TEST_CASE("beams: a rigid rotation carries the element's inertia, each plane its own") {
    // Kinetic energy of a rigid motion (translation rate t, rotation rate w about the element's
    // middle c), twice over: the cross-sections' translation integrates to
    //   rho A L |t|^2 + rho A |w x e_x|^2 L^3 / 12
    // (the cross term vanishes about the middle), and their rotation adds
    //   rho L (Ip (w . e_x)^2 + Iy (w . e_y)^2 + Iz (w . e_z)^2),
    // the bending terms only with rotary inertia. Every consistent mass here integrates the
    // rigid field exactly (it lies in each element's interpolation); lumping puts rho A L / 2
    // at each end, which turns L^3 / 12 into L^3 / 4. A rectangle 0.04 x 0.1 has Iy != Iz and
    // J != Ip, so each plane's and the torsion's inertia count separately. Round-off only.
    const auto rect = steelRectangle(0.04, 0.1);
    const double rho = rect->material.rho;
    struct Geometry {
      DofSet dofs;
      Eigen::Vector3d a, b;
    };
    const std::vector<Geometry> geometries{{DofSet::planar(), {0.1, 0.2, 0}, {0.9, -0.4, 0}},
                                           {DofSet::frame3d(), {0.1, 0.2, 0.3}, {0.7, -0.5, 1.1}},
                                           {DofSet::frame3d(), {0, 0, 0}, {0, 0, 1.5}},
                                           {DofSet::lateral(), {0.2, 0, 0}, {0.8, 0, 0}}};
    const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> motions{
        {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()},
        {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY()},
        {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()},
        {Eigen::Vector3d(0.3, -0.7, 0.4), Eigen::Vector3d(0.9, 0.5, -0.6)}};
    for (BeamTheory theory : {BeamTheory::eulerBernoulli, BeamTheory::timoshenko,
                              BeamTheory::timoshenkoLinearFullIntegration,
                              BeamTheory::timoshenkoLinearReducedIntegration})
      for (MassModel massModel : {MassModel::consistent, MassModel::lumped})
        for (bool rotary : {false, true})
          for (const Geometry& g : geometries)
            for (int released = 0; released < 2; ++released) {
              CAPTURE(int(theory));
              CAPTURE(int(massModel));
              CAPTURE(rotary);
              CAPTURE(released);
              Beam beam(0, g.a, 1, g.b, rect, g.dofs, {theory, massModel, rotary});
              if (released) beam.release(1, g.dofs.contains(Dof::rz) ? Dof::rz : Dof::ry);
              // The element's axes as the constructor documents them: local z is global z
              // (global y for an element along z) made normal to the axis.
              const double L = (g.b - g.a).norm();
              const Eigen::Vector3d ex = (g.b - g.a) / L;
              const Eigen::Vector3d hint =
                  std::abs(ex.z()) > 1 - 1e-9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
              const Eigen::Vector3d ez = (hint - hint.dot(ex) * ex).normalized(), ey = ez.cross(ex);
              const Eigen::Vector3d c = (g.a + g.b) / 2;
              const double lever = massModel == MassModel::lumped ? 0.25 : 1.0 / 12;
              for (auto [t, w] : motions) {
                // Keep the components the dof set carries.
                for (int k = 0; k < 3; ++k) {
                  if (!g.dofs.contains(kAllDofs[k])) t[k] = 0;
                  if (!g.dofs.contains(kAllDofs[k + 3])) w[k] = 0;
                }
                if (w.isZero()) continue;
                const auto dofs = beam.dofs();
                ElementVector u(dofs.size());
                for (int a = 0; a < int(dofs.size()); ++a)
                  u[a] = rigidMotion(dofs[a].dof, (dofs[a].node == 0 ? g.a : g.b) - c, t, w);
                const double expected =
                    rect->rhoA() * L *
                        (t.squaredNorm() + lever * L * L * w.cross(ex).squaredNorm()) +
                    rho * L *
                        (rect->Ip() * std::pow(w.dot(ex), 2) +
                         (rotary ? rect->Iy * std::pow(w.dot(ey), 2) +
                                       rect->Iz * std::pow(w.dot(ez), 2)
                                 : 0));
                CAPTURE(w.transpose());
                CHECK(relError(u.dot(beam.mass() * u), expected) < kElementRoundOff * 10);
              }
            }
  }

  TEST_CASE("springs and inertias") {
    Spring grounded({0, Dof::uy}, 5e6, 10);
    Spring twoNode({0, Dof::rz}, {1, Dof::rz}, 3e4, 2);
    checkSymmetricPsd(grounded.stiffness(), "grounded spring");
    checkSymmetricPsd(twoNode.stiffness(), "two-node spring");
    checkSymmetricPsd(twoNode.damping(), "two-node damper");
    // A two-node spring stores no energy when both ends turn together.
    CHECK((twoNode.stiffness() * Eigen::Vector2d(1, 1)).norm() == 0);
    PointInertia body(0, DofSet::frame3d(), 12.0, 0.4, 0.25, Eigen::Vector3d(1, 1, 0));
    checkSymmetricPsd(body.mass(), "rigid inertia");
    // Kinetic energy of a spin about the body axis is Jp w^2 / 2.
    const Eigen::Vector3d axis = Eigen::Vector3d(1, 1, 0).normalized();
    ElementVector spin(6);
    spin << 0, 0, 0, axis.x(), axis.y(), axis.z();
    CHECK(relError(spin.dot(body.mass() * spin), 0.4) < kElementRoundOff);
  }
}
