// Linear statics: K u = f with supports eliminated (prescribed values moved to the right-hand
// side), solved by UMFPACK; reactions recovered at every constrained dof.
#pragma once

#include <vector>

#include "fem/model/Loading.hpp"
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

/// Solves model's statics under each of `loadings` (load cases on the one model, each in
/// place of the model's own loads, Loading.hpp; null: the model's own loads) with one
/// factorisation of K: each loading is one more right-hand side. The results hold plain values
/// (nothing refers to the loadings). No contacts (they are not linear in the loads):
/// std::invalid_argument. Throws as solveStatic does.
std::vector<StaticResult> solveLoadings(const Model& model,
                                        const std::vector<const Loading*>& loadings,
                                        const StaticOptions& options = {});

}  // namespace beamrotor
