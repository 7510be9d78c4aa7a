// Run-up through the critical speeds against independent references:
//  - the Jeffcott rotor (a disk m on an isotropic bearing k, c: two dofs) passing its critical
//    speed at constant acceleration, against the same equations m r'' + c r' + k r =
//    m e (Omega^2 - i Omega') e^{i phi} (r = uy + i uz) integrated here by the classical
//    fourth-order Runge-Kutta rule with a step 20 times smaller: the peak amplitude and the
//    speed at which it occurs, and the known trend (Markert and Seidler 2001; Genta, Dynamics
//    of Rotating Systems, 2005, sec. 4.9): the faster the passage, the later and lower the peak;
//  - the slow-acceleration limit: amplitude against speed tends to the steady synchronous
//    response of fem/rotor/RotorUnbalance, the error falling in proportion to the rate;
//  - the energy balance of the undamped case: the work of the unbalance is the change of
//    kinetic plus strain energy.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "fem/rotor/RotorUnbalance.hpp"
#include "fem/runup/RunUp.hpp"
#include "meshes/LineBuilder.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using Complex = std::complex<double>;

namespace {

/// The Jeffcott rotor as two dofs: disk m (kg) on an isotropic bearing k (N/m), c (N s/m),
/// unbalance m e (kg m). Natural frequency 10 Hz, damping ratio zeta.
struct Jeffcott {
  double m = 1, omega = 2 * std::numbers::pi * 10, zeta = 0.01, me = 1e-4;
  double k() const { return m * omega * omega; }
  double c() const { return 2 * zeta * m * omega; }
  Model model;
  int node = -1;
  explicit Jeffcott(double dampingRatio = 0.01) : zeta(dampingRatio) {
    node = model.addNode({0, 0, 0});
    model.add<PointInertia>(node, DofSet{Dof::uy, Dof::uz}, m);
    model.add<Bearing>(node, BearingCoefficients::isotropic(k(), c()));
  }
  RunUpOptions options(double dt) const {
    RunUpOptions o;
    o.timeStep = dt;
    o.start = RunUpStart::steady;
    Unbalance u;
    u.node = node;
    u.me = me;
    o.unbalance = {u};
    o.nodes = {node};
    return o;
  }
  /// The steady orbit r = R e^{i phi} at speed w: R = m e w^2 / (k - m w^2 + i c w).
  Complex steady(double w) const { return me * w * w / Complex(k() - m * w * w, c() * w); }
};

/// r(t) of the Jeffcott rotor by classical RK4 with `steps` steps over the profile, from the
/// steady orbit at the start speed; |r| and the speed at each step.
struct Passage {
  std::vector<double> radius, speed;
};
Passage rungeKutta(const Jeffcott& j, const SpeedProfile& p, int steps) {
  const double h = p.duration() / steps;
  const auto force = [&](double t) {
    return j.me * Complex(p.speed(t) * p.speed(t), -p.acceleration(t)) *
           std::polar(1.0, p.angle(t));
  };
  // y' = (r, v); v' = (f - c v - k r) / m
  const auto rate = [&](double t, Complex r, Complex v) {
    return std::pair{v, (force(t) - j.c() * v - j.k() * r) / j.m};
  };
  Complex r = j.steady(p.startSpeed()), v = Complex(0, p.startSpeed()) * r;
  Passage out;
  for (int n = 0; n <= steps; ++n) {
    const double t = n * h;
    out.radius.push_back(std::abs(r));
    out.speed.push_back(p.speed(t));
    if (n == steps) break;
    const auto [r1, v1] = rate(t, r, v);
    const auto [r2, v2] = rate(t + h / 2, r + h / 2 * r1, v + h / 2 * v1);
    const auto [r3, v3] = rate(t + h / 2, r + h / 2 * r2, v + h / 2 * v2);
    const auto [r4, v4] = rate(t + h, r + h * r3, v + h * v3);
    r += h / 6 * (r1 + 2.0 * r2 + 2.0 * r3 + r4);
    v += h / 6 * (v1 + 2.0 * v2 + 2.0 * v3 + v4);
  }
  return out;
}

struct Peak {
  double radius = 0, speed = 0;
};
Peak peakOf(const std::vector<double>& radius, const std::vector<double>& speed) {
  Peak p;
  for (std::size_t i = 0; i < radius.size(); ++i)
    if (radius[i] > p.radius) p = {radius[i], speed[i]};
  return p;
}

Peak runUpPeak(const RunUpResult& r) {
  const RunUpHistory& h = r.histories[0];
  std::vector<double> radius;
  for (std::size_t i = 0; i < h.uy.size(); ++i) radius.push_back(std::hypot(h.uy[i], h.uz[i]));
  return peakOf(radius, r.speed);
}

/// A steel shaft (1 m, D 50 mm, 10 elements) on two damped isotropic bearings (2e6 N/m), a
/// gyroscopic disk (20 kg, Jp 0.2, Jd 0.1 kg m^2) at `diskAt`: with the disk at mid-span and
/// 2e4 N s/m its first forward critical speed is near 328 rad/s.
struct ShaftRotor {
  Model model;
  int disk = -1;
  explicit ShaftRotor(double bearingDamping = 2e4, double diskAt = 0.5) {
    auto sec = std::make_shared<Section>(
        Section::circle("shaft", Material::fromEnu("steel", 2.1e11, 0.3, 7850), 0.05));
    LineSpec spec;
    spec.dofs = DofSet::lateral();
    spec.segments.push_back({1.0, sec, 10, 0, {}});
    spec.points = {{"A", 0}, {"disk", diskAt}, {"B", 1.0}};
    buildLine(model, spec);
    disk = model.node("disk");
    model.add<PointInertia>(disk, DofSet::lateral(), 20.0, 0.2, 0.1);
    for (const char* end : {"A", "B"})
      model.add<Bearing>(model.node(end), BearingCoefficients::isotropic(2e6, bearingDamping));
  }
};

}  // namespace

