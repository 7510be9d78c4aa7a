// The run-up driver: the rotor's matrices at each step's speed, the HHT step on them, and the
// histories, per-revolution amplitudes and energy account kept while stepping.
#include "fem/runup/RunUp.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>
#include <stdexcept>

#include "fem/rotor/DynamicStiffness.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/RotorFactor.hpp"
#include "fem/timing/Stopwatch.hpp"
#include "fem/transient/TransientNewmark.hpp"

namespace beamrotor {

namespace {

/// The equations of motion at one instant: the matrices at its speed and acceleration, and
/// the load at its angle.
struct Instant {
  double t = 0, speed = 0, acceleration = 0, angle = 0;
  SparseMatrix K;  ///< K(Omega) (the bearings' and internal damping's at that speed)
  SparseMatrix C;  ///< C(Omega)
  Eigen::VectorXd f;
};

class RunUpSystem {
 public:
  RunUpSystem(const Model& model, const SpeedProfile& profile, const RunUpOptions& o)
      : rotor_(model, o.damping), profile_(profile) {
    unbalance_ = unbalanceForces(rotor_, o.unbalance);
    // The weight as GravityLoads takes it: f = M a with a = g on every translation.
    const DofMap& dofs = rotor_.dofs();
    Eigen::VectorXd a = Eigen::VectorXd::Zero(rotor_.size());
    for (int eq = 0; eq < rotor_.size(); ++eq) {
      const Dof d = dofs.dofOf(eq).dof;
      if (d == Dof::ux || d == Dof::uy || d == Dof::uz) a[eq] = o.gravity[dofIndex(d)];
    }
    weight_ = rotor_.mass() * a;
  }

  const RotorSystem& rotor() const { return rotor_; }
  const Eigen::VectorXd& weight() const { return weight_; }
  const Eigen::VectorXcd& unbalance() const { return unbalance_; }

  Instant at(double t) const {
    Instant i;
    i.t = t;
    i.speed = profile_.speed(t);
    i.acceleration = profile_.acceleration(t);
    i.angle = profile_.angle(t);
    i.K = rotor_.stiffness(i.speed);
    i.C = rotor_.damping(i.speed);
    // Re(f e^{i phi} (Omega^2 - i Omega')): see unbalanceForces.
    const std::complex<double> turn =
        std::polar(1.0, i.angle) * std::complex<double>(i.speed * i.speed, -i.acceleration);
    i.f = weight_ + (unbalance_ * turn).real();
    return i;
  }

  /// Omega G q' + Omega' G q: the gyroscopic and angular-acceleration forces.
  Eigen::VectorXd gyroscopicForce(const Instant& i, const TransientState& s) const {
    return rotor_.gyroscopic() * (i.speed * s.v + i.acceleration * s.u);
  }

