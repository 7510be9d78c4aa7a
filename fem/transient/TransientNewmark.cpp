#include "fem/transient/TransientNewmark.hpp"

#include <sstream>
#include <stdexcept>

#include "fem/solvers/Errors.hpp"

namespace beamrotor {

NewmarkRule::NewmarkRule(double step, double a) : dt(step), alpha(a) {
  if (!(dt > 0)) throw std::invalid_argument("time step must be positive");
  // The HHT method is unconditionally stable and second order for alpha in [-1/3, 0].
  if (!(alpha >= -1.0 / 3.0 - 1e-15 && alpha <= 0))
    throw std::invalid_argument("HHT alpha must lie in [-1/3, 0]; got " + std::to_string(alpha));
  gamma = (1 - 2 * alpha) / 2;
  beta = (1 - alpha) * (1 - alpha) / 4;
}

void NewmarkRule::predict(const TransientState& s, Eigen::VectorXd& u, Eigen::VectorXd& v) const {
  u = s.u + dt * s.v + (dt * dt * (0.5 - beta)) * s.a;
  v = s.v + (dt * (1 - gamma)) * s.a;
}

void NewmarkRule::correct(TransientState& s, const Eigen::VectorXd& uPredicted,
                          const Eigen::VectorXd& vPredicted, const Eigen::VectorXd& a) const {
  s.a = a;
  s.u = uPredicted + (beta * dt * dt) * a;
  s.v = vPredicted + (gamma * dt) * a;
  s.t += dt;
}

NewmarkStepper::NewmarkStepper(const TransientSystem& system, double dt, double alpha)
    : system_(system), rule_(dt, alpha) {
  const double gamma = rule_.gamma, beta = rule_.beta;

  // Effective matrix: M, C and K share the assembler's pattern, so this is an entrywise sum.
  SparseMatrix S = system.mass() + ((1 + alpha) * beta * dt * dt) * system.stiffness();
  if (system.damped()) S += ((1 + alpha) * gamma * dt) * system.damping();
  lu_.compute(S);
  if (!lu_.healthy(kSingularRcond)) {
    std::ostringstream msg;
    msg << "transient analysis: the effective matrix M + gamma dt C + beta dt^2 K is singular "
           "(rcond = "
        << lu_.rcond()
        << "): some free dof has neither mass nor "
           "stiffness, or the structure has a massless mechanism";
    throw SolveError(msg.str());
  }
}

void NewmarkStepper::step(TransientState& s) {
  const double dt = rule_.dt, alpha = rule_.alpha, a1 = 1 + alpha;
  // 1. Predictors from the known state.
  rule_.predict(s, uPredicted_, vPredicted_);

  // 2. Right-hand side: the load at t_n+1 + alpha dt minus the internal and damping forces
  // of the predictor, weighted as the HHT equation weights u_n+1 and u_n.
  system_.force(s.t + dt + alpha * dt, f_);
  rhs_ = f_ - system_.stiffness() * (a1 * uPredicted_ - alpha * s.u);
  if (system_.damped()) rhs_ -= system_.damping() * (a1 * vPredicted_ - alpha * s.v);

  // 3. Solve for the new acceleration, correct displacement and velocity.
  rule_.correct(s, uPredicted_, vPredicted_, lu_.solve(rhs_));
}

}  // namespace beamrotor
