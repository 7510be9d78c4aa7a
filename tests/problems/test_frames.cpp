// Frames from decks (nodes:, members:): portal frames with fixed and with pinned bases under
// lateral and gravity load against slope-deflection closed forms; a two-bay frame with a
// member release against a dense direct-stiffness solve written here; a 3D L-frame whose
// first arm twists against its closed form; member quantities (exact extrema between nodes,
// deflection from the chord) and the largest displacement.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using beamrotor::test::relError;

namespace {

// A portal frame: columns A-B and D-C of height h, beam B-C of span L; E, Ic, Ib (HEB 200
// columns, IPE 300 beam). The slope-deflection closed forms take the members inextensible, so
// the areas are the real ones (78.1 and 53.8 cm^2) times `stiffening`: a million leaves an
// axial strain effect of about 2e-8 and the round-off of so stiff a system, about 1e-7
// (measured on these cases; kInextensible below).
struct Portal {
  double h = 4, L = 6, E = 210e9, Ic = 5696e-8, Ib = 8356e-8, stiffening = 1e6;
  double Ac() const { return stiffening * 78.1e-4; }
  double Ab() const { return stiffening * 53.8e-4; }
  double a() const { return E * Ic / h; }  // column stiffness ratio
  double b() const { return E * Ib / L; }  // beam stiffness ratio
};

/// The portal's deck: bases `base` (clamped or pinned), H at B along +x, w down on the beam
/// (3 elements, so midspan lies inside an element), plus `extra` lines.
std::string portalDeck(const Portal& p, const std::string& base, double H, double w) {
  std::ostringstream d;
  d.precision(17);
  d << "model: {dimension: planar}\n"
    << "materials: [{name: steel, E: " << p.E << ", nu: 0.3}]\n"
    << "sections:\n"
    << "  - {name: column, shape: general, A: " << p.Ac() << ", I: " << p.Ic << ", J: 1e-6, depth: 0.3, width: 0.15}\n"
    << "  - {name: beam, shape: general, A: " << p.Ab() << ", I: " << p.Ib << ", J: 1e-6, depth: 0.3, width: 0.15}\n"
    << "nodes:\n"
    << "  - {name: A, at: [0, 0]}\n"
    << "  - {name: B, at: [0, " << p.h << "]}\n"
    << "  - {name: C, at: [" << p.L << ", " << p.h << "]}\n"
    << "  - {name: D, at: [" << p.L << ", 0]}\n"
    << "members:\n"
    << "  - {name: left, from: A, to: B, section: column, elements: 2}\n"
    << "  - {name: beam, from: B, to: C, section: beam, elements: 3}\n"
    << "  - {name: right, from: D, to: C, section: column, elements: 2}\n"
    << "supports:\n"
    << "  - {name: A, at: A, fix: " << base << "}\n"
    << "  - {name: D, at: D, fix: " << base << "}\n"
    << "loads:\n"
    << "  - {type: point, at: B, fx: " << H << "}\n"
    << "  - {type: distributed, member: beam, qy: " << -w << "}\n";
  return d.str();
}

const RunResult& frameRun(const Study& s) {
  const auto runs = test::runsOf(s);
  REQUIRE(runs.size() == 1);
  return *runs.front();
}

const StaticResult& frameStatics(const RunResult& run) {
  REQUIRE(staticsOf(run.analyses.front()));
  return *staticsOf(run.analyses.front());
}

double frameDisplacement(const RunResult& run, const std::string& point, Dof d) {
  return frameStatics(run).displacement(run.model->node(point), dofIndex(d));
}

/// A check quantity measured in the run, through a deck check that has it as its only one.
double frameMeasure(const std::string& deck, const std::string& quantity) {
  const Study s = test::solveDeckText(
      deck + "checks: [{name: q, quantity: " + quantity + ", reference: 1, tolerance: 1e300}]\n",
      "frame.yaml");
  return frameRun(s).checks.front().computed;
}


// A planar frame solved by the direct stiffness method in dense matrices, independent of the
// solver: Euler-Bernoulli frame elements with axial strain (e.g. Kassimali, Matrix Analysis
// of Structures, ch. 6), uniform loads by their fixed-end forces, a released end as a
// rotation of its own.
struct DenseFrame {
  struct Element {
    int n1, n2;
    double EA, EI;
    int released = -1;   // the released end rotation at n2: its index among the extra dofs
    double qLocalY = 0;  // uniform load along local y (N/m)
  };
  std::vector<Eigen::Vector2d> nodes;
  std::vector<Element> elements;
  int extra = 0;  // dofs beyond the nodes' three: released end rotations
  int dofs() const { return 3 * int(nodes.size()) + extra; }

