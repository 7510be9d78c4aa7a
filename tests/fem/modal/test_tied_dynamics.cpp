// Rigid ties beyond first-order statics (issue 47): the pencil T' K T, T' M T of the modes and
// T' K T, T' KG T of buckling. A two-storey shear frame whose floors are diaphragms against
// its closed-form modes (storey stiffness 12 E I / h^3 per column; e.g. Chopra, Dynamics of
// Structures, 4th ed., sec. 10.2), a member with end offsets against the same member between
// the offset points on rigid arms transformed by hand and solved densely, a column with a
// rigid cap against the closed form of its buckling load (the cap's own P-delta) and against
// the equilibrium of its deformed state (second order), and a clamp reached only through an
// offset taking the spectrum's whole base force.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>

#include "elements/Beam.hpp"
#include "fem/model/Model.hpp"
#include "tests/fem/static/RigidTieDecks.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace tied_dynamics {

using test::ties::fmt;
using test::ties::kD;
using test::ties::kE;
using test::ties::kNu;

/// A clamped column of length L (16 elements) from A to B under a rigid cap of height e from
/// B to C, loaded at C by fx and fy, and analysed by `analysis`. `chained`: the cap is two
/// links, B to M (halfway, 0.1 e aside) and M to C.
std::string cappedColumn(double L, double e, double fx, double fy, const std::string& analysis,
                         bool chained = false) {
  const std::string cap =
      chained ? "rigid_links: [{name: lower, master: B, slave: M},\n"
                "              {name: upper, master: M, slave: C}]\n"
              : "rigid_links: [{name: cap, master: B, slave: C}]\n";
  const std::string middle =
      chained ? ", {name: M, at: [" + fmt(0.1 * e) + ", " + fmt(L + e / 2) + "]}" : "";
  return "model: {dimension: planar}\n"
         "materials: [{name: steel, E: " + fmt(kE) + ", nu: " + fmt(kNu) + "}]\n"
         "sections: [{name: bar, shape: circle, D: " + fmt(kD) + "}]\n"
         "nodes: [{name: A, at: [0, 0]}, {name: B, at: [0, " + fmt(L) + "]}, {name: C, at: [0, " +
         fmt(L + e) + "]}" + middle + "]\n"
         "members: [{name: col, from: A, to: B, section: bar, elements: 16}]\n"
         "supports: [{name: A, at: A, fix: clamped}]\n" + cap +
         "loads: [{type: point, at: C, fx: " + fmt(fx) + ", fy: " + fmt(fy) + "}]\n"
         "analyses: [" + analysis + "]\n";
}

/// The eigenvalues of the 2-storey shear building [k1 + k2, -k2; -k2, k2] x = w^2 diag(m, m)
/// x with k1 = k2 = k: w^2 = (3 -+ sqrt 5) / 2 k / m.
std::array<double, 2> twoStoreys(double k, double m) {
  return {(3 - std::sqrt(5.0)) / 2 * k / m, (3 + std::sqrt(5.0)) / 2 * k / m};
}

const ModalResult& modesOfFirst(const Study& s) {
  const ModalResult* m = resultOf<ModalResult>(s.run->analyses.front());
  REQUIRE(m);
  return *m;
}

