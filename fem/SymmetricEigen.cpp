#include "fem/SymmetricEigen.hpp"

#include <arpack/arpack.hpp>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <numeric>
#include <sstream>

#include "fem/Errors.hpp"
#include "fem/SparseLU.hpp"

namespace beamrotor {

namespace {

// Below this size a dense solve is cheaper than Lanczos and always applicable.
constexpr int kDenseLimit = 200;
constexpr int kMaxRestarts = 1000;

std::string singularShiftMessage(double sigma, double rcond) {
  std::ostringstream msg;
  msg << "modal analysis: K - sigma M is singular at shift sigma = " << sigma
      << " (UMFPACK rcond = " << rcond << "): the shift coincides with an eigenvalue";
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
EigenPairs denseEigenpairs(const SparseMatrix& K, const SparseMatrix& M, int count,
                           double sigma) {
  const Eigen::MatrixXd Kd(K), Md(M);
  Eigen::LLT<Eigen::MatrixXd> llt(Kd - sigma * Md);
  if (llt.info() != Eigen::Success) {
    // Either sigma sits inside the spectrum or on an eigenvalue: fall back on an LU check.
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Kd - sigma * Md);
    if (!lu.isInvertible()) throw SolveError(singularShiftMessage(sigma, 0.0));
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

}  // namespace

EigenPairs symmetricEigenpairs(const SparseMatrix& K, const SparseMatrix& M, int count,
                               double sigma) {
  const int n = int(K.rows());
  if (count <= 0 || n == 0) return {};
  if (n <= kDenseLimit || count >= n - 1) return denseEigenpairs(K, M, count, sigma);

  // 1. Factorise K - sigma M once.
  const SparseMatrix A = K - sigma * M;
  SparseLU lu;
  lu.compute(A);
  if (!lu.healthy(kSingularRcond)) throw SolveError(singularShiftMessage(sigma, lu.rcond()));

  // 2. Reverse-communication Lanczos: OP = (K - sigma M)^-1 M, inner product B = M.
  const a_int nev = count;
  // A generous Lanczos basis: clustered spectra (long continuous beams) converge in a few
  // restarts with it, and it costs only n x ncv doubles.
  const a_int ncv = std::min<a_int>(n, std::max<a_int>(4 * nev + 1, 40));
  const a_int lworkl = ncv * (ncv + 8);
  std::vector<double> resid(n), v(std::size_t(n) * ncv), workd(3 * std::size_t(n)),
      workl(lworkl);
  std::array<a_int, 11> iparam{}, ipntr{};
  iparam[0] = 1;             // exact shifts
  iparam[2] = kMaxRestarts;  // maximum Arnoldi restarts
  iparam[6] = 3;             // mode 3: shift-invert
  a_int ido = 0, info = 0;
  const double tol = 0.0;    // machine precision
  Eigen::VectorXd y(n);
  while (true) {
    arpack::saupd(ido, arpack::bmat::generalized, n, arpack::which::largest_magnitude, nev, tol,
                  resid.data(), ncv, v.data(), n, iparam.data(), ipntr.data(), workd.data(),
                  workl.data(), lworkl, info);
    Eigen::Map<Eigen::VectorXd> x(&workd[ipntr[0] - 1], n), out(&workd[ipntr[1] - 1], n);
    if (ido == -1) {
      y = M * x;
      out = lu.solve(y);
    } else if (ido == 1) {
      Eigen::Map<Eigen::VectorXd> Bx(&workd[ipntr[2] - 1], n);
      out = lu.solve(Bx);
    } else if (ido == 2) {
      out = M * x;
    } else {
      break;
    }
  }
  if (info < 0) throw SolveError("modal analysis: ARPACK dsaupd failed with info = " +
                                 std::to_string(info));
  if (info == 1)
    throw SolveError("modal analysis: ARPACK did not converge in " +
                     std::to_string(kMaxRestarts) + " restarts (" +
                     std::to_string(iparam[4]) + " of " + std::to_string(nev) + " modes)");

  // 3. Ritz vectors.
  std::vector<a_int> select(ncv);
  Eigen::VectorXd d(nev);
  Eigen::MatrixXd z(n, nev);
  arpack::seupd(1, arpack::howmny::ritz_vectors, select.data(), d.data(), z.data(), n, sigma,
                arpack::bmat::generalized, n, arpack::which::largest_magnitude, nev, tol,
                resid.data(), ncv, v.data(), n, iparam.data(), ipntr.data(), workd.data(),
                workl.data(), lworkl, info);
  if (info != 0)
    throw SolveError("modal analysis: ARPACK dseupd failed with info = " + std::to_string(info));
  for (int k = 0; k < nev; ++k) z.col(k) /= std::sqrt(z.col(k).dot(M * z.col(k)));
  EigenPairs out = nearest(d, z, count, sigma);
  out.factorEntries = lu.factorEntries();
  return out;
}

}  // namespace beamrotor
