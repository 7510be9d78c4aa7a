// Detecting an insufficiently supported structure (a mechanism, a free-free body, a node whose
// rotation nothing resists) and naming the dofs that move without straining.
#pragma once

#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/Dof.hpp"

namespace beamrotor {

class Model;

/// The dofs that take part in a zero-energy mode of the free-free stiffness block Kff:
/// empty when Kff is positive definite to working precision. Found by inverse subspace
/// iteration on Kff + eps diag(Kff), which is regular even where Kff is singular.
std::vector<NodeDof> zeroEnergyDofs(const SparseMatrix& Kff, const DofMap& dofs);

/// Throws UnsupportedStructure naming the moving dofs, with advice, when there are any.
void throwUnsupported(const Model& model, const std::vector<NodeDof>& moving,
                      const std::string& context);

}  // namespace beamrotor