TEST_SUITE("rigid ties in dynamics and stability") {
  TEST_CASE("a two-storey shear frame with diaphragm floors: its closed-form modes") {
    // Four massless columns per storey (clamped at the ground, rx and rz held at the floors
    // by stiff floor beams), each floor a diaphragm in x-z carrying m at its corners. A sway
    // along x or z is the two-storey shear building of storey stiffness k = 4 x 12 E I / h^3;
    // a turn about y that of storey stiffness k a^2 / 2 + 4 G J / h (each column a / sqrt 2
    // from the floor's centre sways and twists) and floor inertia m a^2 / 2. The axial modes
    // lie far above (E A / h against m / 4).
    const double h = 3, a = 4, m = 16e3;
    const double I = std::numbers::pi * std::pow(kD, 4) / 64, J = 2 * I;
    const double G = kE / (2 * (1 + kNu)), k = 4 * 12 * kE * I / (h * h * h);
    std::ostringstream d;
    d.precision(17);
    d << "model: {dimension: 3d}\n"
      << "materials: [{name: steel, E: " << kE << ", nu: " << kNu << "}]\n"
      << "sections: [{name: col, shape: circle, D: " << kD << "}]\n"
      << "nodes:\n";
    const double corners[4][2] = {{0, 0}, {a, 0}, {0, a}, {a, a}};
    for (int level = 0; level <= 2; ++level)
      for (int i = 0; i < 4; ++i)
        d << "  - {name: N" << level << i << ", at: [" << corners[i][0] << ", " << level * h
          << ", " << corners[i][1] << "]}\n";
    d << "members:\n";
    for (int level = 1; level <= 2; ++level)
      for (int i = 0; i < 4; ++i)
        d << "  - {name: c" << level << i << ", from: N" << level - 1 << i << ", to: N" << level
          << i << ", section: col, elements: 2}\n";
    d << "supports:\n";
    for (int i = 0; i < 4; ++i) d << "  - {name: A" << i << ", at: N0" << i << ", fix: clamped}\n";
    for (int level = 1; level <= 2; ++level)
      for (int i = 0; i < 4; ++i)
        d << "  - {name: B" << level << i << ", at: N" << level << i << ", fix: [rx, rz]}\n";
    d << "diaphragms:\n";
    for (int level = 1; level <= 2; ++level)
      d << "  - {name: floor" << level << ", master: N" << level << "0, points: [N" << level
        << "1, N" << level << "2, N" << level << "3], plane: xz}\n";
    d << "masses:\n";
    for (int level = 1; level <= 2; ++level)
      for (int i = 0; i < 4; ++i)
        d << "  - {name: m" << level << i << ", at: N" << level << i << ", m: " << m / 4 << "}\n";
    d << "analyses: [{type: modal, modes: 6}]\n";
    const Study s = test::solveDeckText(d.str(), "storeys.yaml");
    const ModalResult& modal = modesOfFirst(s);
    REQUIRE(modal.modes.size() == 6);

    const std::array<double, 2> sway = twoStoreys(k, m);
    const std::array<double, 2> turn = twoStoreys(k * a * a / 2 + 4 * G * J / h, m * a * a / 2);
    std::vector<double> expected = {sway[0], sway[0], turn[0], sway[1], sway[1], turn[1]};
    std::sort(expected.begin(), expected.end());
    // The elements are exact for end-loaded columns and the ties exact constraints: the
    // eigenvalues agree to the eigensolver's round-off (1e-9 leaves room).
    double worst = 0;
    for (int j = 0; j < 6; ++j) {
      const double w2 = modal.modes[std::size_t(j)].eigenvalue, ref = expected[std::size_t(j)];
      CHECK(w2 == doctest::Approx(ref).epsilon(1e-9));
      worst = std::max(worst, std::abs(w2 - ref) / ref);
    }
    MESSAGE("two storeys, diaphragm floors: largest eigenvalue error " << worst);
    // The floors' masses reach the effective masses through T' M T: all of both floors' mass
    // along x lies in the two x-sway modes (a conservation the six modes complete).
    double alongX = 0, alongZ = 0;
    for (const Mode& mode : modal.modes) {
      alongX += mode.effectiveMass[0];
      alongZ += mode.effectiveMass[2];
    }
    CHECK(modal.totalMass[0] == doctest::Approx(2 * m).epsilon(1e-12));
    CHECK(alongX == doctest::Approx(2 * m).epsilon(1e-9));
    CHECK(alongZ == doctest::Approx(2 * m).epsilon(1e-9));
    // The lower sway pair's effective mass along x: (phi' M 1)^2 / phi' M phi with
    // phi = (1, phi2), phi2 = 2 - w^2 m / k for the shear building. The x and z sways share
    // their frequency, so the eigensolver may return any two orthogonal mixes of them: the
    // pair's sum is what is fixed.
    const double phi2 = 2 - sway[0] * m / k;
    const double lower = std::pow(m * (1 + phi2), 2) / (m * (1 + phi2 * phi2));
    double lowerPairX = 0;
    for (const Mode& mode : modal.modes)
      if (std::abs(mode.eigenvalue - sway[0]) <= 1e-9 * sway[0]) lowerPairX += mode.effectiveMass[0];
    CHECK(lowerPairX == doctest::Approx(lower).epsilon(1e-9));
  }

  TEST_CASE("a member with end offsets vibrates as the member on rigid arms, solved densely") {
    // A cantilever from A (clamped) towards B, its one element running from A + r1 to B + r2,
    // its mass its own. Reference: the same Euler-Bernoulli element's K and M, B's arm
    // transformation T (u_end = u_B + theta x r2) applied by hand, K_B = T' K T and
    // M_B = T' M T, and the dense generalised eigensolver; the clamped end's arm holds the
    // member's start fixed.
    const double L = 2.0, rho = 7850;
    const Eigen::Vector2d r1(0.15, 0.1), r2(-0.2, -0.05);
    const std::string deck =
        "model: {dimension: planar}\n"
        "materials: [{name: steel, E: " + fmt(kE) + ", nu: " + fmt(kNu) + ", rho: " + fmt(rho) +
        "}]\n"
        "sections: [{name: bar, shape: circle, D: " + fmt(kD) + "}]\n"
        "nodes: [{name: A, at: [0, 0]}, {name: B, at: [" + fmt(L) + ", 0]}]\n"
        "members: [{name: arm, from: A, to: B, section: bar, elements: 1,\n"
        "           offsets: {start: [" + fmt(r1.x()) + ", " + fmt(r1.y()) + "], end: [" +
        fmt(r2.x()) + ", " + fmt(r2.y()) + "]}}]\n"
        "supports: [{name: A, at: A, fix: clamped}]\n"
        "analyses: [{type: modal, modes: 3}]\n";
    const Study s = test::solveDeckText(deck, "offsets.yaml");
    const ModalResult& modal = modesOfFirst(s);
    REQUIRE(modal.modes.size() == 3);

    const Material steel = Material::fromEnu("steel", kE, kNu, rho);
    const auto section = std::make_shared<const Section>(Section::circle("bar", steel, kD));
    const Eigen::Vector3d p1(r1.x(), r1.y(), 0), p2(L + r2.x(), r2.y(), 0);
    Model m;
    const int a = m.addNode(p1), b = m.addNode(p2);
    const Beam beam(a, p1, b, p2, section, DofSet::planar());
    const ElementMatrix K = beam.stiffness(), M = beam.mass();  // ux uy rz at each end
    REQUIRE(K.rows() == 6);
    REQUIRE(M.rows() == 6);
    Eigen::Matrix3d T = Eigen::Matrix3d::Identity();
    T(0, 2) = -r2.y();
    T(1, 2) = r2.x();
    const Eigen::Matrix3d KB = T.transpose() * K.bottomRightCorner(3, 3) * T;
    const Eigen::Matrix3d MB = T.transpose() * M.bottomRightCorner(3, 3) * T;
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> dense(KB, MB);
    REQUIRE(dense.info() == Eigen::Success);
    // The same matrices reduced two ways: round-off (1e-9 relative).
    double worst = 0;
    for (int j = 0; j < 3; ++j) {
      const double w2 = modal.modes[std::size_t(j)].eigenvalue, ref = dense.eigenvalues()[j];
      CHECK(w2 == doctest::Approx(ref).epsilon(1e-9));
      worst = std::max(worst, std::abs(w2 - ref) / ref);
    }
    MESSAGE("member with end offsets: largest eigenvalue error against the dense solve " << worst);
    // The shape at B (the arm's master) is the dense eigenvector, up to its scale and sign.
    const int B = s.run->model->node("B");
    const Eigen::Vector3d phi = dense.eigenvectors().col(0);
    const NodalField& shape = modal.modes.front().shape;
    const Eigen::Vector3d atB(shape(B, dofIndex(Dof::ux)), shape(B, dofIndex(Dof::uy)),
                              shape(B, dofIndex(Dof::rz)));
    const double scale = atB.dot(phi) / phi.dot(phi);
    CHECK((atB - scale * phi).norm() <= 1e-9 * atB.norm());
  }

  TEST_CASE("a column with a rigid cap buckles at its closed form, the cap's P-delta included") {
    // A cantilever column of length L, clamped at its foot, carries a rigid cap of height e
    // (a rigid link from its top B to C) loaded downwards at C by P. Buckled, the column's top
    // sways by delta and turns by theta, C by delta + e theta; with v = delta_C (1 - cos k x),
    // k^2 = P / E I, the top's values close to cos kL = e k sin kL, i.e.
    // kL tan kL = L / e (e = 0: Euler's kL = pi / 2). Solved by bisection on (0, pi / 2).
    const double L = 3, e = 0.75, P = 1e3;
    const double I = std::numbers::pi * std::pow(kD, 4) / 64;
    double lo = 1e-9, hi = std::numbers::pi / 2 - 1e-12;
    for (int i = 0; i < 200; ++i) {
      const double mid = (lo + hi) / 2;
      (mid * std::tan(mid) < L / e ? lo : hi) = mid;
    }
    const double critical = kE * I * std::pow(lo / L, 2);
    const std::string column = cappedColumn(L, e, 0, -P, "{type: buckling, modes: 1}");
    const Study s = test::solveDeckText(column, "cap.yaml");
    const BucklingResult* b = resultOf<BucklingResult>(s.run->analyses.front());
    REQUIRE(b);
    REQUIRE(!b->modes.empty());
    // Cubic elements with the consistent geometric stiffness converge as h^4: 16 elements
    // leave 5.4e-8 here (measured); 2e-7 allows it. Without the cap's own
    // geometric stiffness the factor would be Euler's pi^2 E I / (4 L^2) / P, 45 % higher.
    CHECK(b->modes.front().factor * P == doctest::Approx(critical).epsilon(2e-7));
    MESSAGE("column with a rigid cap: closed form " << critical << " N, error "
                                                    << std::abs(b->modes.front().factor * P - critical) / critical);
    const double euler = std::numbers::pi * std::numbers::pi * kE * I / (4 * L * L);
    CHECK(std::abs(b->modes.front().factor * P - euler) > 0.2 * euler);

    // The cap as a chain of two links (through a point off the axis): the same rigid body,
    // so the same factor; the cap's P-delta takes its arm from B, the chain's first master.
    const Study chain = test::solveDeckText(
        cappedColumn(L, e, 0, -P, "{type: buckling, modes: 1}", true), "chain.yaml");
    const BucklingResult* bc = resultOf<BucklingResult>(chain.run->analyses.front());
    REQUIRE(bc);
    REQUIRE(!bc->modes.empty());
    // The same matrices but for round-off: 1e-9 (Lanczos converges to ~1e-12).
    CHECK(bc->modes.front().factor == doctest::Approx(b->modes.front().factor).epsilon(1e-9));
    MESSAGE("cap as a chain of two links: factor off the one-link cap's by "
            << std::abs(bc->modes.front().factor / b->modes.front().factor - 1));
  }

  TEST_CASE("response spectrum: a clamp that holds its member through an offset reacts") {
    // A massless column hangs from its clamp A through a start offset (a rigid arm up its
    // axis), a mass on its top. No element touches A: its reaction is what the arm's tie
    // carries. One sway mode along x (the other, axial, has no x mass): the clamp takes the
    // whole base force m Sa, here with Sa a flat 5 m/s^2.
    const double L = 3, m = 1000;
    const std::string deck =
        "model: {dimension: planar}\n"
        "materials: [{name: steel, E: " + fmt(kE) + ", nu: " + fmt(kNu) + "}]\n"
        "sections: [{name: bar, shape: circle, D: " + fmt(kD) + "}]\n"
        "nodes: [{name: A, at: [0, 0]}, {name: B, at: [0, " + fmt(L) + "]}]\n"
        "members: [{name: col, from: A, to: B, section: bar, elements: 1,\n"
        "           offsets: {start: [0, 0.2]}}]\n"
        "supports: [{name: A, at: A, fix: clamped}]\n"
        "masses: [{name: top, at: B, m: " + fmt(m) + "}]\n"
        "analyses: [{type: response-spectrum, modes: 2, directions: [x],\n"
        "            spectrum: {table: [[0, 5], [10, 5]]}}]\n";
    const Study s = test::solveDeckText(deck, "hung.yaml");
    const auto* r = resultOf<ResponseSpectrumResult>(s.run->analyses.front());
    REQUIRE(r);
    double fx = 0;
    for (const ReactionComponent& c : r->combined.reactions)
      if (c.support == "A" && c.dof == Dof::ux) fx = c.value;
    // One mode carries all of the x mass: m Sa to round-off (1e-9).
    CHECK(r->combined.baseForce[0] == doctest::Approx(m * 5).epsilon(1e-9));
    CHECK(fx == doctest::Approx(m * 5).epsilon(1e-9));
  }

  TEST_CASE("second order: the capped column balances in its deformed state, cap included") {
    // The same column and cap under P down and H across at C. In the deformed state the clamp
    // holds M_A = H (L + e) + P u_C, C's sway lever including the cap's tilt (without the
    // cap's own geometric stiffness it would be P u_B, 1 kN m less here).
    const double L = 3, e = 0.75, P = 1e5, H = 1e3;
    const std::string column = cappedColumn(L, e, H, -P, "{type: static, second_order: true}");
    const Study s = test::solveDeckText(column, "cap.yaml");
    const StaticResult& r = *staticsOf(s.run->analyses.front());
    const int B = s.run->model->node("B"), C = s.run->model->node("C");
    const double uB = r.displacement(B, dofIndex(Dof::ux)), uC = r.displacement(C, dofIndex(Dof::ux));
    const double rz = r.displacement(B, dofIndex(Dof::rz));
    // The cap follows B rigidly: u_C = u_B - e rz (a turn about z moves a point above to -x).
    CHECK(uC == doctest::Approx(uB - e * rz).epsilon(1e-12));
    // Equilibrium of the whole deformed body: the reaction from the element forces and the
    // tie's, against the statics of the loads on their displaced points (round-off; 1e-9).
    CHECK(r.reaction("A", Dof::rz) == doctest::Approx(H * (L + e) + P * uC).epsilon(1e-9));
    CHECK(std::abs(P * (uC - uB)) > 0.1 * H * (L + e));
  }
}

}  // namespace tied_dynamics
