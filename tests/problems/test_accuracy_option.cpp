// `accuracy:` picks the cheapest adequate model; on closed-form cases the model it picks must
// really be within the target, and its shear-contribution estimate must match the closed form.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

namespace beamrotor {

namespace {

/// A simply supported steel bar (L = 2 m, b = 0.04 m, depth h) under a uniform load q, on
/// 64 elements of `theory`; `checks` and `accuracy` as given.
RunResult solveBar(double h, const std::string& theory, const std::string& analyses,
                   const std::string& checks, double accuracy) {
  const std::string text = R"(
parameters: {L: 2.0, b: 0.04, h: )" +
                           std::to_string(h) + R"(, q: 500, E: 210e9, nu: 0.3, rho: 7850}
derived:
  I: b * h^3 / 12
  A: b * h
  G: E / (2 * (1 + nu))
  kappa: 10 * (1 + nu) / (12 + 11 * nu)
model: {dimension: planar, formulation: )" +
                           theory + R"(}
materials: [{name: steel, E: E, nu: nu, rho: rho}]
sections: [{name: bar, shape: rectangle, b: b, h: h}]
segments: [{length: L, section: bar, elements: 64}]
points: [{name: mid, at: L/2}]
supports: [{name: left, at: start, fix: [ux, uy]}, {name: right, at: end, fix: [uy]}]
loads: [{type: distributed, qy: -q}]
analyses: )" + analyses + R"(
accuracy: )" + std::to_string(accuracy) +
                           R"(
checks:
)" + checks;
  StudyRequest request;
  request.deckPath = "bar_accuracy.yaml";
  return *solveStudyText(text, request).run;
}

/// Euler-Bernoulli closed forms (Timoshenko & Gere): midspan deflection 5 q L^4 / (384 E I),
/// first frequency (pi / L)^2 sqrt(E I / (rho A)) / (2 pi).
const std::string kEulerBernoulliChecks =
    "  - {name: w, quantity: displacement mid uy, reference: -5*q*L^4/(384*E*I), tolerance: 1}\n"
    "  - {name: f1, quantity: frequency 1, tolerance: 1,"
    " reference: (pi/L)^2 * sqrt(E*I/(rho*A)) / (2*pi)}\n";

/// Share of shear in the Timoshenko midspan deflection of the simply supported bar of depth h
/// (L = 2 m, nu = 0.3): (w_T - w_EB) / w_T = s / (1 + s) with s = q L^2 / (8 kappa G A) over
/// 5 q L^4 / (384 E I), i.e. 48 E I / (5 kappa G A L^2), Cowper's kappa for a rectangle.
double midspanShearShare(double h) {
  const double nu = 0.3, L = 2.0, kappa = 10 * (1 + nu) / (12 + 11 * nu);
  const double s = 48.0 * (h * h / 12) * 2 * (1 + nu) / (5 * kappa * L * L);
  return s / (1 + s);
}

}  // namespace

TEST_SUITE("accuracy option") {
  TEST_CASE("slender Timoshenko bar, 1e-3: Euler-Bernoulli on a coarse mesh, within target") {
    // L/h = 100: the shear part of the midspan deflection, q L^2 / (8 kappa G A) against
    // 5 q L^4 / (384 E I), is 48 E I / (5 kappa G A L^2) = 2.45e-4 (Cowper's kappa for a
    // rectangle), below the target; the frequency's shear correction is about half that.
    const double target = 1e-3;
    const RunResult run = solveBar(0.02, "timoshenko", "[{type: static}, {type: modal, modes: 2}]",
                                   kEulerBernoulliChecks, target);
    REQUIRE(run.adequate);
    const AdequateChoice& c = *run.adequate;
    CHECK(c.formulation == "euler-bernoulli");
    CHECK(c.deckFormulation == "timoshenko");
    // The checks compare the chosen model with the Euler-Bernoulli closed forms: its actual
    // error must be below the target and below its estimate.
    for (const Check& k : run.checks) {
      INFO(k.name << " rel. error " << k.relError());
      CHECK(k.relError() < target);
      CHECK(k.relError() <= c.estimatedError);
    }
    // Both elements are exact at the nodes for this load, so the measured shear contribution,
    // (w_T - w_EB) / w_T = s / (1 + s) with s the shear term relative to w_EB, is the closed
    // form to round-off (the frequency's is smaller).
    REQUIRE(c.shearContribution);
    CHECK(test::relError(*c.shearContribution, midspanShearShare(0.02)) < 1e-9);
    CHECK(c.dofs < c.deckDofs);  // coarser than the deck's 64 elements
    CHECK(c.elementsPerSegment < 64);
  }

  TEST_CASE("stubby Timoshenko bar, 1e-4: keeps Timoshenko, within target of its closed form") {
    // L/h = 10: the shear part is 2.45e-2, far above the target, so the deck's theory stays.
    // Reference: the Timoshenko midspan deflection 5 q L^4/(384 E I) + q L^2/(8 kappa G A).
    const double target = 1e-4;
    const RunResult run = solveBar(0.2, "timoshenko", "[{type: static}]",
                                   "  - {name: w, quantity: displacement mid uy, tolerance: 1,"
                                   " reference: -5*q*L^4/(384*E*I) - q*L^2/(8*kappa*G*A)}\n",
                                   target);
    REQUIRE(run.adequate);
    CHECK(run.adequate->formulation == "timoshenko");
    CHECK(test::relError(*run.adequate->shearContribution, midspanShearShare(0.2)) < 1e-9);
    CHECK(run.checks.front().relError() < target);
  }

  TEST_CASE("Euler-Bernoulli frequency, 1e-6: the mesh found is within target and coarser") {
    // The consistent-mass error falls as h^4 (converge rates): about 1.0e-6 on 16 elements,
    // 6.4e-8 on 32; the search stops where successive meshes agree to 1e-6, i.e. 32.
    const double target = 1e-6;
    const RunResult run = solveBar(0.02, "euler-bernoulli", "[{type: modal, modes: 1}]",
                                   "  - {name: f1, quantity: frequency 1, tolerance: 1,"
                                   " reference: (pi/L)^2 * sqrt(E*I/(rho*A)) / (2*pi)}\n",
                                   target);
    REQUIRE(run.adequate);
    CHECK(run.adequate->formulation == "euler-bernoulli");
    CHECK_FALSE(run.adequate->shearContribution);
    CHECK(run.adequate->elementsPerSegment == 32);
    CHECK(run.checks.front().relError() < target);
    CHECK(run.checks.front().relError() <= run.adequate->estimatedError);
    CHECK(run.adequate->deckDofs - run.adequate->dofs == 3 * 32);  // 65 vs 33 nodes, 3 dofs
  }
}

}  // namespace beamrotor

