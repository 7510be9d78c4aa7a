#include "fem/static/LinearStatics.hpp"

#include <sstream>

#include "fem/assembly/ReducedSystem.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/SupportCheck.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

namespace {

/// K with the held dofs' rows and columns cleared and their diagonals kept (same pattern).
SparseMatrix holdDofs(const SparseMatrix& K, const std::vector<HeldDof>& held) {
  SparseMatrix A = K;
  std::vector<bool> isHeld(K.rows(), false);
  for (const HeldDof& h : held) isHeld[h.equation] = true;
  for (int col = 0; col < A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it)
      if ((isHeld[col] || isHeld[it.row()]) && it.row() != col) it.valueRef() = 0;
  return A;
}

}  // namespace

LinearStatics::LinearStatics(const Model& model) : model_(model), dofs_(model) {
  // K is assembled once; the assembler's pattern becomes K itself (no copy kept).
  SparseAssembler(model, dofs_).assemble(MatrixKind::stiffness).swap(K_);
  nodalLoads_ = nodalLoadVector(model, dofs_);
  uPrescribed_ = prescribedValues(model, dofs_);
  rhs_ = reducedRightHandSide(model, dofs_, loadVector(model, dofs_), uPrescribed_);
}

Eigen::VectorXd LinearStatics::solve(const std::vector<HeldDof>& held, double singularRcond) {
  Stopwatch clock;
  Eigen::VectorXd u = uPrescribed_;
  const int nf = dofs_.freeCount();
  if (nf == 0) return u;

  // 1. Factorise (symbolic analysis once, numeric every time).
  SparseMatrix heldMatrix;
  if (!held.empty()) heldMatrix = holdDofs(K_, held);
  const SparseMatrix& A = held.empty() ? K_ : heldMatrix;
  if (!analysed_) {
    solver_.analyzePattern(A);
    analysed_ = true;
  }
  solver_.factorize(A);
  rcond_ = solver_.rcond();
  if (!solver_.healthy(singularRcond)) {
    const auto moving = zeroEnergyDofs(A, dofs_);
    if (!moving.empty()) throwUnsupported(model_, moving, "static analysis");
    std::ostringstream msg;
    msg << "static analysis: the stiffness matrix is singular to working precision ("
        << solver_.methodName() << " rcond = " << rcond_
        << "); look for extremely stiff springs next to soft members, "
           "or a mesh refined far past what double precision resolves";
    throw SolveError(msg.str());
  }
  factorSeconds_ += clock.lap();

  // 2. Right-hand side: held values move to the right like prescribed ones.
  Eigen::VectorXd b = rhs_;
  if (!held.empty()) {
    Eigen::VectorXd uHeld = Eigen::VectorXd::Zero(nf);
    for (const HeldDof& h : held) uHeld[h.equation] = h.value;
    b -= K_ * uHeld;
    for (const HeldDof& h : held) b[h.equation] = K_.coeff(h.equation, h.equation) * h.value;
  }
  u.head(nf) = solver_.solve(b);
  if (!u.allFinite()) throw SolveError("static analysis: the solution is not finite");
  solveSeconds_ += clock.lap();
  return u;
}

Eigen::VectorXd LinearStatics::residual(const Eigen::VectorXd& u, bool constrainedOnly) const {
  // Element forces already net out the loads the elements carry.
  return elementForces(model_, dofs_, u, constrainedOnly) - nodalLoads_;
}

}  // namespace beamrotor
