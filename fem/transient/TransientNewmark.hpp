// Implicit time stepping: Newmark's family (Newmark 1959) in the Hilber-Hughes-Taylor form
// (Hilber, Hughes and Taylor 1977). alpha = 0 is the average acceleration rule.
//
// With the predictors
//   u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n,   v~ = v_n + dt (1 - gamma) a_n,
// and u_n+1 = u~ + beta dt^2 a_n+1, v_n+1 = v~ + gamma dt a_n+1, the HHT equation of motion
//   M a_n+1 + C [(1 + alpha) v_n+1 - alpha v_n] + K [(1 + alpha) u_n+1 - alpha u_n]
//     = f(t_n+1 + alpha dt)
// becomes one linear solve for a_n+1 with the effective matrix
//   S = M + (1 + alpha) gamma dt C + (1 + alpha) beta dt^2 K,
// which depends on dt only: factorised once, then two sparse products and one pair of
// triangular solves per step.
#pragma once

#include "fem/solvers/StepFactor.hpp"
#include "fem/transient/TransientSystem.hpp"

namespace beamrotor {

/// The constants of the rule and its predictor and corrector, shared by every implicit
/// stepper: NewmarkStepper below (matrices fixed for the run) and the run-up's
/// (fem/runup/RunUp.cpp, matrices changing with the spin speed).
struct NewmarkRule {
  /// dt in s; alpha in [-1/3, 0] (throws std::invalid_argument otherwise).
  NewmarkRule(double dt, double alpha);
  double dt, alpha, gamma, beta;

  /// u~ and v~ from the state at t_n.
  void predict(const TransientState& s, Eigen::VectorXd& u, Eigen::VectorXd& v) const;
  /// The state at t_n+1 from the predictors and the new acceleration a.
  void correct(TransientState& s, const Eigen::VectorXd& uPredicted,
               const Eigen::VectorXd& vPredicted, const Eigen::VectorXd& a) const;
};

class NewmarkStepper {
 public:
  /// dt in s; alpha in [-1/3, 0] (throws std::invalid_argument otherwise). Factorises S; throws
  /// SolveError when it is singular (e.g. a free dof with neither mass nor stiffness).
  NewmarkStepper(const TransientSystem& system, double dt, double alpha);
  NewmarkStepper(const NewmarkStepper&) = delete;  // the factor holds its matrix
  NewmarkStepper& operator=(const NewmarkStepper&) = delete;

  /// Advances s (consistent: M a + C v + K u = f at s.t) by one step dt.
  void step(TransientState& s);

  double gamma() const { return rule_.gamma; }
  double beta() const { return rule_.beta; }
  /// Fill of S's LU factors.
  double factorEntries() const { return lu_.factorEntries(); }

 private:
  const TransientSystem& system_;
  NewmarkRule rule_;
  StepFactor lu_;  ///< of the effective matrix S
  Eigen::VectorXd uPredicted_, vPredicted_, rhs_, f_;
};

}  // namespace beamrotor
