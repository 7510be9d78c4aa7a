// Run-up with a rub station (fem/runup/RubContact.hpp): a Jeffcott rotor's disk touching a
// stator across a radial clearance, with Coulomb friction, against closed forms:
//  - pressed on the stator by a static load without spin: the contact force is the load's share
//    taken by the penalty spring once the gap is closed (the two springs in parallel past it);
//  - the same at a constant spin with friction: the disk slides sideways until the load, the
//    shaft's spring, the normal force N and the friction mu N balance (a quadratic in the
//    radius), friction opposing the surface's slip, and the friction's torque mu N R;
//  - an unbalanced rotor rubbing at a constant spin: the run's energy account closes, and the
//    energy the friction dissipates equals the work done on the shaft by the contact plus the
//    spin's work against the rub torque, less the contact's stored energy;
//  - full annular rub (Black 1968): the synchronous circular whirl in permanent contact, its
//    radius from the complex balance of shaft, damper, contact, friction and unbalance;
//  - dry whip: with friction the rubbing rotor whirls backward, near its natural frequency;
// and the rub's force derivatives against central differences.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "fem/runup/RunUp.hpp"

using namespace beamrotor;

namespace {

/// A Jeffcott rotor: a disk of `mass` on a shaft spring `shaft` (N/m) to the ground in y and z,
/// with a damper `damping` (N s/m), and a rub station at the disk.
struct RubRotor {
  double mass = 10, shaft = 1e5, damping = 0;
  RubContact rub;
  Model model;
  int disk = -1;
  RubRotor(double diskDamping, const RubContact& contact) : damping(diskDamping), rub(contact) {
    disk = model.addNode({0, 0, 0});
    model.add<PointInertia>(disk, DofSet{Dof::uy, Dof::uz}, mass);
    for (Dof d : {Dof::uy, Dof::uz}) model.add<Spring>(NodeDof{disk, d}, shaft, damping);
    rub.node = disk;
  }
  RunUpOptions options(double dt) const {
    RunUpOptions o;
    o.timeStep = dt;
    o.nodes = {disk};
    o.rubs = {rub};
    return o;
  }
};

RubContact rubStation(double clearance, double stiffness, double friction, double radius) {
  RubContact r;
  r.name = "seal";
  r.clearance = clearance;
  r.stiffness = stiffness;
  r.friction = friction;
  r.radius = radius;
  r.slipVelocity = 1e-3;
  return r;
}

/// The rotor spun at a constant `spin` (rad/s) for `duration` (s) with an unbalance `me` at
/// the disk.
RunUpResult unbalancedRun(const RubRotor& rotor, double dt, double me, double spin,
                          double duration, RunUpStart start = RunUpStart::rest) {
  RunUpOptions o = rotor.options(dt);
  o.start = start;
  Unbalance u;
  u.node = rotor.disk;
  u.me = me;
  o.unbalance = {u};
  return solveRunUp(rotor.model, SpeedProfile::ramp(spin, spin, duration), o);
}

/// The disk's mean whirl speed (rad/s, > 0 forward) over the samples from `from` on: its
/// centre's unwrapped angle against time.
double whirlSpeed(const RunUpResult& r, std::size_t from) {
  const RunUpHistory& h = r.histories[0];
  double turned = 0;
  for (std::size_t i = from + 1; i < h.uy.size(); ++i)
    turned += std::remainder(std::atan2(h.uz[i], h.uy[i]) - std::atan2(h.uz[i - 1], h.uy[i - 1]),
                             2 * std::numbers::pi);
  return turned / (r.times.back() - r.times[from]);
}

}  // namespace

