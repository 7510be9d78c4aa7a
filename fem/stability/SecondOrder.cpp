#include "fem/stability/SecondOrder.hpp"

#include <cmath>
#include <sstream>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/MemberExtrema.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "fem/assembly/RigidTies.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/SparseLU.hpp"
#include "fem/stability/Buckling.hpp"
#include "fem/static/Static.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

namespace {

/// Full-length sum over elements of (K_e + KG_e(state)) v_e: with v = the solution, the
/// element forces in the deformed state (the reactions' source); with v = the prescribed
/// values, what they push onto the free dofs.
Eigen::VectorXd tangentTimes(const Model& model, const DofMap& dofs, const Eigen::VectorXd& state,
                             const Eigen::VectorXd& v) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(dofs.size());
  for (const auto& e : model.elements()) {
    const ElementVector ve = gather(*e, dofs, v);
    if (!ve.any()) continue;
    ElementMatrix k = e->stiffness();
    const ElementMatrix kg = e->geometricStiffness(gather(*e, dofs, state));
    if (kg.size() > 0) k += kg;
    const ElementVector fe = k * ve;
    const auto d = e->dofs();
    for (int a = 0; a < int(d.size()); ++a) r[dofs.equation(d[a])] += fe[a];
  }
  return r;
}

/// The largest of one peak kind over a static solution's beams (0 without beams).
double largestAlongBeams(const Model& model, const NodalField& u, BeamPeak ElementPeaks::*kind) {
  const auto peak = largestPeak(elementPeaks({model, u}), kind);
  return peak ? std::abs(peak->value) : 0.0;
}

/// Largest |value| over translations (0) or rotations (1) of a nodal field.
double largest(const NodalField& u, int rotations) {
  return u.middleCols(3 * rotations, 3).cwiseAbs().maxCoeff();
}

}  // namespace

SecondOrderResult solveSecondOrder(const Model& model, const SecondOrderOptions& options) {
  Stopwatch clock, total;
  if (!model.contacts().empty())
    throw SolveError("second-order statics: contacts are not supported with second-order "
                     "theory; remove the contacts or use first-order statics");
  SecondOrderResult result;
  result.firstOrder = solveStatic(model);

  // 1. K, the loads, the prescribed values, and the critical factor of the first-order state.
  //    Rigid ties (fem/assembly/RigidTies.hpp) reduce the tangent as T' (K + KG) T, with K's
  //    tied diagonals kept, and the loads as T' f; each solution expands as T q.
  const DofMap dofs(model);
  const SparseAssembler assembler(model, dofs);
  const TieReduction ties(model, dofs);
  const SparseMatrix K = assembler.assemble(MatrixKind::stiffness);
  const SparseMatrix Kr = ties.stiffness(K);
  const Eigen::VectorXd f = loadVector(model, dofs);
  const Eigen::VectorXd uPrescribed = prescribedValues(model, dofs);
  const int nf = dofs.freeCount();
  Eigen::VectorXd u = fromNodalField(dofs, result.firstOrder.displacement);
  result.criticalFactor = lowestBucklingFactor(
      Kr, ties.geometric(assembler.assembleGeometric(u), stateResidual(model, dofs, u)));
  requireBelowCritical(result.criticalFactor, "second-order statics");

  // 2. Solve (K + KG(u)) u' = f with the axial forces of the last u until u settles.
  SparseLU lu;
  bool analysed = false;
  const double scaleT = std::max(largest(result.firstOrder.displacement, 0), 1e-300);
  const double scaleR = std::max(largest(result.firstOrder.displacement, 1), 1e-300);
  for (int it = 1;; ++it) {
    // The arms' forces of the last state, as the members' axial forces are.
    const SparseMatrix A =
        Kr + ties.geometric(assembler.assembleGeometric(u),
                            ties.empty() ? Eigen::VectorXd() : tangentTimes(model, dofs, u, u) - f);
    if (!analysed) {
      lu.analyzePattern(A);
      analysed = true;
    }
    lu.factorize(A);
    if (lu.info() != Eigen::Success)
      throw SolveError("second-order statics: the tangent stiffness became singular while "
                       "iterating; the lowest buckling factor of the first-order state is " +
                       std::to_string(result.criticalFactor));
    const Eigen::VectorXd rhs =
        ties.loads(f.head(nf) - tangentTimes(model, dofs, u, uPrescribed).head(nf));
    Eigen::VectorXd next = uPrescribed;
    next.head(nf) = ties.expand(Eigen::MatrixXd(lu.solve(rhs)));
    if (!next.allFinite())
      throw SolveError("second-order statics: the solution is not finite; the lowest buckling "
                       "factor of the first-order state is " +
                       std::to_string(result.criticalFactor));
    const NodalField change = toNodalField(model, dofs, next - u);
    u = std::move(next);
    result.iterations = it;
    const NodalField now = toNodalField(model, dofs, u);
    const double t = std::max(largest(now, 0), scaleT), r = std::max(largest(now, 1), scaleR);
    if (largest(change, 0) <= options.tolerance * t && largest(change, 1) <= options.tolerance * r)
      break;
    if (it >= options.maxIterations) {
      std::ostringstream msg;
      msg << "second-order statics: no convergence in " << options.maxIterations
          << " iterations (the axial forces keep changing with the deflection); the lowest "
             "buckling factor of the first-order state is "
          << result.criticalFactor;
      throw SolveError(msg.str());
    }
  }

  // 3. The second-order state: displacements, and reactions from the element forces in the
  //    deformed state, (K + KG) u - f at the supports.
  StaticResult& s = result.secondOrder;
  s = result.firstOrder;
  s.displacement = toNodalField(model, dofs, u);
  s.activeSetIterations = result.iterations;
  const Eigen::VectorXd forces = tangentTimes(model, dofs, u, u) - f;
  // A fixed master also holds what its ties hold their slaves with.
  Eigen::VectorXd held = forces.tail(dofs.size() - nf);
  addTiedReactions(ties.tied(), dofs, forces, held);
  for (ReactionComponent& r : s.reactions) r.value = held[dofs.equation(r.node, r.dof) - nf];
  s.hinges = hingeRotations({model, s.displacement});
  s.elementForces = namedElementForces(model, s.displacement);
  const auto ratio = [](double a, double b) { return b > 0 ? a / b : 1.0; };
  // Magnitudes, not components: a sway that turns the largest displacement's direction would
  // otherwise be compared along one axis only.
  const auto rotation = [](const NodalField& u) {
    return u.rows() ? u.rightCols(3).rowwise().norm().maxCoeff() : 0.0;
  };
  result.firstOrderTranslation = largestDisplacement({model, result.firstOrder.displacement}).value;
  result.firstOrderRotation = rotation(result.firstOrder.displacement);
  result.displacementAmplification =
      ratio(largestDisplacement({model, s.displacement}).value, result.firstOrderTranslation);
  result.rotationAmplification = ratio(rotation(s.displacement), result.firstOrderRotation);
  for (auto [kind, out] : {std::pair{&ElementPeaks::moment, &result.momentAmplification},
                           std::pair{&ElementPeaks::stress, &result.stressAmplification}})
    *out = ratio(largestAlongBeams(model, s.displacement, kind),
                 largestAlongBeams(model, result.firstOrder.displacement, kind));
  s.time.total = total.lap();
  return result;
}

}  // namespace beamrotor
