#include "fem/modal/Modal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fem/assembly/ReducedSystem.hpp"
#include "fem/assembly/RigidTies.hpp"
#include "fem/modal/RigidMotion.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/SupportCheck.hpp"
#include "fem/solvers/SymmetricEigen.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

namespace {

/// Below this fraction of the nearest elastic eigenvalue (or of |shift| when none was
/// computed), an eigenvalue among the null space's count nearest zero is its round-off.
constexpr double kRigidBodyRatio = 1e-6;

/// With a shift, K may be singular: the structure moves freely (a free body, a free drive
/// train, a mechanism the shift lets through). The dimension of K's null space, r, comes from
/// the rank-revealing QR of its diagonally scaled form (findMechanism, as the support check
/// uses), so it is judged on the scaled system, never against a threshold in the units. The r
/// computed eigenvalues nearest zero are those motions: each is set to exactly 0 (its computed
/// value is round-off of the shifted factorisation) when it is far below the next one.
void markRigidBodyModes(const Model& model, const DofMap& dofs, const SparseMatrix& K,
                        const std::vector<int>& tied, double shift, std::vector<Mode>& modes) {
  if (shift == 0 || modes.empty()) return;  // K was factorised: it has no null space
  // The QR costs about a factorisation: skip it when no eigenvalue could pass the test below
  // (its scale is one of the computed eigenvalues or |shift|), the usual shifted analysis.
  double nearest = std::abs(modes.front().eigenvalue), largest = std::abs(shift);
  for (const Mode& m : modes) {
    nearest = std::min(nearest, std::abs(m.eigenvalue));
    largest = std::max(largest, std::abs(m.eigenvalue));
  }
  if (nearest > kRigidBodyRatio * largest) return;
  const int nullity = findMechanism(model, dofs, K, tied).count;
  if (nullity == 0) return;
  std::vector<int> order(modes.size());
  for (int i = 0; i < int(order.size()); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return std::abs(modes[a].eigenvalue) < std::abs(modes[b].eigenvalue);
  });
  const int rigid = std::min<int>(nullity, int(order.size()));
  const double scale = rigid < int(order.size())
                           ? std::abs(modes[order[rigid]].eigenvalue)
                           : std::abs(shift);
  for (int i = 0; i < rigid; ++i) {
    Mode& mode = modes[order[i]];
    if (std::abs(mode.eigenvalue) > kRigidBodyRatio * scale) continue;
    mode.eigenvalue = 0;
    mode.frequencyHz = 0;
    mode.rigidBody = true;
  }
}

/// The kind (dofIndex) of each free dof.
std::vector<int> kindOfEachEquation(const DofMap& dofs) {
  std::vector<int> kind(dofs.freeCount());
  for (int eq = 0; eq < dofs.freeCount(); ++eq) kind[eq] = dofIndex(dofs.dofOf(eq).dof);
  return kind;
}

std::string describeMode(const std::array<double, kDofKinds>& share) {
  // Group the shares into the physical families a user recognises.
  const double axial = share[0], torsion = share[3];
  const double bendY = share[1] + share[5];  // uy with rz: bending in the x-y plane
  const double bendZ = share[2] + share[4];  // uz with ry: bending in the x-z plane
  const double best = std::max({axial, torsion, bendY, bendZ});
  if (best == bendY && bendZ > 0.25) return "bending uy+uz (two planes)";
  if (best == bendY) return "bending uy (x-y plane)";
  if (best == bendZ) return "bending uz (x-z plane)";
  if (best == axial) return "axial ux";
  return "torsion rx";
}

}  // namespace

ModalResult solveModes(const Model& model, const ModalOptions& options) {
  return solveModesAbout(model, options, Eigen::VectorXd());
}

