// Deck features against closed forms of beam theory: distributed load, self-weight, hinges,
// springs, point masses, 3D frames and the Timoshenko formulation, each built from deck text
// the way a user writes it.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using beamrotor::test::relError;

namespace {

// Euler-Bernoulli (and interdependent Timoshenko) elements with consistent loads give exact
// nodal values for end loads and uniform distributed loads: only round-off remains, far
// below this.
constexpr double kFeaturesExact = 1e-9;

const double L = 2.0, P = 500, D = 0.04, E = 200e9, nu = 0.3, rho = 7800;
const double I = std::numbers::pi * std::pow(D, 4) / 64, A = std::numbers::pi * D * D / 4;

/// Parameters shared by the decks below: the numbers above.
const std::string kParameters = R"(
parameters:
  L: 2.0
  P: 500
  D: 0.04
  E: 200e9
)";

/// A steel rod section of diameter D.
const std::string kSteelRod = R"(
materials:
  - {name: steel, E: E, nu: 0.3, rho: 7800}
sections:
  - {name: rod, shape: circle, D: D}
)";

RunResult solveFeatureDeck(const std::string& body) {
  StudyRequest r;
  r.deckPath = "inline.yaml";
  Study s = solveStudyText(kParameters + body, r);
  REQUIRE(s.run);
  return *s.run;
}

const StaticResult& statics(const RunResult& run) {
  for (const AnalysisOutcome& a : run.analyses)
    if (staticsOf(a)) return *staticsOf(a);
  throw std::logic_error("no static analysis");
}

double displacement(const RunResult& run, const std::string& point, Dof d) {
  return statics(run).displacement(run.model->node(point), dofIndex(d));
}

}  // namespace