TEST_SUITE("run-up with rub") {
  TEST_CASE("the rub force's derivatives are its exact slopes (central differences)") {
    RubContact r = rubStation(1e-4, 2e6, 0.3, 0.02);
    r.damping = 300;
    const Eigen::Vector2d x(1.1e-4, -0.4e-4), v(0.001, -0.002);
    const double speed = 0.2;  // slip R Omega + t.v = 2.5 v_e: where s bends most
    const RubForce f = rubForce(r, x, v, speed);
    REQUIRE(f.touching());
    // Central differences with h ~ 1e-5 of each variable's scale: truncation ~ h^2 ~ 1e-10 of
    // the slope, round-off ~ 1e-16 / 1e-5 = 1e-11: agreement to 1e-7 is a clear test.
    for (int j = 0; j < 2; ++j) {
      const double hx = 1e-10, hv = 1e-8;
      Eigen::Vector2d dx = Eigen::Vector2d::Zero(), dv = Eigen::Vector2d::Zero();
      dx[j] = hx;
      dv[j] = hv;
      const Eigen::Vector2d kx =
          -(rubForce(r, x + dx, v, speed).force - rubForce(r, x - dx, v, speed).force) / (2 * hx);
      const Eigen::Vector2d cv =
          -(rubForce(r, x, v + dv, speed).force - rubForce(r, x, v - dv, speed).force) / (2 * hv);
      for (int i = 0; i < 2; ++i) {
        CHECK(f.stiffness(i, j) == doctest::Approx(kx[i]).epsilon(1e-7).scale(f.stiffness.norm()));
        CHECK(f.damping(i, j) == doctest::Approx(cv[i]).epsilon(1e-7).scale(f.damping.norm()));
      }
    }
    const double hw = 1e-6;
    const double slope =
        (rubForce(r, x, v, speed + hw).torque - rubForce(r, x, v, speed - hw).torque) / (2 * hw);
    CHECK(f.torqueSlope == doctest::Approx(slope).epsilon(1e-7));
    // Clear of the stator: nothing.
    CHECK_FALSE(rubForce(r, Eigen::Vector2d(0.9e-4, 0), v, speed).touching());
  }

  TEST_CASE("pressed on the stator by a static load without spin: the springs in parallel") {
    // 10 kg under 9.81 m/s^2 on a 1e5 N/m shaft sags 0.981 mm; the stator is 0.5 mm away. Past
    // the gap the two springs share the load: rho = (P + k_c c) / (k_s + k_c), N = k_c (rho - c).
    const double c = 0.5e-3, kc = 1e6;
    const RubRotor rotor(20, rubStation(c, kc, 0.3, 0.02));  // friction: no slip, no force
    RunUpOptions o = rotor.options(1e-3);
    o.gravity = {0, -9.81, 0};
    const RunUpResult r = solveRunUp(rotor.model, SpeedProfile::ramp(0, 0, 0.05), o);
    const double P = rotor.mass * 9.81, ks = rotor.shaft;
    const double rho = (P + kc * c) / (ks + kc), N = kc * (rho - c);
    REQUIRE(r.rubs.size() == 1);
    const RubTrack& t = r.rubs[0];
    // Newton's static equilibrium to 1e-10 c at the start, held by every step (the state is a
    // fixed point of the step): the force to 1e-10 c k_c / N ~ 1e-9 relative.
    for (std::size_t i = 0; i < r.times.size(); ++i) {
      CHECK(t.normal[i] == doctest::Approx(N).epsilon(1e-9));
      CHECK(t.radial[i] == doctest::Approx(rho).epsilon(1e-10));
      // No spin: the surface sticks (v_s is the round-off of a still state), so does friction.
      CHECK(std::abs(t.friction[i]) < 1e-9 * N);
    }
    CHECK(t.contactTime == doctest::Approx(0.05).epsilon(1e-12));
    CHECK(t.firstContact == 0.0);
    CHECK(r.histories[0].uz.back() == doctest::Approx(0).scale(1e-15));
    MESSAGE("static contact: N " << t.normal.back() << " N against " << N << " N (error "
                                 << std::abs(t.normal.back() / N - 1) << ")");
  }

  TEST_CASE("the same load at a constant spin: friction slides the disk against the spin") {
    const double c = 0.5e-3, kc = 1e6, mu = 0.3, R = 0.02, spin = 100;
    const RubRotor rotor(20, rubStation(c, kc, mu, R));
    RunUpOptions o = rotor.options(1e-3);
    o.gravity = {0, -9.81, 0};
    const RunUpResult r = solveRunUp(rotor.model, SpeedProfile::ramp(spin, spin, 0.05), o);
    // At rest the surface slides at v_s = R Omega = 2 m/s: s = v_s / sqrt(v_s^2 + v_e^2). The
    // balance along the normal and the tangent, with N = k_c (rho - c) and m = mu s k_c:
    //   (k_s rho + N)^2 + (mu s N)^2 = P^2, a quadratic in rho (the larger root),
    // and the contact sits at angle alpha from the load line towards +z, sin(alpha) = mu s N / P:
    // at the bottom (n = -y) the surface moves along t = -z, so the friction pushes the shaft
    // along +z.
    const double P = rotor.mass * 9.81, ks = rotor.shaft, vs = R * spin;
    const double s = vs / std::hypot(vs, 1e-3), m = mu * s * kc, a = ks + kc, b = -kc * c;
    const double A = a * a + m * m, B = 2 * a * b - 2 * m * m * c, C = b * b + m * m * c * c - P * P;
    const double rho = (-B + std::sqrt(B * B - 4 * A * C)) / (2 * A), N = kc * (rho - c);
    const double alpha = std::asin(mu * s * N / P);
    const RubTrack& t = r.rubs[0];
    const double y = r.histories[0].uy.back(), z = r.histories[0].uz.back();
    // Newton's tolerance 1e-10 c = 5e-14 m on the penetration 4.4e-5 m: 1e-8 on N.
    CHECK(t.normal.back() == doctest::Approx(N).epsilon(1e-8));
    CHECK(std::hypot(y, z) == doctest::Approx(rho).epsilon(1e-10));
    CHECK(y == doctest::Approx(-rho * std::cos(alpha)).epsilon(1e-9));
    CHECK(z == doctest::Approx(rho * std::sin(alpha)).epsilon(1e-9));
    CHECK(z > 0);
    // Friction against the slip, mu N s, and its torque on the spin mu N s R.
    CHECK(t.friction.back() == doctest::Approx(mu * s * N).epsilon(1e-8));
    CHECK(t.torque.back() == doctest::Approx(mu * s * N * R).epsilon(1e-8));
    // Held still: the friction dissipates mu N s R Omega, all of it through the spin.
    CHECK(t.frictionWork == doctest::Approx(mu * s * N * vs * 0.05).epsilon(1e-8));
    MESSAGE("sliding contact: N " << t.normal.back() << " against " << N << ", angle "
                                  << std::atan2(z, -y) << " against " << alpha << " rad, torque "
                                  << t.torque.back() << " N m");
  }

  TEST_CASE("an unbalanced rotor rubbing at a constant spin: the energy the friction dissipates") {
    // omega_n = 100 rad/s, 1 % damping, spun at 90 rad/s from rest with an unbalance whose
    // steady orbit (1 mm) is twice the clearance: the orbit grows into the stator and rubs.
    const double c = 0.5e-3, kc = 1e6, mu = 0.2, R = 0.02, spin = 90;
    std::vector<double> errors;
    for (double dt : {2e-4, 1e-4}) {
      const RubRotor rotor(20, rubStation(c, kc, mu, R));
      const RunUpResult r = unbalancedRun(rotor, dt, 2.36e-3, spin, 0.4);
      const RubTrack& t = r.rubs[0];
      REQUIRE(t.contactTime > 0.05);
      // The run's account: the average acceleration rule's trapezoidal identity, exact up to
      // Newton's tolerance (1e-10 c on the state): round-off of the energies' ~1e-16 x terms.
      const RunUpEnergy& e = r.energy;
      const std::size_t last = e.kinetic.size() - 1;
      CHECK(std::abs(e.balance(last)) < 1e-9 * e.work[last]);
      CHECK(e.rub[last] > 0);
      // Friction's dissipation = the contact's work on the shaft's translation (the rub column,
      // less the energy the penalty spring holds at the end) + the spin's work against the rub
      // torque (Omega times the torque's time integral); both sides trapezoidal in time, but
      // one in the displacement increments, the other in the power.
      double spinWork = 0;
      for (std::size_t i = 1; i < r.times.size(); ++i)
        spinWork += spin * (r.times[i] - r.times[i - 1]) * (t.torque[i] + t.torque[i - 1]) / 2;
      const double delta = std::max(0.0, t.radial.back() - c);
      const double lateral = e.rub[last] - kc * delta * delta / 2;
      const double error = std::abs(lateral + spinWork - t.frictionWork) / t.frictionWork;
      errors.push_back(error);
      MESSAGE("dt " << dt << ": contact " << t.contactTime << " s, peak N " << t.peakNormal
                    << " N, friction dissipated " << t.frictionWork << " J (lateral " << lateral
                    << ", spin " << spinWork << "), relative difference " << error
                    << ", balance " << e.balance(last) << " J on work " << e.work[last]
                    << " J, Newton at most " << r.mostNewtonIterations);
    }
    // Measured 4.4e-7 and 6.1e-7 of the dissipation: the two integrals differ only where the
    // force kinks within a step (contact made or lost), and not by the step's size there.
    // A friction force of the wrong sign or size would leave a difference of order 1.
    for (double e : errors) CHECK(e < 1e-5);
  }

  TEST_CASE("full annular rub: the synchronous forward whirl on the stator (Black 1968)") {
    // An unbalanced Jeffcott rotor whose free orbit (2 mm) exceeds the clearance (1 mm) settles,
    // with little friction, on a synchronous circular whirl in permanent contact (Black,
    // Interaction of a whirling rotor with a vibrating stator across a clearance annulus,
    // J. Mech. Eng. Sci. 10, 1968; Muszynska, Rotordynamics, 2005, on full annular rub). With
    // r = rho e^{i(Omega t + beta)} the stator pushes -(N + i mu N) r / rho (the friction
    // opposes the slip rho Omega + R Omega > 0), N = k_c (rho - c), so
    //   rho |k_s - m Omega^2 + k_c (1 - c / rho) + i (c_d Omega + mu k_c (1 - c / rho))| =
    //   m e Omega^2,
    // one root rho > c (the left side grows with rho), found here by bisection.
    const double c = 1e-3, kc = 1e5, mu = 0.1, R = 0.02, spin = 90, cd = 200, me = 6e-3;
    const RubRotor rotor(cd, rubStation(c, kc, mu, R));
    const double m = rotor.mass, ks = rotor.shaft;
    const auto excess = [&](double rho) {
      const double pen = 1 - c / rho;
      return rho * std::hypot(ks - m * spin * spin + kc * pen, cd * spin + mu * kc * pen) -
             me * spin * spin;
    };
    double lo = c, hi = 1;
    for (int k = 0; k < 200; ++k) (excess((lo + hi) / 2) < 0 ? lo : hi) = (lo + hi) / 2;
    const double rho = (lo + hi) / 2, N = kc * (rho - c);
    // Started on the free orbit, 2 mm: it hits the stator at once.
    const RunUpResult r = unbalancedRun(rotor, 1e-4, me, spin, 1.5, RunUpStart::steady);
    // The last 0.2 s (2.9 whirls).
    const RunUpHistory& h = r.histories[0];
    const RubTrack& t = r.rubs[0];
    const std::size_t n = r.times.size(), from = n - 2000;
    double smallest = 1, largest = 0, lowN = 1e300, highN = 0;
    for (std::size_t i = from; i < n; ++i) {
      const double radius = std::hypot(h.uy[i], h.uz[i]);
      smallest = std::min(smallest, radius);
      largest = std::max(largest, radius);
      lowN = std::min(lowN, t.normal[i]);
      highN = std::max(highN, t.normal[i]);
    }
    const double whirl = whirlSpeed(r, from);
    MESSAGE("full annular rub: radius " << smallest << " .. " << largest << " m against " << rho
                                        << ", N " << lowN << " .. " << highN << " N against " << N
                                        << ", whirl " << whirl << " rad/s against " << spin
                                        << ", contact " << t.contactTime << " s, Newton at most "
                                        << r.mostNewtonIterations);
    // A circle at the steady radius, up to what is left of the transient after 1.5 s: measured
    // 1.4e-5 of the radius, 8e-5 of N (N = k_c (rho - c) magnifies it by rho / (rho - c) = 6).
    CHECK(smallest == doctest::Approx(rho).epsilon(1e-4));
    CHECK(largest == doctest::Approx(rho).epsilon(1e-4));
    CHECK(highN == doctest::Approx(N).epsilon(1e-3));
    CHECK(lowN == doctest::Approx(N).epsilon(1e-3));
    CHECK(t.torque.back() == doctest::Approx(mu * N * R).epsilon(1e-3));
    // Synchronous: the rule's phase error (Omega dt)^2 / 12 = 7e-6 per radian.
    CHECK(whirl == doctest::Approx(spin).epsilon(1e-5));
  }

  TEST_CASE("dry whip: a rub at resonance throws the rotor into backward whirl") {
    // Muszynska (Rotordynamics, 2005) and Black (1968): a rotor bouncing on a stator with
    // enough friction whirls backward, its frequency set by the coupled system: between the
    // free rotor's omega_n (100 rad/s here) and the rotor in permanent contact,
    // sqrt((k_s + k_c) / m) = 1005 rad/s; with contact a small part of each whirl, near the
    // lower end (dry whip). Spun at omega_n with an unbalance whose resonant orbit grows from
    // rest into the stator (c 1 mm, k_c 1e7 N/m, mu 0.3, R 5 mm).
    const double c = 1e-3, kc = 1e7, mu = 0.3, R = 5e-3, spin = 100;
    const RubRotor rotor(20, rubStation(c, kc, mu, R));
    const RunUpResult r = unbalancedRun(rotor, 2e-5, 1e-3, spin, 1.0);
    const std::size_t from = r.times.size() - std::size_t(0.2 / 2e-5);  // the last 0.2 s
    const double whirl = whirlSpeed(r, from);
    MESSAGE("dry whip: whirl " << whirl << " rad/s (spin " << spin << "), contact "
                               << r.rubs[0].contactTime << " s from " << r.rubs[0].firstContact
                               << " s, peak N " << r.rubs[0].peakNormal << " N");
    // Without friction the same rotor whirls forward with the spin (checked below).
    CHECK(whirl < -100);
    CHECK(whirl > -std::sqrt((rotor.shaft + kc) / rotor.mass));
    const RubRotor smooth(20, rubStation(c, kc, 0, R));
    const double forward = whirlSpeed(unbalancedRun(smooth, 2e-5, 1e-3, spin, 1.0), from);
    MESSAGE("without friction: whirl " << forward << " rad/s");
    CHECK(forward > 0);
  }
}
