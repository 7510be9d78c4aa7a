// Linear statics: K u = f with supports eliminated (prescribed values moved to the right-hand
// side), solved by UMFPACK; reactions recovered at every constrained dof.
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "fem/solvers/Tolerances.hpp"

namespace beamrotor {

class SymbolicReuse;

struct StaticOptions {
  /// Reject the solve when UMFPACK's rcond falls below this (see kSingularRcond).
  double singularRcond = kSingularRcond;
  /// When set, K's symbolic analysis is taken from (and left in) this object: systems of one
  /// pattern solved one after another (a design study's points) analyse it once.
  SymbolicReuse* reuse = nullptr;
};

/// Solves model's statics. Throws UnsupportedStructure naming the dofs that can move freely,
/// or SolveError for a system that is singular for another reason.
StaticResult solveStatic(const Model& model, const StaticOptions& options = {});

/// Solves the statics of models that differ only in their loads (load cases: same nodes,
/// elements, supports and stiffness) with one factorisation of K: the first model's, the
/// others as further right-hand sides. No contacts (they are not linear in the loads).
/// Throws as solveStatic does, std::invalid_argument for models whose structure differs.
std::vector<StaticResult> solveStaticCases(const std::vector<const Model*>& loadings,
                                           const StaticOptions& options = {});

}  // namespace beamrotor
