#include "problems/verify/TimeStepStudy.hpp"

#include "fem/transient/Transient.hpp"
#include "problems/verify/VerifyModels.hpp"

namespace beamrotor::verify {

namespace {

constexpr double kSteppedBeamLength = 1.5, kInitialTip = 1e-3;  // m, m

/// u = (x / L)^2 times the initial tip deflection, with its slope on rz: it holds every mode,
/// the highest included, so an unstable step shows within a few hundred steps.
NodalField parabola(const Model& m, const Line& line) {
  NodalField u = NodalField::Zero(m.nodeCount(), kDofKinds);
  for (std::size_t i = 0; i < line.nodes.size(); ++i) {
    const double s = line.stations[i] / kSteppedBeamLength;
    u(line.nodes[i], dofIndex(Dof::uy)) = kInitialTip * s * s;
    u(line.nodes[i], dofIndex(Dof::rz)) = kInitialTip * 2 * s / kSteppedBeamLength;
  }
  return u;
}

}  // namespace

std::vector<TimeStepRun> timeStepStudy(const std::vector<double>& stepFactors, int steps) {
  // 1. A cantilever of 8 Euler-Bernoulli elements, lumped mass with rotary inertia (every dof
  // has mass, as central difference needs), axial dof left out.
  Model model;
  LineSpec spec;
  spec.dofs = DofSet{Dof::uy, Dof::rz};
  spec.segments.push_back({kSteppedBeamLength,
                           steelRectangle(0.04, 0.04),
                           8,
                           0,
                           {BeamTheory::eulerBernoulli, MassModel::lumped, true}});
  spec.points = {{"start", 0}, {"end", kSteppedBeamLength}};
  const Line line = buildLine(model, spec);
  model.addSupport({"root", line.nodes.front(), {{Dof::uy, 0}, {Dof::rz, 0}}});
  const double dtCritical = centralDifferenceLimit(model).dtCritical;
  // 2. One run per step.
  std::vector<TimeStepRun> runs;
  for (double factor : stepFactors) {
    TransientOptions options;
    options.scheme = TimeScheme::centralDifference;
    options.timeStep = factor * dtCritical;
    options.endTime = steps * options.timeStep;
    options.initialDisplacement = parabola(model, line);
    options.histories = {{line.nodes.back(), Dof::uy}};
    const TransientResult r = solveTransient(model, options);
    runs.push_back({factor, dtCritical, r.times, r.histories.at(0).displacement});
  }
  return runs;
}

}  // namespace beamrotor::verify
