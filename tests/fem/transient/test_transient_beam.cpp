// A cantilever under a suddenly applied tip load: Newmark's history against the exact modal
// superposition of the same discrete model, and the outputs (frames, sampling) of a run.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "fem/assembly/Assembly.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/transient/Transient.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

struct TransientCantilever {
  Model model;
  Line line;
  TransientCantilever() {
    line = uniformBeam(model, 1.5, steelCircle(0.04), 8, DofSet{Dof::uy, Dof::rz});
    clamp(model, "root", line.nodes.front(), DofSet{Dof::uy, Dof::rz});
  }
};

}  // namespace

TEST_SUITE("transient beam") {
  TEST_CASE("harmonic tip load: newmark converges at O(dt^2) to the modal superposition") {
    TransientCantilever c;
    const Model& m = c.model;
    // Tip load P (1 - cos W t), W = omega_1 / 2: it starts with zero value and slope, so the
    // modes the steps cannot resolve are excited only at (W / omega_i)^2 / omega_i^2, and
    // the error measured is the rule's own on the modes that carry the motion.
    const double P = -100;  // N along uy
    // 1. Exact response of the discrete model: with M-orthonormal modes phi_i and
    // q_i = phi_i . f, each modal coordinate from rest is
    // x_i = q_i [1 / w^2 - cos(W t) / (w^2 - W^2) + W^2 cos(w t) / (w^2 (w^2 - W^2))].
    const DofMap dofs(m);
    const SparseAssembler a(m, dofs);
    const Eigen::MatrixXd K(a.assemble(MatrixKind::stiffness)), M(a.assemble(MatrixKind::mass));
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(K, M);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.freeCount());
    const int tipEq = dofs.equation(m.node("end"), Dof::uy);
    f[tipEq] = P;
    const Eigen::VectorXd w = modes.eigenvalues().cwiseSqrt();
    const Eigen::VectorXd q = modes.eigenvectors().transpose() * f;
    const double W = w[0] / 2, T1 = 2 * std::numbers::pi / w[0];
    auto exactTip = [&](double t) {
      double u = 0;
      for (int i = 0; i < w.size(); ++i) {
        const double w2 = w[i] * w[i], d = w2 - W * W;
        u += modes.eigenvectors()(tipEq, i) * q[i] *
             (1 / w2 - std::cos(W * t) / d + W * W * std::cos(w[i] * t) / (w2 * d));
      }
      return u;
    };
    // 2. Newmark with the load as a time load at the named point, three steps.
    std::array<double, 3> error{};
    const std::array<int, 3> perPeriod{100, 200, 400};
    for (int j = 0; j < 3; ++j) {
      TransientOptions opt;
      opt.timeStep = T1 / perPeriod[j];
      opt.endTime = 2 * T1;
      opt.loads = {pointTimeLoad(m, "end", Dof::uy, P, timefn::harmonicSeries(W, {{1, -1, 0}}, 1))};
      opt.histories = {{m.node("end"), Dof::uy}};
      const TransientResult r = solveTransient(m, opt);
      for (std::size_t n = 0; n < r.times.size(); ++n)
        error[j] =
            std::max(error[j], std::abs(r.histories[0].displacement[n] - exactTip(r.times[n])));
    }
    const double staticTip = P * std::pow(1.5, 3) / (3 * steelCircle(0.04)->EIz());
    for (double& e : error) e /= std::abs(staticTip);
    const double o1 = std::log2(error[0] / error[1]), o2 = std::log2(error[1] / error[2]);
    MESSAGE("harmonic load, tip error / static deflection: "
            << error[0] << ", " << error[1] << ", " << error[2] << "; orders " << o1 << ", " << o2);
    // Bound: the first mode's phase error (omega_1 dt)^2 / 12 per radian over the 4 pi of the
    // run, times the peak tip motion (at most ~3 static deflections here).
    CHECK(std::abs(o1 - 2) < 0.2);
    CHECK(std::abs(o2 - 2) < 0.2);
    const double Omega = 2 * std::numbers::pi / perPeriod[2];
    CHECK(error[2] < Omega * Omega / 12 * 4 * std::numbers::pi * 3);
  }

  TEST_CASE("a root accelerating uniformly: the moving support is the fixed base plus -m a") {
    // The root's uy follows b(t) = a t^2 / 2. With u = r b + w (r the rigid translation along
    // y, which K does not resist) the free dofs obey M w'' + K w = -(M r) a: the fixed-base
    // cantilever under the uniform load -rho A a (for the consistent mass, M r is exactly the
    // consistent load vector of a uniform load). Newmark integrates the quadratic b exactly, so
    // the two runs agree step by step to round-off. The moving support reaches the free dofs
    // through the stiffness and the consistent-mass coupling of the first element.
    const double a = 30.0;  // m/s^2
    TransientCantilever moving, fixed;
    SupportMotion root;
    root.node = moving.line.nodes.front();
    root.dof = Dof::uy;
    root.displacement = [a](double t) { return a * t * t / 2; };
    root.velocity = [a](double t) { return a * t; };
    root.acceleration = [a](double) { return a; };
    const double rhoA = moving.line.beams.front()->section().rhoA();
    for (Beam* b : fixed.line.beams) b->setDistributedLoad({0, -rhoA * a, 0});
    TransientOptions opt;
    opt.timeStep = 2e-4;
    opt.endTime = 0.02;
    const int tip = moving.line.nodes.back(), middle = moving.line.nodes[4];
    opt.histories = {{tip, Dof::uy}, {middle, Dof::uy}, {middle, Dof::rz}};
    opt.supportMotions = {root};
    const TransientResult withSupport = solveTransient(moving.model, opt);
    opt.supportMotions = {};
    const TransientResult relative = solveTransient(fixed.model, opt);
    REQUIRE(withSupport.times.size() == relative.times.size());
    double worst = 0, scale = 0;
    for (std::size_t k = 0; k < relative.times.size(); ++k) {
      const double t = relative.times[k], rigid = a * t * t / 2;
      for (int h = 0; h < 3; ++h) {
        const double w = relative.histories[h].displacement[k];
        const double u = withSupport.histories[h].displacement[k] - (h < 2 ? rigid : 0);
        worst = std::max(worst, std::abs(u - w));
        scale = std::max(scale, std::abs(w));
      }
    }
    MESSAGE("moving root: largest gap " << worst << " on relative motions up to " << scale);
    CHECK(scale > 0);
    CHECK(worst < 1e-10 * scale);
  }

  TEST_CASE("outputs: sampled histories, bounded evenly spaced frames, support values") {
    TransientCantilever c;
    TransientOptions opt;
    opt.timeStep = 1e-4;
    opt.endTime = 0.0105;  // 105 steps
    opt.sampleEvery = 10;
    opt.maxFrames = 4;
    opt.initialVelocity = NodalField::Zero(c.model.nodeCount(), kDofKinds);
    opt.initialVelocity(c.model.node("end"), dofIndex(Dof::uy)) = 1;
    opt.histories = {{c.model.node("end"), Dof::uy}, {c.model.node("start"), Dof::rz}};
    const TransientResult r = solveTransient(c.model, opt);
    CHECK(r.steps == 105);
    REQUIRE(r.times.size() == 12);  // steps 0, 10, ..., 100 and the last, 105
    CHECK(r.times[1] == doctest::Approx(1e-3));
    CHECK(r.times.back() == doctest::Approx(0.0105));
    CHECK(r.histories[0].velocity[0] == 1);
    for (double v : r.histories[1].displacement) CHECK(v == 0);  // the clamp
    REQUIRE(r.frames.size() == 4);
    CHECK(r.frames[0].time == 0);
    CHECK(r.frames[1].time == doctest::Approx(35e-4));
    CHECK(r.frames[3].time == doctest::Approx(0.0105));
    CHECK(r.frames[3].displacement(c.model.node("end"), dofIndex(Dof::uy)) ==
          r.histories[0].displacement.back());
    CHECK(r.energy.kinetic.size() == r.times.size());
  }

  TEST_CASE("bad options are named") {
    TransientCantilever c;
    TransientOptions opt;
    opt.timeStep = 1e-4;
    opt.endTime = 1e-3;
    SUBCASE("alpha outside [-1/3, 0]") {
      opt.scheme = TimeScheme::hht;
      opt.hhtAlpha = -0.5;
      CHECK_THROWS_WITH_AS(solveTransient(c.model, opt), doctest::Contains("alpha"),
                           std::invalid_argument);
    }
    SUBCASE("a load on a dof no element carries") {
      opt.loads = {pointTimeLoad(c.model, "end", Dof::ux, 1, timefn::constant(1))};
      CHECK_THROWS_WITH_AS(solveTransient(c.model, opt), doctest::Contains("ux"),
                           std::invalid_argument);
    }
    SUBCASE("a stop on a consistent-mass dof is refused (its impulse would move the others)") {
      c.model.addContact({"stop", c.model.node("end"), Dof::uy, -1e-3, 1e-3});
      CHECK_THROWS_WITH_AS(solveTransient(c.model, opt), doctest::Contains("coupled"),
                           std::invalid_argument);
    }
    SUBCASE("no step") {
      opt.timeStep = 0;
      CHECK_THROWS_AS(solveTransient(c.model, opt), std::invalid_argument);
    }
    SUBCASE("central difference with stiffness-proportional damping") {
      Model m;
      const Line line = uniformBeam(m, 1.5, steelCircle(0.04), 4, DofSet{Dof::uy, Dof::rz},
                                    {BeamTheory::eulerBernoulli, MassModel::lumped, true});
      clamp(m, "root", line.nodes.front(), DofSet{Dof::uy, Dof::rz});
      opt.scheme = TimeScheme::centralDifference;
      opt.timeStep = 1e-7;
      opt.endTime = 1e-6;
      opt.rayleighStiffness = 1e-5;
      CHECK_THROWS_WITH_AS(solveTransient(m, opt), doctest::Contains("diagonal damping"),
                           SolveError);
      opt.rayleighStiffness = 0;
      opt.rayleighMass = 3;  // diagonal: accepted
      CHECK(solveTransient(m, opt).steps == 10);
    }
  }
}
