#include "fem/static/LinearStatics.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "fem/assembly/ParallelParts.hpp"
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

/// An upper estimate of the relative error of x as a solution of A x = b, measured with one
/// more solve with the same factor (sizes in the scaled metric sqrt(A_jj) |x_j|, so units do
/// not matter: largest |error| over largest |x|). Two sources, their right-hand sides added
/// with one sign so that neither hides the other:
/// - the solver's own error: the residual r in extended precision (long double products of the
///   double entries), whose response A^-1 r is the error to first order (one step of iterative
///   refinement; Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., ch. 12);
/// - the error A's own rounding causes, which no solver removes (the element matrices and the
///   assembly round every entry, so A is known to about eps |A|): the response to
///   eps (|A| |x|)_i, the componentwise perturbation of Skeel's condition number (Higham ch. 7)
///   for this x, taken with one sign, which excites the smooth modes that amplify it most (on a
///   cantilever with exact element lengths it bounds the true error by a factor 600 to 1100,
///   measured at 16 and 2000 elements: the real roundings have both signs and partly cancel).
double measuredError(const SparseMatrix& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x,
                     const LinearSolver& solver) {
  const Eigen::Index n = b.size();
  // Row i of A is column i of A' (of A itself when the solver took it as symmetric): each
  // residual entry is one sum over a column, kept in extended precision in a register, with
  // (|A| |x|)_i beside it, and no full-length extended-precision vector is stored.
  SparseMatrix transposed;
  if (!solver.symmetric()) transposed = A.transpose();
  const SparseMatrix& rows = solver.symmetric() ? A : transposed;
  const double eps = std::numeric_limits<double>::epsilon();
  Eigen::VectorXd perturbation(n);
  forEvenParts(int(rows.outerSize()), [&](int first, int end) {
    for (int i = first; i < end; ++i) {
      long double r = b[i];
      double magnitude = 0;
      for (SparseMatrix::InnerIterator it(rows, i); it; ++it) {
        r -= static_cast<long double>(it.value()) * x[it.index()];
        magnitude += std::abs(it.value() * x[it.index()]);
      }
      perturbation[i] = double(std::abs(r)) + eps * magnitude;
    }
  });
  const Eigen::VectorXd response = solver.solve(perturbation);
  const Eigen::VectorXd weight = A.diagonal().cwiseAbs().cwiseSqrt();  // after the solve's peak
  const double size = weight.cwiseProduct(x).cwiseAbs().maxCoeff();
  const double error = weight.cwiseProduct(response).cwiseAbs().maxCoeff();
  if (!std::isfinite(error)) return std::numeric_limits<double>::infinity();
  return size > 0 ? error / size : (error > 0 ? std::numeric_limits<double>::infinity() : 0.0);
}

}  // namespace

LinearStatics::LinearStatics(const Model& model, SymbolicReuse* reuse)
    : model_(model), loaded_(&model), dofs_(model), reuse_(reuse) {
  // K is assembled once; the assembler's pattern becomes K itself (no copy kept).
  SparseAssembler assembler(model, dofs_);
  if (assembler.stiffnessSymmetric()) symmetry_ = MatrixSymmetry::byConstruction;
  std::move(assembler).assemble(MatrixKind::stiffness).swap(K_);
  // The factor needs only the pairs that couple (its fill and flops fall by up to 3x), and K
  // keeps only their storage: a planar line's 40 % less, which the factor then reuses.
  dropExactZeros(K_);
  setLoads(model);
}

void LinearStatics::setLoads(const Model& loaded) {
  if (&loaded != &model_) {
    const bool same = loaded.nodes().size() == model_.nodes().size() &&
                      loaded.elements().size() == model_.elements().size() &&
                      loaded.supports().size() == model_.supports().size() &&
                      DofMap(loaded).freeCount() == dofs_.freeCount();
    if (!same)
      throw std::invalid_argument("LinearStatics::setLoads: the loaded model's structure differs");
  }
  loaded_ = &loaded;
  // Only the reduced right-hand side is kept: the nodal loads and the prescribed values are
  // made again where needed (a pass over the loads or the supports), not held through the
  // factorisation, when a static run's memory peaks.
  rhs_ = reducedRightHandSide(loaded, dofs_, loadVector(loaded, dofs_),
                              prescribedValues(loaded, dofs_));
}

