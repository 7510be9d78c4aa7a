// Distributed loads that vary along a member, cover part of it, or act per projected length
// (issue 16), each against its closed form: the fixed-end forces of a trapezoid, a simply
// supported beam under a triangle (peak moment and deflection inside an element), a
// Timoshenko cantilever under a triangle (bending plus shear deflection), a partial load's
// fixed-end forces by integrating the point-load formulas, a rafter under a load per plan
// length, and a partial load on a segment of a line deck. Then the reader's refusals.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "fem/assembly/MemberExtrema.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

constexpr double kMemberE = 210e9, kMemberI = 8e-6, kMemberA = 5e-3;

/// A planar deck of one member A-B along x of length L with `elements` elements, supports
/// `fixA` and `fixB` (none at B when empty), a general section (kappa 5/6, for Timoshenko runs) and `loads`.
std::string oneMemberDeck(double L, int elements, const std::string& fixA, const std::string& fixB,
                          const std::string& loads, const std::string& formulation = "euler-bernoulli") {
  std::ostringstream d;
  d.precision(17);
  d << "model: {dimension: planar, formulation: " << formulation << "}\n"
    << "materials: [{name: steel, E: " << kMemberE << ", nu: 0.3}]\n"
    << "sections: [{name: s, shape: general, A: " << kMemberA << ", I: " << kMemberI
    << ", J: 1e-5, kappa: 0.8333333333333334, depth: 0.2, width: 0.1}]\n"
    << "nodes: [{name: A, at: [0, 0]}, {name: B, at: [" << L << ", 0]}]\n"
    << "members: [{name: beam, from: A, to: B, section: s, elements: " << elements << "}]\n"
    << "supports: [{name: A, at: A, fix: " << fixA << "}"
    << (fixB.empty() ? "" : ", {name: B, at: B, fix: " + fixB + "}") << "]\n"
    << "loads: [" << loads << "]\n"
    << "analyses: [{type: static}]\n";
  return d.str();
}

const RunResult& theRun(const Study& s) {
  const auto runs = test::runsOf(s);
  REQUIRE(runs.size() == 1);
  return *runs.front();
}

std::array<ComponentRange, 6> beamRanges(const RunResult& run) {
  return memberForceRanges({*run.model, staticsOf(run.analyses.front())->displacement},
                           run.model->members().front().second);
}


}  // namespace

