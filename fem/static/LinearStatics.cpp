#include "fem/static/LinearStatics.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "fem/assembly/BandAssembly.hpp"
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

/// The same for a band.
SymmetricBand holdDofs(const SymmetricBand& K, const std::vector<HeldDof>& held) {
  SymmetricBand A = K;
  const int n = A.size(), kd = A.halfBandwidth();
  for (const HeldDof& h : held) {
    const int eq = h.equation;
    for (int i = eq + 1; i <= eq + kd && i < n; ++i) A.lower(i, eq) = 0;
    for (int j = std::max(eq - kd, 0); j < eq; ++j) A.lower(eq, j) = 0;
  }
  return A;
}

/// Calls visit(i, r_i, (|A| |x|)_i) for every row i of A x = b, r = b - A x with each row's
/// sum kept in extended precision in a register (long double products of the double entries;
/// no full-length extended-precision vector is stored). forRow(i, visit) calls visit(j, A_ij)
/// for the entries of row i. Rows are split over the cores; each row's sum keeps its order.
template <class ForRow, class Visit>
void forResidualRows(ForRow&& forRow, const Eigen::VectorXd& b,
                     const Eigen::Ref<const Eigen::VectorXd>& x, Visit&& visit) {
  forEvenParts(int(b.size()), [&](int first, int end) {
    for (int i = first; i < end; ++i) {
      long double r = b[i];
      double magnitude = 0;
      forRow(i, [&](int j, double a) {
        r -= static_cast<long double>(a) * x[j];
        magnitude += std::abs(a * x[j]);
      });
      visit(i, r, magnitude);
    }
  });
}

/// One step of iterative refinement, x += A^-1 (b - A x), the residual in extended precision
/// (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., ch. 12). A backward-stable
/// factor leaves a residual of about eps |L| |D| |L'| |x|, which an ill-conditioned system (a
/// large flexible frame) turns into an error of many digits and a visible imbalance of
/// reactions against loads; one step brings the solution to what A's entries resolve. On the
/// bench's 3D grillage at 10^6 equations (deflections of 3e5 m), the reactions balance the
/// load to 8e-13 instead of 2e-7 to 5e-7, for one more solve (0.07 s of 3 s).
/// forRow as forResidualRows takes it; solve(r) returns A^-1 r.
template <class ForRow, class Solve>
void refineOnce(ForRow&& forRow, const Eigen::VectorXd& b, Eigen::Ref<Eigen::VectorXd> x,
                Solve&& solve) {
  Eigen::VectorXd residual(b.size());
  forResidualRows(forRow, b, x, [&](int i, long double r, double) { residual[i] = double(r); });
  x += solve(residual);
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
/// forRow(i, visit) calls visit(j, A_ij) for the entries of row i; `diagonal` is A's.
template <class ForRow, class Solve>
double measuredError(ForRow&& forRow, Eigen::VectorXd diagonal, const Eigen::VectorXd& b,
                     const Eigen::Ref<const Eigen::VectorXd>& x, Solve&& solve) {
  const double eps = std::numeric_limits<double>::epsilon();
  Eigen::VectorXd perturbation(b.size());
  forResidualRows(forRow, b, x, [&](int i, long double r, double magnitude) {
    perturbation[i] = double(std::abs(r)) + eps * magnitude;
  });
  // Each vector of the equations' length is 22 MB at 10^6 elements: the perturbation is
  // solved in its own storage, and the weights are made in the diagonal's.
  const Eigen::VectorXd response = solve(std::move(perturbation));
  Eigen::VectorXd& weight = diagonal;
  weight = weight.cwiseAbs().cwiseSqrt();
  const double size = weight.cwiseProduct(x).cwiseAbs().maxCoeff();
  const double error = weight.cwiseProduct(response).cwiseAbs().maxCoeff();
  if (!std::isfinite(error)) return std::numeric_limits<double>::infinity();
  return size > 0 ? error / size : (error > 0 ? std::numeric_limits<double>::infinity() : 0.0);
}

/// x refined once (refineOnce), then its measured error (measuredError), for a sparse A
/// factorised by `solver`.
double refineAndMeasure(const SparseMatrix& A, const Eigen::VectorXd& b,
                        Eigen::Ref<Eigen::VectorXd> x, const LinearSolver& solver) {
  // Row i of A is column i of A' (of A itself when the solver took it as symmetric).
  SparseMatrix transposed;
  if (!solver.symmetric()) transposed = A.transpose();
  const SparseMatrix& rows = solver.symmetric() ? A : transposed;
  const auto forRow = [&](int i, auto&& visit) {
    for (SparseMatrix::InnerIterator it(rows, i); it; ++it) visit(int(it.index()), it.value());
  };
  const auto solve = [&](const Eigen::VectorXd& r) { return solver.solve(r); };
  refineOnce(forRow, b, x, solve);
  return measuredError(forRow, A.diagonal(), b, x, solve);
}

double measuredError(const SymmetricBand& A, const Eigen::VectorXd& b,
                     const Eigen::Ref<const Eigen::VectorXd>& x, const BandCholesky& factor) {
  const auto forRow = [&](int i, auto&& visit) { A.forRow(i, visit); };
  return measuredError(forRow, A.diagonal(), b, x,
                       [&](Eigen::VectorXd r) { return factor.solve(std::move(r)); });
}

}  // namespace

