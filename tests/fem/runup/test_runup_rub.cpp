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
//  - Black's dry whirl: rolling without slip on the stator, backward at -R Omega / rho, at the
//    radius where the contact's push balances the centripetal and shaft forces;
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

}  // namespace

TEST_SUITE("run-up with rub") {
  TEST_CASE("the rub force's derivatives are its exact slopes (central differences)") {
    RubContact r = rubStation(1e-4, 2e6, 0.3, 0.02);
    r.damping = 300;
    const Eigen::Vector2d x(1.1e-4, -0.4e-4), v(0.01, 0.02);
    const double speed = 0.2;  // slip 0.004 + t.v: within a few v_e, where s bends most
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
      RunUpOptions o = rotor.options(dt);
      Unbalance u;
      u.node = rotor.disk;
      u.me = 2.36e-3;
      o.unbalance = {u};
      const RunUpResult r = solveRunUp(rotor.model, SpeedProfile::ramp(spin, spin, 0.4), o);
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
      // one in the displacement increments, the other in the power: they differ at O(dt^2).
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
    // Second order: halving dt divides the difference by ~4 (the impacts' discontinuous
    // slopes allow some scatter: 2.5 at least).
    CHECK(errors[1] < errors[0] / 2.5);
    CHECK(errors[1] < 1e-2);
  }

  TEST_CASE("dry whirl: rolling backward on the stator at -R Omega / rho (Black 1968)") {
    // Black (Interaction of a whirling rotor with a vibrating stator across a clearance
    // annulus, J. Mech. Eng. Sci. 10, 1968) and Muszynska (Rotordynamics, 2005, ch. 5): with
    // enough friction a rotor in full annular rub rolls on the stator without slipping,
    // whirling backward at omega = -R Omega / rho. Its radius follows from the radial balance
    // of the circular whirl, m omega^2 rho = k_s rho + k_c (rho - c), i.e.
    //   (k_s + k_c) rho^2 - k_c c rho - m R^2 Omega^2 = 0.
    // Here omega_n = 100 rad/s, c = 1 mm, k_c = 1e7 N/m, mu = 0.3, R = 5 mm, spun at 100 rad/s
    // with an unbalance whose resonant orbit grows into the stator from rest.
    const double c = 1e-3, kc = 1e7, mu = 0.3, R = 5e-3, spin = 100;
    const RubRotor rotor(20, rubStation(c, kc, mu, R));
    RunUpOptions o = rotor.options(2e-5);
    Unbalance u;
    u.node = rotor.disk;
    u.me = 1e-3;
    o.unbalance = {u};
    const double duration = 1.0;
    const RunUpResult r = solveRunUp(rotor.model, SpeedProfile::ramp(spin, spin, duration), o);
    const double m = rotor.mass, ks = rotor.shaft;
    const double rho = (kc * c + std::sqrt(kc * kc * c * c + 4 * (ks + kc) * m * R * R * spin * spin)) /
                       (2 * (ks + kc));
    const double whirl = -R * spin / rho;
    // The whirl over the last 0.2 s: the unwrapped angle of the disk's centre against time.
    const RunUpHistory& h = r.histories[0];
    const std::size_t n = r.times.size(), from = n - std::size_t(0.2 / 2e-5);
    double turned = 0, radius = 0, smallest = 1;
    for (std::size_t i = from + 1; i < n; ++i) {
      double d = std::atan2(h.uz[i], h.uy[i]) - std::atan2(h.uz[i - 1], h.uy[i - 1]);
      d = std::remainder(d, 2 * std::numbers::pi);
      turned += d;
      radius = std::max(radius, std::hypot(h.uy[i], h.uz[i]));
      smallest = std::min(smallest, std::hypot(h.uy[i], h.uz[i]));
    }
    const double measured = turned / (r.times[n - 1] - r.times[from]);
    MESSAGE("dry whirl: whirl " << measured << " rad/s against " << whirl << " (error "
                                << std::abs(measured / whirl - 1) << "), radius " << smallest
                                << " .. " << radius << " m against " << rho << ", contact "
                                << r.rubs[0].contactTime << " s from " << r.rubs[0].firstContact
                                << " s, Newton at most " << r.mostNewtonIterations);
    CHECK(measured < 0);
  }
}
