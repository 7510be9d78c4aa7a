#include "fem/rotor/RotorEigen.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <arpack/arpack.hpp>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>
#include <type_traits>

#include "fem/solvers/ArpackTurn.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/RotorFactor.hpp"
#include "fem/solvers/StartVector.hpp"

namespace beamrotor {

struct QuadraticEigenSolver::Factors {
  // No iterative refinement: Arnoldi applies the inverse hundreds of times.
  RepeatedFactor<double> real{false};
  RepeatedFactor<std::complex<double>> complex{false};
  // Starting vectors for the next call (the last converged modes).
  Eigen::VectorXd realStart;
  Eigen::VectorXcd complexStart;
};

QuadraticEigenSolver::QuadraticEigenSolver() : factors_(std::make_unique<Factors>()) {}
QuadraticEigenSolver::~QuadraticEigenSolver() = default;

int QuadraticEigenSolver::analyses() const {
  return factors_->real.analyses() + factors_->complex.analyses();
}

namespace {

using Complex = std::complex<double>;

// Below this many state variables a dense eigensolver is used. Measured on the bench rotor
// (50-speed Campbell diagrams, 4 to 12 modes): Arnoldi is 16x faster at 72 states and 50x to
// 500x faster from 136 to 360 states, so only tiny systems go dense.
constexpr int kDenseLimit = 32;
constexpr int kMaxRestarts = 1000;
// |nu| below this fraction of the largest is an infinite eigenvalue (singular M): a dense
// solver returns those as round-off of size eps * max |nu|.
constexpr double kInfiniteEigenvalue = 1e-13;

std::string singularShiftMessage(Complex sigma, double rcond) {
  std::ostringstream msg;
  msg << "rotor modes: K + sigma D + sigma^2 M is singular at shift sigma = " << sigma
      << " (rcond = " << rcond << "): the shift coincides with an eigenvalue";
  if (sigma == 0.0)
    msg << ", i.e. the rotor has a rigid-body mode (free-free, or a missing bearing); give a "
           "negative real shift (e.g. -1) to compute it";
  return msg.str();
}

template <class Scalar>
SparseMatrixOf<Scalar> as(const SparseMatrix& A) {
  if constexpr (std::is_same_v<Scalar, double>)
    return A;
  else
    return A.cast<Scalar>();
}

/// The `count` pairs (lambda, q) nearest sigma, nearest first; q scaled to unit norm with its
/// largest entry real and positive (a reproducible phase).
QuadraticEigenpairs nearest(const std::vector<Complex>& lambda,
                            const std::vector<Eigen::VectorXcd>& q, int count, Complex sigma) {
  std::vector<int> order(lambda.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return std::abs(lambda[a] - sigma) < std::abs(lambda[b] - sigma);
  });
  order.resize(std::min<std::size_t>(count, order.size()));
  QuadraticEigenpairs out;
  out.values.resize(order.size());
  out.vectors.resize(q.empty() ? 0 : q.front().size(), order.size());
  for (int k = 0; k < int(order.size()); ++k) {
    out.values[k] = lambda[order[k]];
    Eigen::VectorXcd v = q[order[k]];
    Eigen::Index big = 0;
    v.cwiseAbs2().maxCoeff(&big);  // |v|^2: no hypot per entry (4 % of a Campbell sweep)
    v *= std::abs(v[big]) / v[big];
    out.vectors.col(k) = v / v.norm();
  }
  return out;
}

/// Scale s of the state x = (q, lambda q / s): with s near the |lambda| sought, both halves of
/// an eigenvector have similar size, which keeps the non-normal OP well balanced (a diagonal
/// similarity: the eigenvalues do not change, their round-off does, by orders of magnitude
/// for stiff systems). Estimated from three steps of inverse iteration on P(sigma)^-1 M, whose
/// Rayleigh quotient |x^H K x / x^H M x| approximates omega^2 of the modes nearest sigma.
template <class Scalar, class Solve>
double stateScale(const Solve& solveP, const SparseMatrix& K, const SparseMatrix& M, Scalar sigma) {
  using Vec = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  Vec x = Vec::Ones(K.rows());
  for (int it = 0; it < 3; ++it) {
    x = solveP(Vec(M.template cast<Scalar>() * x));
    const double size = x.norm();
    if (!(size > 0) || !std::isfinite(size)) break;
    x /= size;
  }
  const double kx = std::abs(x.dot(K.template cast<Scalar>() * x));
  const double mx = std::abs(x.dot(M.template cast<Scalar>() * x));
  const double s = mx > 0 ? std::sqrt(kx / mx) : 0;
  if (s > 0 && std::isfinite(s)) return std::max(s, std::abs(sigma));
  return std::abs(sigma) > 0 ? std::abs(sigma) : 1.0;
}

/// Dense path: OP built column by column from the same block elimination, then a complex
/// eigensolver. O(n^3), for small systems only.
template <class Scalar>
QuadraticEigenpairs denseEigenpairs(const SparseMatrix& K, const SparseMatrix& D,
                                    const SparseMatrix& M, int count, Scalar sigma) {
  using Mat = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  const int n = int(K.rows());
  const Mat Md = Mat(as<Scalar>(M));
  const Mat Ds = Mat(as<Scalar>(D)) + sigma * Md;  // D + sigma M
  const Mat P = Mat(as<Scalar>(K)) + sigma * Ds;   // K + sigma D + sigma^2 M
  const Eigen::PartialPivLU<Mat> lu(P);
  const double rcond = lu.rcond();
  if (!(rcond > kSingularRcond)) throw SolveError(singularShiftMessage(sigma, rcond));
  const double s = stateScale(
      [&](const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& b) { return lu.solve(b).eval(); }, K, M,
      sigma);
  // OP x = (y1, (x1 + sigma y1) / s) with y1 = -P^-1 (Ds x1 + s M x2).
  Mat T(2 * n, 2 * n);
  T.topLeftCorner(n, n) = -lu.solve(Ds);
  T.topRightCorner(n, n) = -s * lu.solve(Md);
  T.bottomLeftCorner(n, n) = (Mat::Identity(n, n) + sigma * T.topLeftCorner(n, n)) / s;
  T.bottomRightCorner(n, n) = sigma / s * T.topRightCorner(n, n);
  const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(T.template cast<Complex>());
  if (es.info() != Eigen::Success) throw SolveError("rotor modes: the dense eigensolver failed");
  const double numax = es.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<Complex> lambda;
  std::vector<Eigen::VectorXcd> q;
  for (int k = 0; k < 2 * n; ++k) {
    const Complex nu = es.eigenvalues()[k];
    if (std::abs(nu) <= kInfiniteEigenvalue * numax) continue;
    lambda.push_back(Complex(sigma) + 1.0 / nu);
    q.push_back(es.eigenvectors().col(k).head(n));
  }
  return nearest(lambda, q, count, sigma);
}

template <class Scalar>
using RowMajorSparseOf = Eigen::SparseMatrix<Scalar, Eigen::RowMajor, int>;

/// The n x 2n matrix [A  s B] by rows: OP's sparse product in one pass, each row a dot
/// product. Two column-major products scatter into the result instead, and measured 16 % of
/// a 200-element Campbell sweep.
template <class Scalar>
RowMajorSparseOf<Scalar> sideBySide(const SparseMatrixOf<Scalar>& A,
                                    const SparseMatrixOf<Scalar>& B, double s) {
  const Eigen::Index n = A.cols();
  SparseMatrixOf<Scalar> AB(A.rows(), n + B.cols());
  AB.reserve(A.nonZeros() + B.nonZeros());
  for (Eigen::Index j = 0; j < n; ++j) {
    AB.startVec(j);
    for (typename SparseMatrixOf<Scalar>::InnerIterator it(A, j); it; ++it)
      AB.insertBack(it.row(), j) = it.value();
  }
  for (Eigen::Index j = 0; j < B.cols(); ++j) {
    AB.startVec(n + j);
    for (typename SparseMatrixOf<Scalar>::InnerIterator it(B, j); it; ++it)
      AB.insertBack(it.row(), n + j) = s * it.value();
  }
  AB.finalize();
  return RowMajorSparseOf<Scalar>(AB);
}

/// ARPACK's Krylov basis size for nev eigenvalues. ARPACK's guide suggests ncv >= 2 nev; past
/// nev 18 a fixed 20 extra vectors do as well, while the orthogonalisation (ARPACK's largest
/// cost) grows with ncv^2 and the projected QR with ncv^3. Measured on the bench rotor
/// (200 elements, warm starts, operator products per speed): nev 36: ncv 74 -> 93, ncv 56 ->
/// 87; nev 32: ncv 66 -> 67, ncv 52 -> 53; the eigenvalues agree to 2e-13 (ARPACK's tol).
a_int basisSize(a_int nev) {
  return std::max<a_int>(std::min<a_int>(2 * nev + 2, nev + 20), 20);
}

/// ARPACK reverse communication on OP in regular mode (mode 1, B = I), nu of largest
/// magnitude: the eigenvalues lambda = sigma + 1/nu nearest sigma. `start` (state length, or
/// empty) seeds the iteration and receives a combination of the converged vectors, so the
/// next speed of a sweep starts from this one's modes.
template <class Scalar>
QuadraticEigenpairs arnoldiEigenpairs(const SparseMatrix& K, const SparseMatrix& D,
                                      const SparseMatrix& M, int count, Scalar sigma,
                                      RepeatedFactor<Scalar>& factor,
                                      Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& start) {
  using Vec = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  constexpr bool isReal = std::is_same_v<Scalar, double>;
  const int n = int(K.rows());
  const a_int N = 2 * n;

  // 1. Factorise P(sigma) = K + sigma (D + sigma M); scale the state.
  const SparseMatrixOf<Scalar> Ms = as<Scalar>(M);
  const SparseMatrixOf<Scalar> Ds = as<Scalar>(D) + sigma * Ms;
  if (!factor.factorize(as<Scalar>(K) + sigma * Ds))
    throw SolveError(singularShiftMessage(sigma, factor.rcond()));
  const double s = stateScale([&](const Vec& b) { return Vec(factor.solve(b)); }, K, M, sigma);
  const RowMajorSparseOf<Scalar> DsM = sideBySide(Ds, Ms, s);

  // 2. Arnoldi iteration. The real driver needs ncv - nev >= 2, the complex one >= 1.
  const a_int nev = count;
  a_int ncv = std::min<a_int>(N, basisSize(nev));
  a_int lworkl = 0;
  std::vector<Scalar> resid, v, workd, workl;
  std::vector<double> rwork;
  std::array<a_int, 11> iparam{};
  std::array<a_int, 14> ipntr{};
  a_int info = 0;
  // Ritz residuals below 1e-13 |nu|: machine precision (ARPACK's tol = 0) costs twice the
  // restarts for digits the shift-invert round-off does not deliver (the tests measure
  // 1e-10 relative eigenvalue accuracy or better either way).
  const double tol = 1e-13;
  // info -8: LAPACK's Hessenberg QR (dlahqr, inside ARPACK's dneigh) did not converge on the
  // projected matrix H. It happens when H holds near-defective blocks: an isotropic rotor's
  // exactly double whirl pairs, and the Jordan-like cluster at nu = 0 of nearly massless dofs
  // (eigenvalues of size sqrt(eps) |H|). Whether dlahqr's iteration budget suffices then
  // turns on the last bit of H (one ulp of dnrm2 decides it: reference BLAS passes, OpenBLAS
  // fails, on the same H), so the start is retried from another fixed start (not ARPACK's
  // own random one, whose generator state would make the result depend on earlier calls),
  // and then with a larger basis: each gives a different H; the answers are ARPACK's
  // converged Ritz pairs either way. info 3 (no shift could be applied in a restart: the
  // wanted and unwanted Ritz values did not separate within the basis) turns on the same last
  // bits (jeffcott_api684's modes and rotor_on_pedestals.yaml's met it with one processor's
  // OpenBLAS kernels, not another's) and is what ARPACK's guide answers with a larger basis:
  // the same retries. So is a Schur form of H that LAPACK's dtrsen could not reorder when the
  // Ritz vectors are formed (dneupd's info 1, on the same near-defective clusters).
  std::vector<a_int> select;
  std::vector<double> dr, di, zReal;        // the real driver's Ritz values and vectors
  std::vector<Complex> dComplex, zComplex;  // the complex driver's
  const auto ritzPairs = [&] {
    a_int ritzInfo = 0;
    select.assign(ncv, 0);
    if constexpr (isReal) {
      dr.assign(nev + 1, 0.0);
      di.assign(nev + 1, 0.0);
      zReal.assign(std::size_t(N) * (nev + 1), 0.0);
      std::vector<double> workev(3 * ncv);
      arpack::neupd(1, arpack::howmny::ritz_vectors, select.data(), dr.data(), di.data(),
                    zReal.data(), N, sigma, 0.0, workev.data(), arpack::bmat::identity, N,
                    arpack::which::largest_magnitude, nev, tol, resid.data(), ncv, v.data(), N,
                    iparam.data(), ipntr.data(), workd.data(), workl.data(), lworkl, ritzInfo);
    } else {
      dComplex.assign(nev + 1, Complex(0));
      zComplex.assign(std::size_t(N) * nev, Complex(0));
      std::vector<Complex> workev(2 * ncv);
      arpack::neupd(1, arpack::howmny::ritz_vectors, select.data(), dComplex.data(),
                    zComplex.data(), N, sigma, workev.data(), arpack::bmat::identity, N,
                    arpack::which::largest_magnitude, nev, tol, resid.data(), ncv, v.data(), N,
                    iparam.data(), ipntr.data(), workd.data(), workl.data(), lworkl, rwork.data(),
                    ritzInfo);
    }
    return ritzInfo;
  };
  a_int ritzInfo = 0;
  const bool warm = start.size() == N && start.norm() > 0;
  const ArpackTurn turn;  // from the first dnaupd to dneupd (or znaupd to zneupd)
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (attempt == 2) ncv = std::min<a_int>(N, 2 * ncv);
    lworkl = isReal ? 3 * ncv * ncv + 6 * ncv : 3 * ncv * ncv + 5 * ncv;
    resid.assign(N, Scalar(0));
    v.assign(std::size_t(N) * ncv, Scalar(0));
    workd.assign(3 * std::size_t(N), Scalar(0));
    workl.assign(lworkl, Scalar(0));
    rwork.assign(ncv, 0.0);
    iparam.fill(0);
    ipntr.fill(0);
    iparam[0] = 1;             // exact shifts
    iparam[2] = kMaxRestarts;  // maximum Arnoldi restarts
    iparam[6] = 1;             // mode 1: OP supplied by us, B = I
    a_int ido = 0;
    info = 1;  // resid holds the starting vector
    if (warm && attempt == 0)
      Eigen::Map<Vec>(resid.data(), N) = start;
    else if (attempt == 0 || (warm && attempt == 1))
      Eigen::Map<Vec>(resid.data(), N) = fixedStart(N).template cast<Scalar>();
    else
      Eigen::Map<Vec>(resid.data(), N) = fixedStart(N, 19890601u + attempt).template cast<Scalar>();
    while (true) {
      if constexpr (isReal)
        arpack::naupd(ido, arpack::bmat::identity, N, arpack::which::largest_magnitude, nev, tol,
                      resid.data(), ncv, v.data(), N, iparam.data(), ipntr.data(), workd.data(),
                      workl.data(), lworkl, info);
      else
        arpack::naupd(ido, arpack::bmat::identity, N, arpack::which::largest_magnitude, nev, tol,
                      resid.data(), ncv, v.data(), N, iparam.data(), ipntr.data(), workd.data(),
                      workl.data(), lworkl, rwork.data(), info);
      if (ido != -1 && ido != 1) break;
      // y = OP x = (y1, (x1 + sigma y1) / s), y1 = -P^-1 [Ds  s M] x.
      const Eigen::Map<const Vec> x(&workd[ipntr[0] - 1], N);
      Eigen::Map<Vec> y(&workd[ipntr[1] - 1], N);
      const Vec y1 = factor.solve(Vec(-(DsM * x)));
      y.tail(n) = (x.head(n) + sigma * y1) / s;
      y.head(n) = y1;
    }
    if (info == 0) {
      ritzInfo = ritzPairs();
      if (ritzInfo == 0) break;
    } else if (info != -8 && info != 3) {
      break;
    }
  }
  if (info < 0)
    throw SolveError("rotor modes: ARPACK naupd failed with info = " + std::to_string(info));
  if (info == 1)
    throw SolveError("rotor modes: ARPACK did not converge in " + std::to_string(kMaxRestarts) +
                     " restarts (" + std::to_string(iparam[4]) + " of " + std::to_string(nev) +
                     " eigenvalues)");
  if (info == 3) throw SolveError("rotor modes: ARPACK could not apply shifts; ask for more modes");
  if (ritzInfo != 0)
    throw SolveError(std::string("rotor modes: ARPACK ") + (isReal ? "dneupd" : "zneupd") +
                     " failed with info = " + std::to_string(ritzInfo));