TEST_SUITE("member loads") {
  // Euler-Bernoulli and interdependent Timoshenko elements with the exact fixed-end forces of a
  // linear load are exact at the nodes and, with the clamped span solution, between them: what
  // remains is round-off (measured below 1e-13 on these cases), so 1e-10 is the tolerance.
  constexpr double kExact = 1e-10;

  TEST_CASE("clamped-clamped trapezoid: the textbook fixed-end forces, one element or several") {
    const double L = 5, qa = -10e3, qb = -25e3;
    for (int elements : {1, 3}) {
      CAPTURE(elements);
      std::ostringstream load;
      load.precision(17);
      load << "{type: distributed, member: beam, qy: [" << qa << ", " << qb << "]}";
      const Study s = test::solveDeckText(
          oneMemberDeck(L, elements, "clamped", "clamped", load.str()), "trapezoid.yaml");
      const RunResult& run = theRun(s);
      // Fixed-end forces of q varying linearly from qa to qb (e.g. Roark's Formulas for Stress
      // and Strain, 7th ed., table 8.1 case 2e): R_A = L (7 qa + 3 qb) / 20, M_A =
      // L^2 (3 qa + 2 qb) / 60 and at B the mirror, reactions opposing the load.
      CHECK(test::staticReaction(run, "A", Dof::uy) ==
            doctest::Approx(-L * (7 * qa + 3 * qb) / 20).epsilon(kExact));
      CHECK(test::staticReaction(run, "B", Dof::uy) ==
            doctest::Approx(-L * (3 * qa + 7 * qb) / 20).epsilon(kExact));
      CHECK(test::staticReaction(run, "A", Dof::rz) ==
            doctest::Approx(-L * L * (3 * qa + 2 * qb) / 60).epsilon(kExact));
      CHECK(test::staticReaction(run, "B", Dof::rz) ==
            doctest::Approx(L * L * (2 * qa + 3 * qb) / 60).epsilon(kExact));
    }
  }

  TEST_CASE("simply supported triangle: peak moment and deflection inside an element") {
    // q rising from 0 at A to q0 at B: M(x) = q0 x (L^2 - x^2) / (6 L), largest q0 L^2 / (9
    // sqrt 3) at x = L / sqrt 3; v(x) = q0 x (7 L^4 - 10 L^2 x^2 + 3 x^4) / (360 L EI), largest
    // at x = L sqrt(1 - sqrt(8/15)).
    const double L = 4, q0 = -30e3, EI = kMemberE * kMemberI;
    const Study s = test::solveDeckText(
        oneMemberDeck(L, 1, "pinned", "[uy]",
                      "{type: distributed, member: beam, qy: [0, " + std::to_string(q0) + "]}"),
        "triangle.yaml");
    const RunResult& run = theRun(s);
    const ComponentRange mz = beamRanges(run)[5];
    // Sagging under a downward load: the smallest (most negative) moment in this convention
    // is hogging, so the peak is the largest Mz of -q0.
    CHECK(mz.max.value == doctest::Approx(-q0 * L * L / (9 * std::sqrt(3.0))).epsilon(kExact));
    CHECK(mz.max.along == doctest::Approx(L / std::sqrt(3.0)).epsilon(1e-8));
    const double xPeak = L * std::sqrt(1 - std::sqrt(8.0 / 15.0));
    const double vPeak = std::abs(q0) * xPeak *
                         (7 * std::pow(L, 4) - 10 * L * L * xPeak * xPeak + 3 * std::pow(xPeak, 4)) /
                         (360 * L * EI);
    const MemberValue largest =
        largestDisplacement({*run.model, staticsOf(run.analyses.front())->displacement});
    CHECK(largest.value == doctest::Approx(vPeak).epsilon(kExact));
    // A stationary point found by bisection to the last bit: its place to about sqrt(eps).
    CHECK(largest.x.x() == doctest::Approx(xPeak).epsilon(1e-7));
  }

  TEST_CASE("Timoshenko cantilever under a triangle: bending plus shear deflection at the tip") {
    // q rising from 0 at the clamp to q0 at the tip: bending 11 q0 L^4 / (120 EI); the shear
    // force V(x) = q0 (L^2 - x^2) / (2 L) adds int V / (kappa G A) = q0 L^2 / (3 kappa G A).
    // Falling from q0 at the clamp to 0: q0 L^4 / (30 EI) and q0 L^2 / (6 kappa G A).
    const double L = 1.2, q0 = -50e3, EI = kMemberE * kMemberI;
    const double kGA = 5.0 / 6.0 * kMemberE / (2 * 1.3) * kMemberA;
    struct Profile {
      std::string values;
      double bending, shear;
    };
    const std::string q = std::to_string(q0);
    for (const Profile& p : {Profile{"[0, " + q + "]", 11.0 / 120, 1.0 / 3},
                             Profile{"[" + q + ", 0]", 1.0 / 30, 1.0 / 6}})
      for (int elements : {1, 4}) {
        CAPTURE(p.values);
        CAPTURE(elements);
        const Study s = test::solveDeckText(
            oneMemberDeck(L, elements, "clamped", "",
                          "{type: distributed, member: beam, qy: " + p.values + "}", "timoshenko"),
            "cantilever.yaml");
        const RunResult& run = theRun(s);
        const double tip = staticsOf(run.analyses.front())->displacement(run.model->node("B"), 1);
        const double expected = q0 * (p.bending * std::pow(L, 4) / EI + p.shear * L * L / kGA);
        CHECK(tip == doctest::Approx(expected).epsilon(kExact));
        // The shear part is a visible share here (a stocky cantilever), so the test tells the
        // theories apart.
        CHECK(std::abs(p.shear * L * L / kGA) > 0.01 * std::abs(expected / q0));
      }
  }

  TEST_CASE("partial uniform load on a clamped-clamped beam: the point-load formulas integrated") {
    // A point load P at x on a clamped-clamped span: M_A = P x (L - x)^2 / L^2 and
    // R_A = P (L - x)^2 (L + 2 x) / L^3. Integrated over w on [a, b]:
    //   M_A = w [F(b) - F(a)] / L^2, F(x) = L^2 x^2 / 2 - 2 L x^3 / 3 + x^4 / 4,
    //   R_A = w [G(b) - G(a)] / L^3, G(x) = L^3 x - L x^3 + x^4 / 2.
    const double L = 6, a = 1.5, b = 4, w = -12e3;
    const auto F = [&](double x) { return L * L * x * x / 2 - 2 * L * x * x * x / 3 + std::pow(x, 4) / 4; };
    const auto G = [&](double x) { return L * L * L * x - L * x * x * x + std::pow(x, 4) / 2; };
    std::ostringstream load;
    load.precision(17);
    load << "{type: distributed, member: beam, qy: " << w << ", from_length: " << a
         << ", to_length: " << b << "}";
    const Study s = test::solveDeckText(oneMemberDeck(L, 2, "clamped", "clamped", load.str()),
                                        "partial.yaml");
    const RunResult& run = theRun(s);
    CHECK(test::staticReaction(run, "A", Dof::rz) ==
          doctest::Approx(-w * (F(b) - F(a)) / (L * L)).epsilon(kExact));
    CHECK(test::staticReaction(run, "A", Dof::uy) ==
          doctest::Approx(-w * (G(b) - G(a)) / (L * L * L)).epsilon(kExact));
    // The same part given as fractions, the same answer.
    std::ostringstream fractions;
    fractions.precision(17);
    fractions << "{type: distributed, member: beam, qy: " << w << ", from: " << a / L
              << ", to: " << b / L << "}";
    const Study f = test::solveDeckText(oneMemberDeck(L, 2, "clamped", "clamped", fractions.str()),
                                        "partial.yaml");
    CHECK(test::staticReaction(theRun(f), "A", Dof::rz) ==
          doctest::Approx(-w * (F(b) - F(a)) / (L * L)).epsilon(kExact));
  }

  TEST_CASE("a rafter under a load per plan length: reactions w Lh / 2, moment w Lh^2 / 8") {
    // A simply supported sloped member (pinned at A, a vertical roller at B) under a vertical
    // load w per metre of plan length Lh: statically the beam of span Lh, whatever the slope.
    const double Lh = 6, H = 2.5, w = -4e3;
    std::ostringstream d;
    d.precision(17);
    d << "model: {dimension: planar}\n"
      << "materials: [{name: steel, E: 210e9, nu: 0.3}]\n"
      << "sections: [{name: s, shape: general, A: 5e-3, I: 8e-6, J: 1e-5, depth: 0.2, width: 0.1}]\n"
      << "nodes: [{name: A, at: [0, 0]}, {name: B, at: [" << Lh << ", " << H << "]}]\n"
      << "members: [{name: rafter, from: A, to: B, section: s, elements: 3}]\n"
      << "supports: [{name: A, at: A, fix: pinned}, {name: B, at: B, fix: [uy]}]\n"
      << "loads: [{type: distributed, qy: " << w << ", per: projected}]\n"
      << "analyses: [{type: static}]\n";
    const Study s = test::solveDeckText(d.str(), "rafter.yaml");
    const RunResult& run = theRun(s);
    CHECK(test::staticReaction(run, "A", Dof::uy) == doctest::Approx(-w * Lh / 2).epsilon(kExact));
    CHECK(test::staticReaction(run, "B", Dof::uy) == doctest::Approx(-w * Lh / 2).epsilon(kExact));
    const ComponentRange mz = beamRanges(run)[5];
    CHECK(mz.max.value == doctest::Approx(-w * Lh * Lh / 8).epsilon(kExact));
    // Per member length instead, the same w loads the longer member: reactions grow by
    // the ratio of lengths.
    std::string perLength = d.str();
    perLength.replace(perLength.find(", per: projected"), std::string(", per: projected").size(), "");
    const Study t = test::solveDeckText(perLength, "rafter.yaml");
    CHECK(test::staticReaction(theRun(t), "A", Dof::uy) ==
          doctest::Approx(-w * std::hypot(Lh, H) / 2).epsilon(kExact));
  }

  TEST_CASE("a partial load on a segment of a line deck") {
    // Simply supported span L, w on [a, b]: R_A = w (b - a) (L - (a + b) / 2) / L.
    const double L = 3, a = 0.5, b = 1.7, w = -2e3;
    std::ostringstream d;
    d.precision(17);
    d << "model: {dimension: planar}\n"
      << "materials: [{name: steel, E: 210e9, nu: 0.3}]\n"
      << "sections: [{name: s, shape: general, A: 5e-3, I: 8e-6, J: 1e-5, depth: 0.2, width: 0.1}]\n"
      << "segments: [{name: span, length: " << L << ", section: s, elements: 2}]\n"
      << "supports: [{at: start, fix: pinned}, {at: end, fix: [uy]}]\n"
      << "loads: [{type: distributed, segment: span, qy: " << w << ", from_length: " << a
      << ", to_length: " << b << "}]\n"
      << "analyses: [{type: static}]\n";
    const Study s = test::solveDeckText(d.str(), "line.yaml");
    const RunResult& run = theRun(s);
    const StaticResult& r = *staticsOf(run.analyses.front());
    double RA = 0;
    for (const ReactionComponent& c : r.reactions)
      if (c.node == run.model->node("start") && c.dof == Dof::uy) RA += c.value;
    CHECK(RA == doctest::Approx(-w * (b - a) * (L - (a + b) / 2) / L).epsilon(kExact));
  }

  TEST_CASE("a point force and a point moment along a member: the fixed-end closed forms") {
    // Clamped-clamped span L, a = 0.3 L from A, b = L - a. A force P (+y): R_A = -P b^2 (3a +
    // b) / L^3, M_A = -P a b^2 / L^2. A moment M (+z, counter-clockwise): R_A = 6 M a b / L^3,
    // M_A = M b (2a - b) / L^2 (the support takes all of it, -M, when a = 0; none when b = 0).
    const double L = 5, a = 0.3 * L, b = L - a, P = -8e3, M = 3e3;
    for (int elements : {1, 4}) {
      CAPTURE(elements);
      const auto solved = [&](const std::string& component, double value) {
        std::ostringstream load;
        load.precision(17);
        load << "{type: point, at: {member: beam, at: 0.3}, " << component << ": " << value << "}";
        return test::solveDeckText(oneMemberDeck(L, elements, "clamped", "clamped", load.str()),
                                   "point.yaml");
      };
      const Study force = solved("fy", P);
      CHECK(test::staticReaction(theRun(force), "A", Dof::uy) ==
            doctest::Approx(-P * b * b * (3 * a + b) / (L * L * L)).epsilon(kExact));
      CHECK(test::staticReaction(theRun(force), "A", Dof::rz) ==
            doctest::Approx(-P * a * b * b / (L * L)).epsilon(kExact));
      const Study moment = solved("mz", M);
      CHECK(test::staticReaction(theRun(moment), "A", Dof::uy) ==
            doctest::Approx(6 * M * a * b / (L * L * L)).epsilon(kExact));
      CHECK(test::staticReaction(theRun(moment), "A", Dof::rz) ==
            doctest::Approx(M * b * (2 * a - b) / (L * L)).epsilon(kExact));
    }
  }

  TEST_CASE("distributed loads the reader refuses, naming the field") {
    struct Bad {
      std::string load, field, phrase;
    };
    const std::vector<Bad> cases{
        {"{type: distributed, member: beam, qy: [1, 2, 3]}", "loads[0].qy", "two values"},
        {"{type: distributed, member: beam, qy: 1, from: 0.6, to: 0.4}", "loads[0].to",
         "ends where it starts or before"},
        {"{type: distributed, member: beam, qy: 1, from: 1.5}", "loads[0].from", "[0, 1]"},
        {"{type: distributed, qy: 1, from_length: 1}", "loads[0].from_length",
         "one segment or member"},
        {"{type: distributed, member: beam, qy: 1, from: 0.1, from_length: 1}",
         "loads[0].from_length", "not both"},
        {"{type: distributed, member: beam, qy: 1, to_length: 9}", "loads[0].to_length",
         "lies in [0, 5]"},
        {"{type: distributed, member: beam, qy: 1, axes: member, per: projected}", "loads[0].per",
         "global axes"},
        {"{type: distributed, member: beam, qy: 1, per: plan}", "loads[0].per", "projected"},
        {"{type: distributed, member: beam, qy: [1 m, 2]}", "loads[0].qy[0]", "force per length"},
    };
    for (const Bad& c : cases) {
      CAPTURE(c.load);
      const DeckError e = test::readingError(oneMemberDeck(5, 2, "clamped", "clamped", c.load), "loads.yaml");
      CHECK(e.file() == "loads.yaml");
      CHECK(e.place().line == 7);  // the loads line
      CHECK(e.place().field == c.field);
      CHECK(e.message().find(c.phrase) != std::string::npos);
    }
  }
}
