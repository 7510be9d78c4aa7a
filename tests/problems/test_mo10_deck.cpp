// problems/mo10.yaml end to end: the deck's body (points, a mass, a spring, no beam) against
// the closed form of problems/scenes/Mo10 at every cycle boundary, with Newmark's dt^2 rate;
// against the core's own MO-10 model (plumbing: the same equations built by the library); at
// the resonance k = mu; and the c sweep charting phi_max and spring_force_max.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fem/transient/Transient.hpp"
#include "problems/run/Study.hpp"
#include "problems/scenes/Mo10.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
namespace fs = std::filesystem;

namespace {

const fs::path kMo10Deck = test::problemsDir() / "mo10.yaml";

/// NAME=VALUE with every digit of value, so the deck sees exactly this double.
RunResult solveMo10Deck(const std::vector<std::string>& sets) {
  StudyRequest r;
  r.deckPath = kMo10Deck.string();
  r.sets = sets;
  r.noSweep = true;
  Study s = solveStudy(r);
  REQUIRE(s.run);
  return std::move(*s.run);
}

const TransientOutcome& blows(const RunResult& run) {
  REQUIRE(resultOf<TransientOutcome>(run.analyses.at(0)));
  return *resultOf<TransientOutcome>(run.analyses.at(0));
}

double parameter(const RunResult& run, const std::string& name) {
  for (const auto& [n, v] : run.parameters)
    if (n == name) return v;
  FAIL("no parameter " << name);
  return 0;
}

Mo10Parameters parametersOf(const RunResult& run) {
  Mo10Parameters p;
  p.J = parameter(run, "J");
  p.c = parameter(run, "c");
  p.l = parameter(run, "l");
  p.a = parameter(run, "a");
  p.H = parameter(run, "H");
  p.omega = parameter(run, "omega");
  return p;
}

/// Largest |phi_deck - phi_closed| at the cycle boundaries T, 2T, ..., relative to the closed
/// form's amplitude.
double boundaryError(const RunResult& run) {
  const Mo10Parameters p = parametersOf(run);
  const int cycles = int(parameter(run, "cycles"));
  const Mo10ClosedForm cf(p, cycles);
  const TransientOutcome& t = blows(run);
  const NamedHistory& phi = t.history("phi");
  double worst = 0;
  for (int k = 1; k <= cycles; ++k) {
    const double time = k * p.period();
    worst = std::max(worst, std::abs(t.at(phi, time) - cf.phi(time)));
  }
  return worst / cf.extremes().amplitude;
}

/// Largest |phi_deck - phi_closed| over every sample, relative to the amplitude.
double sampleError(const RunResult& run) {
  const Mo10ClosedForm cf(parametersOf(run), int(parameter(run, "cycles")));
  const TransientOutcome& t = blows(run);
  const NamedHistory& phi = t.history("phi");
  double worst = 0;
  for (std::size_t i = 0; i < phi.values.size(); ++i)
    worst = std::max(worst, std::abs(phi.values[i] - cf.phi(t.result.times[i])));
  return worst / cf.extremes().amplitude;
}

}  // namespace