namespace beamrotor {

namespace {

/// problems/forme_shaft.yaml with `accuracy: target` added, solved with `sets`.
Study formeShaftWithAccuracy(double target, std::vector<std::string> sets = {}) {
  std::ifstream in(std::string(BEAMROTOR_SOURCE_DIR) + "/problems/forme_shaft.yaml");
  std::stringstream text;
  text << in.rdbuf() << "\naccuracy: " << target << "\n";
  StudyRequest request;
  request.deckPath = "forme_shaft_accuracy.yaml";
  request.sets = std::move(sets);
  return solveStudyText(text.str(), request);
}

/// Largest relative difference of the deck's own two-dof frequencies (derived f1, f2: section
/// integrals, independent of the FE model) from the run's two lowest FE frequencies.
double deckRigidError(const Study& s) {
  double largest = 0;
  for (const AnalysisOutcome& a : s.run->analyses) {
    if (!resultOf<ModalResult>(a)) continue;
    for (int i = 0; i < 2; ++i) {
      const double fe = resultOf<ModalResult>(a)->modes[i].frequencyHz;
      const double twoDof = test::deckValue(s.deck, i == 0 ? "f1" : "f2");
      largest = std::max(largest, std::abs(twoDof - fe) / fe);
    }
  }
  return largest;
}

}  // namespace

TEST_SUITE("accuracy option") {
  TEST_CASE("forme shaft: the rigid body on two springs is adequate at 10 %, not at 0.1 %") {
    const Study loose = formeShaftWithAccuracy(0.1);
    REQUIRE(loose.run);
    REQUIRE(loose.run->adequate);
    const AdequateChoice& c = *loose.run->adequate;
    REQUIRE(c.rigidBodyError);
    // The deck's closed form and the rigid-body analysis agree to ~1e-14; the FE frequencies
    // are the same numbers both ways, so only round-off separates the two errors.
    CHECK(*c.rigidBodyError == doctest::Approx(deckRigidError(loose)).epsilon(1e-9));
    // Real steel: the flexible shaft lies about 6 % below the rigid body (issue 5's figures).
    CHECK(*c.rigidBodyError > 0.05);
    CHECK(*c.rigidBodyError < 0.07);
    CHECK(c.rigidBodyAdequate);

    const Study tight = formeShaftWithAccuracy(1e-3);
    REQUIRE(tight.run->adequate);
    CHECK_FALSE(tight.run->adequate->rigidBodyAdequate);
  }

  TEST_CASE("forme shaft with a nearly rigid shaft: the rigid body is adequate at 1e-4") {
    const Study s = formeShaftWithAccuracy(1e-4, {"E=2e17"});
    REQUIRE(s.run->adequate);
    const AdequateChoice& c = *s.run->adequate;
    REQUIRE(c.rigidBodyError);
    CHECK(*c.rigidBodyError < 1e-6);  // measured 6.3e-8 (issue 5)
    CHECK(c.rigidBodyAdequate);
  }
}

}  // namespace beamrotor