Eigen::VectorXd LinearStatics::solve(const std::vector<HeldDof>& held, double singularRcond) {
  Stopwatch clock;
  const int nf = dofs_.freeCount();
  if (nf == 0) return prescribedValues(*loaded_, dofs_);

  // 1. Factorise (symbolic analysis once, numeric every time).
  SparseMatrix heldMatrix;
  if (!held.empty()) heldMatrix = holdDofs(K_, held);
  const SparseMatrix& A = held.empty() ? K_ : heldMatrix;
  const bool sameFactor = held.empty() && factoredUnheld_;
  if (!analysed_) {
    // Held dofs clear rows and columns alike: K's symmetry is the held matrix's.
    if (reuse_)
      solver_ = &reuse_->analysedFor(A, symmetry_);
    else
      solver_->analyzePattern(A, symmetry_);
    analysed_ = true;
  }
  if (!sameFactor) solver_->factorize(A);
  factoredUnheld_ = held.empty();
  rcond_ = solver_->rcond();
  // A nearly singular matrix: a mechanism (named in words), or a structure that is held but
  // ill-conditioned, whose solution's measured round-off then tells how much of it holds.
  bool kinematicsChecked = false;
  const auto requireHeld = [&] {
    if (kinematicsChecked) return;
    kinematicsChecked = true;
    std::vector<int> heldEquations;
    for (const HeldDof& h : held) heldEquations.push_back(h.equation);
    const Mechanism mechanism = findMechanism(model_, dofs_, K_, heldEquations);
    if (mechanism.count > 0) throwUnsupported(model_, dofs_, mechanism, "static analysis");
  };
  if (!sameFactor && !solver_->healthy(singularRcond)) requireHeld();
  factorSeconds_ += clock.lap();

  // 2. Right-hand side: held values move to the right like prescribed ones (rhs_ itself, not
  //    a copy, when nothing is held).
  Eigen::VectorXd heldRhs;
  if (!held.empty()) {
    Eigen::VectorXd uHeld = Eigen::VectorXd::Zero(nf);
    for (const HeldDof& h : held) uHeld[h.equation] = h.value;
    heldRhs = rhs_ - K_ * uHeld;
    for (const HeldDof& h : held) heldRhs[h.equation] = K_.coeff(h.equation, h.equation) * h.value;
  }
  const Eigen::VectorXd& b = held.empty() ? rhs_ : heldRhs;
  Eigen::VectorXd u = prescribedValues(*loaded_, dofs_);
  u.head(nf) = solver_->solve(b);
  roundOff_ = measuredError(A, b, u.head(nf), *solver_);
  if (!u.allFinite() || !std::isfinite(roundOff_)) {
    requireHeld();
    std::ostringstream msg;
    msg << "static analysis: the solution is not finite (scaled rcond " << rcond_
        << "); the structure is held (no mechanism), but its stiffness matrix is singular to "
           "working precision: a mesh refined far past what double precision resolves, or "
           "extremely stiff springs next to soft members";
    throw SolveError(msg.str());
  }
  solveSeconds_ += clock.lap();
  return u;
}

Eigen::VectorXd LinearStatics::residual(const Eigen::VectorXd& u) const {
  // Element forces already net out the loads the elements carry.
  return elementForces(*loaded_, dofs_, u) - nodalLoadVector(*loaded_, dofs_);
}

Eigen::VectorXd LinearStatics::reactions(const Eigen::VectorXd& u) const {
  Eigen::VectorXd r = constrainedElementForces(*loaded_, dofs_, u);
  for (const NodalLoad& l : loaded_->loads()) {
    const int eq = dofs_.equation(l.node, l.dof);
    if (dofs_.isConstrained(eq)) r[eq - dofs_.freeCount()] -= l.value;
  }
  return r;
}

}  // namespace beamrotor
