// Linear statics: K u = f with supports eliminated (prescribed values moved to the right-hand
// side), solved by UMFPACK; reactions recovered at every constrained dof.
#pragma once

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "fem/solvers/Tolerances.hpp"

namespace beamrotor {

struct StaticOptions {
  /// Reject the solve when UMFPACK's rcond falls below this (see kSingularRcond).
  double singularRcond = kSingularRcond;
};

/// Solves model's statics. Throws UnsupportedStructure naming the dofs that can move freely,
/// or SolveError for a system that is singular for another reason.
StaticResult solveStatic(const Model& model, const StaticOptions& options = {});

}  // namespace beamrotor
