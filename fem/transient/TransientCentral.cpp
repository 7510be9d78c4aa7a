#include "fem/transient/TransientCentral.hpp"

#include <Eigen/Eigenvalues>
#include <arpack/arpack.hpp>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "fem/solvers/ArpackTurn.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/StartVector.hpp"

namespace beamrotor {

namespace {

// Below this size the dense eigenvalues are cheaper than Lanczos (and ARPACK needs n > ncv).
constexpr int kDenseLimit = 64;
constexpr int kMaxRestarts = 5000;
// Lanczos residual tolerance relative to the eigenvalue: the Ritz value's error is below it,
// far finer than any margin one keeps on a time step.
constexpr double kLanczosTol = 1e-12;

/// The first off-diagonal nonzero of a matrix, as (row, col), or (-1, -1).
std::array<int, 2> firstOffDiagonal(const SparseMatrix& A) {
  for (int k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it)
      if (it.row() != k && it.value() != 0) return {int(it.row()), k};
  return {-1, -1};
}

/// Largest eigenvalue of the symmetric positive semi-definite A: Lanczos (ARPACK dsaupd, mode 1,
/// largest algebraic), one sparse product per iteration.
double largestEigenvalueLanczos(const SparseMatrix& A) {
  const a_int n = a_int(A.rows()), nev = 1, ncv = std::min<a_int>(n, 20);
  const a_int lworkl = ncv * (ncv + 8);
  Eigen::VectorXd resid = fixedStart(n);
  std::vector<double> v(std::size_t(n) * ncv), workd(3 * std::size_t(n)), workl(lworkl);
  std::array<a_int, 11> iparam{}, ipntr{};
  iparam[0] = 1;  // exact shifts
  iparam[2] = kMaxRestarts;
  iparam[6] = 1;  // mode 1: A x = lambda x
  a_int ido = 0, info = 1;  // start from resid (ARPACK's own start would vary from run to run)
  const ArpackTurn turn;    // from the first dsaupd to dseupd
  while (true) {
    arpack::saupd(ido, arpack::bmat::identity, n, arpack::which::largest_algebraic, nev,
                  kLanczosTol, resid.data(), ncv, v.data(), n, iparam.data(), ipntr.data(),
                  workd.data(), workl.data(), lworkl, info);
    if (ido != -1 && ido != 1) break;
    Eigen::Map<const Eigen::VectorXd> x(&workd[ipntr[0] - 1], n);
    Eigen::Map<Eigen::VectorXd> y(&workd[ipntr[1] - 1], n);
    y.noalias() = A * x;
  }
  if (info != 0)
    throw SolveError("critical time step: ARPACK dsaupd failed (info = " + std::to_string(info) +
                     ") computing the largest eigenvalue");
  std::vector<a_int> select(ncv);
  double lambda = 0;
  std::vector<double> z(n);  // not referenced without Ritz vectors, but must exist
  arpack::seupd(0, arpack::howmny::ritz_vectors, select.data(), &lambda, z.data(), n, 0.0,
                arpack::bmat::identity, n, arpack::which::largest_algebraic, nev, kLanczosTol,
                resid.data(), ncv, v.data(), n, iparam.data(), ipntr.data(), workd.data(),
                workl.data(), lworkl, info);
  if (info != 0)
    throw SolveError("critical time step: ARPACK dseupd failed (info = " + std::to_string(info) +
                     ")");
  return lambda;
}

}  // namespace

Eigen::VectorXd lumpedMassDiagonal(const SparseMatrix& M, const Model& model, const DofMap& dofs) {
  if (const auto [r, c] = firstOffDiagonal(M); r >= 0)
    throw SolveError("central difference needs a lumped (diagonal) mass matrix, but M couples " +
                     model.describe(dofs.dofOf(r)) + " with " + model.describe(dofs.dofOf(c)) +
                     "; build beams with MassModel::lumped, or use the newmark or hht scheme");
  Eigen::VectorXd m = M.diagonal();
  std::ostringstream massless;
  int count = 0;
  for (int eq = 0; eq < int(m.size()); ++eq)
    if (!(m[eq] > 0) && count++ < 3)
      massless << (count > 1 ? "; " : "") << model.describe(dofs.dofOf(eq));
  if (count > 0)
    throw SolveError("central difference needs mass on every free dof, but " +
                     std::to_string(count) + " have none (" + massless.str() +
                     (count > 3 ? "; ..." : "") +
                     "); lumped beams carry rotary inertia only with rotaryInertia = true; add "
                     "it or a PointInertia, or use the newmark or hht scheme");
  return m;
}

StabilityLimit criticalTimeStep(const SparseMatrix& K, const Eigen::VectorXd& m) {
  StabilityLimit out;
  const int n = int(m.size());
  if (n == 0) return out;
  // 1. The symmetric form A = D K D, D = diag(m)^-1/2: same eigenvalues as the pencil (K, M).
  const Eigen::VectorXd d = m.cwiseSqrt().cwiseInverse();
  const SparseMatrix A = d.asDiagonal() * K * d.asDiagonal();

  // 2. Gershgorin: every eigenvalue lies below the largest absolute row sum.
  Eigen::VectorXd rowSum = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it) rowSum[it.row()] += std::abs(it.value());
  out.omegaMaxBound = std::sqrt(rowSum.maxCoeff());

