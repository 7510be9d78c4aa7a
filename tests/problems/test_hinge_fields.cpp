// Fields next to a hinge: a Gerber beam (clamped, hinged, propped) under a uniform load
// against its closed form along both elements, the two rotations at the hinge as check
// quantities, in results.json and in the summary, and the hinge's missing rotation as bad
// input; an element released at one end only, against the condensation by hand; and a
// frame's hinged joint, each member end's rotation by its member.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>

#include "fem/assembly/Recovery.hpp"
#include "fem/static/Static.hpp"
#include "problems/cli/Summary.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

// The Gerber beam: clamped at x = 0, hinge at x = a, roller at x = a + b, uniform load q
// (N/m along y) on both parts, Euler-Bernoulli, E I constant. Statically determinate: the
// right part is simply supported on the hinge and the roller, so it hands q b / 2 to the tip of
// the left part, a cantilever.
struct GerberBeam {
  double a = 1.2, b = 0.8, q = -3000, D = 0.04, E = 200e9;
  double EI() const { return E * test::kPi * std::pow(D, 4) / 64; }
  double tipForce() const { return q * b / 2; }
  // Left part, 0 <= x <= a: cantilever under q and the tip force F = q b / 2 (Gere & Goodno,
  // Mechanics of Materials, table G-1, cases 1 and 4):
  //   E I w = q x^2 (6 a^2 - 4 a x + x^2) / 24 + F x^2 (3 a - x) / 6, theta = w'.
  double leftDeflection(double x) const {
    const double F = tipForce();
    return (q * x * x * (6 * a * a - 4 * a * x + x * x) / 24 + F * x * x * (3 * a - x) / 6) / EI();
  }
  double leftRotation(double x) const {
    const double F = tipForce();
    return (q * x * (3 * a * a - 3 * a * x + x * x) / 6 + F * x * (2 * a - x) / 2) / EI();
  }
  // Right part, xi = x - a in [0, b]: the hinge's deflection falling linearly to the roller plus
  // the simply supported span under q: E I w = q xi (b^3 - 2 b xi^2 + xi^3) / 24 (table G-2,
  // case 1).
  double rightDeflection(double x) const {
    const double xi = x - a, wh = leftDeflection(a);
    return wh * (1 - xi / b) + q * xi * (b * b * b - 2 * b * xi * xi + xi * xi * xi) / (24 * EI());
  }
  double rightRotation(double x) const {
    const double xi = x - a, wh = leftDeflection(a);
    return -wh / b + q * (b * b * b - 6 * b * xi * xi + 4 * xi * xi * xi) / (24 * EI());
  }
};

/// The deck of the Gerber beam, one element per part unless `elements` says otherwise, with
/// `checks` appended.
std::string gerberDeck(const GerberBeam& g, const std::string& checks, int elements = 1) {
  std::ostringstream deck;
  deck.precision(17);
  deck << "parameters: {a: " << g.a << ", b: " << g.b << ", q: " << g.q << ", D: " << g.D
       << ", E: " << g.E << "}\n"
       << R"(derived:
  EI: E*pi*D^4/64
  F: q*b/2
  theta_left: (q*a^3/6 + F*a^2/2) / EI
  wh: (q*a^4/8 + F*a^3/3) / EI
  theta_right: -wh/b + q*b^3/(24*EI)
materials:
  - {name: steel, E: E, nu: 0.3, rho: 7850}
sections:
  - {name: rod, shape: circle, D: D}
segments:
)"
       << "  - {length: a, section: rod, elements: " << elements
       << "}\n  - {length: b, section: rod, elements: " << elements << "}\n"
       << R"(points:
  - {name: hinge, at: a}
supports:
  - {name: wall, at: start, fix: clamped}
  - {name: prop, at: end, fix: [uy]}
hinges:
  - {at: hinge}
loads:
  - {type: distributed, qy: q}
)" << checks;
  return deck.str();
}

Study solveGerber(const std::string& text) {
  return test::solveDeckText(text, "gerber.yaml");
}

}  // namespace

