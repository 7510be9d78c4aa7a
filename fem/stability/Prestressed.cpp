#include "fem/stability/Prestressed.hpp"

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "fem/stability/Buckling.hpp"
#include "fem/static/Static.hpp"

namespace beamrotor {

ModalResult solvePrestressedModes(const Model& model, const ModalOptions& options) {
  const StaticResult loaded = solveStatic(model);
  const DofMap dofs(model);
  const SparseAssembler assembler(model, dofs);
  const Eigen::VectorXd state = fromNodalField(dofs, loaded.displacement);
  requireBelowCritical(lowestBucklingFactor(assembler.assemble(MatrixKind::stiffness),
                                            assembler.assembleGeometric(state)),
                       "prestressed modal analysis");
  return solveModesAbout(model, options, state);
}

}  // namespace beamrotor