TEST_SUITE("deck features") {
  TEST_CASE("uniform load on a simply supported beam: 5 q L^4 / (384 E I) at midspan") {
    const RunResult run = solveFeatureDeck(kSteelRod + R"(
segments:
  - {name: span, length: L, section: rod, elements: 6}
points:
  - {name: mid, at: L/2}
supports:
  - {name: a, at: start, fix: pinned}
  - {name: b, at: end, fix: [uy]}
loads:
  - {type: distributed, segment: span, qy: -P}
)");
    CHECK(relError(displacement(run, "mid", Dof::uy), -5 * P * std::pow(L, 4) / (384 * E * I)) <
          kFeaturesExact);
  }

  TEST_CASE("self-weight of a cantilever: q L^4 / (8 E I) at the tip, q = rho A g") {
    const RunResult run = solveFeatureDeck(kSteelRod + R"(
segments:
  - {length: L, section: rod, size: 0.25}
supports:
  - {name: root, at: start, fix: clamped}
loads:
  - {type: self-weight}
)");
    const double q = rho * A * 9.81;
    CHECK(relError(displacement(run, "end", Dof::uy), -q * std::pow(L, 4) / (8 * E * I)) <
          kFeaturesExact);
  }

  // The equivalent nodal load at a supported node belongs in its reaction exactly once (an
  // earlier core version subtracted it twice: 5/12 q L instead of q L / 2 here).
  TEST_CASE("reactions of distributed loads include the share at supported nodes") {
    const RunResult run = solveFeatureDeck(kSteelRod + R"(
segments:
  - {length: L, section: rod, elements: 6}
supports:
  - {name: a, at: start, fix: pinned}
  - {name: b, at: end, fix: [uy]}
loads:
  - {type: distributed, qy: -P}
)");
    CHECK(relError(statics(run).reaction("a", Dof::uy), P * L / 2) < kFeaturesExact);
    CHECK(relError(statics(run).reaction("b", Dof::uy), P * L / 2) < kFeaturesExact);
  }

  TEST_CASE("a hinge between two cantilevers shares the load equally") {
    // Clamped at both ends, hinged at midspan, P at the hinge: by symmetry each half is a
    // cantilever of length L/2 carrying P/2.
    const RunResult run = solveFeatureDeck(kSteelRod + R"(
segments:
  - {length: L, section: rod, elements: 4}
points:
  - {name: hinge, at: L/2}
supports:
  - {name: left, at: start, fix: clamped}
  - {name: right, at: end, fix: clamped}
hinges:
  - {at: hinge}
loads:
  - {type: point, at: hinge, fy: -P}
)");
    const double h = L / 2;
    CHECK(relError(displacement(run, "hinge", Dof::uy), -(P / 2) * h * h * h / (3 * E * I)) <
          kFeaturesExact);
    // Without the hinge the clamped-clamped beam would carry P L / 8 at each end instead.
    CHECK(relError(statics(run).reaction("left", Dof::rz), P / 2 * h) < kFeaturesExact);
  }

  TEST_CASE("a grounded spring at the tip: deflection P / (k + 3 E I / L^3)") {
    const RunResult run = solveFeatureDeck(kSteelRod + R"(
segments:
  - {length: L, section: rod, elements: 3}
supports:
  - {name: root, at: start, fix: clamped}
springs:
  - {name: prop, at: end, dof: uy, k: 2e4}
loads:
  - {type: point, at: end, fy: -P}
)");
    CHECK(relError(displacement(run, "end", Dof::uy), -P / (2e4 + 3 * E * I / (L * L * L))) <
          kFeaturesExact);
  }

  TEST_CASE("a two-point axial spring in parallel with half a bar") {
    // Bar fixed at the start, pulled by P at the end; a spring k joins midpoint and end:
    // u_end = P / (2 E A / L) + P / (2 E A / L + k).
    const RunResult run = solveFeatureDeck(kSteelRod + R"(
segments:
  - {length: L, section: rod, elements: 4}
points:
  - {name: mid, at: L/2}
supports:
  - {name: root, at: start, fix: clamped}
  - {name: guide, at: end, fix: [uy, rz]}
springs:
  - {at: mid, to: end, dof: ux, k: 3e8}
loads:
  - {type: point, at: end, fx: P}
)");
    const double half = 2 * E * A / L;
    CHECK(relError(displacement(run, "end", Dof::ux), P / half + P / (half + 3e8)) <
          kFeaturesExact);
  }

  TEST_CASE("a point mass on a massless cantilever: f = sqrt(3 E I / (m L^3)) / (2 pi)") {
    const RunResult run = solveFeatureDeck(R"(
materials:
  - {name: massless, E: E, nu: 0.3}
sections:
  - {name: rod, shape: circle, D: D}
segments:
  - {length: L, section: rod, elements: 4}
supports:
  - {name: root, at: start, fix: clamped}
masses:
  - {name: bob, at: end, m: 12}
analyses:
  - {type: modal, modes: 1}
)");
    REQUIRE(resultOf<ModalResult>(run.analyses[0]));
    const double f = std::sqrt(3 * E * I / (12 * L * L * L)) / (2 * std::numbers::pi);
    // The massless beam condenses exactly to its tip stiffness; the eigen solver converges to
    // ~1e-12, so 1e-8 is generous without hiding a wrong mass or stiffness.
    CHECK(relError(resultOf<ModalResult>(run.analyses[0])->modes[0].frequencyHz, f) < 1e-8);
  }

  TEST_CASE("3D frame: bending about y and torsion") {
    const RunResult run = solveFeatureDeck(kSteelRod + R"(
model: {dimension: 3d}
segments:
  - {length: L, section: rod, elements: 2}
supports:
  - {name: root, at: start, fix: clamped}
loads:
  - {type: point, at: end, fz: -P, mx: 40}
)");
    const double G = E / (2 * (1 + nu)), J = 2 * I;
    CHECK(relError(displacement(run, "end", Dof::uz), -P * L * L * L / (3 * E * I)) <
          kFeaturesExact);
    CHECK(relError(displacement(run, "end", Dof::rx), 40 * L / (G * J)) < kFeaturesExact);
    CHECK(relError(statics(run).reaction("root", Dof::uz), P) < kFeaturesExact);
  }

  TEST_CASE("Timoshenko formulation adds the shear deflection P L / (kappa G A)") {
    // A deep rectangle (L/h = 5) where shear deflection is about 3 % of bending.
    const std::string deck = R"(
materials:
  - {name: steel, E: E, nu: 0.3}
sections:
  - {name: deep, shape: rectangle, b: 0.1, h: 0.4}
segments:
  - {length: L, section: deep, elements: 2, formulation: FORM}
supports:
  - {name: root, at: start, fix: clamped}
loads:
  - {type: point, at: end, fy: -P}
)";
    const double b = 0.1, h = 0.4, Iz = b * h * h * h / 12, G = E / (2 * (1 + nu));
    const double kappa = 10 * (1 + nu) / (12 + 11 * nu);  // Cowper, rectangle
    const double bending = P * L * L * L / (3 * E * Iz), shear = P * L / (kappa * G * b * h);
    auto tip = [&](const std::string& formulation) {
      std::string d = deck;
      d.replace(d.find("FORM"), 4, formulation);
      return displacement(solveFeatureDeck(d), "end", Dof::uy);
    };
    // The interdependent-interpolation element is exact for end loads.
    CHECK(relError(tip("timoshenko"), -(bending + shear)) < kFeaturesExact);
    CHECK(relError(tip("euler-bernoulli"), -bending) < kFeaturesExact);
  }
}

TEST_SUITE("deck features") {
  TEST_CASE("contacts: a cantilever tip over a floor closes past P = 3 E I gap / L^3") {
    // Closing load of a 2 m, D = 40 mm steel cantilever over a 2 mm gap: 3 E I g / L^3.
    const double gap = 0.002, closing = 3 * E * I * gap / (L * L * L);
    REQUIRE(closing > 10);  // 18.85 N: 10 N stays open, 40 N closes (loads exact in text)
    for (double load : {10.0, 40.0}) {
      CAPTURE(load);
      const std::string deck = kSteelRod + R"(
segments:
  - {length: L, section: rod, elements: 4}
supports:
  - {name: root, at: start, fix: clamped}
contacts:
  - {name: floor, at: end, dof: uy, min: -0.002}
loads:
  - {type: point, at: end, fy: -)" +
                               std::to_string(load) + R"(}
analyses:
  - {type: static}
)";
      const RunResult run = solveFeatureDeck(deck);
      const StaticResult& s = *staticsOf(run.analyses.at(0));
      REQUIRE(s.contacts.size() == 1);
      if (load < closing) {
        CHECK_FALSE(s.contacts[0].active);
        CHECK(std::abs(s.contacts[0].gap - (gap - load / (3 * E * I / (L * L * L)))) <
              kFeaturesExact * gap);
      } else {
        CHECK(s.contacts[0].active);
        CHECK(std::abs(s.contacts[0].force - (load - closing)) < kFeaturesExact * load);
      }
    }
  }
}
