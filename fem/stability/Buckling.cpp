#include "fem/stability/Buckling.hpp"

#include <limits>
#include <sstream>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "fem/assembly/RigidTies.hpp"
#include "fem/solvers/BucklingEigen.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/static/Static.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

namespace {

/// Largest distance between two nodes along any axis (m): a length to compare rotations with.
double extent(const Model& model) {
  if (model.nodes().empty()) return 0;
  Eigen::Vector3d low = model.nodes().front(), high = low;
  for (const Eigen::Vector3d& x : model.nodes()) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  return (high - low).maxCoeff();
}

/// The modes of one sign, each shape scaled to a largest translation of 1 with that entry
/// positive; a mode that barely translates (a twist: translations below 1e-9 of its largest
/// rotation times the model's size) to a largest rotation of 1 instead.
std::vector<BucklingMode> toModes(const Model& model, const DofMap& dofs, const BucklingPairs& p) {
  std::vector<BucklingMode> modes;
  const double size = extent(model);
  for (int k = 0; k < int(p.factors.size()); ++k) {
    BucklingMode m;
    m.factor = p.factors[k];
    m.shape = freeToNodalField(model, dofs, p.vectors.col(k));
    Eigen::Index row = 0, col = 0, rrow = 0, rcol = 0;
    const double translation = m.shape.leftCols(3).cwiseAbs().maxCoeff(&row, &col);
    const double rotation = m.shape.rightCols(3).cwiseAbs().maxCoeff(&rrow, &rcol);
    const bool twist = translation <= 1e-9 * rotation * size;
    const double entry = twist ? m.shape(rrow, 3 + rcol) : m.shape(row, col);
    if (entry != 0) m.shape /= entry;
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
  //    Rigid ties reduce both as T' K T and T' KG T, with the arms' own geometric stiffness
  //    (fem/assembly/RigidTies.hpp); the tied equations have no geometric stiffness, so no
  //    finite factor, and the shapes expand.
  const DofMap dofs(model);
  const SparseAssembler assembler(model, dofs);
  const TieReduction ties(model, dofs);
  const SparseMatrix K = ties.stiffness(assembler.assemble(MatrixKind::stiffness));
  const Eigen::VectorXd state = fromNodalField(dofs, result.reference.displacement);
  const SparseMatrix KG = ties.geometric(assembler.assembleGeometric(state),
                                         stateResidual(model, dofs, state));
  result.time.assembly = clock.lap();

  // 3. The load factors of least magnitude, positive and (when asked) negative.
  const auto solve = [&](int sign) {
    BucklingPairs pairs = bucklingEigenpairs(K, KG, options.count, sign);
    pairs.vectors = ties.expand(pairs.vectors);
    return pairs;
  };
  const BucklingPairs positive = solve(+1);
  result.modes = toModes(model, dofs, positive);
  if (options.reversed) result.reversed = toModes(model, dofs, solve(-1));
  result.time.solve = clock.lap();
  // Copied from static strings: GCC 12 misreads a long literal moved into the vector as a read
  // past a temporary's inline buffer (a false -Warray-bounds, GCC bug 105651's family).
  static const std::string kNoneCompressed =
      "buckling: the reference load compresses nothing, so no positive load factor exists "
      "(the structure cannot buckle under this load, only under its reverse)";
  static const std::string kNoneInTension =
      "buckling: the reference load puts nothing in tension, so the reversed load cannot "
      "buckle the structure: no negative load factor exists";
  if (result.modes.empty()) result.warnings.push_back(kNoneCompressed);
  if (options.reversed && result.reversed.empty()) result.warnings.push_back(kNoneInTension);
  result.size = systemSize(model, dofs, K.nonZeros(), positive.factorEntries);
  result.time.total = total.lap();
  return result;
}

}  // namespace beamrotor
