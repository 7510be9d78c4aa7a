// Harmonic motion of the ground against the closed forms of a single oscillator (a mass on a
// spring and damper to the moving ground; e.g. Chopra, Dynamics of Structures, sec. 3.6):
// the transmissibility |u''_abs| / |a_g| = sqrt((1 + (2 zeta b)^2) / ((1 - b^2)^2 + (2 zeta b)^2))
// and the relative displacement |u| = (a_g / w_n^2) / sqrt((1 - b^2)^2 + (2 zeta b)^2),
// b = w / w_n, by modes and directly.
#include <doctest/doctest.h>

#include <cmath>

#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "fem/modal/BaseMotion.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

TEST_SUITE("base motion") {
  TEST_CASE("a single oscillator on a shaking ground: transmissibility and relative motion") {
    const double m = 800, k = 3.2e6, zeta = 0.04;
    const double wn = std::sqrt(k / m), c = 2 * zeta * m * wn;
    Model model;
    const int ground = model.addNode({0, 0, 0}), body = model.addNode({0, 1, 0});
    model.addSupport({"ground", ground, {{Dof::ux, 0}}});
    model.addElement(std::make_unique<PointInertia>(body, DofSet{Dof::ux}, m));
    BaseMotionOptions o;
    o.acceleration = 2.5;
    for (double b : {0.3, 0.9, 1.0, 1.1, std::sqrt(2.0), 3.0})
      o.frequenciesHz.push_back(b * wn / (2 * kPi));
    const auto closedForm = [&](double b, double& T, double& u) {
      const double den = std::sqrt(std::pow(1 - b * b, 2) + std::pow(2 * zeta * b, 2));
      T = std::sqrt(1 + std::pow(2 * zeta * b, 2)) / den;
      u = o.acceleration / (wn * wn) / den;
    };
    SUBCASE("modal, with modal damping zeta; a plain spring") {
      model.addElement(std::make_unique<Spring>(NodeDof{ground, Dof::ux}, NodeDof{body, Dof::ux}, k));
      o.method = BaseMotionMethod::modal;
      o.modes = 1;
      o.modalDamping = zeta;
    }
    SUBCASE("direct, with the damper c of the same zeta") {
      model.addElement(
          std::make_unique<Spring>(NodeDof{ground, Dof::ux}, NodeDof{body, Dof::ux}, k, c));
      o.method = BaseMotionMethod::direct;
    }
    SUBCASE("direct, with stiffness-proportional Rayleigh damping beta = c / k") {
      model.addElement(std::make_unique<Spring>(NodeDof{ground, Dof::ux}, NodeDof{body, Dof::ux}, k));
      o.method = BaseMotionMethod::direct;
      o.beta = c / k;
    }
    const BaseMotionResult r = solveBaseMotion(model, o);
    REQUIRE(r.points.size() == o.frequenciesHz.size());
    for (const BaseMotionPoint& p : r.points) {
      const double b = 2 * kPi * p.frequencyHz / wn;
      double T = 0, u = 0;
      closedForm(b, T, u);
      CAPTURE(b);
      // One equation solved (or one mode, its eigenvalue to round-off): round-off, a few
      // ulps amplified by 1/(2 zeta) at resonance.
      CHECK(relError(p.transmissibility(body, 0), T) < 1e-10);
      CHECK(relError(std::abs(p.relative(body, 0)), u) < 1e-10);
      // The ground's force is the mass times the absolute acceleration.
      CHECK(relError(std::abs(p.baseForce), m * T * o.acceleration) < 1e-10);
    }
  }

  TEST_CASE("a ground displacement amplitude u_g reads as a_g = w^2 u_g; at b = sqrt 2, T = 1") {
    const double m = 50, k = 2e5;
    Model model;
    const int ground = model.addNode({0, 0, 0}), body = model.addNode({0, 1, 0});
    model.addSupport({"ground", ground, {{Dof::uy, 0}}});
    model.addElement(std::make_unique<PointInertia>(body, DofSet{Dof::uy}, m));
    model.addElement(std::make_unique<Spring>(NodeDof{ground, Dof::uy}, NodeDof{body, Dof::uy}, k));
    BaseMotionOptions o;
    o.direction = 1;
    o.displacement = 1e-3;
    o.modes = 1;
    o.modalDamping = 0.1;
    const double wn = std::sqrt(k / m);
    o.frequenciesHz = {std::sqrt(2.0) * wn / (2 * kPi)};
    const BaseMotionResult r = solveBaseMotion(model, o);
    // At b = sqrt 2 every damping transmits exactly the ground's motion: |u_abs| = u_g.
    CHECK(relError(std::abs(r.points[0].absolute(body, 1)), 1e-3) < 1e-12);
    CHECK(relError(std::abs(r.points[0].groundAcceleration), 2 * wn * wn * 1e-3) < 1e-14);
  }
}
