#include "fem/static/Static.hpp"

#include <stdexcept>

#include "fem/assembly/Recovery.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "fem/static/ActiveSet.hpp"
#include "fem/static/LinearStatics.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

namespace {

/// Reactions (what each support exerts: K u - f at its dofs), the nodal field, hinge rotations
/// and the solve's diagnostics of displacement u of `loaded` under `loading` (null: its own
/// loads), solved by `system`, whose matrices are freed first when `lastSolve`.
void recover(const Model& loaded, const Loading* loading, LinearStatics& system,
             const Eigen::VectorXd& u, StaticResult& result, bool lastSolve) {
  if (lastSolve) system.releaseMatrices();
  const DofMap& dofs = system.dofs();
  const Eigen::VectorXd r = system.reactions(u);
  for (const Support& s : loaded.supports())
    for (const PrescribedDof& p : s.dofs)
      result.reactions.push_back(
          {s.name, s.node, p.dof, r[dofs.equation(s.node, p.dof) - dofs.freeCount()]});
  result.displacement = toNodalField(loaded, dofs, u);
  result.hinges = hingeRotations({loaded, result.displacement, loading});
  result.elementForces = namedElementForces(loaded, result.displacement);
  result.rcond = system.rcond();
  result.roundOff = system.roundOff();
  result.solver = system.solverName();
  result.size = systemSize(loaded, dofs, system.stiffnessEntries(), system.factorEntries());
}

}  // namespace

StaticResult solveStatic(const Model& model, const StaticOptions& options) {
  Stopwatch clock, total;
  StaticResult result;

  // 1. Number the dofs, assemble K and the reduced right-hand side.
  LinearStatics system(model, options.reuse);
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

  // 3. Recover reactions and the nodal field.
  recover(model, nullptr, system, u, result, true);
  result.time.total = total.lap();
  return result;
}

std::vector<StaticResult> solveLoadings(const Model& model,
                                        const std::vector<const Loading*>& loadings,
                                        const StaticOptions& options) {
  std::vector<StaticResult> results;
  if (loadings.empty()) return results;
  if (!model.contacts().empty())
    throw std::invalid_argument("solveLoadings: contacts are not linear in the loads");
  Stopwatch clock;
  LinearStatics system(model, options.reuse);
  const double assembly = clock.lap();
  for (std::size_t k = 0; k < loadings.size(); ++k) {
    Stopwatch total;
    StaticResult result;
    const double factorBefore = system.factorSeconds(), solveBefore = system.solveSeconds();
    system.setLoads(loadings[k]);
    const Eigen::VectorXd u = system.solve({}, options.singularRcond);
    result.activeSetIterations = 1;
    result.time.factor = system.factorSeconds() - factorBefore;
    result.time.solve = system.solveSeconds() - solveBefore;
    recover(model, loadings[k], system, u, result, k + 1 == loadings.size());
    result.time.assembly = results.empty() ? assembly : 0;
    result.time.total = total.lap() + result.time.assembly;
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace beamrotor
