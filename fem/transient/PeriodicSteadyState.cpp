#include "fem/transient/PeriodicSteadyState.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "fem/model/DofMap.hpp"
#include "fem/solvers/Errors.hpp"

namespace beamrotor {

namespace {

/// The free dofs' state (u then v) at the end of `run` (one period, or one step).
Eigen::VectorXd endState(const Model& model, const TransientOptions& run,
                         const std::vector<NodeDof>& free) {
  const TransientResult r = solveTransient(model, run);
  const int n = int(free.size());
  Eigen::VectorXd x(2 * n);
  for (int i = 0; i < n; ++i) {
    x[i] = r.histories[i].displacement.back();
    x[n + i] = r.histories[i].velocity.back();
  }
  return x;
}

/// The linear part of the affine map from a start state to the state at the end of `run`:
/// column j is the end state from a unit displacement (j < n) or velocity of one free dof under
/// the same loads (and supports), less `fromRest`, the end state from rest.
Eigen::MatrixXd linearPart(const Model& model, const TransientOptions& run,
                           const std::vector<NodeDof>& free, const Eigen::VectorXd& fromRest) {
  const int n = int(free.size());
  Eigen::MatrixXd m(2 * n, 2 * n);
  for (int j = 0; j < 2 * n; ++j) {
    TransientOptions unit = run;
    NodalField& field = j < n ? unit.initialDisplacement : unit.initialVelocity;
    field(free[j % n].node, dofIndex(free[j % n].dof)) = 1;
    m.col(j) = endState(model, unit, free) - fromRest;
  }
  return m;
}

/// Newmark's one-step map of the free dofs' state (u, v).
Eigen::MatrixXd oneStepMap(const Model& model, const TransientOptions& run,
                           const std::vector<NodeDof>& free) {
  TransientOptions step = run;
  step.endTime = run.timeStep;
  step.sampleEvery = 1;
  return linearPart(model, step, free, endState(model, step, free));
}

/// How near each free vibration is to resonance with the period T = steps dt, from the
/// eigenvalues s of the one-step map. Newmark's average acceleration rule turns an undamped
/// mode of frequency k through arg s = 2 atan(k dt / 2) per step (Newmark 1959; e.g. Hughes,
/// The Finite Element Method, 1987, section 9.3), so k = 2 tan(arg s / 2) / dt, and one period
/// takes it through steps arg s where the exact motion turns through k T. Fills the nearest
/// mode's distance, period error, frequency and harmonic into `out`.
void nearestResonance(const Eigen::MatrixXd& oneStep, int steps, double dt, PeriodicStart& out) {
  const double twoPi = 2 * std::numbers::pi;
  out.resonanceDistance = std::numeric_limits<double>::infinity();
  const Eigen::VectorXcd s = oneStep.eigenvalues();
  for (const std::complex<double>& si : s) {
    const double angle = std::abs(std::arg(si));  // per step, in [0, pi]
    const double decay = std::pow(std::abs(si), steps);
    // A step turning the state through pi stands for k dt = infinity: no frequency to compare.
    const bool oscillates = angle < std::numbers::pi - 1e-9;
    const double k = oscillates ? 2 * std::tan(angle / 2) / dt : 0;
    const double exactAngle = k * steps * dt, newmarkAngle = steps * angle;
    const double distance =
        std::min(std::abs(1.0 - std::polar(decay, newmarkAngle)),
                 oscillates ? std::abs(1.0 - std::polar(decay, exactAngle)) : 1.0);
    if (distance < out.resonanceDistance) {
      out.resonanceDistance = distance;
      out.periodError = oscillates ? std::abs(newmarkAngle - exactAngle) : 0;
      out.nearestFrequency = k;
      out.nearestHarmonic = int(std::lround(exactAngle / twoPi));
    }
  }
}

}  // namespace

PeriodicStart periodicStart(const Model& model, const TransientOptions& options, double period) {
  // 1. The scheme and the grid: whole steps per period, Newmark's state (u, v).
  if (options.scheme != TimeScheme::newmark)
    throw std::invalid_argument(
        "periodic steady state: needs the newmark scheme, whose state is u and v alone");
  const double steps = period / options.timeStep;
  if (!(std::abs(steps - std::round(steps)) <= 1e-9 * steps) || std::round(steps) < 1)
    throw std::invalid_argument("periodic steady state: the period is not a whole number of "
                                "time steps (period / dt = " + std::to_string(steps) + ")");

  // 2. One period, recording the end state of every free dof, the stops left out.
  const DofMap dofs(model);
  std::vector<NodeDof> free;
  for (int eq = 0; eq < dofs.freeCount(); ++eq) free.push_back(dofs.dofOf(eq));
  const int n = int(free.size());
  TransientOptions run = options;
  run.endTime = std::round(steps) * options.timeStep;
  run.histories = free;
  run.sampleEvery = int(std::round(steps));
  run.maxFrames = 0;
  run.energy = false;
  run.stops = false;
  run.initialDisplacement = NodalField::Zero(model.nodeCount(), kDofKinds);
  run.initialVelocity = NodalField::Zero(model.nodeCount(), kDofKinds);

  // 3. x_f: from rest under the loads.
  const Eigen::VectorXd forced = endState(model, run, free);

  // 4. Phi column by column: the map is affine, so a unit start of one free dof under the same
  //    loads (and supports) differs from x_f by that column.
  const Eigen::MatrixXd phi = linearPart(model, run, free, forced);

  // 5. Refused at or near resonance, judged by the modes' multipliers (a condition number of
  //    I - Phi cannot tell: near resonance it is a small multiple of a rotation).
  PeriodicStart out;
  out.largestMultiplier = phi.eigenvalues().cwiseAbs().maxCoeff();
  nearestResonance(oneStepMap(model, run, free), int(std::round(steps)), options.timeStep, out);
  if (!(out.resonanceDistance >= kPeriodicMinDistance) ||
      out.resonanceDistance < kPeriodicErrorMargin * out.periodError) {
    std::ostringstream msg;
    msg << "no periodic steady state: resonance, a free vibration of k = "
        << out.nearestFrequency << " rad/s against the period " << period << " s (k period = "
        << out.nearestFrequency * period << " rad, near " << out.nearestHarmonic
        << " x 2 pi; its one-period multiplier is " << out.resonanceDistance
        << " from 1";
    if (out.resonanceDistance >= kPeriodicMinDistance)
      msg << ", within " << kPeriodicErrorMargin << " times Newmark's own period error "
          << out.periodError << " rad, so the amplitude would be mostly that error";
    msg << "); add damping, move the frequency or the period, or refine dt";
    throw SolveError(msg.str());
  }

  // 6. The fixed point. Velocities are scaled by T / (2 pi) so that both halves of the state
  //    have one unit.
  const double scale = period / (2 * std::numbers::pi);
  Eigen::VectorXd d = Eigen::VectorXd::Ones(2 * n);
  d.tail(n).setConstant(scale);
  const Eigen::MatrixXd a =
      Eigen::MatrixXd::Identity(2 * n, 2 * n) - d.asDiagonal() * phi * d.cwiseInverse().asDiagonal();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
  out.rcond = lu.rcond();
  const Eigen::VectorXd x0 = d.cwiseInverse().asDiagonal() * lu.solve(d.asDiagonal() * forced);
  out.displacement = NodalField::Zero(model.nodeCount(), kDofKinds);
  out.velocity = NodalField::Zero(model.nodeCount(), kDofKinds);
  for (int i = 0; i < n; ++i) {
    out.displacement(free[i].node, dofIndex(free[i].dof)) = x0[i];
    out.velocity(free[i].node, dofIndex(free[i].dof)) = x0[n + i];
  }
  return out;
}

}  // namespace beamrotor