 private:
  RotorSystem rotor_;
  const SpeedProfile& profile_;
  Eigen::VectorXcd unbalance_;
  Eigen::VectorXd weight_;
};

/// The initial state (RunUpStart): the static deflection under gravity at the start speed,
/// plus on request the steady unbalance orbit there, its acceleration from the equation of
/// motion.
TransientState initialState(const RunUpSystem& system, const Instant& start, RunUpStart how,
                            RepeatedFactor<double>& factor) {
  const int n = system.rotor().size();
  TransientState s;
  s.u = Eigen::VectorXd::Zero(n);
  s.v = Eigen::VectorXd::Zero(n);
  if (system.weight().squaredNorm() > 0) {
    if (!factor.factorize(start.K))
      throw SolveError(
          "run-up: the rotor has no static equilibrium under gravity at the start speed (its "
          "stiffness is singular: a rigid-body motion the bearings do not hold)");
    s.u = factor.solve(system.weight());
  }
  if (how == RunUpStart::steady && start.speed > 0 && system.unbalance().squaredNorm() > 0) {
    using Complex = std::complex<double>;
    const double w = start.speed;
    const RotorSystem& r = system.rotor();
    RepeatedFactor<Complex> dynamic;
    const ComplexSparseMatrix Z =
        start.K.cast<Complex>() - (w * w) * r.mass().cast<Complex>() +
        Complex(0, w) * (start.C + w * r.gyroscopic()).cast<Complex>();
    factorizeDynamicStiffness(dynamic, Z, w, "run-up's steady start", "the start speed");
    const Eigen::VectorXcd q = dynamic.solve(Eigen::VectorXcd((w * w) * system.unbalance()));
    const Eigen::VectorXcd turn = q * std::polar(1.0, start.angle);
    s.u += turn.real();
    s.v += (turn * Complex(0, w)).real();
  }
  // M a = f - C v - K u - Omega G v - Omega' G u (massless dofs at a = 0: the first step's
  // solve puts them in equilibrium).
  s.a = accelerationOf(system.rotor().mass(),
                       start.f - start.C * s.v - start.K * s.u - system.gyroscopicForce(start, s),
                       "run-up");
  return s;
}

/// Keeps the energy account step by step (RunUpEnergy), trapezoidal in the increments.
class EnergyAccount {
 public:
  EnergyAccount(const RunUpSystem& system, const Instant& i, const TransientState& s)
      : system_(system) {
    measure(i, s);
  }

  void advance(const Instant& i, const TransientState& s) {
    const Eigen::VectorXd du = s.u - u_;
    const Eigen::VectorXd f0 = f_, c0 = Cv_, g0 = gyro_;
    measure(i, s);
    work_ += du.dot(f0 + f_) / 2;
    dissipated_ += du.dot(c0 + Cv_) / 2;
    gyroscopic_ += du.dot(g0 + gyro_) / 2;
  }

  void record(RunUpEnergy& e) const {
    e.kinetic.push_back(kinetic_);
    e.strain.push_back(strain_);
    e.dissipated.push_back(dissipated_);
    e.work.push_back(work_);
    e.gyroscopic.push_back(gyroscopic_);
  }

 private:
  void measure(const Instant& i, const TransientState& s) {
    u_ = s.u;
    f_ = i.f;
    Cv_ = i.C * s.v;
    gyro_ = system_.gyroscopicForce(i, s);
    kinetic_ = 0.5 * s.v.dot(system_.rotor().mass() * s.v);
    strain_ = 0.5 * s.u.dot(i.K * s.u);
  }