TEST_SUITE("hinge fields") {
  TEST_CASE("Gerber beam: deflection and rotation along both elements match the closed form") {
    const GerberBeam g;
    const Study study = solveGerber(gerberDeck(g, ""));
    REQUIRE(study.run);
    const RunResult& run = *study.run;
    const StaticResult& r = *staticsOf(run.analyses.front());
    const double wScale = std::abs(g.leftDeflection(g.a)), thetaScale = wScale / g.b;
    // The stations the CSV, VTK and charts are written from: every quarter of each element,
    // the hinge on both sides (s = 1 of the left element, s = 0 of the right one).
    int stations = 0;
    for (const StaticStation& st : sampleStatics({*run.model, r.displacement})) {
      const double x = st.place.x;
      const bool left = st.place.element == 0;
      CAPTURE(x);
      CAPTURE(left);
      const double w = left ? g.leftDeflection(x) : g.rightDeflection(x);
      const double theta = left ? g.leftRotation(x) : g.rightRotation(x);
      // Exact elements (the end-loaded cubic plus the clamped span solution, the hinge's
      // rotation from the condensation): round-off of a two-element solve, ~1e-15 observed.
      CHECK(std::abs(st.displacement[int(Dof::uy)] - w) <= 1e-12 * wScale);
      CHECK(std::abs(st.displacement[int(Dof::rz)] - theta) <= 1e-12 * thetaScale);
      ++stations;
    }
    CHECK(stations == 2 * (kIntervalsPerElement + 1));
    // The two sides of the hinge really differ (the test would not see a node rotation
    // otherwise), and the hinge node carries no rotation of its own.
    CHECK(std::abs(g.leftRotation(g.a) - g.rightRotation(g.a)) > 0.5 * thetaScale);
    const int hinge = run.model->node("hinge");
    REQUIRE(r.hinges.size() == 1);
    CHECK(r.hinges[0].node == hinge);
    CHECK(std::abs((*r.hinges[0].left)[2] - g.leftRotation(g.a)) <= 1e-12 * thetaScale);
    CHECK(std::abs((*r.hinges[0].right)[2] - g.rightRotation(g.a)) <= 1e-12 * thetaScale);
  }

  TEST_CASE("Gerber beam: the hinge's two rotations as checks, in results.json and the summary") {
    const GerberBeam g;
    const Study study = solveGerber(gerberDeck(g, R"(checks:
  - {name: left side, quantity: displacement hinge rz left, reference: theta_left, tolerance: 1e-11}
  - {name: right side, quantity: displacement hinge rz right, reference: theta_right, tolerance: 1e-11}
  - {name: hinge drop, quantity: displacement hinge uy, reference: wh, tolerance: 1e-11}
)",
                                               3));
    REQUIRE(study.run);
    const RunResult& run = *study.run;
    REQUIRE(run.checks.size() == 3);
    // The deck's references are the closed form at the hinge (written independently of the
    // test's functions above); three elements per part: still exact, round-off only.
    CHECK(run.checks[0].computed == doctest::Approx(g.leftRotation(g.a)).epsilon(1e-11));
    CHECK(run.checks[1].computed == doctest::Approx(g.rightRotation(g.a)).epsilon(1e-11));
    for (const Check& c : run.checks) {
      CAPTURE(c.name);
      CHECK(c.pass());
    }
    // results.json: both sides by name, and no rz of the node (it has none).
    const Json doc = runJson(run);
    const Json& hinge = doc.at("analyses").at(0).at("displacements").at("hinge");
    CHECK(hinge.at("rz_left").get<double>() == doctest::Approx(g.leftRotation(g.a)).epsilon(1e-11));
    CHECK(hinge.at("rz_right").get<double>() ==
          doctest::Approx(g.rightRotation(g.a)).epsilon(1e-11));
    CHECK_FALSE(hinge.contains("rz"));
    // The summary prints both sides.
    std::ostringstream summary;
    cli::printRunResults(summary, study.deck, run);
    CHECK(summary.str().find("rz left " + cli::formatValue(g.leftRotation(g.a))) !=
          std::string::npos);
    CHECK(summary.str().find("rz right " + cli::formatValue(g.rightRotation(g.a))) !=
          std::string::npos);
  }

  TEST_CASE("a hinge's rotation without a side, or a side with no beam, is bad input") {
    const GerberBeam g;
    // Before: 'displacement hinge rz' returned 0 (the node has no rz) and a check against 0
    // passed.
    const auto failure = [&](const std::string& quantity) -> std::string {
      try {
        solveGerber(gerberDeck(
            g, "checks:\n  - {name: c, quantity: " + quantity + ", reference: 0, tolerance: 1}\n"));
      } catch (const DeckError& e) {
        return e.what();
      }
      return "";
    };
    const std::string noSide = failure("displacement hinge rz");
    CHECK(noSide.find("gerber.yaml:") == 0);
    CHECK(noSide.find("quantity") != std::string::npos);
    CHECK(noSide.find("'displacement hinge rz left' or 'displacement hinge rz right'") !=
          std::string::npos);
    CHECK(failure("displacement start rz left").find("no beam on its left") != std::string::npos);
    CHECK(failure("displacement end rz right").find("no beam on its right") != std::string::npos);
    CHECK(failure("displacement hinge uy left").find("translation") != std::string::npos);
    CHECK(failure("displacement hinge rz up").find("not a side") != std::string::npos);
  }

  TEST_CASE("one end released: the element's own end rotation is the condensation's") {
    // Two elements, the first released at its end only: the node between keeps the second
    // element's rotation. Clamped at 0, propped at 2h, uniform load: the moment-free joint at
    // h makes it the Gerber beam above with a = b = h, but here the joint node turns with the
    // right element and the left element's end turns on its own.
    GerberBeam g;
    g.a = g.b = 1.0;
    Model model;
    const Line line = test::uniformBeam(model, g.a + g.b, test::steelCircle(g.D), 2);
    for (Beam* beam : line.beams) beam->setDistributedLoad({0, g.q, 0});
    line.beams[0]->release(1, Dof::rz);
    test::clamp(model, "wall", line.nodes[0], DofSet::planar());
    model.addSupport({"prop", line.nodes[2], {{Dof::uy, 0}}});
    const StaticResult r = solveStatic(model);
    const int joint = line.nodes[1], uy = int(Dof::uy), rz = int(Dof::rz);
    const double thetaScale = std::abs(g.leftDeflection(g.a)) / g.b;
    CHECK(std::abs(r.displacement(joint, rz) - g.rightRotation(g.a)) <= 1e-12 * thetaScale);

    // The condensation by hand: the released row of the Hermite stiffness (Przemieniecki)
    // E I / h^3 (6h v1 + 2h^2 theta1 - 6h v2 + 4h^2 theta2) equals its fixed-end moment
    // -q h^2 / 12, so theta2 = (-q h^2 / 12 - E I / h^3 (6h v1 + 2h^2 theta1 - 6h v2)) h / (4 E I).
    const double h = g.a, EI = g.EI();
    const double v1 = r.displacement(line.nodes[0], uy), t1 = r.displacement(line.nodes[0], rz),
                 v2 = r.displacement(joint, uy);
    const double byHand =
        (-g.q * h * h / 12 - EI / (h * h * h) * (6 * h * v1 + 2 * h * h * t1 - 6 * h * v2)) * h /
        (4 * EI);
    const auto end = displacementAlong(*line.beams[0], r.displacement, 1, SpanLoad::applied);
    CHECK(std::abs(end[rz] - byHand) <= 1e-12 * thetaScale);
    CHECK(std::abs(end[rz] - g.leftRotation(g.a)) <= 1e-12 * thetaScale);
    // A quarter-element from the joint, on each side.
    const auto leftQuarter =
        displacementAlong(*line.beams[0], r.displacement, 0.75, SpanLoad::applied);
    const auto rightQuarter =
        displacementAlong(*line.beams[1], r.displacement, 0.25, SpanLoad::applied);
    const double wScale = std::abs(g.leftDeflection(g.a));
    CHECK(std::abs(leftQuarter[uy] - g.leftDeflection(0.75 * h)) <= 1e-12 * wScale);
    CHECK(std::abs(leftQuarter[rz] - g.leftRotation(0.75 * h)) <= 1e-12 * thetaScale);
    CHECK(std::abs(rightQuarter[uy] - g.rightDeflection(1.25 * h)) <= 1e-12 * wScale);
    CHECK(std::abs(rightQuarter[rz] - g.rightRotation(1.25 * h)) <= 1e-12 * thetaScale);
  }

  // A frame's hinged joint: two clamped members meeting at a hinge under a load there, each a
  // cantilever carrying half the load (equal tip deflections by symmetry), so each end turns
  // by (P/2) L^2 / (2 EI), the two in opposite senses; results.json names each by its member.
  TEST_CASE("each member end at a hinged joint is reported by its member") {
    constexpr double kE = 210e9, kI = 8356e-8, kL = 3, kP = 20e3;
    std::ostringstream d;
    d.precision(17);
    d << "model: {dimension: planar}\n"
      << "materials: [{name: steel, E: " << kE << ", nu: 0.3}]\n"
      << "sections: [{name: beam, shape: general, A: 53.8e-4, I: " << kI
      << ", J: 1e-6, depth: 0.3}]\n"
      << "nodes: [{name: A, at: [0, 0]}, {name: B, at: [" << kL << ", 0]}, {name: C, at: ["
      << 2 * kL << ", 0]}]\n"
      << "members:\n"
      << "  - {name: west, from: A, to: B, section: beam, elements: 3}\n"
      << "  - {name: east, from: B, to: C, section: beam, elements: 3}\n"
      << "supports: [{name: A, at: A, fix: clamped}, {name: C, at: C, fix: clamped}]\n"
      << "hinges: [{at: B}]\n"
      << "loads: [{type: point, at: B, fy: " << -kP << "}]\n";
    const Study s = test::solveDeckText(d.str(), "hinged.yaml");
    const auto runs = test::runsOf(s);
    REQUIRE(runs.size() == 1);
    const Json doc = runJson(*runs.front());
    const Json& B = doc["analyses"][0]["displacements"]["B"];
    INFO(B.dump());
    // Euler-Bernoulli elements under nodal loads are exact: round-off only (1e-10 leaves room).
    const double theta = (kP / 2) * kL * kL / (2 * kE * kI);
    REQUIRE(B.contains("rz_west_end"));
    REQUIRE(B.contains("rz_east_start"));
    CHECK(B["rz_west_end"].get<double>() == doctest::Approx(-theta).epsilon(1e-10));
    CHECK(B["rz_east_start"].get<double>() == doctest::Approx(theta).epsilon(1e-10));
    // A line's left and right name one member end of several at a joint: not given in a frame.
    CHECK_FALSE(B.contains("rz_left"));
    CHECK_FALSE(B.contains("rz_right"));
    CHECK(B["uy"].get<double>() ==
          doctest::Approx(-(kP / 2) * kL * kL * kL / (3 * kE * kI)).epsilon(1e-10));
  }
}
