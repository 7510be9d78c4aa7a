#include "fem/static/Static.hpp"

#include "fem/assembly/Recovery.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "fem/static/ActiveSet.hpp"
#include "fem/static/LinearStatics.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

StaticResult solveStatic(const Model& model, const StaticOptions& options) {
  Stopwatch clock, total;
  StaticResult result;

  // 1. Number the dofs, assemble K and the reduced right-hand side.
  LinearStatics system(model);
  result.time.assembly = clock.lap();

  // 2. Solve: once, or until the contact set settles.
  Eigen::VectorXd u;
  if (model.contacts().empty()) {
    u = system.solve({}, options.singularRcond);
    result.activeSetIterations = 1;
  } else {
    ActiveSetSolution s = solveWithContacts(model, system, options.singularRcond);
    u = std::move(s.displacement);
    result.contacts = std::move(s.contacts);
    result.activeSetIterations = s.iterations;
  }
  result.time.factor = system.factorSeconds();
  result.time.solve = system.solveSeconds();

  // 3. Recover reactions: what each support exerts, K u - f at its dofs.
  const DofMap& dofs = system.dofs();
  const Eigen::VectorXd r = system.residual(u, /*constrainedOnly=*/true);
  for (const Support& s : model.supports())
    for (const PrescribedDof& p : s.dofs)
      result.reactions.push_back({s.name, s.node, p.dof, r[dofs.equation(s.node, p.dof)]});
  result.displacement = toNodalField(model, dofs, u);
  result.hinges = hingeRotations(model, result.displacement);
  result.rcond = system.rcond();
  result.roundOff = system.roundOff();
  result.solver = system.solverName();
  result.size = systemSize(model, dofs, system.stiffness(), system.factorEntries());
  result.time.total = total.lap();
  return result;
}

}  // namespace beamrotor
