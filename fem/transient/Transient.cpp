// The transient driver: builds the system, starts the chosen scheme from a consistent initial
// state, and records histories, the energy account and frames while stepping.
#include "fem/transient/Transient.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "fem/assembly/ReducedSystem.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/timing/Stopwatch.hpp"
#include "fem/transient/TransientCentral.hpp"
#include "fem/transient/TransientNewmark.hpp"
#include "fem/transient/TransientStops.hpp"
#include "fem/transient/TransientSystem.hpp"

namespace beamrotor {

namespace {

/// Keeps the energy account step by step (see EnergyHistory for the increments).
class EnergyAccount {
 public:
  EnergyAccount(const TransientSystem& system, const TransientState& s) : system_(system) {
    measure(s);
  }

  /// Adds the step from the previous state to s.
  void advance(const TransientState& s) {
    du_ = s.u - u_;
    f_.swap(fPrevious_);
    Cv_.swap(CvPrevious_);
    measure(s);
    external_ += du_.dot(fPrevious_ + f_) / 2;
    if (system_.damped()) damping_ += du_.dot(CvPrevious_ + Cv_) / 2;
  }

  void record(EnergyHistory& h) const {
    h.kinetic.push_back(kinetic_);
    h.strain.push_back(strain_);
    h.damping.push_back(damping_);
    h.external.push_back(external_);
  }

 private:
  void measure(const TransientState& s) {
    u_ = s.u;
    system_.force(s.t, f_);
    // The products into kept vectors: no allocation a step (the same operations).
    product_.noalias() = system_.mass() * s.v;
    kinetic_ = 0.5 * s.v.dot(product_);
    product_.noalias() = system_.stiffness() * s.u;
    strain_ = 0.5 * s.u.dot(product_);
    if (system_.damped()) Cv_.noalias() = system_.damping() * s.v;
  }

  const TransientSystem& system_;
  Eigen::VectorXd u_, du_, f_, fPrevious_, Cv_, CvPrevious_, product_;
  double kinetic_ = 0, strain_ = 0, damping_ = 0, external_ = 0;

