#include "fem/Static.hpp"

#include <cmath>
#include <sstream>

#include "fem/Assembly.hpp"
#include "fem/Errors.hpp"
#include "fem/ReducedSystem.hpp"
#include "fem/SparseLU.hpp"
#include "fem/Stopwatch.hpp"
#include "fem/SupportCheck.hpp"

namespace beamrotor {

StaticResult solveStatic(const Model& model, const StaticOptions& options) {
  Stopwatch clock, total;
  StaticResult result;

  // 1. Number the dofs and assemble the free-free stiffness and the reduced right-hand side.
  const DofMap dofs(model);
  const SparseAssembler assembler(model, dofs);
  const SparseMatrix K = assembler.assemble(MatrixKind::stiffness);
  const Eigen::VectorXd f = loadVector(model, dofs);
  Eigen::VectorXd u = prescribedValues(model, dofs);
  const Eigen::VectorXd rhs = reducedRightHandSide(model, dofs, f, u);
  result.time.assembly = clock.lap();

  // 2. Factorise; a singular matrix means a mechanism: name its dofs instead of solving.
  const int nf = dofs.freeCount();
  if (nf > 0) {
    SparseLU lu;
    lu.compute(K);
    result.rcond = lu.rcond();
    result.size.factorEntries = lu.factorEntries();
    if (!lu.healthy(options.singularRcond)) {
      const auto moving = zeroEnergyDofs(K, dofs);
      if (!moving.empty()) throwUnsupported(model, moving, "static analysis");
      std::ostringstream msg;
      msg << "static analysis: the stiffness matrix is singular to working precision (UMFPACK "
             "rcond = " << lu.rcond() << "); look for extremely stiff springs next to soft "
             "members, or a mesh refined far past what double precision resolves";
      throw SolveError(msg.str());
    }
    result.time.factor = clock.lap();
    u.head(nf) = lu.solve(rhs);
    if (!u.allFinite()) throw SolveError("static analysis: the solution is not finite");
    result.time.solve = clock.lap();
  }

  // 3. Recover reactions (element forces minus applied loads at constrained dofs).
  const Eigen::VectorXd r = elementForces(model, dofs, u) - f;
  for (const Support& s : model.supports())
    for (const PrescribedDof& p : s.dofs)
      result.reactions.push_back({s.name, s.node, p.dof, r[dofs.equation(s.node, p.dof)]});
  result.displacement = toNodalField(model, dofs, u);
  result.size = systemSize(model, dofs, K, result.size.factorEntries);
  result.time.total = total.lap();
  return result;
}

}  // namespace beamrotor