LinearStatics::LinearStatics(const Model& model, SymbolicReuse* reuse)
    : model_(model), dofs_(model), ties_(model, dofs_), reuse_(reuse) {
  // A line numbered node by node goes into a band, without a pattern (fem/assembly/
  // BandAssembly); other structures, and any with rigid ties, into the sparse pattern.
  const std::optional<int> kd = ties_.empty() ? stiffnessBand(model, dofs_) : std::nullopt;
  if (kd) {
    bandK_ = assembleBand(model, dofs_, MatrixKind::stiffness, *kd);
    banded_ = true;
    // The sparse K a fallback makes of it keeps the same entries.
    stiffnessEntries_ = bandK_.nonZeros();
    solverName_ = "LAPACK band Cholesky, half-bandwidth " + std::to_string(*kd);
    rhs_ = reducedRightHandSide(model, dofs_, loadVector(model, dofs_),
                                prescribedValues(model, dofs_));
    return;
  }
  // K is assembled once; the assembler's pattern becomes K itself (no copy kept).
  SparseAssembler assembler(model, dofs_);
  if (assembler.stiffnessSymmetric()) symmetry_ = MatrixSymmetry::byConstruction;
  std::move(assembler).assemble(MatrixKind::stiffness).swap(K_);
  // The factor needs only the pairs that couple (its fill and flops fall by up to 3x), and K
  // keeps only their storage: a planar line's 40 % less, which the factor then reuses.
  if (!ties_.empty()) K_ = ties_.stiffness(K_);
  dropExactZeros(K_);
  stiffnessEntries_ = K_.nonZeros();
  // Only the reduced right-hand side is kept: the nodal loads and the prescribed values are
  // made again where needed (a pass over the loads or the supports), not held through the
  // factorisation, when a static run's memory peaks.
  rhs_ = reducedLoads(loadVector(model, dofs_));
}

Eigen::VectorXd LinearStatics::reducedLoads(Eigen::VectorXd f) const {
  Eigen::VectorXd rhs = reducedRightHandSide(model_, dofs_, std::move(f),
                                             prescribedValues(model_, dofs_));
  return ties_.loads(rhs);
}

void LinearStatics::setLoads(const Loading* loading) {
  loading_ = loading;
  rhs_ = reducedLoads(loading ? loadVector(model_, dofs_, *loading) : loadVector(model_, dofs_));
}

