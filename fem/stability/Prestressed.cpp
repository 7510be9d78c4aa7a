#include "fem/stability/Prestressed.hpp"

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "fem/assembly/RigidTies.hpp"
#include "fem/stability/Buckling.hpp"
#include "fem/static/Static.hpp"

namespace beamrotor {

ModalResult solvePrestressedModes(const Model& model, const ModalOptions& options) {
  const StaticResult loaded = solveStatic(model);
  const DofMap dofs(model);
  const SparseAssembler assembler(model, dofs);
  const TieReduction ties(model, dofs);
  const Eigen::VectorXd state = fromNodalField(dofs, loaded.displacement);
  requireBelowCritical(lowestBucklingFactor(ties.stiffness(assembler.assemble(MatrixKind::stiffness)),
                                            ties.geometric(assembler.assembleGeometric(state),
                                                           stateResidual(model, dofs, state))),
                       "prestressed modal analysis");
  return solveModesAbout(model, options, state);
}

}  // namespace beamrotor