TEST_SUITE("run-up") {
  TEST_CASE("a speed profile's angle is the exact integral of its speed") {
    const SpeedProfile ramp = SpeedProfile::ramp(10, 50, 4);  // 10 rad/s^2
    CHECK(ramp.speed(1) == doctest::Approx(20).epsilon(1e-15));
    CHECK(ramp.acceleration(3) == doctest::Approx(10).epsilon(1e-15));
    CHECK(ramp.angle(3) == doctest::Approx(10 * 3 + 5 * 9).epsilon(1e-15));
    CHECK(ramp.angle(5) == doctest::Approx(10 * 4 + 5 * 16 + 50).epsilon(1e-15));  // held after
    const SpeedProfile table = SpeedProfile::table({0, 1, 3}, {0, 10, 0});  // up, then down
    CHECK(table.acceleration(2) == doctest::Approx(-5).epsilon(1e-15));
    CHECK(table.angle(3) == doctest::Approx(5 + 10).epsilon(1e-15));
    CHECK(table.angle(2) == doctest::Approx(5 + 10 - 2.5).epsilon(1e-15));
    CHECK_THROWS_AS(SpeedProfile::table({0, 1, 1}, {0, 1, 2}), std::invalid_argument);
    CHECK_THROWS_AS(SpeedProfile::ramp(-1, 1, 1), std::invalid_argument);
  }

  TEST_CASE("a Jeffcott rotor passing its critical speed against Runge-Kutta") {
    const Jeffcott j;
    const double w = j.omega;
    // Dimensionless accelerations Omega' / omega^2 (Markert and Seidler's eta): slow to fast.
    const std::vector<double> rates{0.002, 0.006, 0.02};
    Peak previous{1e300, 0};
    for (double eta : rates) {
      CAPTURE(eta);
      const double accel = eta * w * w;
      const SpeedProfile p = SpeedProfile::ramp(0.5 * w, 1.6 * w, 1.1 * w / accel);
      const double dt = 2 * std::numbers::pi / w / 200;  // 200 steps per natural period
      const RunUpResult r = solveRunUp(j.model, p, j.options(dt));
      const Passage ref = rungeKutta(j, p, 20 * r.steps);
      const Peak fe = runUpPeak(r), rk = peakOf(ref.radius, ref.speed);
      MESSAGE("eta " << eta << ": peak " << fe.radius << " (RK4 " << rk.radius << ", rel "
                     << std::abs(fe.radius / rk.radius - 1) << ") at " << fe.speed / w
                     << " omega (RK4 " << rk.speed / w << ")");
      // The average acceleration rule's period error (omega dt)^2 / 12 = 8e-5 shifts the phase
      // of the free vibration the passage rings with; measured 1e-4 on the peak and 2e-4 on
      // its speed. RK4's error at 4000 steps a period is ~1e-12.
      CHECK(std::abs(fe.radius / rk.radius - 1) < 5e-4);
      CHECK(std::abs(fe.speed / rk.speed - 1) < 5e-4);
      // The faster the passage, the lower and later the peak (the steady peak is
      // 1 / (2 zeta) = 50 times the eccentricity e, at omega).
      CHECK(fe.radius < previous.radius);
      CHECK(fe.speed > previous.speed);
      CHECK(fe.radius < j.me / j.m / (2 * j.zeta));
      CHECK(fe.speed > w);
      previous = fe;
    }
  }

  TEST_CASE("the undamped Jeffcott rotor's energy: the unbalance's work is kinetic plus strain") {
    const Jeffcott j(0);
    const double w = j.omega;
    const SpeedProfile p = SpeedProfile::ramp(0.5 * w, 1.5 * w, w / (0.01 * w * w));
    RunUpOptions o = j.options(2 * std::numbers::pi / w / 100);
    o.start = RunUpStart::rest;
    const RunUpResult r = solveRunUp(j.model, p, o);
    const RunUpEnergy& e = r.energy;
    double largest = 0, worst = 0;
    for (std::size_t i = 0; i < e.kinetic.size(); ++i) {
      largest = std::max(largest, e.kinetic[i] + e.strain[i]);
      worst = std::max(worst, std::abs(e.balance(i)));
    }
    MESSAGE("energy " << largest << " J, balance off by " << worst << " J");
    // The average acceleration rule keeps the trapezoidal balance exactly (no gyroscopic
    // matrix, constant K): round-off over ~10^4 steps.
    CHECK(largest > 1e-3);
    CHECK(worst < 1e-11 * largest);
  }

  TEST_CASE("slow acceleration: amplitude against speed tends to the steady unbalance response") {
    const ShaftRotor rotor;
    Unbalance u;
    u.node = rotor.disk;
    u.me = 2e-4;
    u.phase = 0.3;
    double previous = 1e300;
    for (double rate : {200.0, 100.0, 50.0}) {  // rad/s^2
      CAPTURE(rate);
      const SpeedProfile p = SpeedProfile::ramp(200, 500, 300 / rate);
      RunUpOptions o;
      o.timeStep = 1e-4;  // 125 steps a revolution at the top speed
      o.start = RunUpStart::steady;
      o.unbalance = {u};
      o.nodes = {rotor.disk};
      o.sampleEvery = 100;
      const RunUpResult r = solveRunUp(rotor.model, p, o);
      const RevolutionAmplitudes& rev = r.histories[0].revolutions;
      const UnbalanceResult steady = solveUnbalance(rotor.model, {u}, rev.speed, {rotor.disk});
      double worst = 0, top = 0;
      for (std::size_t i = 0; i < rev.speed.size(); ++i) {
        top = std::max(top, steady.orbits[0][i].major());
        worst = std::max(worst, std::abs(rev.amplitude[i] - steady.orbits[0][i].major()));
      }
      MESSAGE("rate " << rate << " rad/s^2: largest difference " << worst / top
                      << " of the steady peak " << top << " m over " << rev.speed.size()
                      << " revolutions");
      // The lag of the response behind the quasi-steady one is proportional to the rate
      // (Omega' / omega^2 = 2e-3 .. 5e-4, well below 2 zeta^2 ~ 0.02): halving it halves the
      // error (measured 6.9 %, 3.3 %, 1.6 % of the peak; ratios 0.48).
      CHECK(worst < 0.6 * previous);
      previous = worst;
      if (rate == 50) CHECK(worst < 0.02 * top);
    }
  }

  TEST_CASE("an undamped gyroscopic rotor's energy balance, the drive's share converging") {
    const ShaftRotor rotor(0, 0.3);  // off the middle: the disk tilts as it whirls
    Unbalance u;
    u.node = rotor.disk;
    u.me = 2e-4;
    const SpeedProfile p = SpeedProfile::ramp(200, 450, 0.5);  // through the first critical
    std::vector<double> driven;  // the work done through Omega' G q by the end
    for (double dt : {2e-4, 1e-4, 5e-5}) {
      CAPTURE(dt);
      RunUpOptions o;
      o.timeStep = dt;
      o.unbalance = {u};
      o.nodes = {rotor.disk};
      o.sampleEvery = 10;
      const RunUpEnergy e = solveRunUp(rotor.model, p, o).energy;
      double largest = 0, balance = 0;
      for (std::size_t i = 0; i < e.kinetic.size(); ++i) {
        largest = std::max(largest, e.kinetic[i] + e.strain[i]);
        balance = std::max(balance, std::abs(e.balance(i)));
      }
      driven.push_back(-e.gyroscopic.back());
      MESSAGE("dt " << dt << ": energy " << largest << " J, balance " << balance
                    << " J, work of the drive through the tilting disk " << driven.back()
                    << " J, of the unbalance " << e.work.back() << " J");
      // The rule's balance with the gyroscopic and angular-acceleration moments' work in it
      // holds to round-off (the stiffness is constant).
      CHECK(balance < 1e-9 * largest);
    }
    // Omega G q' does no work (G skew); Omega' G q does: Omega' q'^T G q, the drive's share as
    // the disk's lateral angular momentum grows with the spin. Its trapezoidal sum converges
    // at second order: successive differences fall by 4 (3 allows for round-off).
    const double d1 = std::abs(driven[0] - driven[1]), d2 = std::abs(driven[1] - driven[2]);
    MESSAGE("successive differences " << d1 << ", " << d2);
    CHECK(d2 < d1 / 3);
  }
}
