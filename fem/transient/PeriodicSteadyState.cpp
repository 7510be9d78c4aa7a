#include "fem/transient/PeriodicSteadyState.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "fem/model/DofMap.hpp"
#include "fem/solvers/Errors.hpp"

namespace beamrotor {

namespace {

/// The free dofs' state (u then v) after one period of `run`'s options from the given start.
Eigen::VectorXd stateAfterPeriod(const Model& model, const TransientOptions& run,
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
  const Eigen::VectorXd forced = stateAfterPeriod(model, run, free);

  // 4. Phi column by column: the map is affine, so a unit start of one free dof under the same
  //    loads (and supports) differs from x_f by that column.
  Eigen::MatrixXd phi(2 * n, 2 * n);
  for (int j = 0; j < 2 * n; ++j) {
    TransientOptions unit = run;
    NodalField& field = j < n ? unit.initialDisplacement : unit.initialVelocity;
    field(free[j % n].node, dofIndex(free[j % n].dof)) = 1;
    phi.col(j) = stateAfterPeriod(model, unit, free) - forced;
  }

  // 5. The fixed point, refused near resonance. Velocities are scaled by T / (2 pi) so that
  //    both halves of the state have one unit: then an undamped mode with k T near n 2 pi
  //    makes I - Phi a rotation by its angle from n 2 pi, and rcond is that angle.
  const double scale = period / (2 * std::numbers::pi);
  Eigen::VectorXd d = Eigen::VectorXd::Ones(2 * n);
  d.tail(n).setConstant(scale);
  const Eigen::MatrixXd a =
      Eigen::MatrixXd::Identity(2 * n, 2 * n) - d.asDiagonal() * phi * d.cwiseInverse().asDiagonal();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
  PeriodicStart out;
  out.rcond = lu.rcond();
  out.largestMultiplier = phi.eigenvalues().cwiseAbs().maxCoeff();
  if (!(out.rcond >= kPeriodicMinRcond)) {
    std::ostringstream msg;
    msg << "no periodic steady state: the one-period map has a multiplier at 1 (rcond of "
           "I - Phi = "
        << out.rcond << "), i.e. resonance: a free vibration completes a whole number of "
        << "cycles in the period " << period << " s (natural frequency k = n 2 pi / T); add "
        << "damping or move the frequency";
    throw SolveError(msg.str());
  }
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
