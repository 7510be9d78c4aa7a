// Second-order statics: equilibrium in the deformed state, (K + KG(N(u))) u = f, with the
// axial forces N of the solution itself (P-delta along and between the elements' nodes). The
// first-order solution starts the iteration; a statically determinate axial force needs one
// more solve, an indeterminate one a few.
#pragma once

#include "fem/model/Model.hpp"
#include "fem/stability/StabilityResults.hpp"

namespace beamrotor {

struct SecondOrderOptions {
  int maxIterations = 50;
  /// Converged when the largest change of a dof over an iteration is below this fraction of
  /// the largest displacement (translations and rotations measured separately).
  double tolerance = 1e-12;
};

/// Throws SolveError, naming the lowest buckling factor, when the load is at or above the
/// critical load of its first-order state (that factor <= 1) or when the iteration does not
/// converge; SolveError for a model with contacts (not supported here); UnsupportedStructure
/// for a mechanism.
SecondOrderResult solveSecondOrder(const Model& model, const SecondOrderOptions& options = {});

}  // namespace beamrotor
