#include "fem/stability/Buckling.hpp"

#include <limits>
#include <sstream>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "fem/solvers/BucklingEigen.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/static/Static.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

namespace {

/// The modes of one sign, each shape scaled to a largest translation of 1 with its largest
/// entry positive.
std::vector<BucklingMode> toModes(const Model& model, const DofMap& dofs, const BucklingPairs& p) {
  std::vector<BucklingMode> modes;
  for (int k = 0; k < int(p.factors.size()); ++k) {
    BucklingMode m;
    m.factor = p.factors[k];
    m.shape = freeToNodalField(model, dofs, p.vectors.col(k));
    const auto translations = m.shape.leftCols(3);
    Eigen::Index row = 0, col = 0;
    const double largest = translations.cwiseAbs().maxCoeff(&row, &col);
    const double scale = largest > 0 ? largest : m.shape.cwiseAbs().maxCoeff();
    if (scale > 0) m.shape /= (translations(row, col) < 0 ? -scale : scale);
    modes.push_back(std::move(m));
  }
  return modes;
}

}  // namespace

double lowestBucklingFactor(const SparseMatrix& K, const SparseMatrix& KG) {
  const BucklingPairs lowest = bucklingEigenpairs(K, KG, 1, +1);
  return lowest.factors.size() > 0 ? lowest.factors[0] : std::numeric_limits<double>::infinity();
}

void requireBelowCritical(double factor, const std::string& analysis) {
  // A factor within round-off of 1 is the critical load itself: K + KG is singular there.
  if (factor > 1 + 1e-9) return;
  std::ostringstream msg;
  msg << analysis << ": the load is " << (factor < 1 - 1e-9 ? "past" : "at")
      << " the critical load: the lowest buckling factor of its first-order state is " << factor
      << " (the structure buckles at that multiple of the load), so no equilibrium about the "
         "loaded state exists; reduce the load below the critical one, or run a `type: "
         "buckling` analysis to see the mode";
  throw SolveError(msg.str());
}

BucklingResult solveBuckling(const Model& model, const BucklingOptions& options) {
  Stopwatch clock, total;
  BucklingResult result;

  // 1. The reference state: first-order statics under the model's loads.
  result.reference = solveStatic(model);

  // 2. K and the geometric stiffness of the reference state's axial forces.
  const DofMap dofs(model);
  const SparseAssembler assembler(model, dofs);
  const SparseMatrix K = assembler.assemble(MatrixKind::stiffness);
  const SparseMatrix KG =
      assembler.assembleGeometric(fromNodalField(dofs, result.reference.displacement));
  result.time.assembly = clock.lap();

  // 3. The load factors of least magnitude, positive and (when asked) negative.
  const BucklingPairs positive = bucklingEigenpairs(K, KG, options.count, +1);
  result.modes = toModes(model, dofs, positive);
  if (options.reversed)
    result.reversed = toModes(model, dofs, bucklingEigenpairs(K, KG, options.count, -1));
  result.time.solve = clock.lap();
  if (result.modes.empty())
    result.warnings.push_back(
        "buckling: the reference load compresses nothing, so no positive load factor exists "
        "(the structure cannot buckle under this load, only under its reverse)");
  if (options.reversed && result.reversed.empty())
    result.warnings.push_back(
        "buckling: the reference load puts nothing in tension, so the reversed load cannot "
        "buckle the structure: no negative load factor exists");
  result.size = systemSize(model, dofs, K, positive.factorEntries);
  result.time.total = total.lap();
  return result;
}

}  // namespace beamrotor