ModalResult solveModesAbout(const Model& model, const ModalOptions& options,
                            const Eigen::VectorXd& state) {
  Stopwatch clock, total;
  ModalResult result;
  result.shift = options.shift;

  // 1. Assemble the free-free blocks of K and M, in one pass over the elements.
  // M takes over the assembler's pattern, which is not held while the eigensolver runs, and
  // both keep only the entries that couple, as the statics keep K (a straight line's
  // axial-bending pairs are over 40 % of its pattern): every product and copy reads less.
  const DofMap dofs(model);
  SparseAssembler assembler(model, dofs);
  const SparseMatrix geometric =
      state.size() > 0 ? assembler.assembleGeometric(state) : SparseMatrix();
  auto [K, M] = std::move(assembler).assemble(MatrixKind::stiffness, MatrixKind::mass);
  dropExactZeros(M);
  // Rigid ties (fem/assembly/RigidTies.hpp): the pencil T' K T, T' M T in the same numbering;
  // each tied equation is an infinite eigenvalue (no mass), which the eigensolvers drop.
  // About a loaded state, K gains its geometric stiffness (the arms' own with ties).
  const TieReduction ties(model, dofs);
  SparseMatrix Kr, Mr;
  if (!ties.empty()) {
    Kr = ties.stiffness(K);
    if (state.size() > 0) Kr += ties.geometric(geometric, stateResidual(model, dofs, state));
    Mr = ties.projected(M);
    dropExactZeros(Kr);
    dropExactZeros(Mr);
  } else if (state.size() > 0) {
    K += geometric;
  }
  dropExactZeros(K);
  const SparseMatrix& pencilK = ties.empty() ? K : Kr;
  const SparseMatrix& pencilM = ties.empty() ? M : Mr;
  result.time.assembly = clock.lap();

  // 2. Eigenpairs nearest the shift. At shift 0 a singular K is a mechanism: name its dofs.
  EigenPairs pairs;
  try {
    const int independent = dofs.freeCount() - int(ties.tied().size());
    pairs = symmetricEigenpairs(pencilK, pencilM, std::min(options.modes, independent),
                                options.shift, dofs.freeNodes());
  } catch (const SingularSystem& e) {
    if (options.shift == 0) {
      const Mechanism mechanism = findMechanism(model, dofs, pencilK, ties.tiedNumbers());
      if (mechanism.count > 0)
        throwUnsupported(model, dofs, mechanism,
                         std::string(e.what()) + ".\nmodal analysis at shift 0");
    }
    throw;
  }
  result.time.solve = clock.lap();
  // The modes over every free dof, the tied ones following their masters: their effective
  // masses below are r' M phi with the whole mass matrix (a follower of a fixed master moves
  // with the ground, and its mass still pulls on the free dofs it couples to).
  pairs.vectors = ties.expand(pairs.vectors);
  if (pairs.missedBySturmCount > 0)
    result.warnings.push_back(
        "a Sturm count finds " + std::to_string(pairs.missedBySturmCount) +
        " eigenvalue(s) below the highest frequency listed that Lanczos did not return, even "
        "when run again away from the modes it found: the list may skip modes (or the count "
        "is off, for a matrix this near singular); give a shift near that frequency to "
        "compute them");

  // 3. Describe each mode: frequency, effective masses, energy share per dof kind. With r_k
  // the rigid translation along axis k (1 on each free dof of that kind), the total mass is
  // r_k' M r_k, the sum of M's entries between dofs of kind k, and a mode's participation
  // r_k' M phi is the sum of M phi over those dofs: one pass over M for all modes.
  const std::vector<int> kind = kindOfEachEquation(dofs);
  for (int col = 0; col < M.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(M, col); it; ++it)
      if (kind[col] < 3 && kind[it.row()] == kind[col]) result.totalMass[kind[col]] += it.value();
  const Eigen::MatrixXd massTimesModes = M * pairs.vectors;
  for (int m = 0; m < int(pairs.values.size()); ++m) {
    Mode mode;
    const auto phi = pairs.vectors.col(m);
    const auto Mphi = massTimesModes.col(m);
    mode.eigenvalue = pairs.values[m];
    mode.frequencyHz = std::sqrt(std::max(0.0, mode.eigenvalue)) / (2 * std::numbers::pi);
    mode.shape = freeToNodalField(model, dofs, phi);
    std::array<double, 3> participation{};
    double sum = 0;
    for (int eq = 0; eq < dofs.freeCount(); ++eq) {
      if (kind[eq] < 3) participation[kind[eq]] += Mphi[eq];
      const double e = std::abs(phi[eq] * Mphi[eq]);
      mode.energyShare[kind[eq]] += e;
      sum += e;
    }
    mode.participation = participation;
    for (int k = 0; k < 3; ++k) mode.effectiveMass[k] = participation[k] * participation[k];
    if (sum > 0)
      for (double& s : mode.energyShare) s /= sum;
    mode.description = describeMode(mode.energyShare);
    result.modes.push_back(std::move(mode));
  }
  markRigidBodyModes(model, dofs, pencilK, ties.tiedNumbers(), options.shift, result.modes);
  // A frame's modes are named by the rigid motion their effective mass follows (sway,
  // torsion), which the energy shares by global dof kind do not tell for members across x.
  if (!model.members().empty()) {
    const std::vector<RigidShares> shares = rigidMotionShares(model, dofs, M, pairs.vectors);
    for (std::size_t m = 0; m < shares.size(); ++m)
      result.modes[m].description = describeRigidMotion(shares[m], "mass");
  }
  result.size = systemSize(model, dofs, K.nonZeros(), pairs.factorEntries);
  result.time.total = total.lap();
  return result;
}

}  // namespace beamrotor
