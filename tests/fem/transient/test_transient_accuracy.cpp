// Accuracy of the time-stepping schemes on one-dof oscillators with exact solutions: period
// error and its order, Rayleigh damping, harmonic base motion, and the energy account.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "fem/transient/Transient.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using beamrotor::test::kPi;
using beamrotor::test::relError;

namespace {

/// Mass m (kg) on a grounded spring along uy at node 0, natural period 1 s.
struct Oscillator {
  double m = 2, omega = 2 * kPi;
  Model model;
  Oscillator(double springDamping = 0) {
    const int n = model.addNode({0, 0, 0});
    model.add<PointInertia>(n, DofSet{Dof::uy}, m);
    model.add<Spring>(NodeDof{n, Dof::uy}, m * omega * omega, springDamping);
  }
  NodalField at(double value) const {
    NodalField f = NodalField::Zero(1, kDofKinds);
    f(0, dofIndex(Dof::uy)) = value;
    return f;
  }
};

TransientOptions freeVibration(const Oscillator& o, TimeScheme scheme, int stepsPerPeriod,
                               double periods) {
  TransientOptions opt;
  opt.scheme = scheme;
  opt.hhtAlpha = -0.1;
  opt.timeStep = 1.0 / stepsPerPeriod;
  opt.endTime = periods;
  opt.initialDisplacement = o.at(1);
  opt.histories = {{0, Dof::uy}};
  return opt;
}

/// Period from the downward zero crossings of a sampled history: linear interpolation between
/// samples. At a crossing of a free undamped oscillation u'' = -omega^2 u = 0, so the
/// interpolated crossing time errs by O(dt^3) only, below the O(dt^2) period error measured.
double measuredPeriod(const TransientResult& r) {
  const auto& u = r.histories[0].displacement;
  std::vector<double> crossings;
  for (std::size_t n = 0; n + 1 < u.size(); ++n)
    if (u[n] > 0 && u[n + 1] <= 0)
      crossings.push_back(r.times[n] + (r.times[n + 1] - r.times[n]) * u[n] / (u[n] - u[n + 1]));
  REQUIRE(crossings.size() >= 2);
  return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

}  // namespace

TEST_SUITE("transient accuracy") {
  TEST_CASE("period error is O(dt^2) for newmark, hht and central difference") {
    const Oscillator o;
    struct Case {
      TimeScheme scheme;
      std::string name;
    };
    for (const Case& c : {Case{TimeScheme::newmark, "newmark"}, Case{TimeScheme::hht, "hht"},
                          Case{TimeScheme::centralDifference, "central difference"}}) {
      CAPTURE(c.name);
      std::array<double, 3> error{};
      const std::array<int, 3> perPeriod{20, 40, 80};
      for (int i = 0; i < 3; ++i) {
        const TransientResult r =
            solveTransient(o.model, freeVibration(o, c.scheme, perPeriod[i], 10));
        const double Tbar = measuredPeriod(r);
        error[i] = std::abs(Tbar - 1.0);
        const double Omega = o.omega / perPeriod[i];
        // Independent check of the measured value against the schemes' known discrete
        // frequencies (Hughes 2000, sec. 9.3): average acceleration omega_bar dt =
        // 2 atan(Omega / 2), central difference 2 asin(Omega / 2). Interpolating a sampled
        // sinusoid linearly misplaces a zero crossing by at most Omega^3 / 24 rad; two such
        // errors over the 9 periods between first and last crossing are below 2e-3 Omega^3
        // of a period (measured: 1e-5 at Omega = 0.31, 7e-8 at 0.08).
        const double crossingError = 2e-3 * std::pow(Omega, 3);
        if (c.scheme == TimeScheme::newmark)
          CHECK(relError(Tbar, Omega / (2 * std::atan(Omega / 2))) < crossingError);
        if (c.scheme == TimeScheme::centralDifference)
          CHECK(relError(Tbar, Omega / (2 * std::asin(Omega / 2))) < crossingError);
      }
      const double order1 = std::log2(error[0] / error[1]), order2 = std::log2(error[1] / error[2]);
      MESSAGE(c.name << ": period errors " << error[0] << ", " << error[1] << ", " << error[2]
                     << "; orders " << order1 << ", " << order2);
      CHECK(std::abs(order1 - 2) < 0.1);
      CHECK(std::abs(order2 - 2) < 0.1);
    }
  }

  TEST_CASE("Rayleigh damping decays at zeta = a/(2 omega) + b omega/2, to O(dt^2)") {
    const Oscillator o;
    const double zeta = 0.05, wd = o.omega * std::sqrt(1 - zeta * zeta);
    auto exact = [&](double t) {
      return std::exp(-zeta * o.omega * t) *
             (std::cos(wd * t) + zeta * o.omega / wd * std::sin(wd * t));
    };
    struct Case {
      TimeScheme scheme;
      double a, b;  // Rayleigh coefficients
      std::string name;
    };
    // Half the damping from each term for the implicit rule; central difference takes the
    // mass-proportional (diagonal) part only.
    for (const Case& c : {Case{TimeScheme::newmark, zeta * o.omega, zeta / o.omega, "newmark"},
                          Case{TimeScheme::centralDifference, 2 * zeta * o.omega, 0, "central"}}) {
      CAPTURE(c.name);
      std::array<double, 2> error{};
      for (int i = 0; i < 2; ++i) {
        TransientOptions opt = freeVibration(o, c.scheme, 100 << i, 5);
        opt.rayleighMass = c.a;
        opt.rayleighStiffness = c.b;
        const TransientResult r = solveTransient(o.model, opt);
        for (std::size_t n = 0; n < r.times.size(); ++n)
          error[i] =
              std::max(error[i], std::abs(r.histories[0].displacement[n] - exact(r.times[n])));
      }
      MESSAGE(c.name << ", Rayleigh damping: max error " << error[0] << " (100 steps/period), "
                     << error[1] << " (200)");
      // Bound: phase error Omega^2 / 12 per radian over the 31 radians of the run, Omega = 2 pi /
      // 200.
      CHECK(error[1] < std::pow(2 * kPi / 200, 2) / 12 * 10 * kPi);
      CHECK(std::abs(std::log2(error[0] / error[1]) - 2) < 0.1);
    }
  }

  TEST_CASE("harmonic base motion through a support: newmark converges to the exact response") {
    // Ground node 0 moves u_g = U sin(W t) along uy; mass m at node 1 on a spring k to it.
    // From rest: x = U w^2 / (w^2 - W^2) (sin W t - (W / w) sin w t).
    const double m = 1.5, w = 2 * kPi, W = 0.6 * w, U = 0.01;
    Model model;
    const int g = model.addNode({0, 0, 0}), n = model.addNode({1, 0, 0});
    model.add<PointInertia>(n, DofSet{Dof::uy}, m);
    model.add<Spring>(NodeDof{g, Dof::uy}, NodeDof{n, Dof::uy}, m * w * w);
    model.addSupport({"ground", g, {{Dof::uy, 0}}});
    auto exact = [&](double t) {
      return U * w * w / (w * w - W * W) * (std::sin(W * t) - W / w * std::sin(w * t));
    };
    std::array<double, 2> error{};
    for (int i = 0; i < 2; ++i) {
      TransientOptions opt;
      opt.timeStep = 0.01 / (1 << i);
      opt.endTime = 3;
      opt.supportMotions = {harmonicSupportMotion(g, Dof::uy, U, W)};
      opt.histories = {{n, Dof::uy}, {g, Dof::uy}};
      const TransientResult r = solveTransient(model, opt);
      for (std::size_t k = 0; k < r.times.size(); ++k) {
        error[i] = std::max(error[i], std::abs(r.histories[0].displacement[k] - exact(r.times[k])));
        // The support's history is the prescribed motion itself.
        CHECK(r.histories[1].displacement[k] == U * std::sin(W * r.times[k]));
      }
    }
    const double amplitude = U * w * w / (w * w - W * W) * (1 + W / w);  // bound on |x|
    MESSAGE("base motion: max error " << error[0] << ", " << error[1] << " (amplitude " << amplitude
                                      << ")");
    // Bound: the rule's phase error (w dt)^2 / 12 per radian over w t = 19 rad of motion.
    const double wdt = w * 0.005;
    CHECK(error[1] < wdt * wdt / 12 * w * 3 * amplitude);
    CHECK(std::abs(std::log2(error[0] / error[1]) - 2) < 0.1);
  }

  TEST_CASE("energy account balances to round-off for average acceleration, forced and damped") {
    const Oscillator o(3.0);  // spring damper 3 N s/m
    TransientOptions opt = freeVibration(o, TimeScheme::newmark, 37, 6);
    opt.rayleighMass = 0.2;
    opt.initialVelocity = o.at(-2);
    opt.loads.push_back(
        {"shaker", {{0, Dof::uy, 40}}, timefn::harmonicSeries(5.0, {{1, 1.0, 0.3}, {2, 0.4, 0}})});
    const TransientResult r = solveTransient(o.model, opt);
    const auto& e = r.energy;
    double scale = 0, drift = 0;
    for (std::size_t n = 0; n < r.times.size(); ++n) {
      scale = std::max({scale, e.kinetic[n] + e.strain[n], e.damping[n], std::abs(e.external[n])});
      drift = std::max(drift, std::abs(e.balance(n) - e.balance(0)));
    }
    MESSAGE("energy balance drift " << drift / scale << " of the largest energy");
    CHECK(e.damping.back() > 0);
    // The increments are exact for the rule (du = dt (v_n + v_n+1) / 2); only round-off stays.
    CHECK(drift < 1e-12 * scale);
    CHECK(r.factorizations == 1);
  }
}
