#include "fem/solvers/SymmetricEigen.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <arpack/arpack.hpp>
#include <functional>
#include <memory>
#include <numeric>
#include <sstream>

#include "fem/solvers/Errors.hpp"
#include "fem/solvers/SparseLU.hpp"
#include "fem/solvers/SturmShift.hpp"

namespace beamrotor {

namespace {

// Below this size a dense solve is cheaper than Lanczos and always applicable.
constexpr int kDenseLimit = 200;
constexpr int kMaxRestarts = 1000;

std::string singularShiftMessage(double sigma, double rcond) {
  std::ostringstream msg;
  msg << "modal analysis: K - sigma M is singular at shift sigma = " << sigma
      << " (reciprocal condition estimate " << rcond << "): the shift coincides with an eigenvalue";
  if (sigma == 0)
    msg << ", i.e. the structure has rigid-body modes or mechanisms; give a negative shift "
           "(e.g. shift: -1) to compute them";
  return msg.str();
}

/// Sorts eigenpairs ascending and keeps the `count` nearest sigma.
EigenPairs nearest(const Eigen::VectorXd& values, const Eigen::MatrixXd& vectors, int count,
                   double sigma) {
  std::vector<int> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return std::abs(values[a] - sigma) < std::abs(values[b] - sigma);
  });
  order.resize(std::min<int>(count, int(order.size())));
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values[a] < values[b]; });
  EigenPairs out;
  out.values.resize(order.size());
  out.vectors.resize(vectors.rows(), order.size());
  for (int k = 0; k < int(order.size()); ++k) {
    out.values[k] = values[order[k]];
    out.vectors.col(k) = vectors.col(order[k]);
  }
  return out;
}

/// Dense path: with K - sigma M = L L^T, the symmetric C = L^-1 M L^-T has eigenvalues
/// mu = 1 / (lambda - sigma); a singular M only gives mu = 0 (infinite lambda), dropped.
EigenPairs denseEigenpairs(const SparseMatrix& K, const SparseMatrix& M, int count, double sigma) {
  const Eigen::MatrixXd Kd(K), Md(M);
  Eigen::LLT<Eigen::MatrixXd> llt(Kd - sigma * Md);
  if (llt.info() == Eigen::Success) {
    // A positive definite factor is not enough: a singular K (free-free, shift 0) whose null
    // space is exact in floating point (element lengths exact) can factor with round-off-sized
    // positive pivots. Judged as the sparse path judges its LDL': the pivots of the
    // symmetrically scaled matrix D^-1/2 A D^-1/2 (D = diag A) are L_jj^2 / A_jj, independent
    // of the dofs' units; their smallest over largest below kSingularRcond means singular.
    const Eigen::VectorXd a = (Kd - sigma * Md).diagonal();
    const Eigen::VectorXd l = llt.matrixLLT().diagonal();
    const Eigen::ArrayXd pivots = l.array().square() / a.array();
    const double rcond = pivots.maxCoeff() > 0 ? pivots.minCoeff() / pivots.maxCoeff() : 0.0;
    if (!(rcond > kSingularRcond)) throw SingularSystem(singularShiftMessage(sigma, rcond));
  } else {
    // Either sigma sits inside the spectrum or on an eigenvalue: fall back on an LU check.
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Kd - sigma * Md);
    if (!lu.isInvertible()) throw SingularSystem(singularShiftMessage(sigma, 0.0));
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ges(Kd, Md);
    if (ges.info() != Eigen::Success)
      throw SolveError("modal analysis: the dense generalised eigensolver failed");
    return nearest(ges.eigenvalues(), ges.eigenvectors(), count, sigma);
  }
  const Eigen::MatrixXd Linv = llt.matrixL().solve(Eigen::MatrixXd::Identity(K.rows(), K.rows()));
  const Eigen::MatrixXd C = Linv * Md * Linv.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (C + C.transpose()));
  const double muMax = es.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<int> finite;
  for (int k = 0; k < int(C.rows()); ++k)
    if (std::abs(es.eigenvalues()[k]) > 1e-13 * muMax) finite.push_back(k);
  Eigen::VectorXd lambda(finite.size());
  Eigen::MatrixXd X(K.rows(), finite.size());
  for (int i = 0; i < int(finite.size()); ++i) {
    lambda[i] = sigma + 1.0 / es.eigenvalues()[finite[i]];
    X.col(i) = Linv.transpose() * es.eigenvectors().col(finite[i]);
    X.col(i) /= std::sqrt(X.col(i).dot(Md * X.col(i)));
  }
  return nearest(lambda, X, count, sigma);
}

