// The forme-shaft decks (problems/scenes/README.md section 2) through `beamrotor solve`'s path:
// rigid-body properties and the two-dof closed form, the rigid limit (--set E=2e17), how much real
// steel lowers the frequencies (and, as plumbing, that the deck builds the scene's own C++
// model), the decoupled case C1 l1 = C2 l2, and the spinning shaft's checks in the rigid limit.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "fem/modal/Modal.hpp"
#include "problems/cli/RotorSummary.hpp"
#include "problems/output/rotor/RotorJson.hpp"
#include "problems/run/Study.hpp"
#include "problems/scenes/FormeShaft.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

RunResult solveFormeDeck(const char* deck, std::vector<std::string> sets = {}) {
  StudyRequest r;
  r.deckPath = (problemsDir() / deck).string();
  r.sets = std::move(sets);
  const Study s = solveStudy(r);
  REQUIRE(s.run);
  return *s.run;
}

const AnalysisOutcome& analysisOfType(const RunResult& run, const std::string& type) {
  for (const AnalysisOutcome& a : run.analyses)
    if (a.type == type) return a;
  FAIL("no " << type << " analysis");
  return run.analyses.front();
}

/// Every check that applied passed; returns how many applied.
int passedChecks(const RunResult& run) {
  for (const Check& c : run.checks) {
    CAPTURE(c.name);
    CAPTURE(c.relError());
    CHECK(c.pass());
  }
  return int(run.checks.size());
}

}  // namespace

