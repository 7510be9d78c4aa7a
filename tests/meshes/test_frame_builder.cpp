// The frame builder: the default member axes of FORMAT.md (local z from global z, local y =
// global y for members along z), references and roll, against the axes written out by hand;
// joints shared by the members meeting there, stations on nodes.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "meshes/FrameBuilder.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;

namespace {

/// |R - expected| for rows x, y, z given as global vectors.
double axesError(const Eigen::Matrix3d& R, const Eigen::Vector3d& x, const Eigen::Vector3d& y,
                 const Eigen::Vector3d& z) {
  Eigen::Matrix3d expected;
  expected.row(0) = x;
  expected.row(1) = y;
  expected.row(2) = z;
  return (R - expected).cwiseAbs().maxCoeff();
}

const Eigen::Vector3d kX = Eigen::Vector3d::UnitX(), kY = Eigen::Vector3d::UnitY(),
                      kZ = Eigen::Vector3d::UnitZ();

}  // namespace

TEST_SUITE("frame builder") {
  TEST_CASE("default member axes follow the stated convention") {
    // Exact unit vectors in, exact unit vectors out: round-off only (1e-15).
    const MemberOrientation none;
    // Level member along +x: z = +z, y = z x x = +y.
    CHECK(axesError(memberAxes(3 * kX, none), kX, kY, kZ) < 1e-15);
    // Leftward member: local z still +z (planar frames), y = z x (-x) = -y.
    CHECK(axesError(memberAxes(-2 * kX, none), -kX, -kY, kZ) < 1e-15);
    // Column going up: z = +z, y = z x y = -x.
    CHECK(axesError(memberAxes(4 * kY, none), kY, -kX, kZ) < 1e-15);
    // Member along global z: local y = global +y, z = x x y = z x y = -x.
    CHECK(axesError(memberAxes(kZ, none), kZ, kY, -kX) < 1e-15);
    CHECK(axesError(memberAxes(-kZ, none), -kZ, kY, kX) < 1e-15);
    // Sloped member in the x-y plane at 30 degrees: y is x turned 90 degrees counter-clockwise.
    const double c = std::cos(test::kPi / 6), s = std::sin(test::kPi / 6);
    CHECK(axesError(memberAxes(Eigen::Vector3d(c, s, 0), none), Eigen::Vector3d(c, s, 0),
                    Eigen::Vector3d(-s, c, 0), kZ) < 1e-15);
  }

  TEST_CASE("references and roll turn the member's axes") {
    MemberOrientation zUp;
    zUp.zReference = Eigen::Vector3d(0.7, 5, 0);  // only its part across the member counts
    CHECK(axesError(memberAxes(kX, zUp), kX, -kZ, kY) < 1e-15);
    MemberOrientation yAcross;
    yAcross.yReference = kZ;
    CHECK(axesError(memberAxes(kX, yAcross), kX, kZ, -kY) < 1e-15);
    // A roll of 90 degrees about +x takes y to z and z to -y (round-off of cos(pi/2)).
    MemberOrientation rolled;
    rolled.roll = test::kPi / 2;
    CHECK(axesError(memberAxes(kX, rolled), kX, kZ, -kY) < 1e-15);
    MemberOrientation parallel;
    parallel.zReference = 2 * kX;
    CHECK_THROWS_AS(memberAxes(kX, parallel), std::invalid_argument);
  }

  TEST_CASE("members share their joints; stations become nodes") {
    // A portal: 4 joints, 3 members of 2, 3 and 2 elements, one station at 0.5 of the beam
    // (inside its second element, so it adds a cut: 2 + (2 + 2) + 2 elements, 4 + 1 + 4 + 1
    // nodes: joints, the columns' middles, the beam's cuts).
    Model model;
    FrameSpec spec;
    spec.joints = {{"A", Eigen::Vector3d(0, 0, 0)}, {"B", Eigen::Vector3d(0, 3, 0)},
                   {"C", Eigen::Vector3d(4, 3, 0)}, {"D", Eigen::Vector3d(4, 0, 0)}};
    const auto section = test::steelRectangle(0.05, 0.1);
    spec.members = {{0, 1, Segment{0, section, 2, 0, {}}, {}, {}},
                    {1, 2, Segment{0, section, 3, 0, {}}, {}, {}},
                    {3, 2, Segment{0, section, 2, 0, {}}, {}, {}}};
    spec.stations = {{"middle", 1, 0.5}};
    const FrameMesh mesh = buildFrame(model, spec);
    CHECK(mesh.memberBeams[0].size() == 2);
    CHECK(mesh.memberBeams[1].size() == 4);
    CHECK(mesh.memberBeams[2].size() == 2);
    CHECK(model.nodeCount() == 4 + 1 + 3 + 1);
    CHECK(mesh.memberBeams[0].back()->endNodes()[1] == model.node("B"));
    CHECK(mesh.memberBeams[1].front()->endNodes()[0] == model.node("B"));
    CHECK(mesh.memberBeams[2].back()->endNodes()[1] == model.node("C"));
    CHECK((model.nodes()[model.node("middle")] - Eigen::Vector3d(2, 3, 0)).norm() < 1e-15);
    spec.joints[3].x = spec.joints[0].x;
    Model other;
    CHECK_THROWS_AS(buildFrame(other, spec), std::invalid_argument);
  }
}
