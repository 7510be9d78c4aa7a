// Rigid ties eliminated exactly (issue 47): member end offsets against the same member between
// the offset points with rigid arms built into a dense system by hand, and a rigid floor
// (diaphragm) on four fixed-fixed columns against the textbook storey stiffness 12 E I / h^3
// per column (e.g. Chopra, Dynamics of Structures, 4th ed., sec. 1.3) and its twist.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>

#include "elements/Beam.hpp"
#include "fem/model/Model.hpp"
#include "fem/static/Static.hpp"
#include "tests/fem/static/RigidTieDecks.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace rigid_ties_tests {

using test::ties::fmt;
using test::ties::kD;
using test::ties::kE;
using test::ties::kNu;

TEST_SUITE("rigid ties") {
  TEST_CASE("a member with end offsets: the member between the offset points on rigid arms") {
    // A cantilever from A (clamped) to B, its member running from A + r1 to B + r2; B carries
    // a force and a moment. Reference: one Euler-Bernoulli beam from A + r1 to B + r2, its end
    // displacements those of the rigid arms (u_end = u_node + theta x r), K_node = T' K T,
    // solved densely for B's three dofs.
    const double L = 2.0;
    const Eigen::Vector2d r1(0.15, 0.1), r2(-0.2, -0.05);
    const double Fx = 3e3, Fy = -8e3, M = 1.5e3;
    const std::string deck =
        "model: {dimension: planar}\n"
        "materials: [{name: steel, E: " + fmt(kE) + ", nu: " + fmt(kNu) + "}]\n"
        "sections: [{name: bar, shape: circle, D: " + fmt(kD) + "}]\n"
        "nodes: [{name: A, at: [0, 0]}, {name: B, at: [" + fmt(L) + ", 0]}]\n"
        "members: [{name: arm, from: A, to: B, section: bar, elements: 3,\n"
        "           offsets: {start: [" + fmt(r1.x()) + ", " + fmt(r1.y()) + "], end: [" +
        fmt(r2.x()) + ", " + fmt(r2.y()) + "]}}]\n"
        "supports: [{name: A, at: A, fix: clamped}]\n"
        "loads: [{type: point, at: B, fx: " + fmt(Fx) + ", fy: " + fmt(Fy) + ", mz: " + fmt(M) + "}]\n"
        "analyses: [{type: static}]\n";
    const Study s = test::solveDeckText(deck, "offsets.yaml");
    const RunResult& run = *s.run;
    const StaticResult& r = *staticsOf(run.analyses.front());
    const int B = run.model->node("B");

    // The reference, by hand.
    const Material steel = Material::fromEnu("steel", kE, kNu, 0);
    const auto section = std::make_shared<const Section>(Section::circle("bar", steel, kD));
    const Eigen::Vector3d p1(r1.x(), r1.y(), 0), p2(L + r2.x(), r2.y(), 0);
    Model m;
    const int a = m.addNode(p1), b = m.addNode(p2);
    const Beam beam(a, p1, b, p2, section, DofSet::planar());
    const ElementMatrix K = beam.stiffness();  // ux uy rz at each end
    REQUIRE(K.rows() == 6);
    Eigen::Matrix3d T = Eigen::Matrix3d::Identity();  // end (ux, uy, rz) from node's
    T(0, 2) = -r2.y();
    T(1, 2) = r2.x();
    const Eigen::Matrix3d KB = T.transpose() * K.bottomRightCorner(3, 3) * T;
    const Eigen::Vector3d u = KB.ldlt().solve(Eigen::Vector3d(Fx, Fy, M));
    // The clamped end's arm holds the member's start fixed: only B's arm enters.
    // Both solutions are exact (end-loaded elements): round-off, 1e-9 relative.
    CHECK(r.displacement(B, dofIndex(Dof::ux)) == doctest::Approx(u[0]).epsilon(1e-9));
    CHECK(r.displacement(B, dofIndex(Dof::uy)) == doctest::Approx(u[1]).epsilon(1e-9));
    CHECK(r.displacement(B, dofIndex(Dof::rz)) == doctest::Approx(u[2]).epsilon(1e-9));
    // The clamp holds the whole load through the start arm: statics of the free body.
    CHECK(r.reaction("A", Dof::ux) == doctest::Approx(-Fx).epsilon(1e-9));
    CHECK(r.reaction("A", Dof::uy) == doctest::Approx(-Fy).epsilon(1e-9));
    CHECK(r.reaction("A", Dof::rz) == doctest::Approx(-M - L * Fy).epsilon(1e-9));
  }

  TEST_CASE("a rigid floor on four fixed-fixed columns: 12 E I / h^3 each, and its twist") {
    const double h = 3, a = 4, F = 20e3, Mt = 5e3;
    const double I = std::numbers::pi * std::pow(kD, 4) / 64, J = 2 * I;
    const double G = kE / (2 * (1 + kNu)), k = 12 * kE * I / (h * h * h);
    std::ostringstream d;
    d.precision(17);
    d << "model: {dimension: 3d}\n"
      << "materials: [{name: steel, E: " << kE << ", nu: " << kNu << "}]\n"
      << "sections: [{name: col, shape: circle, D: " << kD << "}]\n"
      << "nodes:\n";
    const double corners[4][2] = {{0, 0}, {a, 0}, {0, a}, {a, a}};
    for (int i = 0; i < 4; ++i)
      d << "  - {name: A" << i << ", at: [" << corners[i][0] << ", 0, " << corners[i][1] << "]}\n"
        << "  - {name: B" << i << ", at: [" << corners[i][0] << ", " << h << ", " << corners[i][1]
        << "]}\n";
    d << "members:\n";
    for (int i = 0; i < 4; ++i)
      d << "  - {name: c" << i << ", from: A" << i << ", to: B" << i << ", section: col, elements: 2}\n";
    d << "supports:\n";
    for (int i = 0; i < 4; ++i)
      d << "  - {name: A" << i << ", at: A" << i << ", fix: clamped}\n"
        << "  - {name: B" << i << ", at: B" << i << ", fix: [rx, rz]}\n";  // the floor beams
    d << "diaphragms: [{name: floor, master: B0, points: [B1, B2, B3], plane: xz}]\n";
    const std::string frame = d.str();

    // Sway: F along x split over the two corners at x = 0, so the floor does not turn.
    const Study sway = test::solveDeckText(
        frame + "loads: [{type: point, at: B0, fx: " + fmt(F / 2) + "}, {type: point, at: B2, fx: " +
            fmt(F / 2) + "}]\nanalyses: [{type: static}]\n",
        "floor.yaml");
    const StaticResult& s = *staticsOf(sway.run->analyses.front());
    // The columns' axial strain does not enter a sway; exact elements: round-off.
    for (const char* corner : {"0", "1", "2", "3"}) {
      std::string top = "B", base = "A";  // appended piece by piece (GCC 12's -Wrestrict)
      top += corner;
      base += corner;
      const int node = sway.run->model->node(top);
      CHECK(s.displacement(node, dofIndex(Dof::ux)) == doctest::Approx(F / (4 * k)).epsilon(1e-9));
      CHECK(std::abs(s.displacement(node, dofIndex(Dof::ry))) <= 1e-9 * F / (4 * k) / a);
      CHECK(s.reaction(base, Dof::ux) == doctest::Approx(-F / 4).epsilon(1e-9));
    }

    // Twist: a torque about y at the master turns the floor about its centre, where each
    // column (a / sqrt 2 away) sways by theta a / sqrt 2 and twists by theta.
    const Study twist = test::solveDeckText(
        frame + "loads: [{type: point, at: B0, my: " + fmt(Mt) + "}]\nanalyses: [{type: static}]\n",
        "floor.yaml");
    const StaticResult& t = *staticsOf(twist.run->analyses.front());
    const double theta = Mt / (4 * k * a * a / 2 + 4 * G * J / h);
    const int B0 = twist.run->model->node("B0"), B3 = twist.run->model->node("B3");
    CHECK(t.displacement(B0, dofIndex(Dof::ry)) == doctest::Approx(theta).epsilon(1e-9));
    CHECK(t.displacement(B3, dofIndex(Dof::ry)) == doctest::Approx(theta).epsilon(1e-9));
    // Corner B3 at (a, a) turns about the centre (a/2, a/2): ux = theta (z - a/2) about y.
    CHECK(t.displacement(B3, dofIndex(Dof::ux)) == doctest::Approx(theta * a / 2).epsilon(1e-9));
  }

  TEST_CASE("rigid ties are refused where they cannot act, with the reason") {
    const std::string base =
        "model: {dimension: planar}\n"
        "materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]\n"
        "sections: [{name: bar, shape: circle, D: 0.1}]\n"
        "nodes: [{name: A, at: [0, 0]}, {name: B, at: [2, 0]}, {name: C, at: [4, 0]}]\n"
        "members: [{name: ab, from: A, to: B, section: bar, elements: 1},\n"
        "          {name: bc, from: B, to: C, section: bar, elements: 1}]\n"
        "supports: [{name: A, at: A, fix: clamped}]\n";
    CHECK(std::string(test::readingError(base + "rigid_links: [{name: l, master: B, slave: C}]\n"
                                                "analyses: [{type: transient, dt: 1 ms, end: 0.1 s}]\n",
                                         "ties.yaml").what())
              .find("frame analyses") != std::string::npos);
    CHECK(std::string(test::readingError(base + "rigid_links: [{name: l, master: B, slave: A}]\n"
                                                "analyses: [{type: static}]\n",
                                         "ties.yaml").what())
              .find("held by support 'A'") != std::string::npos);
    CHECK(std::string(test::readingError(base + "rigid_links: [{name: l, master: B, slave: C},"
                                                " {name: m, master: C, slave: A}]\n"
                                                "analyses: [{type: static}]\n",
                                         "ties.yaml").what())
              .find("lead or follow") != std::string::npos);
  }
}

}  // namespace rigid_ties_tests