/// (K - shift M)^-1 applied to vectors, from whichever factorisation suits the shift.
struct ShiftedInverse {
  double shift = 0;
  /// x = (K - shift M)^-1 b; x keeps its storage from call to call.
  std::function<void(const Eigen::VectorXd& b, Eigen::VectorXd& x)> solve;
  double factorEntries = 0;
  /// The solve uses the Sturm counter's factor, which every later count overwrites.
  bool fromCounter = false;
};

/// Rayleigh quotient after a few steps of inverse iteration with a factor of K - sigma M:
/// an upper bound on the lowest eigenvalue, close to it (within the cluster it lies in).
double rayleighUpperBound(const SparseLDLT& factor, const SparseMatrix& K, const SparseMatrix& M) {
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(K.rows(), 1.0, 2.0);
  for (int step = 0; step < 4; ++step) {
    x = factor.solve(M * x);
    x /= x.norm();
  }
  return x.dot(K * x) / x.dot(M * x);
}

/// Below the spectrum (the usual request: the lowest modes), LDL' at a shift moved up to just
/// below the lowest eigenvalue by Sturm counts; inside it, UMFPACK's LU at sigma itself.
/// `counter` has factorised K - sigma M already; `below` is its count there.
ShiftedInverse shiftedInverse(SturmCounter& counter, int below, const SparseMatrix& K,
                              const SparseMatrix& M, int count, double sigma) {
  ShiftedInverse op;
  if (below == 0) {
    const double upper = rayleighUpperBound(counter.factor(), K, M);
    op.shift = shiftBelowLowest(counter, sigma, upper, count);
    // The counter's own factor, refactorised at the shift: its symbolic analysis and storage
    // serve again. A later count overwrites it; the caller refactorises it at the shift then.
    counter.below(op.shift);
    const SparseLDLT& ldlt = counter.factor();
    // Positive definite below the spectrum: judged scaled, whatever the units of the dofs.
    if (ldlt.info() == Eigen::Success && ldlt.scaledRcond() > kSingularRcond) {
      op.factorEntries = ldlt.factorEntries();
      op.solve = [&ldlt](const Eigen::VectorXd& b, Eigen::VectorXd& x) { ldlt.solveInto(b, x); };
      op.fromCounter = true;
      return op;
    }
  }
  op.shift = sigma;
  // Eigen's UmfPackLU keeps a reference to the matrix (UMFPACK's solve refines with it), so
  // the shifted matrix must live as long as the factor: a temporary here left it dangling.
  auto shifted = std::make_shared<const SparseMatrix>(K - sigma * M);
  auto lu = std::make_shared<SparseLU>();
  lu->compute(*shifted);
  if (!lu->healthy(kSingularRcond)) throw SingularSystem(singularShiftMessage(sigma, lu->rcond()));
  op.factorEntries = lu->factorEntries();
  op.solve = [lu, shifted](const Eigen::VectorXd& b, Eigen::VectorXd& x) { x = lu->solve(b); };
  return op;
}

/// How many eigenvalues a Sturm count finds below (just under) the largest of `values` beyond
/// those of `values` that lie there: modes Lanczos missed (0 when none).
int missedBelow(SturmCounter& counter, const Eigen::VectorXd& values, double shift) {
  if (values.size() == 0) return 0;
  const double top = values.maxCoeff();
  const double justBelow = top - 1e-9 * std::abs(top - shift) - 1e-12 * std::abs(top);
  const int found = int((values.array() < justBelow).count());
  return std::max(0, counter.below(justBelow) - found);
}