TEST_SUITE("forme shaft decks") {
  TEST_CASE("real steel: the deck's FE frequencies are the scene's, ~6 % below k1, k2") {
    const RunResult run = solveFormeDeck("forme_shaft.yaml");
    CHECK(passedChecks(run) == 11);  // the rigid-limit checks do not apply to steel
    CHECK(run.skippedChecks.size() == 2);
    const RigidBodyOutcome& rigid = *resultOf<RigidBodyOutcome>(analysisOfType(run, "rigid-body"));
    const ModalResult& modal = *resultOf<ModalResult>(analysisOfType(run, "modal"));

    // Plumbing, not a second method: the same shaft built in C++ by the scene
    // (problems/scenes/FormeShaft) with the same mesh and solved the same way gives the same
    // frequencies up to the eigensolver's round-off, which shows the deck builds that model.
    // The independent references are the rigid two-dof closed form (the drop below) and, in
    // tests/problems/test_forme_shaft.cpp, Weyl's bound on the drop.
    const FormeShaftModel scene = buildFormeShaft(FormeShaftDesign{}, DofSet::planar());
    const ModalResult reference = solveModes(scene.model, {2, 0});
    for (int i = 0; i < 2; ++i) {
      CAPTURE(i);
      const double fe = modal.modes[i].frequencyHz, k = rigid.modes[i].k / kTwoPi;
      CHECK(relError(fe, reference.modes[i].frequencyHz) < 1e-10);
      // Flexibility only lowers the frequencies (Rayleigh); tests/problems/test_forme_shaft
      // bounds the drop by Weyl's inequality and shows it is the model's, not the mesh's.
      const double drop = 1 - fe / k;
      CHECK(drop > 0);
      CHECK(drop < 0.1);
      MESSAGE("forme shaft, real steel: mode " << i + 1 << " FE " << fe << " Hz, rigid two-dof "
                                               << k << " Hz: " << 100 * drop << " % lower");
    }
  }

  TEST_CASE("rigid limit (--set E=2e17): FE frequencies reach k1, k2 to 1e-6") {
    const RunResult run = solveFormeDeck("forme_shaft.yaml", {"E=2e17"});
    CHECK(passedChecks(run) == 13);
    CHECK(run.skippedChecks.empty());
    const RigidBodyOutcome& rigid = *resultOf<RigidBodyOutcome>(analysisOfType(run, "rigid-body"));
    const ModalResult& modal = *resultOf<ModalResult>(analysisOfType(run, "modal"));
    for (int i = 0; i < 2; ++i)
      CHECK(relError(modal.modes[i].frequencyHz, rigid.modes[i].k / kTwoPi) < 1e-6);
  }

  TEST_CASE("decoupled deck (C1 l1 = C2 l2): pure bounce and rocking, n reported as null") {
    // C2 from the lever arms of the default deck; the FE centre of mass is the section
    // integrals' to round-off (checked by the deck), so b is round-off too.
    const RunResult first = solveFormeDeck("forme_shaft.yaml");
    const FormeShaftRigid s =
        resultOf<RigidBodyOutcome>(analysisOfType(first, "rigid-body"))->rigid;
    const double C2 = s.C1 * s.l1 / s.l2;
    const RunResult run = solveFormeDeck("forme_shaft.yaml", {"E=2e17", setting("C2", C2)});
    const AnalysisOutcome& outcome = analysisOfType(run, "rigid-body");
    const RigidBodyOutcome& rigid = *resultOf<RigidBodyOutcome>(outcome);
    const int ib = rigid.modes[0].kind == FormeModeKind::bounce ? 0 : 1;
    REQUIRE(rigid.modes[ib].kind == FormeModeKind::bounce);
    REQUIRE(rigid.modes[1 - ib].kind == FormeModeKind::rocking);
    // Closed forms of the decoupled modes: bounce sqrt((C1 + C2)/m), rocking sqrt(d/rho^2).
    const FormeShaftRigid& r = rigid.rigid;
    CHECK(relError(rigid.modes[ib].k, std::sqrt((r.C1 + r.C2) / r.m)) < 1e-12);
    CHECK(relError(rigid.modes[1 - ib].k, std::sqrt(r.d() / r.rho2())) < 1e-12);
    // The deck's n and load checks (written with n) say n/a (0/0), the FE frequencies still
    // reach the closed form.
    CHECK(passedChecks(run) == 7);
    REQUIRE(run.skippedChecks.size() == 6);
    CHECK(run.skippedChecks[0] == "two-dof n1");
    const ModalResult& modal = *resultOf<ModalResult>(analysisOfType(run, "modal"));
    for (int i = 0; i < 2; ++i)
      CHECK(relError(modal.modes[i].frequencyHz, rigid.modes[i].k / kTwoPi) < 1e-6);
    // results.json: n of the bounce mode is null (infinite), of the rocking mode 0.
    const Json doc = rotorJson(outcome, rigid);
    CHECK(doc.at("two_dof").at("decoupled") == true);
    CHECK(doc.at("two_dof").at("modes")[ib].at("n").is_null());
    CHECK(doc.at("two_dof").at("modes")[1 - ib].at("n") == 0.0);
  }

  TEST_CASE("spinning shaft deck: rigid-rotor whirl, critical speeds and orbits (E=2e17)") {
    for (const char* speed : {"speed=300rpm", "speed=12000rpm"}) {
      CAPTURE(speed);
      const RunResult run = solveFormeDeck("forme_shaft_rotor.yaml", {"E=2e17", speed});
      CHECK(passedChecks(run) == 15);
      CHECK(run.skippedChecks.empty());
    }
    // Real steel: only the inertia checks apply; the flexible shaft's critical speeds lie
    // below the rigid ones (flexibility lowers every frequency line).
    const RunResult steel = solveFormeDeck("forme_shaft_rotor.yaml");
    CHECK(passedChecks(steel) == 4);
    const RunResult stiff = solveFormeDeck("forme_shaft_rotor.yaml", {"E=2e17"});
    const auto& soft = resultOf<CampbellOutcome>(analysisOfType(steel, "campbell"))->criticalSpeeds;
    const auto& rigid =
        resultOf<CampbellOutcome>(analysisOfType(stiff, "campbell"))->criticalSpeeds;
    REQUIRE(soft.size() == 4);
    REQUIRE(rigid.size() == 4);
    for (int i = 0; i < 4; ++i) {
      CHECK(soft[i].rpm < rigid[i].rpm);
      MESSAGE("critical speed " << i + 1 << ": steel " << soft[i].rpm << " rpm, rigid "
                                << rigid[i].rpm << " rpm");
    }
  }

  TEST_CASE("spinning shaft deck: its undamped modes print damping 0, not round-off of a sign") {
    // The bearings are springs without damping and the shaft has none: M q'' + Omega G q' +
    // K q = 0 with G skew conserves energy, so every eigenvalue is imaginary. The eigensolver
    // leaves damping ratios of +-1e-17 to 1e-16, whose sign a reader would take for a verdict.
    const RunResult steel = solveFormeDeck("forme_shaft_rotor.yaml");
    const AnalysisOutcome& a = analysisOfType(steel, "rotor");
    const RotorModesResult& r = *resultOf<RotorModesResult>(a);
    REQUIRE(r.modes.size() == 4);
    for (const RotorMode& m : r.modes) CHECK(std::abs(m.dampingRatio) <= m.roundOff);
    std::ostringstream summary;
    cli::printRotor(summary, a, r);
    const std::string text = summary.str();
    for (const char* mode : {"mode 1 ", "mode 2 ", "mode 3 ", "mode 4 "}) {
      CAPTURE(mode);
      const std::size_t at = text.find(mode);
      REQUIRE(at != std::string::npos);
      const std::string line = text.substr(at, text.find('\n', at) - at);
      CHECK(line.find("  damping 0  log decrement 0  ") != std::string::npos);
    }
  }
}