Eigen::VectorXd LinearStatics::solve(const std::vector<HeldDof>& held, double singularRcond) {
  if (released_) throw std::logic_error("LinearStatics::solve after releaseMatrices()");
  Stopwatch clock;
  const int nf = dofs_.freeCount();
  if (nf == 0) return prescribedValues(model_, dofs_);

  // A nearly singular matrix: a mechanism (named in words), or a structure that is held but
  // ill-conditioned, whose solution's measured round-off then tells how much of it holds.
  bool kinematicsChecked = false;
  const auto requireHeld = [&] {
    if (kinematicsChecked) return;
    kinematicsChecked = true;
    std::vector<int> heldEquations;
    for (const HeldDof& h : held) heldEquations.push_back(h.equation);
    for (int tied : ties_.tiedNumbers()) heldEquations.push_back(tied);
    const SparseMatrix fromBand = banded_ ? bandK_.toSparse() : SparseMatrix();
    const Mechanism mechanism =
        findMechanism(model_, dofs_, banded_ ? fromBand : K_, heldEquations);
    if (mechanism.count > 0) throwUnsupported(model_, dofs_, mechanism, "static analysis");
  };

  // 1. Factorise (the band's Cholesky; or the sparse factor: symbolic analysis once, numeric
  //    every time). Held dofs keep their place: their rows and columns are cleared.
  const bool sameFactor = held.empty() && factoredUnheld_;
  SymmetricBand heldBand;
  if (banded_ && !held.empty()) heldBand = holdDofs(bandK_, held);
  if (banded_ && !sameFactor) {
    if (bandFactor_.factorize(held.empty() ? bandK_ : heldBand)) {
      rcond_ = bandFactor_.scaledRcond();
      if (!(rcond_ > singularRcond)) requireHeld();
    } else {
      // Not positive definite: a mechanism (thrown in words), else a held structure made
      // indefinite (negative springs), which the sparse LDL' factorises.
      requireHeld();
      SparseMatrix fromBand = bandK_.toSparse();
      K_.swap(fromBand);  // an assignment would copy it
      bandK_ = SymmetricBand();
      heldBand = SymmetricBand();
      banded_ = false;
      symmetry_ = MatrixSymmetry::byConstruction;
    }
  }
  SparseMatrix heldMatrix;
  if (!banded_) {
    if (!held.empty()) heldMatrix = holdDofs(K_, held);
    const SparseMatrix& A = held.empty() ? K_ : heldMatrix;
    if (!analysed_) {
      // Held dofs clear rows and columns alike: K's symmetry is the held matrix's.
      const std::vector<int> nodeOfRow = dofs_.freeNodes();
      // A supported structure's stiffness is positive definite: a large one may take the
      // supernodal Cholesky (a mechanism or negative springs fall back to the LDL').
      if (reuse_)
        solver_ = &reuse_->analysedFor(A, symmetry_, nodeOfRow, Definiteness::positiveExpected);
      else
        solver_->analyzePattern(A, symmetry_, nodeOfRow, Definiteness::positiveExpected);
      analysed_ = true;
    }
    if (!sameFactor) {
      solver_->factorize(A);
      solverName_ = solver_->methodName() + ", " + solver_->orderingName() + " ordering";
      rcond_ = solver_->rcond();
      if (!solver_->healthy(singularRcond)) requireHeld();
    }
  }
  factoredUnheld_ = held.empty();
  if (!sameFactor)
    factorEntries_ = banded_ ? bandFactor_.factorEntries() : solver_->factorEntries();
  factorSeconds_ += clock.lap();

  // 2. Right-hand side: held values move to the right like prescribed ones (rhs_ itself, not
  //    a copy, when nothing is held).
  Eigen::VectorXd heldRhs;
  if (!held.empty()) {
    Eigen::VectorXd uHeld = Eigen::VectorXd::Zero(nf);
    for (const HeldDof& h : held) uHeld[h.equation] = h.value;
    heldRhs = rhs_ - (banded_ ? bandK_ * uHeld : Eigen::VectorXd(K_ * uHeld));
    for (const HeldDof& h : held) {
      const double diagonal =
          banded_ ? bandK_.lower(h.equation, h.equation) : K_.coeff(h.equation, h.equation);
      heldRhs[h.equation] = diagonal * h.value;
    }
  }
  const Eigen::VectorXd& b = held.empty() ? rhs_ : heldRhs;
  Eigen::VectorXd u = prescribedValues(model_, dofs_);
  if (banded_) {
    u.head(nf) = b;
    bandFactor_.solveInPlace(u.head(nf));
    roundOff_ = measuredError(held.empty() ? bandK_ : heldBand, b, u.head(nf), bandFactor_);
  } else {
    u.head(nf) = solver_->solve(b);
    roundOff_ = refineAndMeasure(held.empty() ? K_ : heldMatrix, b, u.head(nf), *solver_);
    if (!ties_.empty()) u.head(nf) = ties_.expand(Eigen::MatrixXd(u.head(nf)));  // the slaves' values
  }
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

void LinearStatics::releaseMatrices() {
  released_ = true;
  bandK_ = SymmetricBand();
  bandFactor_ = BandCholesky();
  K_ = SparseMatrix();
  rhs_ = Eigen::VectorXd();
}

Eigen::VectorXd LinearStatics::residual(const Eigen::VectorXd& u) const {
  // Element forces already net out the loads the elements carry.
  if (!loading_) return elementForces(model_, dofs_, u) - nodalLoadVector(model_, dofs_);
  Eigen::VectorXd r = elementForces(model_, dofs_, u, *loading_);
  for (const NodalLoad& l : loading_->nodal()) r[dofs_.equation(l.node, l.dof)] -= l.value;
  return r;
}

Eigen::VectorXd LinearStatics::reactions(const Eigen::VectorXd& u) const {
  Eigen::VectorXd r = loading_ ? constrainedElementForces(model_, dofs_, u, *loading_)
                               : constrainedElementForces(model_, dofs_, u);
  for (const NodalLoad& l : loading_ ? loading_->nodal() : model_.loads()) {
    const int eq = dofs_.equation(l.node, l.dof);
    if (dofs_.isConstrained(eq)) r[eq - dofs_.freeCount()] -= l.value;
  }
  // A fixed master also holds what its ties hold their slaves with.
  if (!ties_.empty()) addTiedReactions(ties_.tied(), dofs_, residual(u), r);
  return r;
}

}  // namespace beamrotor
