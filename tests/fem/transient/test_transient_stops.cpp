// Unilateral stops in time (TransientStops): a body in free flight hitting a rigid stop, where
// the event method with Newton's restitution law is exact, and an elastic oscillator bouncing
// off a stop at its rest position, whose closed form is a rectified sine.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "fem/transient/Transient.hpp"

using namespace beamrotor;

namespace {

/// A body of mass m on ux (and a spring k to ground when k > 0), stop `stop` with bounds.
Model body(double m, double k, double lower, double upper) {
  Model model;
  const int n = model.addNode(Eigen::Vector3d::Zero());
  model.nameNode("body", n);
  model.add<PointInertia>(n, DofSet{Dof::ux}, m);
  if (k > 0) model.add<Spring>(NodeDof{n, Dof::ux}, k);
  model.addContact({"stop", n, Dof::ux, lower, upper});
  return model;
}

TransientOptions run(double dt, double end, double v0, double e, TimeScheme scheme) {
  TransientOptions opt;
  opt.scheme = scheme;
  opt.timeStep = dt;
  opt.endTime = end;
  opt.restitution = e;
  opt.initialVelocity = NodalField::Zero(1, kDofKinds);
  opt.initialVelocity(0, dofIndex(Dof::ux)) = v0;
  opt.histories = {{0, Dof::ux}};
  return opt;
}

}  // namespace

TEST_SUITE("transient stops") {
  TEST_CASE("a free body hits a rigid stop: rebound -e v0 and the flight after it, exactly") {
    // Moving at v0 = -1.5 m/s from x = 0 towards a stop at -0.0123 m (inside a step, at
    // t* = 8.2 ms): afterwards x = -0.0123 + e |v0| (t - t*). In free flight both schemes
    // move the body exactly, and the event method locates t* and reflects exactly, so only
    // round-off remains (1e-12 m on values of 1e-2 m).
    const double v0 = -1.5, bound = -0.0123, e = 0.6, end = 0.05;
    const double tStar = bound / v0;
    for (TimeScheme scheme : {TimeScheme::newmark, TimeScheme::centralDifference}) {
      CAPTURE(int(scheme));
      const Model model = body(2.0, 0, bound, std::numeric_limits<double>::infinity());
      const TransientResult r = solveTransient(model, run(1e-3, end, v0, e, scheme));
      REQUIRE(r.impacts.size() == 1);
      CHECK(std::abs(r.impacts[0].time - tStar) < 1e-15);
      CHECK(std::abs(r.impacts[0].velocityBefore - v0) < 1e-12);
      CHECK(std::abs(r.impacts[0].velocityAfter + e * v0) < 1e-12);
      const DofHistory& h = r.histories[0];
      for (std::size_t i = 0; i < r.times.size(); ++i) {
        const double t = r.times[i];
        const double exact = t < tStar ? v0 * t : bound - e * v0 * (t - tStar);
        CHECK(std::abs(h.displacement[i] - exact) < 1e-12);
        CHECK(h.displacement[i] >= bound);  // never through the stop
      }
      CHECK(std::abs(h.velocity.back() + e * v0) < 1e-12);
      // A plastic impact (e = 0) leaves the body resting on the stop.
      const TransientResult plastic = solveTransient(model, run(1e-3, end, v0, 0, scheme));
      CHECK(plastic.histories[0].displacement.back() == bound);
      CHECK(plastic.histories[0].velocity.back() == 0);
    }
  }

  TEST_CASE("an oscillator bouncing elastically at its rest position: |sin|, order 2 here") {
    // m = 1 kg, k = (2 pi)^2 N/m (omega = 2 pi rad/s) leaving x = 0 at v0 = 1 m/s with a stop
    // at x >= 0 and e = 1: x(t) = |sin(omega t)| / omega, a bounce every half period. The
    // crossing is located by linear interpolation and the rest of the step is flown freely:
    // O(dt) in general, but this bounce is symmetric and the errors of approach and rebound
    // cancel to leading order. Measured: 1.42e-5 m at dt = 1e-3 s, 3.56e-6 m at 5e-4 s (ratio
    // 3.98); asked: ratio > 3.5 and 1e-5 m (6e-5 of the amplitude) at the finer step. The
    // energy 1/2 m v0^2 is kept to second order as well: measured errors 7.80e-5 J and
    // 1.96e-5 J (78 dt^2, ratio 3.98); asked 100 dt^2.
    const double w = 2 * std::numbers::pi, end = 2.3;
    const Model model = body(1.0, w * w, 0.0, std::numeric_limits<double>::infinity());
    auto error = [&](double dt) {
      const TransientResult r = solveTransient(model, run(dt, end, 1.0, 1.0, TimeScheme::newmark));
      CHECK(r.impacts.size() == 4);  // at 0.5, 1, 1.5 and 2 s
      double worst = 0;
      for (std::size_t i = 0; i < r.times.size(); ++i) {
        CHECK(r.histories[0].displacement[i] >= 0);
        worst = std::max(worst, std::abs(r.histories[0].displacement[i] -
                                         std::abs(std::sin(w * r.times[i])) / w));
      }
      const double energy = r.energy.kinetic.back() + r.energy.strain.back();
      CHECK(std::abs(energy - 0.5) < 100 * dt * dt);
      return worst;
    };
    const double coarse = error(1e-3), fine = error(5e-4);
    CAPTURE(coarse);
    CAPTURE(fine);
    CHECK(coarse / fine > 3.5);
    CHECK(fine < 1e-5);
  }

  TEST_CASE("stops that cannot work are refused") {
    Model model = body(2.0, 100, -0.01, 0.01);
    TransientOptions opt = run(1e-3, 0.01, 0, 1.5, TimeScheme::newmark);
    CHECK_THROWS_WITH_AS(solveTransient(model, opt), doctest::Contains("restitution"),
                         std::invalid_argument);
    opt.restitution = 0.5;
    opt.initialDisplacement = NodalField::Zero(1, kDofKinds);
    opt.initialDisplacement(0, dofIndex(Dof::ux)) = 0.02;
    CHECK_THROWS_WITH_AS(solveTransient(model, opt), doctest::Contains("outside its bounds"),
                         std::invalid_argument);
  }
}