/// The nev eigenpairs of (K - shift M)^-1 M of largest magnitude (those nearest the shift) by
/// reverse-communication Lanczos with the M inner product, M-normalised.
EigenPairs lanczos(const SparseMatrix& M, const ShiftedInverse& op, int nevWanted) {
  const a_int n = a_int(M.rows());
  const a_int nev = nevWanted;
  // A generous Lanczos basis: clustered spectra (long continuous beams) converge in a few
  // restarts with it, and it costs only n x ncv doubles.
  const a_int ncv = std::min<a_int>(n, std::max<a_int>(4 * nev + 1, 40));
  const a_int lworkl = ncv * (ncv + 8);
  std::vector<double> resid(n), v(std::size_t(n) * ncv), workd(3 * std::size_t(n)), workl(lworkl);
  std::array<a_int, 11> iparam{}, ipntr{};
  iparam[0] = 1;             // exact shifts
  iparam[2] = kMaxRestarts;  // maximum Arnoldi restarts
  iparam[6] = 3;             // mode 3: shift-invert
  a_int ido = 0, info = 0;
  const double tol = 0.0;  // machine precision
  Eigen::VectorXd y(n), solution(n);
  while (true) {
    arpack::saupd(ido, arpack::bmat::generalized, n, arpack::which::largest_magnitude, nev, tol,
                  resid.data(), ncv, v.data(), n, iparam.data(), ipntr.data(), workd.data(),
                  workl.data(), lworkl, info);
    Eigen::Map<Eigen::VectorXd> x(&workd[ipntr[0] - 1], n), out(&workd[ipntr[1] - 1], n);
    if (ido == -1) {
      y = M * x;
      op.solve(y, solution);
      out = solution;
    } else if (ido == 1) {
      y = Eigen::Map<Eigen::VectorXd>(&workd[ipntr[2] - 1], n);  // M x, from ARPACK
      op.solve(y, solution);
      out = solution;
    } else if (ido == 2) {
      out = M * x;
    } else {
      break;
    }
  }
  if (info < 0)
    throw SolveError("modal analysis: ARPACK dsaupd failed with info = " + std::to_string(info));
  if (info == 1)
    throw SolveError("modal analysis: ARPACK did not converge in " + std::to_string(kMaxRestarts) +
                     " restarts (" + std::to_string(iparam[4]) + " of " + std::to_string(nev) +
                     " modes)");

  // Ritz vectors.
  std::vector<a_int> select(ncv);
  Eigen::VectorXd d(nev);
  Eigen::MatrixXd z(n, nev);
  arpack::seupd(1, arpack::howmny::ritz_vectors, select.data(), d.data(), z.data(), n, op.shift,
                arpack::bmat::generalized, n, arpack::which::largest_magnitude, nev, tol,
                resid.data(), ncv, v.data(), n, iparam.data(), ipntr.data(), workd.data(),
                workl.data(), lworkl, info);
  if (info != 0)
    throw SolveError("modal analysis: ARPACK dseupd failed with info = " + std::to_string(info));
  for (int k = 0; k < nev; ++k) z.col(k) /= std::sqrt(z.col(k).dot(M * z.col(k)));
  EigenPairs out;
  out.values = d;
  out.vectors = std::move(z);
  return out;
}

}  // namespace

EigenPairs symmetricEigenpairs(const SparseMatrix& K, const SparseMatrix& M, int count,
                               double sigma) {
  const int n = int(K.rows());
  if (count <= 0 || n == 0) return {};
  if (n <= kDenseLimit || count >= n - 1) {
    EigenPairs dense = denseEigenpairs(K, M, count, sigma);
    dense.shiftUsed = sigma;
    return dense;
  }

  // 1. Factorise K - shift M once, with the shift moved up to the lowest eigenvalues when
  //    sigma lies below all of them.
  SturmCounter counter(K, M);
  const int belowSigma = counter.below(sigma);
  const ShiftedInverse op = shiftedInverse(counter, belowSigma, K, M, count, sigma);

  // 2. Lanczos; when a Sturm count shows that it missed eigenvalues among the lowest (it can,
  //    with multiple or tightly clustered ones), again with a larger subspace.
  // Lanczos multiplies by M about three times per step (its M inner product): without the
  // pattern's exact zeros (in a planar beam the axial dofs never couple with the bending
  // ones, over 40 % of the entries) the products read less memory and give the same sums.
  const SparseMatrix massNonzeros = M.pruned();
  int nev = count;
  for (int attempt = 0;; ++attempt) {
    // The Sturm check of the previous attempt refactorised the counter away from the shift.
    if (attempt > 0 && op.fromCounter) counter.below(op.shift);
    const EigenPairs all = lanczos(massNonzeros, op, nev);
    // The shift was only moved within [sigma, lambda_1): nearest it is still nearest sigma.
    EigenPairs out = nearest(all.values, all.vectors, count, op.shift);
    const int missed = belowSigma == 0 ? missedBelow(counter, out.values, op.shift) : 0;
    if (missed == 0 || attempt == 2 || nev >= n - 2) {
      // Still missing after the retries: the caller reports it (the count itself can be off
      // by a few for a matrix this near singular, so the modes found are not thrown away).
      out.factorEntries = op.factorEntries;
      out.shiftUsed = op.shift;
      out.missedBySturmCount = missed;
      return out;
    }
    nev = std::min(n - 2, nev + 2 * missed + 2);
  }
}

}  // namespace beamrotor