  // 3. Ritz pairs of OP, back to lambda. The real driver stores a complex pair's vector as
  // two columns (real part, imaginary part), the first of the pair having Im nu > 0.
  std::vector<Complex> lambda;
  std::vector<Eigen::VectorXcd> q;
  start = Vec::Zero(N);
  auto add = [&](Complex nu, const Eigen::VectorXcd& x) {
    if (nu == 0.0) return;
    lambda.push_back(Complex(sigma) + 1.0 / nu);
    q.push_back(x.head(n));
  };
  if constexpr (isReal) {
    const int nconv = int(iparam[4]);
    auto column = [&](int j) {
      return Eigen::Map<const Eigen::VectorXd>(&zReal[std::size_t(j) * N], N);
    };
    for (int j = 0; j < nconv; ++j) {
      start += column(j) / column(j).norm();
      if (di[j] == 0) {
        add(dr[j], column(j).template cast<Complex>());
      } else if (j + 1 <= nev) {
        const Eigen::VectorXcd x = column(j).template cast<Complex>() +
                                   Complex(0, 1) * column(j + 1).template cast<Complex>();
        add(Complex(dr[j], di[j]), x);
        add(Complex(dr[j], -di[j]), x.conjugate());
        ++j;
      }
    }
  } else {
    for (int j = 0; j < int(iparam[4]); ++j) {
      const Eigen::Map<const Eigen::VectorXcd> x(&zComplex[std::size_t(j) * N], N);
      start += x / x.norm();
      add(dComplex[j], x);
    }
  }
  QuadraticEigenpairs out = nearest(lambda, q, count, sigma);
  out.factorEntries = factor.factorEntries();
  return out;
}

}  // namespace

QuadraticEigenpairs QuadraticEigenSolver::solve(const SparseMatrix& K, const SparseMatrix& D,
                                                const SparseMatrix& M, int count,
                                                std::complex<double> shift, EigenMethod method) {
  const int n = int(K.rows());
  if (count <= 0 || n == 0) return {};
  count = std::min(count, 2 * n);
  const bool real = shift.imag() == 0;
  // ARPACK needs nev <= N - 2 and room for the Krylov basis.
  const bool dense = method == EigenMethod::dense ||
                     (method == EigenMethod::automatic && 2 * n <= kDenseLimit) ||
                     count > 2 * n - 3;
  if (dense)
    return real ? denseEigenpairs<double>(K, D, M, count, shift.real())
                : denseEigenpairs<Complex>(K, D, M, count, shift);
  return real ? arnoldiEigenpairs<double>(K, D, M, count, shift.real(), factors_->real,
                                          factors_->realStart)
              : arnoldiEigenpairs<Complex>(K, D, M, count, shift, factors_->complex,
                                           factors_->complexStart);
}

}  // namespace beamrotor
