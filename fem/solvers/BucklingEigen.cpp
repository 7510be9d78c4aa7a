#include "fem/solvers/BucklingEigen.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <arpack/arpack.hpp>
#include <numeric>
#include <string>
#include <vector>

#include "fem/solvers/ArpackTurn.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/LinearSolver.hpp"
#include "fem/solvers/StartVector.hpp"

namespace beamrotor {

namespace {

// Below this size the dense solve is cheaper than Lanczos (as for the modal solver).
constexpr int kDenseBucklingLimit = 200;
constexpr int kBucklingRestarts = 1000;
// mu = 1 / lambda below this fraction of the largest |mu| is taken as infinite lambda (dofs the
// reference state does not load: axial, or every dof of an unloaded member).
constexpr double kNegligibleMu = 1e-10;

const char* kNotPositiveDefinite =
    "buckling analysis: the stiffness matrix is not positive definite (a mechanism or a "
    "support missing); linear buckling needs a structure that is stable without load";

/// The size of mu the reference state can give at most, about: the largest ratio of a
/// diagonal entry of KG to K's (a Rayleigh quotient of a unit vector). A mu far below it is
/// round-off of a dof the reference state does not load.
double muScale(const SparseMatrix& K, const SparseMatrix& KG) {
  double scale = 0;
  const Eigen::VectorXd k = K.diagonal(), g = KG.diagonal();
  for (int i = 0; i < int(k.size()); ++i)
    if (k[i] > 0) scale = std::max(scale, std::abs(g[i]) / k[i]);
  return scale;
}

/// Keeps the pairs whose mu has the wanted sign and is not negligible, largest |mu| (smallest
/// |lambda|) first, at most count of them, and turns mu into lambda = 1 / mu.
BucklingPairs select(const Eigen::VectorXd& mu, const Eigen::MatrixXd& x, int count, int sign,
                     double muScale) {
  std::vector<int> order;
  for (int k = 0; k < int(mu.size()); ++k)
    if (sign * mu[k] > kNegligibleMu * muScale) order.push_back(k);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return std::abs(mu[a]) > std::abs(mu[b]); });
  order.resize(std::min<std::size_t>(order.size(), std::size_t(std::max(count, 0))));
  BucklingPairs out;
  out.factors.resize(order.size());
  out.vectors.resize(x.rows(), order.size());
  for (int k = 0; k < int(order.size()); ++k) {
    out.factors[k] = 1 / mu[order[k]];
    out.vectors.col(k) = x.col(order[k]);
  }
  return out;
}

BucklingPairs denseBuckling(const SparseMatrix& K, const SparseMatrix& KG, int count, int sign) {
  const Eigen::MatrixXd Kd(K), Gd(KG);
  Eigen::LLT<Eigen::MatrixXd> llt(Kd);
  if (llt.info() != Eigen::Success) throw SolveError(kNotPositiveDefinite);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ges(-Gd, Kd);
  if (ges.info() != Eigen::Success)
    throw SolveError("buckling analysis: the dense generalised eigensolver failed");
  return select(ges.eigenvalues(), ges.eigenvectors(), count, sign, muScale(K, KG));
}

/// ARPACK mode 2 (regular inverse, B = K): OP = K^-1 (-KG), inner product K.
BucklingPairs lanczosBuckling(const SparseMatrix& K, const SparseMatrix& KG, int count,
                              int sign) {
  SparseLDLT ldlt;
  ldlt.analyzePattern(K);
  ldlt.factorize(K);
  if (ldlt.info() != Eigen::Success || ldlt.negativePivots() > 0 ||
      !(ldlt.scaledRcond() > 0))
    throw SolveError(kNotPositiveDefinite);
  const a_int n = a_int(K.rows());
  const a_int nev = std::min<a_int>(count, n - 2);
  const a_int ncv = std::min<a_int>(n, std::max<a_int>(4 * nev + 1, 40));
  const a_int lworkl = ncv * (ncv + 8);
  Eigen::VectorXd resid = fixedStart(n);
  std::vector<double> v(std::size_t(n) * ncv), workd(3 * std::size_t(n)), workl(lworkl);
  std::array<a_int, 11> iparam{}, ipntr{};
  iparam[0] = 1;
  iparam[2] = kBucklingRestarts;
  iparam[6] = 2;  // mode 2: regular inverse with B = K
  const auto which = sign > 0 ? arpack::which::largest_algebraic : arpack::which::smallest_algebraic;
  a_int ido = 0, info = 1;  // start from resid (ARPACK's own start would vary from run to run)
  const double tol = 0.0;
  Eigen::VectorXd y(n);
  const ArpackTurn turn;  // from the first dsaupd to dseupd
  while (true) {
    arpack::saupd(ido, arpack::bmat::generalized, n, which, nev, tol, resid.data(), ncv, v.data(),
                  n, iparam.data(), ipntr.data(), workd.data(), workl.data(), lworkl, info);
    Eigen::Map<Eigen::VectorXd> x(&workd[ipntr[0] - 1], n), out(&workd[ipntr[1] - 1], n);
    if (ido == -1 || ido == 1) {
      y = -(KG * x);
      x = y;  // mode 2 wants A x back in place of x
      out = ldlt.solve(y);
    } else if (ido == 2) {
      out = K * x;
    } else {
      break;
    }
  }
  if (info < 0)
    throw SolveError("buckling analysis: ARPACK dsaupd failed with info = " +
                     std::to_string(info));
  if (info == 1)
    throw SolveError("buckling analysis: ARPACK did not converge in " +
                     std::to_string(kBucklingRestarts) + " restarts");
  std::vector<a_int> selected(ncv);
  Eigen::VectorXd d(nev);
  Eigen::MatrixXd z(n, nev);
  arpack::seupd(1, arpack::howmny::ritz_vectors, selected.data(), d.data(), z.data(), n, 0.0,
                arpack::bmat::generalized, n, which, nev, tol, resid.data(), ncv, v.data(), n,
                iparam.data(), ipntr.data(), workd.data(), workl.data(), lworkl, info);
  if (info != 0)
    throw SolveError("buckling analysis: ARPACK dseupd failed with info = " +
                     std::to_string(info));
  for (int k = 0; k < nev; ++k) z.col(k) /= std::sqrt(z.col(k).dot(K * z.col(k)));
  BucklingPairs out = select(d, z, count, sign, muScale(K, KG));
  out.factorEntries = ldlt.factorEntries();
  return out;
}

}  // namespace

BucklingPairs bucklingEigenpairs(const SparseMatrix& K, const SparseMatrix& KG, int count,
                                 int sign) {
  const int n = int(K.rows());
  if (count <= 0 || n == 0) return {};
  if (n <= kDenseBucklingLimit || count >= n - 2) return denseBuckling(K, KG, count, sign);
  return lanczosBuckling(K, KG, count, sign);
}

}  // namespace beamrotor