  int addNode(double x, double y) {
    nodes.emplace_back(x, y);
    return int(nodes.size()) - 1;
  }
  void add(int n1, int n2, double EA, double EI, bool releaseEnd = false, double q = 0) {
    Element e{n1, n2, EA, EI, -1, q};
    if (releaseEnd) e.released = extra++;
    elements.push_back(e);
  }
  /// Displacements and reactions (K u - f) with `fixed` dofs held at zero.
  std::pair<Eigen::VectorXd, Eigen::VectorXd> solve(const Eigen::VectorXd& loads,
                                                    const std::vector<int>& fixed) const {
    const int n = dofs();
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd F = Eigen::VectorXd::Zero(n);
    F.head(loads.size()) = loads;
    for (const Element& e : elements) {
      const Eigen::Vector2d d = nodes[e.n2] - nodes[e.n1];
      const double L = d.norm(), c = d.x() / L, s = d.y() / L;
      Eigen::Matrix<double, 6, 6> k = Eigen::Matrix<double, 6, 6>::Zero();
      const double a = e.EA / L, b = 12 * e.EI / (L * L * L), g = 6 * e.EI / (L * L),
                   r4 = 4 * e.EI / L, r2 = 2 * e.EI / L;
      k(0, 0) = k(3, 3) = a, k(0, 3) = k(3, 0) = -a;
      k(1, 1) = k(4, 4) = b, k(1, 4) = k(4, 1) = -b;
      k(1, 2) = k(2, 1) = k(1, 5) = k(5, 1) = g;
      k(4, 2) = k(2, 4) = k(4, 5) = k(5, 4) = -g;
      k(2, 2) = k(5, 5) = r4, k(2, 5) = k(5, 2) = r2;
      Eigen::Matrix<double, 6, 6> T = Eigen::Matrix<double, 6, 6>::Zero();
      for (int i = 0; i < 2; ++i) {
        T(3 * i, 3 * i) = c, T(3 * i, 3 * i + 1) = s;
        T(3 * i + 1, 3 * i) = -s, T(3 * i + 1, 3 * i + 1) = c;
        T(3 * i + 2, 3 * i + 2) = 1;
      }
      Eigen::Matrix<double, 6, 1> fixedEnd;
      const double q = e.qLocalY;
      fixedEnd << 0, q * L / 2, q * L * L / 12, 0, q * L / 2, -q * L * L / 12;
      const Eigen::Matrix<double, 6, 6> kg = T.transpose() * k * T;
      const Eigen::Matrix<double, 6, 1> fg = T.transpose() * fixedEnd;
      std::array<int, 6> map{3 * e.n1, 3 * e.n1 + 1, 3 * e.n1 + 2,
                             3 * e.n2, 3 * e.n2 + 1, 3 * e.n2 + 2};
      if (e.released >= 0) map[5] = 3 * int(nodes.size()) + e.released;
      for (int i = 0; i < 6; ++i) {
        F(map[i]) += fg(i);
        for (int j = 0; j < 6; ++j) K(map[i], map[j]) += kg(i, j);
      }
    }
    std::vector<int> free;
    for (int i = 0; i < n; ++i)
      if (std::find(fixed.begin(), fixed.end(), i) == fixed.end()) free.push_back(i);
    Eigen::MatrixXd Kff(free.size(), free.size());
    Eigen::VectorXd Ff(free.size());
    for (std::size_t i = 0; i < free.size(); ++i) {
      Ff(i) = F(free[i]);
      for (std::size_t j = 0; j < free.size(); ++j) Kff(i, j) = K(free[i], free[j]);
    }
    const Eigen::VectorXd uf = Kff.fullPivLu().solve(Ff);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
    for (std::size_t i = 0; i < free.size(); ++i) u(free[i]) = uf(i);
    return {u, K * u - F};
  }
};

// Against the inextensible closed forms: measured at most 1e-7 (see Portal); 1e-6 still
// catches the real axial strain (0.5 to 2 %) and any wrong stiffness.
constexpr double kInextensible = 1e-6;
// Where both sides are exact (the dense solve with the same axial strain, members without
// axial force): round-off, measured about 1e-13 on these small systems; 1e-9 leaves room.
constexpr double kFrameRoundOff = 1e-9;

}  // namespace

