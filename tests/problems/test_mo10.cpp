// MO-10 impact mechanism body on springs (problems/scenes/README.md section 4): the closed form
// checked on its own (equation of motion, continuity, the resonant limit) and the finite-element
// time history with Newmark's rule checked against it at every cycle boundary, with its O(dt^2)
// rate.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "fem/transient/Transient.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/scenes/Mo10.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using beamrotor::test::relError;

namespace {

/// The FE history of phi (Newmark) with `perCycle` steps a cycle (a multiple of 10 puts
/// t1 = 0.9 T on a step, so the load's kink falls on a step), sampled every `sampleEvery`.
std::vector<double> feHistory(const Mo10Parameters& p, int cycles, int perCycle,
                              int sampleEvery = 1) {
  Mo10Model body = buildMo10Model(p);
  TransientOptions opt;
  opt.timeStep = p.period() / perCycle;
  opt.endTime = cycles * p.period();
  opt.loads = {body.blows};
  opt.histories = {{body.node, Dof::rz}};
  opt.sampleEvery = sampleEvery;
  opt.energy = false;
  return solveTransient(body.model, opt).histories[0].displacement;
}

std::vector<double> feAtCycleBoundaries(const Mo10Parameters& p, int cycles, int perCycle) {
  return feHistory(p, cycles, perCycle, perCycle);
}

/// Stiffness that puts k exactly (up to round-off) on mu: c = J mu^2 / l^2.
double resonantStiffness(const Mo10Parameters& p) {
  return p.J * p.mu() * p.mu() / (p.l * p.l);
}

}  // namespace