TEST_SUITE("MO-10 deck") {
  TEST_CASE("phi at every cycle boundary matches the closed form; the error falls as dt^2") {
    // Deck tolerance 1e-3 of the amplitude at 3000 steps a cycle. Halving the step must divide
    // the error by 4 (Newmark's average acceleration rule is second order); measured ratios
    // 3.99 to 4.00 over the c below.
    for (double c : {1e4, 1e5, 1e6}) {
      CAPTURE(c);
      const RunResult fine = solveMo10Deck({test::setting("c", c)});
      const RunResult coarse = solveMo10Deck({test::setting("c", c), "steps_per_cycle=1500"});
      for (const Check& k : fine.checks) {
        CAPTURE(k.name);
        CHECK(k.pass());
      }
      CHECK(boundaryError(fine) < 1e-3);
      const double ratio = sampleError(coarse) / sampleError(fine);
      CAPTURE(ratio);
      CHECK(ratio > 3.8);
      CHECK(ratio < 4.2);
    }
  }

  TEST_CASE("plumbing: the deck builds the core's MO-10 model (same history to round-off)") {
    // Plumbing, not a second method: the same equations built twice (deck: a point, a mass, a
    // spring, a preload load and a load of pieces repeated with the period; core:
    // buildMo10Model with mo10BlowFactor) and solved by the same integrator, same step, so the
    // histories agree to round-off. It shows the deck reader builds that model; the
    // independent reference is the closed form (boundaryError here, and the case above). With a
    // preload a = 2 mm the body swings about -a/l.
    const RunResult run = solveMo10Deck({"a=0.002", "cycles=3"});
    const Mo10Parameters p = parametersOf(run);
    const Mo10Model body = buildMo10Model(p);
    TransientOptions opt;
    opt.timeStep = p.period() / parameter(run, "steps_per_cycle");
    opt.endTime = 3 * p.period();
    opt.loads = {body.blows};
    opt.histories = {{body.node, Dof::rz}};
    const TransientResult core = solveTransient(body.model, opt);
    const NamedHistory& phi = blows(run).history("phi");
    REQUIRE(phi.values.size() == core.histories[0].displacement.size());
    const Mo10ClosedForm cf(p, 3);
    const double scale = cf.extremes().amplitude;
    double worst = 0;
    for (std::size_t i = 0; i < phi.values.size(); ++i)
      worst = std::max(worst, std::abs(phi.values[i] - core.histories[0].displacement[i]));
    CHECK(worst < 1e-12 * scale);
    CHECK(boundaryError(run) < 1e-3);
    // The spring force history is c (l phi + a), as the deck defines it.
    const NamedHistory& force = blows(run).history("spring_force");
    CHECK(std::abs(force.values.back() - p.c * (p.l * phi.values.back() + p.a)) <
          1e-12 * force.maxAbs());
  }

  TEST_CASE("resonance: at exactly k = mu the deck follows the limit form of the closed form") {
    // c = J mu^2 / l^2 puts k on mu to round-off; the closed form switches to its limit
    // (the D t cos k t term) and the deck's checks (which call it) pass as elsewhere.
    Mo10Parameters p;
    const double c = p.J * p.mu() * p.mu() / (p.l * p.l);
    p.c = c;
    REQUIRE(Mo10ClosedForm(p, 1).resonant());
    const RunResult run = solveMo10Deck({test::setting("c", c)});
    CHECK(parametersOf(run).c == c);
    for (const Check& k : run.checks) {
      CAPTURE(k.name);
      CHECK(k.pass());
    }
    CHECK(boundaryError(run) < 1e-3);
    // The response grows from cycle to cycle at resonance with the pulses (the amplitude over
    // 6 cycles exceeds that over 1).
    CHECK(Mo10ClosedForm(p, 6).extremes().amplitude > Mo10ClosedForm(p, 1).extremes().amplitude);
  }

  TEST_CASE("the c sweep writes phi_max and spring_force_max per value and charts them") {
    const fs::path out = test::scratchDir("mo10_sweep");
    const auto r = test::runBeamrotor({"solve", kMo10Deck.string(), "--out", out.string(),
                                       "--sweep", "c=1e4,1e6", "--set", "cycles=2"});
    REQUIRE(r.exitCode == 0);
    CHECK(fs::exists(out / "sweep_blows.png"));
    std::ifstream in(out / "sweep.json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    REQUIRE(doc.at("runs").size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
      Mo10Parameters p;
      p.c = doc["values"][i];
      const Mo10Extremes e = Mo10ClosedForm(p, 2).extremes();
      const auto& maxima = doc["runs"][i]["analyses"][0]["maxima"];
      CAPTURE(p.c);
      CHECK(std::abs(maxima["phi_max"].get<double>() / e.amplitude - 1) < 1e-3);
      CHECK(std::abs(maxima["spring_force_max"].get<double>() / e.pressingForce - 1) < 1e-3);
    }
    std::ifstream csv(out / "sweep.csv");
    std::string header, units;
    std::getline(csv, header);
    std::getline(csv, units);
    CHECK(header.find("blows.phi_max,blows.spring_force_max") != std::string::npos);
    CHECK(units.find(",rad,N") != std::string::npos);
    fs::remove_all(out);
  }

  TEST_CASE("the tool collar: the body strikes it, never passes it, rebounds at -e v") {
    // At c = 1e5 N/m the free motion reaches -0.153 rad; a collar at -0.1 rad is struck.
    // Newton's law with e = 0.5 holds at every impact to round-off; the closed-form checks do
    // not apply (n/a) since the motion is no longer the free one.
    const RunResult run = solveMo10Deck({"collar=0.1"});
    const TransientOutcome& t = blows(run);
    CHECK(t.history("phi").min() >= -0.1);
    REQUIRE(t.result.impacts.size() >= 2);
    for (const Impact& i : t.result.impacts) {
      CHECK(i.stop == "collar");
      CHECK(i.velocityBefore < 0);
      CHECK(std::abs(i.velocityAfter + 0.5 * i.velocityBefore) <=
            1e-15 * std::abs(i.velocityBefore));
    }
    CHECK(run.checks.empty());
    CHECK(run.skippedChecks.size() == 9);
    // Before the first impact the motion is the free one (closed form to the deck tolerance).
    const Mo10ClosedForm cf(parametersOf(run), 6);
    const double first = t.result.impacts.front().time;
    const NamedHistory& phi = t.history("phi");
    for (std::size_t i = 0; i < phi.values.size() && t.result.times[i] < first; ++i)
      CHECK(std::abs(phi.values[i] - cf.phi(t.result.times[i])) < 1e-3 * cf.extremes().amplitude);
  }
}
