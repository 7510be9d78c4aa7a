// Rotor element properties: gyroscopic matrices of the shaft element and the rigid disk,
// bearings, and the assembled rotor matrices.
#include <doctest/doctest.h>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "fem/rotor/RotorSystem.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

// Matrices built from a few dozen products of O(1) coefficients: round-off only.
constexpr double kRotorElementRoundOff = 1e-13;

using Matrix12 = Beam::Matrix12;

/// Rigid tilt of a lateral beam element along x about global y (ry = 1) or z (rz = 1), local
/// dofs u v w rx ry rz per end: the translations follow the tilt (dw/dx = -ry, dv/dx = rz).
Beam::Vector12 rigidTilt(Dof about, double x1, double x2) {
  Beam::Vector12 t = Beam::Vector12::Zero();
  for (int end = 0; end < 2; ++end) {
    const double x = end == 0 ? x1 : x2;
    if (about == Dof::ry) {
      t[6 * end + 4] = 1;
      t[6 * end + 2] = -x;
    } else {
      t[6 * end + 5] = 1;
      t[6 * end + 1] = x;
    }
  }
  return t;
}

}  // namespace

TEST_SUITE("rotor elements") {
  TEST_CASE("shaft gyroscopic matrix: skew-symmetric, Jp of a rigid tilt, rotary mass pattern") {
    const auto sec = steelCircle(0.08);
    const double L = 0.3, x1 = 0.2;
    for (BeamTheory theory : {BeamTheory::eulerBernoulli, BeamTheory::timoshenko}) {
      CAPTURE(int(theory));
      const Beam beam(0, {x1, 0, 0}, 1, {x1 + L, 0, 0}, sec, DofSet::lateral(),
                      {theory, MassModel::consistent, true});
      const Matrix12 G = beam.localGyroscopic();
      const double scale = G.cwiseAbs().maxCoeff();
      REQUIRE(scale > 0);
      CHECK((G + G.transpose()).cwiseAbs().maxCoeff() <= kRotorElementRoundOff * scale);

      // A rigid tilt about y against one about z: the spinning shaft's polar inertia rho Ip L
      // (the interpolation reproduces rigid rotations exactly).
      const double Jp = sec->material.rho * sec->Ip() * L;
      const double coupling =
          rigidTilt(Dof::ry, x1, x1 + L).dot(G * rigidTilt(Dof::rz, x1, x1 + L));
      CHECK(relError(coupling, Jp) < kRotorElementRoundOff);

      // Nelson (1980): for equal shear parameters in both planes the coupling block is the
      // rotary-inertia mass block times Ip / I, with the x-z plane's rotation sign
      // (theta = -ry). The mass comes from Friedman and Kosmatka's printed coefficients, G
      // from integrating the rotation shape functions: two independent routes.
      const Beam noRotary(0, {x1, 0, 0}, 1, {x1 + L, 0, 0}, sec, DofSet::lateral(),
                          {theory, MassModel::consistent, false});
      const Matrix12 rotary = beam.localMass() - noRotary.localMass();
      const std::array<int, 4> xy{1, 5, 7, 11}, xz{2, 4, 8, 10};
      const Eigen::Vector4d flip(1, -1, 1, -1);
      const double ratio = sec->Ip() / sec->Iz;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const double expected = -flip[a] * ratio * rotary(xy[a], xy[b]);
          CHECK(std::abs(G(xz[a], xy[b]) - expected) <= kRotorElementRoundOff * scale);
        }
      // In the global carried dofs (uy, uz, ry, rz per node) of a lateral beam the sign of
      // the (ry, rz) coupling at a node is that of a disk's: positive.
      const ElementMatrix Gg = beam.gyroscopic();
      REQUIRE(Gg.rows() == 8);
      CHECK(Gg(2, 3) > 0);
      CHECK(Gg(6, 7) > 0);
    }
  }

  TEST_CASE("lumped mass: the shaft's polar inertia shared between the end nodes") {
    const auto sec = steelCircle(0.08);
    const double L = 0.3, half = sec->material.rho * sec->Ip() * L / 2;
    const Beam beam(0, {0, 0, 0}, 1, {L, 0, 0}, sec, DofSet::lateral(),
                    {BeamTheory::eulerBernoulli, MassModel::lumped, true});
    const ElementMatrix G = beam.gyroscopic();  // uy uz ry rz at each end
    Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(8, 8);
    for (int end : {0, 4}) {
      expected(end + 2, end + 3) = half;
      expected(end + 3, end + 2) = -half;
    }
    CHECK((G - expected).cwiseAbs().maxCoeff() <= kRotorElementRoundOff * half);
  }

  TEST_CASE("no rotary inertia or a planar beam: no gyroscopic matrix") {
    const auto sec = steelCircle(0.08);
    const Beam eb(0, {0, 0, 0}, 1, {1, 0, 0}, sec, DofSet::lateral());
    CHECK(eb.gyroscopic().size() == 0);
    const Beam planar(0, {0, 0, 0}, 1, {1, 0, 0}, sec, DofSet::planar(),
                      {BeamTheory::timoshenko, MassModel::consistent, true});
    CHECK(planar.gyroscopic().size() == 0);
  }

  TEST_CASE("disk gyroscopic matrix: Jp [0 1; -1 0] on (ry, rz), and -Jp [a]x for any axis") {
    const double Jp = 0.7;
    const PointInertia disk(3, DofSet::lateral(), 20, Jp, 0.4);
    const ElementMatrix G = disk.gyroscopic();  // dofs uy, uz, ry, rz
    REQUIRE(G.rows() == 4);
    Eigen::Matrix4d expected = Eigen::Matrix4d::Zero();
    expected(2, 3) = Jp;
    expected(3, 2) = -Jp;
    CHECK((G - expected).cwiseAbs().maxCoeff() == 0.0);

    // Spin about y is the cyclic permutation x -> y -> z -> x of spin about x, so (ry, rz)
    // becomes (rz, rx): G(rz, rx) = +Jp.
    const PointInertia yDisk(0, DofSet::frame3d(), 20, Jp, 0.4, Eigen::Vector3d::UnitY());
    const ElementMatrix Gy = yDisk.gyroscopic();  // dofs ux uy uz rx ry rz
    CHECK(Gy(5, 3) == doctest::Approx(Jp));
    CHECK(Gy(3, 5) == doctest::Approx(-Jp));
    CHECK((Gy + Gy.transpose()).cwiseAbs().maxCoeff() == 0.0);

    CHECK(PointInertia(0, DofSet::lateral(), 20).gyroscopic().size() == 0);
    CHECK(PointInertia(0, DofSet::planar(), 20, Jp, 0.4).gyroscopic().size() == 0);
  }

  TEST_CASE("bearing: global mapping, linear interpolation in speed, end rows held") {
    BearingCoefficients lo{1e7, 2e6, -3e6, 2e7, 100, 10, -20, 200};
    BearingCoefficients hi{3e7, 4e6, -1e6, 6e7, 300, 30, 20, 600};
    const Bearing b(5, {100, 300}, {lo, hi});
    REQUIRE(b.dofs().size() == 2);
    CHECK((b.dofs()[0] == NodeDof{5, Dof::uy}));
    CHECK((b.dofs()[1] == NodeDof{5, Dof::uz}));
    const ElementMatrix k = b.stiffnessAt(150);  // a quarter of the way
    CHECK(k(0, 0) == doctest::Approx(1.5e7));
    CHECK(k(0, 1) == doctest::Approx(2.5e6));
    CHECK(k(1, 0) == doctest::Approx(-2.5e6));
    CHECK(k(1, 1) == doctest::Approx(3e7));
    CHECK(b.dampingAt(150)(1, 0) == doctest::Approx(-10));
    CHECK(b.stiffness()(0, 0) == 1e7);       // at rest: below the table, first row held
    CHECK(b.stiffnessAt(1e4)(1, 1) == 6e7);  // above: last row held
    CHECK_THROWS_AS(Bearing(0, {2, 1}, {lo, hi}), std::invalid_argument);
    CHECK_THROWS_AS(Bearing(0, {1}, {lo, hi}), std::invalid_argument);
    CHECK(Bearing(0, BearingCoefficients::isotropic(1e7)).damping().size() == 0);
  }

  TEST_CASE("assembled rotor matrices: M symmetric, G skew, K(Omega) follows the bearings") {
    Model m;
    const Line line = uniformBeam(m, 1.2, steelCircle(0.06), 12, DofSet::lateral(),
                                  {BeamTheory::timoshenko, MassModel::consistent, true});
    m.add<PointInertia>(line.nodes[4], DofSet::lateral(), 15, 0.3, 0.17);
    m.add<Bearing>(line.nodes.front(), BearingCoefficients::isotropic(1e8, 1e3));
    BearingCoefficients slow{1e8, 0, 0, 1e8}, fast{2e8, 5e7, -5e7, 3e8, 10, 0, 0, 10};
    m.add<Bearing>(line.nodes.back(), std::vector<double>{0, 1000},
                   std::vector<BearingCoefficients>{slow, fast});
    const RotorSystem sys(m, {2.0, 1e-5});
    const Eigen::MatrixXd M(sys.mass()), G(sys.gyroscopic());
    CHECK((M - M.transpose()).cwiseAbs().maxCoeff() <=
          kRotorElementRoundOff * M.cwiseAbs().maxCoeff());
    CHECK((G + G.transpose()).cwiseAbs().maxCoeff() == 0.0);

    const DofMap& dofs = sys.dofs();
    const int y = dofs.equation(line.nodes.back(), Dof::uy);
    const int z = dofs.equation(line.nodes.back(), Dof::uz);
    const Eigen::MatrixXd K0(sys.stiffness(0)), K500(sys.stiffness(500));
    Eigen::MatrixXd dK = K500 - K0;
    CHECK(dK(y, y) == doctest::Approx(0.5e8));
    CHECK(dK(y, z) == doctest::Approx(0.25e8));
    CHECK(dK(z, y) == doctest::Approx(-0.25e8));
    CHECK(dK(z, z) == doctest::Approx(1e8));
    dK(y, y) = dK(y, z) = dK(z, y) = dK(z, z) = 0;
    CHECK(dK.cwiseAbs().maxCoeff() == 0.0);  // nothing else depends on speed
    // Rayleigh damping: C(Omega) = C_bearings(Omega) + alpha M + beta K(Omega).
    const Eigen::MatrixXd C(sys.damping(500));
    Eigen::MatrixXd expected = 2.0 * M + 1e-5 * K500;
    const int y0 = dofs.equation(line.nodes.front(), Dof::uy);
    expected(y0, y0) += 1e3;
    expected(dofs.equation(line.nodes.front(), Dof::uz),
             dofs.equation(line.nodes.front(), Dof::uz)) += 1e3;
    expected(y, y) += 5;
    expected(z, z) += 5;
    CHECK((C - expected).cwiseAbs().maxCoeff() <=
          kRotorElementRoundOff * expected.cwiseAbs().maxCoeff());
    // Every matrix shares one pattern (so sums keep it and the symbolic LU is reusable).
    CHECK(sys.stiffness(500).nonZeros() == sys.mass().nonZeros());
    CHECK(sys.gyroscopic().nonZeros() == sys.mass().nonZeros());
  }
}