TEST_SUITE("frames") {
  TEST_CASE("fixed-base portal under lateral load: slope-deflection sway and base moments") {
    // Antisymmetric: both joints turn by theta, the beam sways by Delta. Slope-deflection
    // (Hibbeler, Structural Analysis, ch. 11) with a = E Ic / h, b = E Ib / L:
    //   joint B:  2a (2 theta - 3 Delta/h) + 6 b theta = 0
    //   shear:    H = (4a / h) (6 Delta / h - 3 theta)
    // so Delta = H h^2 (4a + 6b) / (24 a (a + 6b)), and the base moment 2a (3 Delta/h - theta).
    const Portal p;
    const double H = 10e3, a = p.a(), b = p.b();
    const double Delta = H * p.h * p.h * (4 * a + 6 * b) / (24 * a * (a + 6 * b));
    const double theta = 6 * a * Delta / (p.h * (4 * a + 6 * b));
    const double Mbase = 2 * a * (3 * Delta / p.h - theta);
    const Study s = test::solveDeckText(portalDeck(p, "clamped", H, 0), "portal.yaml");
    const RunResult& run = frameRun(s);
    CHECK(relError(frameDisplacement(run, "B", Dof::ux), Delta) < kInextensible);
    CHECK(relError(frameDisplacement(run, "C", Dof::ux), Delta) < kInextensible);
    // Joint rotation: the sway turns the joints clockwise (negative rz).
    CHECK(relError(frameDisplacement(run, "B", Dof::rz), -theta) < kInextensible);
    // Reactions: each base takes half the shear and a counter-clockwise moment; the rest of
    // the overturning moment H h is the couple of the vertical reactions over L.
    for (const char* base : {"A", "D"}) {
      CHECK(relError(frameStatics(run).reaction(base, Dof::ux), -H / 2) < kInextensible);
      CHECK(relError(frameStatics(run).reaction(base, Dof::rz), Mbase) < kInextensible);
    }
    CHECK(relError(frameStatics(run).reaction("D", Dof::uy), (H * p.h - 2 * Mbase) / p.L) < kInextensible);
  }

  TEST_CASE("fixed-base portal under gravity: Kleinlogel's corner moment, midspan between nodes") {
    // Symmetric, no sway: joint B turns by theta, C by -theta.
    //   joint B:  4 a theta + 2 b theta - w L^2 / 12 = 0
    // corner moment M_B = 4 a theta = w L^2 / (6 (2 + k)), k = b / a (Kleinlogel), base
    // moment M_B / 2, thrust 3 M_B / (2 h), midspan moment w L^2 / 8 - M_B; the beam's
    // midspan deflection from its chord 5 w L^4 / (384 E Ib) - M_B L^2 / (8 E Ib).
    const Portal p;
    const double w = 20e3, k = p.b() / p.a();
    const double MB = w * p.L * p.L / (6 * (2 + k));
    const std::string deck = portalDeck(p, "clamped", 0, w);
    const Study s = test::solveDeckText(deck, "portal.yaml");
    const RunResult& run = frameRun(s);
    CHECK(relError(frameStatics(run).reaction("A", Dof::ux), 1.5 * MB / p.h) < kInextensible);
    CHECK(relError(frameStatics(run).reaction("D", Dof::ux), -1.5 * MB / p.h) < kInextensible);
    CHECK(relError(frameStatics(run).reaction("A", Dof::uy), w * p.L / 2) < kInextensible);
    CHECK(relError(std::abs(frameStatics(run).reaction("A", Dof::rz)), MB / 2) < kInextensible);
    // Member quantities. Beam B -> C: local y = global +y; the corners hog, midspan sags,
    // so Mz has one sign at the ends and the other at midspan (3 elements: midspan is inside
    // the middle one, found exactly, not sampled).
    const double sagging = w * p.L * p.L / 8 - MB;
    CHECK(relError(frameMeasure(deck, "member beam Mz maxabs"), std::max(MB, sagging)) <
          kInextensible);
    const double ends = frameMeasure(deck, "member beam Mz min");
    const double middle = frameMeasure(deck, "member beam Mz max");
    CHECK(std::abs(ends) == doctest::Approx(MB).epsilon(kInextensible));
    CHECK(std::abs(middle) == doctest::Approx(sagging).epsilon(kInextensible));
    CHECK(ends * middle < 0);
    // Axial force in the beam: the thrust, compression.
    CHECK(relError(frameMeasure(deck, "member beam N max"), -1.5 * MB / p.h) < kInextensible);
    const double EIb = p.E * p.Ib;
    const double sag =
        5 * w * std::pow(p.L, 4) / (384 * EIb) - MB * p.L * p.L / (8 * EIb);
    CHECK(relError(frameMeasure(deck, "member beam deflection max"), sag) < kInextensible);
    // The largest displacement is the beam's midspan: the chord moves only by the columns'
    // axial strain (1e-12 here), so it equals the sag.
    CHECK(relError(frameMeasure(deck, "displacement max"), sag) < 1e-6);
  }

  TEST_CASE("pinned-base portal: lateral sway and gravity corner moment") {
    // Lateral: columns pinned at the base, M_BA = 3a (theta - Delta/h); joint B:
    // 3a (theta - Delta/h) + 6 b theta = 0; shear H = (6a / h^2) (Delta - h theta), so
    // Delta = H h^2 (a + 2b) / (12 a b); the corner moment is H h / 2 by statics.
    // Gravity: 3a theta + 2b theta = w L^2 / 12, M_B = w L^2 / (4 (3 + 2k)) (Kleinlogel).
    const Portal p;
    const double H = 10e3, w = 20e3, a = p.a(), b = p.b(), k = b / a;
    const double Delta = H * p.h * p.h * (a + 2 * b) / (12 * a * b);
    const std::string lateral = portalDeck(p, "pinned", H, 0);
    const Study s = test::solveDeckText(lateral, "portal.yaml");
    const RunResult& run = frameRun(s);
    CHECK(relError(frameDisplacement(run, "B", Dof::ux), Delta) < kInextensible);
    CHECK(relError(frameStatics(run).reaction("A", Dof::ux), -H / 2) < kInextensible);
    CHECK(relError(frameStatics(run).reaction("D", Dof::uy), H * p.h / p.L) < kInextensible);
    CHECK(relError(frameMeasure(lateral, "member left Mz maxabs"), H * p.h / 2) < kInextensible);

    const std::string gravity = portalDeck(p, "pinned", 0, w);
    const double MB = w * p.L * p.L / (4 * (3 + 2 * k));
    // The corners hog by M_B, midspan sags by w L^2 / 8 - M_B.
    CHECK(relError(std::abs(frameMeasure(gravity, "member beam Mz min")), MB) < kInextensible);
    CHECK(relError(frameMeasure(gravity, "member beam Mz max"), w * p.L * p.L / 8 - MB) <
          kInextensible);
    CHECK(relError(frameMeasure(gravity, "reaction A fx"), MB / p.h) < kInextensible);
  }

  TEST_CASE("a planar frame equals its 3d twin: the default member axes agree") {
    // The same portal in a 3d model (bases clamped in all six dofs) carries the same in-plane
    // solution: local z = global z for every member of the x-y plane in both.
    Portal p;
    p.stiffening = 1;  // real areas: both models strain alike, round-off only
    std::string planar = portalDeck(p, "clamped", 10e3, 20e3);
    std::string spatial = planar;
    spatial.replace(spatial.find("planar"), 6, "3d");
    for (const std::string from : {"[0, 0]", "[0, 4]", "[6, 4]", "[6, 0]"}) {
      const std::string to = from.substr(0, from.size() - 1) + ", 0]";
      spatial.replace(spatial.find(from), from.size(), to);
    }
    for (const char* q : {"displacement B ux", "reaction A mz", "member beam Mz min",
                          "member left N max", "member right Vy maxabs"})
      CHECK(frameMeasure(spatial, q) == doctest::Approx(frameMeasure(planar, q)).epsilon(1e-9));
  }
  TEST_CASE("two-bay frame with a sloped beam, a released end and loads on members: dense solve") {
    // Bases A clamped, D pinned, F clamped; beam 1 B-C level, beam 2 C-E sloped with its end
    // at E released (rz); H at B, a point load at 0.4 of beam 1 (an inline member place), a
    // moment at E and a uniform load across beam 2 in its own axes. Euler-Bernoulli elements
    // are exact for all of these, so the two methods agree to round-off.
    const double E = 210e9, Ac = 78.1e-4, Ic = 5696e-8, Ab = 53.8e-4, Ib = 8356e-8;
    const double H = 15e3, P = -30e3, M = 5e3, q = -8e3;
    std::ostringstream deck;
    deck.precision(17);
    deck << "materials: [{name: steel, E: " << E << ", nu: 0.3}]\n"
         << "sections:\n"
         << "  - {name: column, shape: general, A: " << Ac << ", I: " << Ic << ", depth: 0.3}\n"
         << "  - {name: beam, shape: general, A: " << Ab << ", I: " << Ib << ", depth: 0.3}\n"
         << "nodes:\n"
         << "  - {name: A, at: [0, 0]}\n  - {name: B, at: [0, 4]}\n"
         << "  - {name: C, at: [5, 4]}\n  - {name: D, at: [5, 0]}\n"
         << "  - {name: E, at: [11, 4.6]}\n  - {name: F, at: [11, 0]}\n"
         << "members:\n"
         << "  - {name: colA, from: A, to: B, section: column, elements: 2}\n"
         << "  - {name: colD, from: D, to: C, section: column, size: 1.5}\n"
         << "  - {name: colF, from: F, to: E, section: column, elements: 1}\n"
         << "  - {name: beam1, from: B, to: C, section: beam, elements: 3}\n"
         << "  - {name: beam2, from: C, to: E, section: beam, elements: 4, release: {end: rz}}\n"
         << "points: [{name: P, member: beam1, at_length: 2}]\n"
         << "supports:\n"
         << "  - {name: A, at: A, fix: clamped}\n"
         << "  - {name: D, at: D, fix: pinned}\n"
         << "  - {name: F, at: F, fix: clamped}\n"
         << "loads:\n"
         << "  - {type: point, at: B, fx: " << H << "}\n"
         << "  - {type: point, at: {member: beam1, at: 0.4}, fy: " << P << "}\n"
         << "  - {type: point, at: E, mz: " << M << "}\n"
         << "  - {type: distributed, member: beam2, axes: member, qy: " << q << "}\n";
    const Study s = test::solveDeckText(deck.str(), "two_bay.yaml");
    const RunResult& run = frameRun(s);

    DenseFrame d;
    const int A = d.addNode(0, 0), B = d.addNode(0, 4), C = d.addNode(5, 4), D = d.addNode(5, 0),
              Ej = d.addNode(11, 4.6), F = d.addNode(11, 0), Pn = d.addNode(2, 4);
    d.add(A, B, E * Ac, E * Ic);
    d.add(D, C, E * Ac, E * Ic);
    d.add(F, Ej, E * Ac, E * Ic);
    d.add(B, Pn, E * Ab, E * Ib);
    d.add(Pn, C, E * Ab, E * Ib);
    d.add(C, Ej, E * Ab, E * Ib, /*releaseEnd=*/true, q);
    Eigen::VectorXd loads = Eigen::VectorXd::Zero(3 * 7);
    loads(3 * B) = H, loads(3 * Pn + 1) = P, loads(3 * Ej + 2) = M;
    const std::vector<int> fixed{3 * A, 3 * A + 1, 3 * A + 2, 3 * D, 3 * D + 1,
                                 3 * F, 3 * F + 1, 3 * F + 2};
    const auto [u, reactions] = d.solve(loads, fixed);

    // Displacements: relative to the largest translation, rotations to the largest rotation.
    const double uScale = u.head(21).cwiseAbs().maxCoeff();
    const std::vector<std::pair<std::string, int>> points{{"B", B}, {"C", C}, {"E", Ej}, {"P", Pn}};
    for (const auto& [name, node] : points) {
      CAPTURE(name);
      for (Dof dof : {Dof::ux, Dof::uy}) {
        const int k = dofIndex(dof);
        CHECK(std::abs(frameDisplacement(run, name, dof) - u(3 * node + k)) < kFrameRoundOff * uScale);
      }
    }
    // The node rotation at E is the column's (beam 2 is released there).
    double rScale = 0;
    for (int n = 0; n < 7; ++n) rScale = std::max(rScale, std::abs(u(3 * n + 2)));
    CHECK(std::abs(frameDisplacement(run, "E", Dof::rz) - u(3 * Ej + 2)) < kFrameRoundOff * rScale);
    CHECK(std::abs(frameDisplacement(run, "C", Dof::rz) - u(3 * C + 2)) < kFrameRoundOff * rScale);
    // Reactions, relative to the largest.
    const double rMax = reactions.cwiseAbs().maxCoeff();
    const std::vector<std::pair<std::string, int>> bases{{"A", A}, {"D", D}, {"F", F}};
    for (const auto& [name, node] : bases) {
      CAPTURE(name);
      for (Dof dof : {Dof::ux, Dof::uy})
        CHECK(std::abs(frameStatics(run).reaction(name, dof) - reactions(3 * node + dofIndex(dof))) <
              kFrameRoundOff * rMax);
    }
    CHECK(std::abs(frameStatics(run).reaction("A", Dof::rz) - reactions(3 * A + 2)) < kFrameRoundOff * rMax);
  }

  TEST_CASE("3d L-frame: the first arm twists, the tip deflection sums bending and torsion") {
    // Arm 1 A -> B along x (length a, clamped at A), arm 2 B -> C along z (length b), force P
    // down (-y) at C. Arm 2 is a cantilever from B; arm 1 carries the bending moment P (a - x)
    // and the torque P b. Tip deflection (Castigliano; e.g. Timoshenko, Strength of Materials
    // I, the bent cantilever): P a^3 / (3 E I) + P b^3 / (3 E I) + P b^2 a / (G J).
    const double a = 2, b = 1.5, P = 2e3, D = 0.08, E = 210e9, nu = 0.3;
    const double I = test::kPi * std::pow(D, 4) / 64, J = 2 * I, G = E / (2 * (1 + nu));
    std::ostringstream deck;
    deck.precision(17);
    deck << "model: {dimension: 3d}\n"
         << "materials: [{name: steel, E: " << E << ", nu: " << nu << "}]\n"
         << "sections: [{name: rod, shape: circle, D: " << D << "}]\n"
         << "nodes:\n  - {name: A, at: [0, 0, 0]}\n  - {name: B, at: [" << a << ", 0, 0]}\n"
         << "  - {name: C, at: [" << a << ", 0, " << b << "]}\n"
         << "members:\n"
         << "  - {name: arm1, from: A, to: B, section: rod, elements: 3}\n"
         << "  - {name: arm2, from: B, to: C, section: rod, elements: 2}\n"
         << "supports: [{name: A, at: A, fix: clamped}]\n"
         << "loads: [{type: point, at: C, fy: " << -P << "}]\n";
    const std::string text = deck.str();
    const double tip = P * std::pow(a, 3) / (3 * E * I) + P * std::pow(b, 3) / (3 * E * I) +
                       P * b * b * a / (G * J);
    const Study s = test::solveDeckText(text, "l_frame.yaml");
    const RunResult& run = frameRun(s);
    CHECK(relError(frameDisplacement(run, "C", Dof::uy), -tip) < kFrameRoundOff);
    // Arm 1 twists by P b a / (G J) at B.
    CHECK(relError(std::abs(frameDisplacement(run, "B", Dof::rx)), P * b * a / (G * J)) < kFrameRoundOff);
    CHECK(relError(frameMeasure(text, "member arm1 T maxabs"), P * b) < kFrameRoundOff);
    CHECK(relError(frameMeasure(text, "member arm1 T min"), frameMeasure(text, "member arm1 T max")) <
          kFrameRoundOff);  // constant along the arm
    CHECK(relError(frameMeasure(text, "member arm1 Mz maxabs"), P * a) < kFrameRoundOff);
    CHECK(relError(frameMeasure(text, "member arm2 Mz maxabs"), P * b) < kFrameRoundOff);
    CHECK(relError(frameMeasure(text, "displacement max"), tip) < kFrameRoundOff);
    CHECK(std::abs(frameMeasure(text, "member arm1 My maxabs")) < kFrameRoundOff * P * a);
    CHECK(std::abs(frameMeasure(text, "reaction A mx")) ==
          doctest::Approx(P * b).epsilon(kFrameRoundOff));
  }

  TEST_CASE("3d member orientation: roll and reference vectors turn a rectangle's stiff axis") {
    // A cantilever along x, rectangle b x h (h along local y by FORMAT.md), tip force along
    // global y: by default local y = global y and the tip deflects P L^3 / (3 E b h^3 / 12);
    // rolled a quarter turn (or with local y given as global z, or local z as global y) the
    // force bends it about the other axis: P L^3 / (3 E h b^3 / 12). Exact for EB elements.
    const double L = 1.5, b = 0.02, h = 0.06, E = 2e11, P = 500;
    const auto tip = [&](const std::string& orientation) {
      std::ostringstream deck;
      deck.precision(17);
      deck << "model: {dimension: 3d}\n"
           << "materials: [{name: steel, E: " << E << ", nu: 0.3}]\n"
           << "sections: [{name: bar, shape: rectangle, b: " << b << ", h: " << h << "}]\n"
           << "nodes: [{name: A, at: [0, 0, 0]}, {name: B, at: [" << L << ", 0, 0]}]\n"
           << "members: [{name: m, from: A, to: B, section: bar, elements: 2" << orientation
           << "}]\n"
           << "supports: [{at: A, fix: clamped}]\n"
           << "loads: [{type: point, at: B, fy: " << -P << "}]\n";
      return frameMeasure(deck.str(), "displacement B uy");
    };
    const double stiff = P * L * L * L / (3 * E * b * h * h * h / 12);
    const double weak = P * L * L * L / (3 * E * h * b * b * b / 12);
    CHECK(relError(tip(""), -stiff) < kFrameRoundOff);
    CHECK(relError(tip(", roll: pi/2"), -weak) < kFrameRoundOff);
    CHECK(relError(tip(", y: [0, 0, 1]"), -weak) < kFrameRoundOff);
    CHECK(relError(tip(", z: [0, 1, 0]"), -weak) < kFrameRoundOff);
    CHECK(relError(tip(", roll: pi"), -stiff) < kFrameRoundOff);
  }

  TEST_CASE("frame decks refuse what they cannot mean") {
    const std::string head =
        "materials: [{name: steel, E: 2e11, nu: 0.3}]\n"
        "sections: [{name: bar, shape: rectangle, b: 0.02, h: 0.05}]\n"
        "nodes: [{name: A, at: [0, 0]}, {name: B, at: [1, 0]}]\n";
    const auto fails = [](const std::string& text, const std::string& field) {
      CAPTURE(text);
      try {
        test::solveDeckText(text, "bad.yaml");
        FAIL("accepted");
      } catch (const DeckError& e) {
        CHECK(e.place().field == field);
      }
    };
    const std::string member = "members: [{name: m, from: A, to: B, section: bar, elements: 2";
    const std::string rest = "supports: [{at: A, fix: clamped}]\n";
    fails(head + member + ", roll: 0.1}]\n" + rest, "members[0].roll");
    fails(head + member + "}]\n" + rest + "loads: [{type: point, at: {member: m, at: 1.5}, fy: 1}]\n",
          "loads[0].at.at");
    fails(head + member + "}]\n" + rest + "loads: [{type: point, at: {member: x, at: 0.5}, fy: 1}]\n",
          "loads[0].at.member");
    fails(head + "members: [{name: m, from: A, to: A, section: bar, elements: 2}]\n" + rest,
          "members[0].to");
    fails(head + member + "}]\n" + rest + "segments: [{length: 1, section: bar, elements: 1}]\n",
          "segments");
    fails(head + member + "}]\n" + rest +
              "loads: [{type: distributed, segment: m, qy: 1}]\n",
          "loads[0].segment");
    fails(head + member + "}]\n" + rest +
              "checks: [{name: c, quantity: member n Mz max, reference: 1, tolerance: 1}]\n",
          "checks[0].quantity");
  }

  TEST_CASE("a member starting on another member shares its node there") {
    // A post standing on the middle of a simply supported beam (span L, E I) carries a load P
    // from its top into the beam: the beam takes P at midspan, deflecting P L^3 / (48 E I)
    // there, the supports P / 2 each, and the top moves down P h / (E A) more (the post's
    // shortening). Euler-Bernoulli elements are exact for point loads: round-off only.
    constexpr double E = 210e9, I = 8356e-8, A = 53.8e-4, L = 6, h = 2, P = 30e3;
    for (const std::string from : {"front@0.5", "{member: front, at: 0.5}"}) {
      std::ostringstream d;
      d.precision(17);
      d << "model: {dimension: planar}\n"
        << "materials: [{name: steel, E: " << E << ", nu: 0.3}]\n"
        << "sections: [{name: s, shape: general, A: " << A << ", I: " << I
        << ", J: 1e-6, depth: 0.3}]\n"
        << "nodes: [{name: A, at: [0, 0]}, {name: B, at: [" << L << ", 0]}, {name: C, at: ["
        << L / 2 << ", " << h << "]}]\n"
        << "members:\n"
        << "  - {name: front, from: A, to: B, section: s, elements: 3}\n"
        << "  - {name: post, from: " << from << ", to: C, section: s, elements: 2}\n"
        << "supports: [{name: A, at: A, fix: pinned}, {name: B, at: B, fix: [uy]}]\n"
        << "loads: [{type: point, at: C, fy: " << -P << "}]\n";
      INFO(from);
      const Study s = test::solveDeckText(d.str(), "post.yaml");
      REQUIRE(s.run);
      const RunResult& run = *s.run;
      const StaticResult& r = *staticsOf(run.analyses.front());
      const int mid = run.model->node("front@0.5");
      const double sag = P * L * L * L / (48 * E * I);
      CHECK(relError(-r.displacement(mid, 1), sag) < 1e-10);
      CHECK(relError(-r.displacement(run.model->node("C"), 1), sag + P * h / (E * A)) < 1e-10);
      CHECK(relError(r.reaction("B", Dof::uy), P / 2) < 1e-10);
      // The beam is cut at the post: 3 elements and the cut make 4, the post 2.
      CHECK(run.model->elements().size() == 6);
    }
    const DeckError e = test::readingError(
        "model: {dimension: planar}\n"
        "materials: [{name: steel, E: 210e9, nu: 0.3}]\n"
        "sections: [{name: s, shape: general, A: 1e-3, I: 1e-6, J: 1e-6, depth: 0.3}]\n"
        "nodes: [{name: A, at: [0, 0]}, {name: B, at: [6, 0]}, {name: C, at: [3, 2]}]\n"
        "members:\n"
        "  - {name: post, from: front@0.5, to: C, section: s, elements: 2}\n"
        "  - {name: front, from: A, to: B, section: s, elements: 3}\n",
        "bad.yaml");
    CHECK(std::string(e.what()).find("no member named 'front' before this one") !=
          std::string::npos);
  }
}