TEST_SUITE("MO-10") {
  TEST_CASE("closed form: satisfies J phi'' + c l^2 (phi + phi0) = M and is continuous") {
    for (double c : {1e4, 1e5, 1e6}) {
      for (double a : {0.0, 0.002}) {
        CAPTURE(c);
        CAPTURE(a);
        Mo10Parameters p;
        p.c = c;
        p.a = a;
        const Mo10ClosedForm cf(p, 4);
        const double T = p.period(), h = 1e-6 * T, scale = cf.extremes().amplitude;
        CHECK(std::abs(cf.phi(0)) < 1e-15);  // from rest
        CHECK(std::abs(cf.rate(0)) < 1e-12);
        for (int i = 0; i < 4; ++i)
          for (double s : {0.13, 0.5, 0.85, 0.95, 0.97}) {  // both phases of every cycle
            const double t = (i + s) * T;
            // phi'' by a central difference of the closed-form rate: error O(h^2) ~ 1e-9 of
            // the terms, far below the 1e-6 asked.
            const double acc = (cf.rate(t + h) - cf.rate(t - h)) / (2 * h);
            const double lhs = p.J * acc + p.c * p.l * p.l * (cf.phi(t) + p.phi0());
            CHECK(std::abs(lhs - cf.moment(t)) < 1e-6 * (p.H + p.c * p.l * p.l * scale));
          }
        // Continuity of phi and phi' at t1 and at the cycle boundaries.
        for (int i = 0; i < 4; ++i)
          for (double t : {i * T + p.t1(), (i + 1) * T}) {
            if (t >= 4 * T) continue;
            const double e = 1e-9 * T;
            CHECK(std::abs(cf.phi(t - e) - cf.phi(t + e)) < 1e-6 * scale);
            CHECK(std::abs(cf.rate(t - e) - cf.rate(t + e)) < 1e-6 * scale * p.k());
          }
      }
    }
  }

  // A deck's history calls mo10_phi(t, ...) at every step; the function keeps one form and
  // extends it cycle by cycle (problems/deck/parse/SceneFunctions.cpp). The reference is a
  // form built afresh for each call, as before: the same operations, so equal to the bit.
  TEST_CASE("closed form: extended cycle by cycle it is the form built at once, to the bit") {
    Mo10Parameters p;
    p.a = 0.002;
    Mo10ClosedForm grown(p, 1);
    for (int cycles = 2; cycles <= 6; ++cycles) {
      grown.extend(cycles);
      const Mo10ClosedForm once(p, cycles);
      REQUIRE(grown.cycles().size() == std::size_t(cycles));
      for (int i = 0; i < cycles; ++i) {
        const Mo10Cycle &a = grown.cycles()[i], &b = once.cycles()[i];
        CHECK(a.A1 == b.A1);
        CHECK(a.A2 == b.A2);
        CHECK(a.B1 == b.B1);
        CHECK(a.B2 == b.B2);
        CHECK(a.C1 == b.C1);
      }
      // t = k T ends cycle k in a form of k cycles: the grown form reads it there too.
      for (int k = 1; k <= cycles; ++k)
        CHECK(grown.phiOverCycles(k, k * p.period()) == Mo10ClosedForm(p, k).phi(k * p.period()));
    }
  }

  TEST_CASE("mo10_phi in an expression equals a fresh closed form at every t, to the bit") {
    const ExpressionEvaluator ev;
    // Forward in time, back to an earlier cycle, and across a change of parameters.
    for (double c : {1e5, 3e5, 1e5}) {
      const CompiledExpression phi = ev.compile(
          "mo10_phi(t, 0.5, " + std::to_string(c) + ", 0.1, 0.002, 200, 37.18)", {"t"});
      Mo10Parameters p;
      p.c = c;
      p.a = 0.002;
      const double T = p.period();
      for (double t : {0.0, 0.3 * T, T, 2.5 * T, 3 * T, 5.97 * T, 1.2 * T, 6 * T, 0.95 * T}) {
        CAPTURE(t / T);
        const int cycles = int(std::max(1.0, std::ceil(t / T * (1 - 1e-14))));
        CHECK(phi(t) == Mo10ClosedForm(p, cycles).phi(t));
      }
    }
  }

  TEST_CASE("closed form: the blow train built from time functions is M(t) / H") {
    const Mo10Parameters p;
    const Mo10ClosedForm cf(p, 3);
    const TimeFunction f = mo10BlowFactor(p);
    for (double t = 0; t < 3 * p.period(); t += p.period() / 97)
      CHECK(p.H * f(t) == doctest::Approx(cf.moment(t)).epsilon(1e-12).scale(p.H));
    // mu t1 = 9 pi: the blow is a negative half-sine.
    CHECK(relError(cf.moment(p.t1() + 0.5 * std::numbers::pi / p.mu()), -p.H) < 1e-12);
  }

  TEST_CASE("closed form at k = mu is the limit of k -> mu") {
    Mo10Parameters p;
    p.c = resonantStiffness(p);
    const Mo10ClosedForm res(p, 5);
    REQUIRE(res.resonant());
    CHECK(relError(res.cycles()[0].D, -p.H / (2 * p.J * p.k())) < 1e-14);
    std::vector<double> gaps;
    for (double delta : {1e-3, 1e-4, 1e-5, 1e-6}) {
      Mo10Parameters q = p;
      q.c = p.c * (1 + delta) * (1 + delta);  // k = mu (1 + delta)
      const Mo10ClosedForm near(q, 5);
      CHECK_FALSE(near.resonant());
      double gap = 0;
      for (double t = 0; t <= 5 * p.period(); t += p.period() / 50)
        gap = std::max(gap, std::abs(near.phi(t) - res.phi(t)));
      gaps.push_back(gap / res.extremes().amplitude);
      MESSAGE("k = mu (1 + " << delta
                             << "): max |phi - phi_resonant| / amplitude = " << gaps.back());
    }
    // The solution is smooth in k, so the gap shrinks like delta (a factor 10 per decade);
    // the off-resonance form's cancellation error, eps / delta <= 1e-10, stays far below.
    for (std::size_t i = 0; i + 1 < gaps.size(); ++i)
      CHECK(std::abs(gaps[i] / gaps[i + 1] - 10) < 0.5);
    CHECK(gaps.back() < 1e-4);
  }

  TEST_CASE("newmark FE history matches the closed form at every cycle boundary, O(dt^2)") {
    const int cycles = 6;
    const std::array<int, 3> perCycle{1600, 3200, 6400};
    Mo10Parameters p;
    std::vector<double> stiffnesses{1e4, 1e5, 1e6, resonantStiffness(p)};
    for (double c : stiffnesses) {
      CAPTURE(c);
      p.c = c;
      const Mo10ClosedForm cf(p, cycles);
      const double scale = cf.extremes().amplitude;
      std::array<double, 3> error{};
      for (int j = 0; j < 3; ++j) {
        const std::vector<double> fe = feAtCycleBoundaries(p, cycles, perCycle[j]);
        REQUIRE(int(fe.size()) == cycles + 1);
        for (int i = 0; i <= cycles; ++i)
          error[j] = std::max(error[j], std::abs(fe[i] - cf.phi(i * p.period())) / scale);
      }
      const double o1 = std::log2(error[0] / error[1]), o2 = std::log2(error[1] / error[2]);
      MESSAGE("c = " << c << " (k = " << p.k() << " rad/s): amplitude " << scale
                     << " rad; error at cycle boundaries / amplitude " << error[0] << ", "
                     << error[1] << ", " << error[2] << "; orders " << o1 << ", " << o2);
      CHECK(std::abs(o1 - 2) < 0.2);
      CHECK(std::abs(o2 - 2) < 0.2);
      // Bound: the rule's phase error, (omega dt)^2 / 12 per radian with omega = max(k, mu),
      // accumulated over the k T cycles radians of the free swing.
      const double Omega = std::max(p.k(), p.mu()) * p.period() / perCycle[2];
      CHECK(error[2] < Omega * Omega / 12 * p.k() * p.period() * cycles);
    }
  }

  TEST_CASE("with a preload the FE model (constant moment -c l^2 phi0) follows the closed form") {
    Mo10Parameters p;
    p.a = 0.002;
    const Mo10ClosedForm cf(p, 3);
    const std::vector<double> fe = feAtCycleBoundaries(p, 3, 1600);
    for (int i = 0; i <= 3; ++i)
      CHECK(std::abs(fe[i] - cf.phi(i * p.period())) < 1e-3 * cf.extremes().amplitude);
  }

  TEST_CASE("amplitude and pressing force over the stiffness range (scene 4 example values)") {
    Mo10Parameters p;
    for (double c : {1e4, 3e4, 1e5, 3e5, 1e6}) {
      p.c = c;
      const Mo10Extremes e = Mo10ClosedForm(p, 20).extremes();
      MESSAGE("c = " << c << " N/m: phi_max " << e.phiMax << ", phi_min " << e.phiMin
                     << " rad, pressing force max |c (l phi + a)| " << e.pressingForce << " N");
      // The extremes' search against the closed form sampled densely, for the force as
      // defined, c (l phi(t) + a), also with a preload (a = 2 mm shifts the force by c a, so
      // its peak is no longer c l max |phi|): sampling every T / 2000 misses a smooth peak by at
      // most (w dt)^2 / 8 = 3e-5 of it, w = max(k, mu) <= 186 rad/s, and never exceeds it.
      for (double preload : {0.0, 0.002}) {
        Mo10Parameters q = p;
        q.a = preload;
        const Mo10ClosedForm cf(q, 20);
        const double dt = q.period() / 2000, w = std::max(q.k(), q.mu());
        double sampled = 0;
        for (int i = 0; i <= 20 * 2000; ++i)
          sampled = std::max(sampled, std::abs(q.c * (q.l * cf.phi(i * dt) + q.a)));
        const double searched = cf.extremes().pressingForce;
        CAPTURE(preload);
        CHECK(sampled <= searched * (1 + 1e-12));
        CHECK(sampled >= searched * (1 - w * w * dt * dt / 8));
      }
      // The extremes from the FE history sampled every step: sampling a peak misses
      // (omega dt)^2 / 8 = 3e-5 of it and Newmark's phase error, (omega dt)^2 / 12 per radian,
      // shifts the beating between free swing and blows by up to 6.5e-3 rad over 10 cycles.
      // Measured: 1.6e-5 to 5.8e-5 of the extremes for c <= 3e5, 5.0e-4 at c = 1e6 (the
      // fastest free swing); asked 2e-3.
      const std::vector<double> fe = feHistory(p, 10, 2000);
      const auto [lo, hi] = std::minmax_element(fe.begin(), fe.end());
      const Mo10Extremes e10 = Mo10ClosedForm(p, 10).extremes();
      MESSAGE("   FE (10 cycles): phi_max " << *hi << " vs " << e10.phiMax << ", phi_min " << *lo
                                            << " vs " << e10.phiMin);
      CHECK(relError(*hi, e10.phiMax) < 2e-3);
      CHECK(relError(*lo, e10.phiMin) < 2e-3);
    }
  }
}
