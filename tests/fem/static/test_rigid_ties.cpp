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

  TEST_CASE("a chain of two links equals one link to the end, in statics and modes") {
    // A clamped column A-B carries a bracket: B leads C (l1), C leads D (l2), loaded and
    // massed at D. The chain composes the rigid motions, so it must equal one link from B to
    // D: D's motion, B's, the clamp's reactions and the frequencies to round-off; and the
    // middle point C follows B as a rigid body, u_C = u_B + theta_B x (x_C - x_B).
    const double L = 2.5;
    const Eigen::Vector3d B(0, L, 0), C(0.4, L + 0.1, -0.3), D(0.9, L - 0.2, 0.25);
    const auto point = [](const char* name, const Eigen::Vector3d& x) {
      return std::string("{name: ") + name + ", at: [" + fmt(x.x()) + ", " + fmt(x.y()) + ", " +
             fmt(x.z()) + "]}";
    };
    const std::string head =
        "model: {dimension: 3d}\n"
        "materials: [{name: steel, E: " + fmt(kE) + ", nu: " + fmt(kNu) + ", rho: 7850}]\n"
        "sections: [{name: bar, shape: circle, D: " + fmt(kD) + "}]\n";
    const std::string tail =
        "members: [{name: col, from: A, to: B, section: bar, elements: 4}]\n"
        "supports: [{name: A, at: A, fix: clamped}]\n"
        "masses: [{name: bracket, at: D, m: 150, Jp: 4, Jd: 3}]\n"
        "loads: [{type: point, at: D, fx: 2e3, fy: -5e3, fz: 1.5e3, mx: 300, my: -700, mz: 450}]\n"
        "analyses: [{type: static}, {type: modal, modes: 6}]\n";
    const std::string chained =
        head + "nodes: [" + point("A", Eigen::Vector3d::Zero()) + ", " + point("B", B) + ", " +
        point("C", C) + ", " + point("D", D) + "]\n" +
        "rigid_links: [{name: l1, master: B, slave: C}, {name: l2, master: C, slave: D}]\n" + tail;
    const std::string direct =
        head + "nodes: [" + point("A", Eigen::Vector3d::Zero()) + ", " + point("B", B) + ", " +
        point("D", D) + "]\n" + "rigid_links: [{name: l, master: B, slave: D}]\n" + tail;
    const Study sc = test::solveDeckText(chained, "chain.yaml");
    const Study sd = test::solveDeckText(direct, "direct.yaml");
    const StaticResult& rc = *staticsOf(sc.run->analyses[0]);
    const StaticResult& rd = *staticsOf(sd.run->analyses[0]);
    const Model& mc = *sc.run->model;
    const Model& md = *sd.run->model;
    double scale = 0;  // the largest translation or rotation, for absolute round-off bounds
    for (int k = 0; k < 6; ++k) scale = std::max(scale, std::abs(rd.displacement(md.node("D"), k)));
    // Both are exact eliminations of the same constraint, the column's elements the same:
    // round-off, 1e-12 of the largest displacement.
    double worst = 0;
    for (const char* p : {"B", "D"})
      for (int k = 0; k < 6; ++k) {
        CAPTURE(p);
        CAPTURE(k);
        const double off =
            std::abs(rc.displacement(mc.node(p), k) - rd.displacement(md.node(p), k));
        CHECK(off <= 1e-12 * scale);
        worst = std::max(worst, off / scale);
      }
    MESSAGE("chain of two links against one: displacements of B and D differ by "
            << worst << " of the largest");
    for (Dof d : kAllDofs)
      CHECK(rc.reaction("A", d) == doctest::Approx(rd.reaction("A", d)).epsilon(1e-12));
    // The middle of the chain moves with B.
    const auto translation = [&](int node) {
      return Eigen::Vector3d(rc.displacement(node, 0), rc.displacement(node, 1),
                             rc.displacement(node, 2));
    };
    const auto rotation = [&](int node) {
      return Eigen::Vector3d(rc.displacement(node, 3), rc.displacement(node, 4),
                             rc.displacement(node, 5));
    };
    const int nb = mc.node("B"), nc = mc.node("C");
    CHECK((translation(nc) - translation(nb) - rotation(nb).cross(C - B)).norm() <= 1e-12 * scale);
    CHECK((rotation(nc) - rotation(nb)).norm() <= 1e-12 * scale);
    // The modes: the same pencil, reduced through the composed chain or the one link (the
    // Lanczos eigenpairs converge to ~1e-12; 1e-9 leaves room).
    const ModalResult* fc = resultOf<ModalResult>(sc.run->analyses[1]);
    const ModalResult* fd = resultOf<ModalResult>(sd.run->analyses[1]);
    REQUIRE(fc);
    REQUIRE(fd);
    REQUIRE(fc->modes.size() == fd->modes.size());
    double frequencies = 0;
    for (std::size_t m = 0; m < fc->modes.size(); ++m) {
      CHECK(fc->modes[m].frequencyHz == doctest::Approx(fd->modes[m].frequencyHz).epsilon(1e-9));
      frequencies = std::max(frequencies,
                             std::abs(fc->modes[m].frequencyHz / fd->modes[m].frequencyHz - 1));
    }
    MESSAGE("chain of two links against one: frequencies differ by " << frequencies);
  }

  TEST_CASE("a loop of ties is refused at reading, naming the file, line and field") {
    const std::string base =
        "model: {dimension: planar}\n"
        "materials: [{name: steel, E: 210e9, nu: 0.3}]\n"
        "sections: [{name: bar, shape: circle, D: 0.1}]\n"
        "nodes: [{name: A, at: [0, 0]}, {name: B, at: [2, 0]}, {name: C, at: [4, 0]},\n"
        "        {name: D, at: [5, 1]}]\n"
        "members: [{name: ab, from: A, to: B, section: bar, elements: 1}]\n"
        "supports: [{name: A, at: A, fix: clamped}]\n"
        "analyses: [{type: static}]\n";
    // Three links B -> C -> D -> B: the third closes the loop (line 12, its slave).
    const DeckError loop = test::readingError(base +
                                                  "rigid_links:\n"
                                                  "  - {name: l1, master: B, slave: C}\n"
                                                  "  - {name: l2, master: C, slave: D}\n"
                                                  "  - {name: l3, master: D, slave: B}\n",
                                              "loop.yaml");
    const std::string what = loop.what();
    CAPTURE(what);
    CHECK(what.find("loop.yaml") != std::string::npos);
    CHECK(loop.place().line == 12);
    CHECK(what.find("loop") != std::string::npos);
    CHECK(what.find("'B' -> 'D' -> 'C' -> 'B'") != std::string::npos);
    // Two points leading each other.
    const DeckError pair = test::readingError(
        base + "rigid_links: [{name: l1, master: B, slave: C}, {name: l2, master: C, slave: B}]\n",
        "pair.yaml");
    CHECK(std::string(pair.what()).find("loop") != std::string::npos);
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
  }
}

}  // namespace rigid_ties_tests
