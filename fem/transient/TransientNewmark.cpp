#include "fem/transient/TransientNewmark.hpp"

#include <sstream>
#include <stdexcept>

#include "fem/solvers/Errors.hpp"

namespace beamrotor {

NewmarkStepper::NewmarkStepper(const TransientSystem& system, double dt, double alpha)
    : system_(system), dt_(dt), alpha_(alpha) {
  if (!(dt > 0)) throw std::invalid_argument("time step must be positive");
  // The HHT method is unconditionally stable and second order for alpha in [-1/3, 0].
  if (!(alpha >= -1.0 / 3.0 - 1e-15 && alpha <= 0))
    throw std::invalid_argument("HHT alpha must lie in [-1/3, 0]; got " + std::to_string(alpha));
  gamma_ = (1 - 2 * alpha) / 2;
  beta_ = (1 - alpha) * (1 - alpha) / 4;

  // Effective matrix: M, C and K share the assembler's pattern, so this is an entrywise sum.
  S_ = system.mass() + ((1 + alpha) * beta_ * dt * dt) * system.stiffness();
  if (system.damped()) S_ += ((1 + alpha) * gamma_ * dt) * system.damping();
  lu_.compute(S_);
  if (!lu_.healthy(kSingularRcond)) {
    std::ostringstream msg;
    msg << "transient analysis: the effective matrix M + gamma dt C + beta dt^2 K is singular "
           "(UMFPACK rcond = "
        << lu_.rcond()
        << "): some free dof has neither mass nor "
           "stiffness, or the structure has a massless mechanism";
    throw SolveError(msg.str());
  }
}

void NewmarkStepper::step(TransientState& s) {
  const double dt = dt_, a1 = 1 + alpha_;
  // 1. Predictors from the known state.
  uPredicted_ = s.u + dt * s.v + (dt * dt * (0.5 - beta_)) * s.a;
  vPredicted_ = s.v + (dt * (1 - gamma_)) * s.a;

  // 2. Right-hand side: the load at t_n+1 + alpha dt minus the internal and damping forces
  // of the predictor, weighted as the HHT equation weights u_n+1 and u_n.
  system_.force(s.t + dt + alpha_ * dt, f_);
  rhs_ = f_ - system_.stiffness() * (a1 * uPredicted_ - alpha_ * s.u);
  if (system_.damped()) rhs_ -= system_.damping() * (a1 * vPredicted_ - alpha_ * s.v);

  // 3. Solve for the new acceleration, correct displacement and velocity.
  s.a = lu_.solve(rhs_);
  s.u = uPredicted_ + (beta_ * dt * dt) * s.a;
  s.v = vPredicted_ + (gamma_ * dt) * s.a;
  s.t += dt;
}

}  // namespace beamrotor