 public:
  /// Whether every term of the account is a finite number.
  bool finite() const {
    return std::isfinite(kinetic_) && std::isfinite(strain_) && std::isfinite(damping_) &&
           std::isfinite(external_);
  }
};

/// What part of the state after a step is not finite (nullptr when all is).
const char* nonFinite(const TransientState& s, const EnergyAccount* energy) {
  if (!s.u.allFinite()) return "displacement";
  if (!s.v.allFinite()) return "velocity";
  if (!s.a.allFinite()) return "acceleration";
  if (energy && !energy->finite()) return "energy";
  return nullptr;
}

std::string shortTime(double t) {
  std::ostringstream s;
  s << t;
  return s.str();
}

/// The steps at which frames are stored: evenly spaced over [0, steps], at most `count`.
std::vector<int> frameSteps(int steps, int count) {
  std::vector<int> out;
  if (count <= 0) return out;
  if (count == 1) return {steps};
  for (int j = 0; j < count; ++j) out.push_back(int(std::llround(double(j) * steps / (count - 1))));
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string schemeName(TimeScheme s) {
  switch (s) {
    case TimeScheme::newmark:
      return "newmark";
    case TimeScheme::hht:
      return "hht";
    case TimeScheme::centralDifference:
      return "central-difference";
  }
  return "?";
}

}  // namespace

TransientResult solveTransient(const Model& model, const TransientOptions& options) {
  Stopwatch clock, total;
  TransientResult result;
  result.scheme = schemeName(options.scheme);

  // 1. Check the options that need no model.
  const double dt = options.timeStep;
  if (!(dt > 0) || !std::isfinite(dt))
    throw std::invalid_argument("transient analysis: the time step must be positive");
  if (!(options.endTime > 0) || !std::isfinite(options.endTime))
    throw std::invalid_argument("transient analysis: the end time must be positive");
  const double stepCount = std::round(options.endTime / dt);
  if (stepCount < 1 || stepCount > 1e9)
    throw std::invalid_argument("transient analysis: end time / time step gives " +
                                std::to_string(stepCount) + " steps");
  const int steps = int(stepCount);
  const int every = std::max(1, options.sampleEvery);
  result.timeStep = dt;
  result.steps = steps;

  // 2. The system, the recorded dofs and the initial state (at rest by default).
  const TransientSystem system(model, options);
  const TransientStops stops(system, options.restitution);
  const bool useStops = options.stops && !stops.empty();
  const DofMap& dofs = system.dofs();
  if (system.size() == 0)
    throw std::invalid_argument("transient analysis: the model has no free dof to move");
  std::vector<int> historyEq;
  for (const NodeDof& d : options.histories) {
    const int eq = d.node >= 0 && d.node < model.nodeCount() ? dofs.equation(d) : -1;
    if (eq < 0)
      throw std::invalid_argument("transient analysis: a history is requested at " +
                                  model.describe(d) + ", which no element carries");
    historyEq.push_back(eq);
    result.histories.push_back({d, {}, {}, {}});
  }
  TransientState s;
  s.u = system.freeVector(options.initialDisplacement, "initial displacement");
  s.v = system.freeVector(options.initialVelocity, "initial velocity");
  s.a = system.initialAcceleration(s);
  if (options.stops) stops.requireWithin(s);
  result.time.assembly = clock.lap();

  // 3. The scheme: an implicit stepper factorises once here, the explicit one checks its limit.
  std::function<void(TransientState&)> advance;
  std::unique_ptr<NewmarkStepper> implicit;
  std::unique_ptr<CentralDifferenceStepper> explicitStepper;
  double factorEntries = 0;
  if (options.scheme == TimeScheme::centralDifference) {
    explicitStepper = std::make_unique<CentralDifferenceStepper>(system, dt);
    result.stability = criticalTimeStep(system.stiffness(), explicitStepper->mass());
    if (dt > result.stability.dtCritical) {
      std::ostringstream msg;
      msg << "central difference: the time step " << dt << " s exceeds the critical step "
          << "2/omega_max = " << result.stability.dtCritical
          << " s (omega_max = " << result.stability.omegaMax
          << " rad/s); the solution will grow without bound";
      result.warnings.push_back(msg.str());
    }
    explicitStepper->start(s);
    advance = [&](TransientState& st) { explicitStepper->step(st); };
  } else {
    const double alpha = options.scheme == TimeScheme::hht ? options.hhtAlpha : 0.0;
    implicit = std::make_unique<NewmarkStepper>(system, dt, alpha);
    result.factorizations = 1;
    factorEntries = implicit->factorEntries();
    advance = [&](TransientState& st) { implicit->step(st); };
  }
  result.size = systemSize(model, dofs, system.stiffness().nonZeros(), factorEntries);
  result.time.factor = clock.lap();

  // 4. Step, recording every `every` steps, the frames on their own schedule.
  std::optional<EnergyAccount> energy;
  if (options.energy) energy.emplace(system, s);
  const std::vector<int> frames = frameSteps(steps, options.maxFrames);
  auto nextFrame = frames.begin();
  auto record = [&](int n) {
    if (nextFrame != frames.end() && *nextFrame == n) {
      result.frames.push_back({s.t, system.nodalField(s.u, s.t)});
      ++nextFrame;
    }
    if (n % every != 0 && n != steps) return;
    result.times.push_back(s.t);
    for (std::size_t h = 0; h < historyEq.size(); ++h) {
      const int eq = historyEq[h];
      DofHistory& out = result.histories[h];
      const bool free = dofs.isFree(eq);
      out.displacement.push_back(free ? s.u[eq] : system.supportValue(eq, s.t, 0));
      out.velocity.push_back(free ? s.v[eq] : system.supportValue(eq, s.t, 1));
      out.acceleration.push_back(free ? s.a[eq] : system.supportValue(eq, s.t, 2));
    }
    if (energy) energy->record(result.energy);
  };
  // The samples' count is known: room for all of them at once, not by repeated doubling (up
  // to 2^20 samples, 8 MiB a series: a run that stops early reserves no more than that).
  const std::size_t samples = std::min<std::size_t>(std::size_t(steps / every) + 2, 1 << 20);
  result.times.reserve(samples);
  for (DofHistory& h : result.histories)
    for (auto* v : {&h.displacement, &h.velocity, &h.acceleration}) v->reserve(samples);
  if (energy)
    for (auto* v : {&result.energy.kinetic, &result.energy.strain, &result.energy.damping,
                    &result.energy.external})
      v->reserve(samples);
  record(0);
  Eigen::VectorXd uBefore, vBefore;
  for (int n = 1; n <= steps; ++n) {
    if (useStops) {
      uBefore = s.u;
      vBefore = s.v;
    }
    advance(s);
    s.t = n * dt;  // no drift from summing dt
    if (useStops && stops.apply(uBefore, vBefore, dt, s, result.impacts)) {
      s.a = system.initialAcceleration(s);
      if (explicitStepper) explicitStepper->start(s);
    }
    if (energy) energy->advance(s);
    if (const char* what = nonFinite(s, energy ? &*energy : nullptr))
      throw SolveError("the " + std::string(what) + " overflowed at step " + std::to_string(n) +
                       " (t = " + shortTime(s.t) +
                       " s): the loads, initial conditions or properties are too large for "
                       "finite numbers (or the step is unstable)");
    record(n);
  }
  result.time.solve = clock.lap();
  result.time.total = total.lap();
  return result;
}

StabilityLimit centralDifferenceLimit(const Model& model) {
  const DofMap dofs(model);
  const SparseAssembler assembler(model, dofs);
  const SparseMatrix M = assembler.assemble(MatrixKind::mass);
  return criticalTimeStep(assembler.assemble(MatrixKind::stiffness),
                          lumpedMassDiagonal(M, model, dofs));
}

}  // namespace beamrotor
