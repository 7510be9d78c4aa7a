// The periodic steady state (fem/transient/PeriodicSteadyState, `periodic: true`) on the MO-10
// body: the closed form's fixed point repeats itself; the deck problems/mo10_steady.yaml matches
// that closed form at every step over the swept c; with light damping a long run from rest
// decays onto the periodic run (a second method: no fixed point computed); and at k = n omega,
// where no periodic state exists, both the closed form and the solver say so.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/solvers/Errors.hpp"
#include "fem/transient/PeriodicSteadyState.hpp"
#include "problems/run/Study.hpp"
#include "problems/scenes/Mo10.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

constexpr double mo10Pi = std::numbers::pi;

/// One cycle of Newmark steps on the core's MO-10 body, the blows as its load.
TransientOptions steadyOptions(const Mo10Model& body, const Mo10Parameters& p, int stepsPerCycle) {
  TransientOptions o;
  o.timeStep = p.period() / stepsPerCycle;
  o.endTime = p.period();
  o.loads = {body.blows};
  o.histories = {{body.node, Dof::rz}};
  return o;
}

}  // namespace

TEST_SUITE("MO-10 periodic steady state") {
  TEST_CASE("closed form: the periodic start repeats itself cycle after cycle") {
    // phi(t + T) = phi(t) and phi'(t + T) = phi'(t) to round-off of the 2 x 2 solve (the
    // amplification 1 / (1 - cos kT) is below 1e3 at these c).
    for (const double c : {2e4, 1e5, 4e5, 1e6}) {
      CAPTURE(c);
      Mo10Parameters p;
      p.c = c;
      p.a = 0.002;  // with a preload the state swings about -a / l
      const Mo10ClosedForm cf(p, 3, Mo10ClosedForm::Start::periodic);
      const double T = p.period(), amp = cf.extremes().amplitude;
      for (const double f : {0.0, 0.13, 0.5, 0.97}) {
        CHECK(std::abs(cf.phi((f + 1) * T) - cf.phi(f * T)) < 1e-9 * amp);
        CHECK(std::abs(cf.phi((f + 2) * T) - cf.phi(f * T)) < 1e-9 * amp);
        CHECK(std::abs(cf.rate((f + 1) * T) - cf.rate(f * T)) < 1e-9 * amp * cf.parameters().mu());
      }
    }
  }

  TEST_CASE("the solver's periodic start against the closed form at the cycle start") {
    // Newmark at 3000 steps a cycle: period error (k dt)^2 / 12 per radian, amplified by the
    // nearness to resonance; the deck measures up to 1.2e-4 of the amplitude over a cycle (at
    // c = 1e6, the stiffest), so 3e-4 here.
    for (const double c : {2e4, 1e5, 4e5, 1e6}) {
      CAPTURE(c);
      Mo10Parameters p;
      p.c = c;
      const Mo10Model body = buildMo10Model(p);
      const PeriodicStart start = periodicStart(body.model, steadyOptions(body, p, 3000), p.period());
      const Mo10ClosedForm cf(p, 1, Mo10ClosedForm::Start::periodic);
      const double amp = cf.extremes().amplitude;
      MESSAGE("c = " << c << ": phi0 " << start.displacement(body.node, dofIndex(Dof::rz))
                     << " (closed form " << cf.phi(0) << "), rcond " << start.rcond);
      CHECK(std::abs(start.displacement(body.node, dofIndex(Dof::rz)) - cf.phi(0)) < 3e-4 * amp);
      CHECK(std::abs(start.velocity(body.node, dofIndex(Dof::rz)) - cf.rate(0)) <
            3e-4 * amp * p.mu());
      // Undamped: the free body's one-cycle map is a rotation, its multipliers on the unit
      // circle (Newmark's average acceleration rule conserves energy exactly).
      // (3000 steps of round-off: 1e-10.)
      CHECK(std::abs(start.largestMultiplier - 1) < 1e-10);
    }
  }

  TEST_CASE("the deck: every swept c matches the closed form at every step") {
    StudyRequest request = test::shippedDeckRequest("mo10_steady.yaml");
    request.noSweep = false;
    const Study s = solveStudy(request);
    REQUIRE(s.sweep);
    CHECK(s.sweep->runs.size() == 13);
    CHECK(test::checkAllPass(s) == 13 * 4);
  }

  TEST_CASE("light damping: a long run from rest decays onto the periodic run") {
    // Rayleigh alpha = 1/s damps the free swing as exp(-alpha t / 2): after 120 cycles (20 s)
    // by exp(-10) = 4.5e-5 of the start's difference, which is about the amplitude. Both runs
    // take the same step, so the discrete maps agree and only that decay separates them.
    Mo10Parameters p;
    p.c = 1.5e5;
    const int steps = 600, cycles = 120;
    const double alpha = 1.0;
    const Mo10Model body = buildMo10Model(p);
    TransientOptions longRun = steadyOptions(body, p, steps);
    longRun.rayleighMass = alpha;
    longRun.endTime = cycles * p.period();
    const TransientResult fromRest = solveTransient(body.model, longRun);

    const RunResult run = *solveStudy(test::shippedDeckRequest(
                                          "mo10_steady.yaml",
                                          {test::setting("c", p.c), "damping=1",
                                           "steps_per_cycle=" + std::to_string(steps)}))
                               .run;
    const NamedHistory& periodic = resultOf<TransientOutcome>(run.analyses.at(0))->history("phi");
    REQUIRE(periodic.values.size() == std::size_t(2 * steps + 1));
    const auto& rest = fromRest.histories[0].displacement;
    const double amp = periodic.maxAbs();
    const double decay = std::exp(-alpha * (cycles - 1) * p.period() / 2);
    double worst = 0;
    for (int j = 0; j <= steps; ++j)
      worst = std::max(worst, std::abs(rest[(cycles - 1) * steps + j] - periodic.values[j]));
    MESSAGE("last cycle from rest against the periodic run: " << worst / amp
                                                               << " of the amplitude; decay bound "
                                                               << decay);
    CHECK(worst < 2 * decay * amp);
    // And it has not settled before: the first cycle differs by about the amplitude.
    double first = 0;
    for (int j = 0; j <= steps; ++j) first = std::max(first, std::abs(rest[j] - periodic.values[j]));
    CHECK(first > 0.1 * amp);
  }

  TEST_CASE("resonance k = n omega: the closed form says there is no periodic state") {
    for (const int n : {1, 2, 3}) {
      CAPTURE(n);
      Mo10Parameters p;
      p.c = n * n * p.J * p.omega * p.omega / (p.l * p.l);  // k = n omega
      CHECK_THROWS_AS(Mo10ClosedForm(p, 1, Mo10ClosedForm::Start::periodic), std::domain_error);
    }
  }

  TEST_CASE("resonance: the solver refuses exactly at k = n omega and at Newmark's own resonance") {
    // At k = n omega the exact one-period multiplier is 1; Newmark's is exp(i steps theta),
    // theta = 2 atan(k dt / 2) per step, which is 1 where tan(pi n / steps) = k dt / 2 instead.
    // Both are refused: the first is 2 pi n (k dt)^2 / 12 = 6e-5 rad (n = 3) from Newmark's
    // resonance, which is within twice that error of it.
    const int steps = 3000;
    for (const int n : {1, 2, 3}) {
      CAPTURE(n);
      Mo10Parameters p;
      const double dt = p.period() / steps;
      for (const double k : {n * p.omega, 2 * std::tan(mo10Pi * n / steps) / dt}) {
        CAPTURE(k);
        p.c = p.J * k * k / (p.l * p.l);
        const Mo10Model body = buildMo10Model(p);
        try {
          periodicStart(body.model, steadyOptions(body, p, steps), p.period());
          FAIL("a periodic state at resonance");
        } catch (const SolveError& e) {
          const std::string what = e.what();
          CHECK(what.find("resonance") != std::string::npos);
          CHECK(what.find("near " + std::to_string(n) + " x 2 pi") != std::string::npos);
        }
      }
    }
  }

  TEST_CASE("distance from resonance and Newmark's period error against their closed forms") {
    // Undamped: the exact multiplier exp(i k T) is 2 |sin(k T / 2)| from 1, Newmark's
    // exp(i steps theta) 2 |sin(steps theta / 2)|; the period error is |steps theta - k T|.
    // The solver reads them from the eigenvalues of its one-step map (round-off: 1e-9 of the
    // angle, the step map being the difference of two runs of ~1 rad states).
    const int steps = 3000;
    for (const double c : {2e4, 1e5, 4e5, 6.2e5, 1e6}) {
      CAPTURE(c);
      Mo10Parameters p;
      p.c = c;
      const Mo10Model body = buildMo10Model(p);
      const PeriodicStart start =
          periodicStart(body.model, steadyOptions(body, p, steps), p.period());
      const double dt = p.period() / steps, kT = p.k() * p.period();
      const double theta = 2 * std::atan(p.k() * dt / 2);
      const double exact = 2 * std::abs(std::sin(kT / 2));
      const double newmark = 2 * std::abs(std::sin(steps * theta / 2));
      CHECK(std::abs(start.resonanceDistance - std::min(exact, newmark)) < 1e-9);
      CHECK(std::abs(start.periodError - std::abs(steps * theta - kT)) < 1e-9 * kT);
      CHECK(std::abs(start.nearestFrequency / p.k() - 1) < 1e-9);
      CHECK(start.nearestHarmonic == std::lround(kT / (2 * mo10Pi)));
    }
  }

  TEST_CASE("near resonance the amplitude is off by Newmark's period error over the distance") {
    // c = 6.215e5 N/m: k T is 8.5e-3 rad short of 6 pi, and Newmark's period error
    // k T (k dt)^2 / 12 is 6.2e-5 rad, so the steady amplitude (1 / distance) is off by about
    // their ratio, 0.73 %: the deck's largest |phi| differs from the closed form's by that,
    // within 10 % of it (the ratio is the first-order term of 1 / (d + e) - 1 / d, and the
    // non-resonant harmonics carry no such error).
    Mo10Parameters p;
    p.c = 6.215e5;
    const Mo10Model body = buildMo10Model(p);
    const PeriodicStart start = periodicStart(body.model, steadyOptions(body, p, 3000), p.period());
    const double predicted = start.periodError / start.resonanceDistance;
    const Mo10ClosedForm cf(p, 1, Mo10ClosedForm::Start::periodic);
    const RunResult run =
        *solveStudy(test::shippedDeckRequest("mo10_steady.yaml", {test::setting("c", p.c)})).run;
    const double amp = cf.extremes().amplitude;
    const double measured =
        std::abs(resultOf<TransientOutcome>(run.analyses.at(0))->history("phi").maxAbs() - amp) /
        amp;
    MESSAGE("amplitude error " << measured << ", predicted " << predicted);
    CHECK(predicted == doctest::Approx(7.32e-3).epsilon(0.01));
    CHECK(measured == doctest::Approx(predicted).epsilon(0.1));
  }

  TEST_CASE("the deck at resonance: refused at its periodic field, exit 2") {
    // At Newmark's own resonance for n = 3 (tan(3 pi / steps) = k dt / 2): the deck's closed
    // form still evaluates there (k T is 6e-5 rad off 6 pi), so the refusal is the solver's.
    // (Exactly at k = 3 omega the deck's derived closed-form values refuse first.)
    Mo10Parameters p;
    const double dt = p.period() / 3000, k = 2 * std::tan(3 * mo10Pi / 3000) / dt;
    const double c = p.J * k * k / (p.l * p.l);
    try {
      solveStudy(test::shippedDeckRequest("mo10_steady.yaml", {test::setting("c", c)}));
      FAIL("the deck ran at resonance");
    } catch (const DeckError& e) {
      CHECK(e.place().field.find("periodic") != std::string::npos);
      CHECK(e.place().line > 0);
      CHECK(e.message().find("no periodic steady state: resonance") != std::string::npos);
    }
    const test::ProcessResult run = test::runBeamrotor(
        {"solve", "problems/mo10_steady.yaml", "--set", test::setting("c", c), "--out",
         (test::scratchDir("mo10_resonance") / "out").string()});
    CHECK(run.exitCode == 2);
    CHECK(run.err.find("periodic") != std::string::npos);
    std::filesystem::remove_all(test::scratchDir("mo10_resonance"));
  }

  TEST_CASE("the periodic closed form peaks at k = 3 omega: the blows have a third harmonic") {
    // The blow train is a half-sine pulse of width tau = pi / mu = T / 10 once a period; its
    // Fourier coefficients are proportional to cos(n pi tau / T) / (1 - (2 n tau / T)^2)
    // (Fourier transform of a half-sine), so |c_3| / |c_1| = (cos 0.3 pi / 0.64) /
    // (cos 0.1 pi / 0.96) = 0.92705: the third harmonic is almost as strong as the first, and
    // the zeros fall at n = 15, 25, ... only. The steady state is then
    // phi = (H / J) sum_n c_n exp(i n omega t) / (k^2 - n^2 omega^2), which peaks at k = 3 omega.
    Mo10Parameters p;
    const double T = p.period(), w = p.omega, t1 = p.t1();
    // c_n by Simpson's rule over the pulse (smooth there): error (h nu)^4 / 180 relative, nu
    // the integrand's frequency, 1e-13 for the low harmonics that matter.
    const auto coefficient = [&](int n) {
      const int m = 2000;
      const double h = (T - t1) / m;
      std::complex<double> sum = 0;
      for (int i = 0; i <= m; ++i) {
        const double t = t1 + i * h;
        const double weight = (i == 0 || i == m) ? 1 : (i % 2 ? 4 : 2);
        sum += weight * std::sin(p.mu() * t) * std::polar(1.0, -n * w * t);
      }
      return sum * h / 3.0 / T;
    };
    const double ratio = std::abs(coefficient(3)) / std::abs(coefficient(1));
    CHECK(ratio == doctest::Approx(std::cos(0.3 * mo10Pi) / 0.64 / (std::cos(0.1 * mo10Pi) / 0.96))
                       .epsilon(1e-10));
    // The closed form's periodic phi against the Fourier series, near and away from
    // k = 3 omega. |c_n| ~ 1.6 / n^2, so the terms fall as (H / J) 1.6 / (n^4 omega^2): the
    // tail beyond |n| = 1000 is 3e-10 rad, 1.3e-8 of the smallest amplitude here (0.024 rad).
    const int harmonics = 1000;
    std::vector<std::complex<double>> cn;
    for (int n = -harmonics; n <= harmonics; ++n) cn.push_back(coefficient(n));
    double peak = 0, away = 0;
    for (const double c : {5e5, 6.215e5, 7e5}) {
      CAPTURE(c);
      p.c = c;
      const Mo10ClosedForm cf(p, 1, Mo10ClosedForm::Start::periodic);
      const double k2 = p.k() * p.k(), amp = cf.extremes().amplitude;
      for (const double f : {0.0, 0.3, 0.95}) {
        std::complex<double> series = 0;
        for (int n = -harmonics; n <= harmonics; ++n)
          series += cn[n + harmonics] * std::polar(1.0, n * w * f * T) / (k2 - n * n * w * w);
        CHECK(std::abs(cf.phi(f * T) - p.H / p.J * series.real()) < 1e-7 * amp);
      }
      if (c == 6.215e5)
        peak = amp;
      else
        away = std::max(away, amp);
    }
    MESSAGE("amplitude near k = 3 omega " << peak << " rad, at 5e5 and 7e5 at most " << away);
    CHECK(peak > 100 * away);
  }
}
