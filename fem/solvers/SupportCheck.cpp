#include "fem/solvers/SupportCheck.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SPQRSupport>
#include <algorithm>
#include <cmath>

#include "fem/model/Model.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/MechanismWords.hpp"

namespace beamrotor {

namespace {

/// SuiteSparseQR works on 64-bit indices.
using QrMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;

// An element's scaled eigenvalue below this fraction of its largest is one of its own
// zero-energy motions (rigid-body or released): those come out at round-off, ~1e-16, while
// deformations of the most slender inclined element stay above ~1e-9.
constexpr double kElementNullSpace = 1e-12;
// A mode entry (scaled) below this fraction of the mode's largest does not move.
constexpr double kMoves = 1e-9;
constexpr int kListedModes = 12;

/// The rows of B_e (scaled, on the free columns) of one element, appended as triplets.
void appendStrainRows(const Element& e, const DofMap& dofs, const Eigen::VectorXd& scale,
                      const std::vector<bool>& held,
                      std::vector<Eigen::Triplet<double, SuiteSparse_long>>& t,
                      SuiteSparse_long& row) {
  const ElementMatrix K = e.stiffness();
  if (K.size() == 0) return;
  const auto d = e.dofs();
  const int n = int(d.size());
  std::vector<int> column(n, -1);
  Eigen::VectorXd s(n);
  for (int a = 0; a < n; ++a) {
    const int eq = dofs.equation(d[a]);
    if (dofs.isFree(eq) && !held[eq]) column[a] = eq;
    // Fixed dofs drop out of B; their scale only keeps the element's matrix balanced.
    s[a] = column[a] >= 0 ? scale[eq] : (K(a, a) > 0 ? 1 / std::sqrt(K(a, a)) : 1.0);
  }
  const ElementMatrix sym = 0.5 * (K + K.transpose());
  const ElementMatrix scaled = s.asDiagonal() * sym * s.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<ElementMatrix> eigen(scaled);
  const auto& lambda = eigen.eigenvalues();
  const double largest = lambda.cwiseAbs().maxCoeff();
  if (!(largest > 0)) return;
  for (int k = 0; k < n; ++k) {
    if (std::abs(lambda[k]) <= kElementNullSpace * largest) continue;
    const double root = std::sqrt(std::abs(lambda[k]));
    for (int a = 0; a < n; ++a)
      if (column[a] >= 0 && eigen.eigenvectors()(a, k) != 0)
        t.emplace_back(row, column[a], root * eigen.eigenvectors()(a, k));
    ++row;
  }
}

}  // namespace

Mechanism findMechanism(const Model& model, const DofMap& dofs, const SparseMatrix& Kff,
                        const std::vector<int>& heldEquations) {
  const int n = dofs.freeCount();
  Mechanism out;
  if (n == 0) return out;

  // 1. B: every element's strain rows in the scaled dofs diag(K)^-1/2, and a unit row per
  //    held dof. A dof with no stiffness at all keeps scale 1 and an empty column.
  Eigen::VectorXd scale = Kff.diagonal();
  for (int i = 0; i < n; ++i) scale[i] = scale[i] > 0 ? 1 / std::sqrt(scale[i]) : 1.0;
  std::vector<bool> held(n, false);
  for (int eq : heldEquations) held.at(eq) = true;
  std::vector<Eigen::Triplet<double, SuiteSparse_long>> triplets;
  SuiteSparse_long rows = 0;
  for (const auto& e : model.elements()) appendStrainRows(*e, dofs, scale, held, triplets, rows);
  for (int eq : heldEquations) triplets.emplace_back(rows++, eq, 1.0);
  QrMatrix B(std::max<SuiteSparse_long>(rows, 1), n);
  B.setFromTriplets(triplets.begin(), triplets.end());

  // 2. Its rank (SuiteSparseQR's column-norm tolerance, 20 (m + n) eps max |B_j|, far below
  //    the O(1) columns a held dof leaves) and a basis of its null space: with B E = Q [R11 R12]
  //    and R11 of full rank, x = E [-R11^-1 R12; I].
  Eigen::SPQR<QrMatrix> qr;
  qr.compute(B);
  if (qr.info() != Eigen::Success) return out;
  const Eigen::Index rank = qr.rank();
  out.count = int(n - rank);
  if (out.count == 0) return out;
  const QrMatrix R = qr.matrixR();
  const auto E = qr.colsPermutation();
  std::vector<bool> moving(n, false);
  for (Eigen::Index k = rank; k < n; ++k) {
    moving[E.indices()[k]] = true;  // each free column of the QR moves in its own mode
    if (int(out.modes.size()) == kListedModes) continue;
    Eigen::VectorXd y = Eigen::VectorXd::Zero(n);
    y[k] = 1;
    if (rank > 0) {
      // Solved in place into a named vector: an unnamed temporary here draws a false
      // -Wuse-after-free from GCC 12 in some unity batches.
      Eigen::VectorXd head = R.col(k).toDense().head(rank);
      R.topLeftCorner(rank, rank).triangularView<Eigen::Upper>().solveInPlace(head);
      y.head(rank) = -head;
    }
    Eigen::VectorXd x(n);
    for (Eigen::Index i = 0; i < n; ++i) x[E.indices()[i]] = y[i];
    const double largest = x.cwiseAbs().maxCoeff();
    for (int i = 0; i < n; ++i)
      if (std::abs(x[i]) > kMoves * largest) moving[i] = true;
    out.modes.push_back(scale.cwiseProduct(x));  // back to the dofs' own units
  }
  for (int i = 0; i < n; ++i)
    if (moving[i]) out.moving.push_back(dofs.dofOf(i));
  return out;
}

void throwUnsupported(const Model& model, const DofMap& dofs, const Mechanism& mechanism,
                      const std::string& context) {
  throw UnsupportedStructure(context + ": " + describeMechanism(model, dofs, mechanism),
                             mechanism.moving);
}

}  // namespace beamrotor
