// Supports, hinges, springs and 3D frames: unsupported structures are named, not solved;
// hinges, springs and 3D members match their closed forms.
#include <doctest/doctest.h>

#include "elements/Spring.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/static/Static.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {
constexpr double kJointsExact = 1e-10;  // exact elements: round-off only

bool mentions(const std::vector<NodeDof>& dofs, int node, Dof d) {
  return std::find(dofs.begin(), dofs.end(), NodeDof{node, d}) != dofs.end();
}
}  // namespace

TEST_SUITE("supports and joints") {
  TEST_CASE("a beam held by one pin turns freely: the error names the moving dofs") {
    Model m;
    const Line line = uniformBeam(m, 2.0, steelCircle(0.05), 4);
    m.addSupport({"pin", line.nodes.front(), {{Dof::ux, 0}, {Dof::uy, 0}}});
    m.addLoad({line.nodes.back(), Dof::uy, -100});
    try {
      solveStatic(m);
      FAIL("an unsupported structure was solved");
    } catch (const UnsupportedStructure& e) {
      const std::string msg = e.what();
      MESSAGE(msg);
      CHECK(msg.find("not fully supported") != std::string::npos);
      // The rigid rotation about the pin moves every uy except the pin's, and every rz.
      CHECK(mentions(e.freeDofs(), line.nodes.back(), Dof::uy));
      CHECK(mentions(e.freeDofs(), line.nodes.front(), Dof::rz));
      CHECK_FALSE(mentions(e.freeDofs(), line.nodes.back(), Dof::ux));
    }
  }

  TEST_CASE("two hinges in a row make a mechanism at the node between them") {
    Model m;
    const Line line = uniformBeam(m, 2.0, steelCircle(0.05), 2);
    clamp(m, "left", line.nodes.front(), DofSet::planar());
    clamp(m, "right", line.nodes.back(), DofSet::planar());
    line.beams[0]->release(1, Dof::rz);
    line.beams[1]->release(0, Dof::rz);
    // Both elements drop the middle rotation, so it is not a dof at all; the structure is a
    // clamped-hinged-clamped beam, stable, and a central load gives P L^3 / (3 EI) per half
    // shared by two cantilevers: w = P (L/2)^3 / (6 EI).
    m.addLoad({line.nodes[1], Dof::uy, -100});
    const StaticResult r = solveStatic(m);
    const double EI = steelCircle(0.05)->EIz();
    CHECK(relError(r.displacement(line.nodes[1], 1), -100 * 1.0 / (6 * EI)) < kJointsExact);
    // The moment vanishes at the hinge.
    const auto stations = recoverBeamFields({m, r.displacement}, 2);
    for (const BeamStation& st : stations)
      if ((st.element == 0 && st.s == 1) || (st.element == 1 && st.s == 0))
        CHECK(std::abs(st.forces.Mz) < 1e-9 * 100);
  }

  TEST_CASE("a free node rotation is named") {
    // A point mass hung on a translational spring at a node nothing else holds.
    Model m;
    const int n = m.addNode({0, 0, 0});
    m.add<Spring>(NodeDof{n, Dof::uy}, 1e3);
    m.add<Spring>(NodeDof{n, Dof::ux}, NodeDof{n, Dof::rz}, 1e3);
    try {
      solveStatic(m);
      FAIL("solved");
    } catch (const UnsupportedStructure& e) {
      CHECK(mentions(e.freeDofs(), n, Dof::ux));
      CHECK(mentions(e.freeDofs(), n, Dof::rz));
      CHECK_FALSE(mentions(e.freeDofs(), n, Dof::uy));
    }
  }

  TEST_CASE("cantilever on a tip spring: w = P / (k + 3 EI / L^3)") {
    Model m;
    const auto s = steelCircle(0.05);
    const Line line = uniformBeam(m, 2.0, s, 5);
    clamp(m, "root", line.nodes.front(), DofSet::planar());
    const double k = 2e5, P = 500;
    m.add<Spring>(NodeDof{line.nodes.back(), Dof::uy}, k);
    m.addLoad({line.nodes.back(), Dof::uy, -P});
    const StaticResult r = solveStatic(m);
    const double w = -P / (k + 3 * s->EIz() / 8.0);
    CHECK(relError(r.displacement(line.nodes.back(), 1), w) < kJointsExact);
    // The root carries what the spring does not.
    CHECK(relError(r.reaction("root", Dof::uy), P + k * w) < kJointsExact);
  }

  TEST_CASE("3D frame: an inclined cantilever under a tip force and a tip torque") {
    Model m;
    const auto s = steelCircle(0.05);
    LineSpec spec;
    spec.dofs = DofSet::frame3d();
    spec.direction = Eigen::Vector3d(1, 2, 2);  // |d| = 3
    spec.segments.push_back({3.0, s, 6});
    spec.points = {{"root", 0}, {"tip", 3.0}};
    buildLine(m, spec);
    clamp(m, "root", m.node("root"), DofSet::frame3d());
    const int tip = m.node("tip");
    // A force perpendicular to the axis and a torque about it.
    const Eigen::Vector3d axis = spec.direction.normalized();
    const Eigen::Vector3d perp = Eigen::Vector3d(2, -1, 0).normalized();
    const double P = 300, T = 150;
    for (int k = 0; k < 3; ++k) {
      m.addLoad({tip, kAllDofs[k], P * perp[k]});
      m.addLoad({tip, kAllDofs[k + 3], T * axis[k]});
    }
    const StaticResult r = solveStatic(m);
    const Eigen::Vector3d u = r.displacement.row(tip).head<3>();
    const Eigen::Vector3d rot = r.displacement.row(tip).tail<3>();
    CHECK(relError(u.dot(perp), P * 27 / (3 * s->EIz())) < kJointsExact);
    CHECK(std::abs(u.dot(axis)) < kJointsExact * u.norm());
    CHECK(relError(rot.dot(axis), T * 3.0 / s->GJ()) < kJointsExact);
  }
}

TEST_SUITE("supports and joints") {
  TEST_CASE("distributed load: reactions q L / 2 and the fixed-end moments q L^2 / 12") {
    const double L = 3.0, q = -2000.0;
    Model m;
    const Line line = uniformBeam(m, L, steelCircle(0.06), 6);
    for (Beam* b : line.beams) b->setDistributedLoad({0, q, 0});
    clamp(m, "left", line.nodes.front(), DofSet::planar());
    clamp(m, "right", line.nodes.back(), DofSet::planar());
    const StaticResult r = solveStatic(m);
    CHECK(relError(r.reaction("left", Dof::uy), -q * L / 2) < kJointsExact);
    CHECK(relError(r.reaction("right", Dof::uy), -q * L / 2) < kJointsExact);
    CHECK(relError(r.reaction("left", Dof::rz), -q * L * L / 12) < kJointsExact);
    CHECK(relError(r.reaction("right", Dof::rz), q * L * L / 12) < kJointsExact);
  }
}