  // 3. The largest eigenvalue itself.
  double lambda = 0;
  if (n <= kDenseLimit) {
    const Eigen::MatrixXd dense(A);
    lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense, Eigen::EigenvaluesOnly)
                 .eigenvalues()
                 .maxCoeff();
    out.method = "dense";
  } else {
    lambda = largestEigenvalueLanczos(A);
    out.method = "arpack-lanczos";
  }
  out.omegaMax = std::sqrt(std::max(0.0, lambda));
  const double inf = std::numeric_limits<double>::infinity();
  out.dtCritical = out.omegaMax > 0 ? 2 / out.omegaMax : inf;
  out.dtCriticalSafe = out.omegaMaxBound > 0 ? 2 / out.omegaMaxBound : inf;
  return out;
}

CentralDifferenceStepper::CentralDifferenceStepper(const TransientSystem& system, double dt)
    : system_(system), dt_(dt) {
  if (!(dt > 0)) throw std::invalid_argument("time step must be positive");
  m_ = lumpedMassDiagonal(system.mass(), system.model(), system.dofs());
  c_ = Eigen::VectorXd::Zero(m_.size());
  if (system.damped()) {
    if (const auto [r, c] = firstOffDiagonal(system.damping()); r >= 0)
      throw SolveError(
          "central difference needs a diagonal damping matrix (grounded dampers, "
          "mass-proportional Rayleigh damping), but C couples " +
          system.model().describe(system.dofs().dofOf(r)) + " with " +
          system.model().describe(system.dofs().dofOf(c)) +
          "; stiffness-proportional damping and dampers between nodes need newmark or hht");
    c_ = system.damping().diagonal();
  }
}

void CentralDifferenceStepper::start(const TransientState& s) {
  // v_-1/2 = v_0 - dt/2 a_0 put into the first leapfrog update gives this (M a_0 + C v_0 = r_0).
  vHalf_ = s.v + (dt_ / 2) * s.a;
}

void CentralDifferenceStepper::step(TransientState& s) {
  s.u += dt_ * vHalf_;
  s.t += dt_;
  system_.force(s.t, f_);
  f_ -= system_.stiffness() * s.u;
  // (M/dt + C/2) v_n+3/2 = (M/dt - C/2) v_n+1/2 + f - K u, dof by dof.
  vNext_ = ((m_ / dt_ - c_ / 2).cwiseProduct(vHalf_) + f_).cwiseQuotient(m_ / dt_ + c_ / 2);
  s.v = (vHalf_ + vNext_) / 2;
  s.a = (vNext_ - vHalf_) / dt_;
  vHalf_.swap(vNext_);
}

}  // namespace beamrotor