  const RunUpSystem& system_;
  Eigen::VectorXd u_, f_, Cv_, gyro_;
  double kinetic_ = 0, strain_ = 0, work_ = 0, dissipated_ = 0, gyroscopic_ = 0;
};

/// The free equations of uy and uz at `node`; throws when either is not free.
std::pair<int, int> lateralEquations(const RotorSystem& rotor, int node) {
  const DofMap& dofs = rotor.dofs();
  if (node < 0 || node >= rotor.model().nodeCount())
    throw std::invalid_argument("run-up: no node " + std::to_string(node) + " to record");
  const int y = dofs.equation(node, Dof::uy), z = dofs.equation(node, Dof::uz);
  if (!dofs.isFree(y) || !dofs.isFree(z))
    throw std::invalid_argument("run-up: a recorded node needs free uy and uz, not " +
                                rotor.model().describe({node, Dof::uy}));
  return {y, z};
}

}  // namespace

RunUpResult solveRunUp(const Model& model, const SpeedProfile& profile,
                       const RunUpOptions& o) {
  Stopwatch clock, total;
  const NewmarkRule rule(o.timeStep, o.hhtAlpha);
  if (o.sampleEvery < 1) throw std::invalid_argument("run-up: sampleEvery must be at least 1");
  const RunUpSystem system(model, profile, o);
  const RotorSystem& rotor = system.rotor();
  std::vector<std::pair<int, int>> recorded;
  for (int node : o.nodes) recorded.push_back(lateralEquations(rotor, node));

  RunUpResult out;
  out.timeStep = o.timeStep;
  out.steps = std::max(1, int(std::lround(profile.duration() / o.timeStep)));
  out.histories.resize(o.nodes.size());
  std::vector<RevolutionAmplitude> trackers(o.nodes.size());
  for (std::size_t k = 0; k < o.nodes.size(); ++k) out.histories[k].node = o.nodes[k];

  RepeatedFactor<double> factor;
  Instant now = system.at(0);
  TransientState s = initialState(system, now, o.start, factor);
  EnergyAccount energy(system, now, s);
  out.time.assembly = clock.lap();

  const auto sample = [&](bool keep) {
    for (std::size_t k = 0; k < recorded.size(); ++k) {
      const double y = s.u[recorded[k].first], z = s.u[recorded[k].second];
      trackers[k].add(now.t, now.angle, now.speed, y, z);
      if (!keep) continue;
      out.histories[k].uy.push_back(y);
      out.histories[k].uz.push_back(z);
    }
    if (!keep) return;
    out.times.push_back(now.t);
    out.speed.push_back(now.speed);
    out.angle.push_back(now.angle);
    energy.record(out.energy);
  };
  sample(true);

  // HHT with matrices that change in time (alpha = 0: the average acceleration rule):
  //   M a_n+1 + (1 + alpha) r_n+1 - alpha r_n = (1 + alpha) f_n+1 - alpha f_n,
  // r = (C + Omega G) v + (K + Omega' G) u, one solve for a_n+1 with the effective matrix
  //   S = M + (1 + alpha) [gamma dt (C + Omega G) + beta dt^2 (K + Omega' G)] at t_n+1.
  const double a1 = 1 + rule.alpha, dt = rule.dt;
  Eigen::VectorXd uPredicted, vPredicted;
  Eigen::VectorXd residual = now.f - now.C * s.v - now.K * s.u - system.gyroscopicForce(now, s);
  for (int step = 1; step <= out.steps; ++step) {
    Instant next = system.at(step * dt);
    const SparseMatrix damping = next.C + next.speed * rotor.gyroscopic();
    const SparseMatrix stiffness = next.K + next.acceleration * rotor.gyroscopic();
    const SparseMatrix S =
        rotor.mass() + (a1 * rule.gamma * dt) * damping + (a1 * rule.beta * dt * dt) * stiffness;
    out.time.assembly += clock.lap();
    if (!factor.factorize(S)) {
      std::ostringstream msg;
      msg << "run-up: the effective matrix M + gamma dt C + beta dt^2 K is singular at t = "
          << next.t << " s (UMFPACK rcond = " << factor.rcond()
          << "): some free dof has neither mass nor stiffness";
      throw SolveError(msg.str());
    }
    out.time.factor += clock.lap();
    rule.predict(s, uPredicted, vPredicted);
    const Eigen::VectorXd rhs =
        a1 * (next.f - damping * vPredicted - stiffness * uPredicted) - rule.alpha * residual;
    rule.correct(s, uPredicted, vPredicted, factor.solve(rhs));
    s.t = next.t;  // the step's own time, free of the sum's round-off
    residual = next.f - damping * s.v - stiffness * s.u;
    now = std::move(next);
    energy.advance(now, s);
    sample(step % o.sampleEvery == 0 || step == out.steps);
    out.time.solve += clock.lap();
  }

  for (std::size_t k = 0; k < recorded.size(); ++k) {
    RunUpHistory& h = out.histories[k];
    h.revolutions = trackers[k].amplitudes();
    const auto& amp = h.revolutions.amplitude;
    if (amp.empty()) continue;
    const std::size_t peak = std::size_t(std::max_element(amp.begin(), amp.end()) - amp.begin());
    h.peakAmplitude = amp[peak];
    h.speedAtPeak = h.revolutions.speed[peak];
    h.timeAtPeak = h.revolutions.time[peak];
  }
  out.factorizations = factor.factorizations();
  out.size = rotor.systemSize(factor.factorEntries());
  out.time.total = total.lap();
  return out;
}

}  // namespace beamrotor
