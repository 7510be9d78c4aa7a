// Linear buckling: the load factors lambda for which (K + lambda KG) x = 0, KG the geometric
// stiffness of the axial forces of the model's loads (a first-order static solution, prescribed
// support displacements included).
#pragma once

#include "fem/assembly/Assembly.hpp"
#include "fem/model/Model.hpp"
#include "fem/stability/StabilityResults.hpp"

namespace beamrotor {

struct BucklingOptions {
  int count = 4;          ///< how many positive factors (the lowest)
  bool reversed = false;  ///< also as many negative ones (the load reversed)
};

/// Throws UnsupportedStructure for a mechanism, SolveError when the eigensolver fails. A
/// reference state without compression (or tension, for the reversed factors) gives no modes
/// and a warning.
BucklingResult solveBuckling(const Model& model, const BucklingOptions& options = {});

}  // namespace beamrotor

namespace beamrotor {

/// The lowest positive load factor of (K + lambda KG) x = 0 (infinity when KG compresses
/// nothing).
double lowestBucklingFactor(const SparseMatrix& K, const SparseMatrix& KG);

/// Throws SolveError naming `analysis` and the factor when the load is at or past the critical
/// one (factor <= 1, within round-off): no equilibrium about the loaded state exists there.
void requireBelowCritical(double factor, const std::string& analysis);

}  // namespace beamrotor
