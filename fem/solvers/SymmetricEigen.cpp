#include "fem/solvers/SymmetricEigen.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <arpack/arpack.hpp>
#include <cmath>
#include <functional>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>

#include "fem/assembly/ParallelParts.hpp"
#include "fem/solvers/ArpackTurn.hpp"
#include "fem/solvers/DecoupledBlocks.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/MassFactor.hpp"
#include "fem/solvers/SparseLU.hpp"
#include "fem/solvers/StartVector.hpp"
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

/// One step of inverse iteration with a factor of K - sigma M: x <- (K - sigma M)^-1 M x,
/// normalised.
void inverseIterationStep(const SparseLDLT& factor, const SparseMatrix& M, Eigen::VectorXd& x) {
  x = factor.solve(M * x);
  x /= x.norm();
}

double rayleighQuotient(const SparseMatrix& K, const SparseMatrix& M, const Eigen::VectorXd& x) {
  return x.dot(K * x) / x.dot(M * x);
}

/// How fast inverse iteration with a factor of K - sigma M settles: its Rayleigh quotients q_k
/// approach lambda_1 from above with errors shrinking as r^2k, r = (lambda_1 - sigma) /
/// (lambda_2 - sigma) (Parlett, The Symmetric Eigenvalue Problem, ch. 4), so the ratio of
/// successive differences, (q3 - q4) / (q2 - q3), measures r^2. The start holds every mode and
/// is the same on every run: a smooth one (a straight ramp) holds little of a line's lowest,
/// alternating modes and made a tight band look separated. 1 when the differences are all
/// round-off: q moves that little inside a tight cluster (counted as one), and as little once a
/// very well separated lambda_1 is found (then the shift search's first counts end it).
struct Settling {
  double ratio = 1;
  /// q4, a Rayleigh quotient: an upper bound on lambda_1, and from a start that holds every
  /// mode a close one (on the benchmark's line of spans near the band's lower edge, where a
  /// smooth start's quotient lay 3.3 lambda_1 up and cost the search two more counts).
  double quotient = 0;
};

/// The seed of every start here (fem/solvers/StartVector.hpp); the step counts measured for
/// lanczosBasisSize were taken with it.
constexpr unsigned kStartSeed = 20261125u;

Settling settling(const SparseLDLT& factor, const SparseMatrix& K, const SparseMatrix& M) {
  Eigen::VectorXd x = fixedStart(K.rows(), kStartSeed);
  double quotient[5] = {};
  for (int step = 1; step <= 4; ++step) {
    inverseIterationStep(factor, M, x);
    if (step >= 2) quotient[step] = rayleighQuotient(K, M, x);
  }
  const double earlier = quotient[2] - quotient[3], later = quotient[3] - quotient[4];
  const double noise = 1e-12 * std::abs(quotient[4]);
  return {earlier > noise ? std::max(0.0, later) / earlier : 1.0, quotient[4]};
}

/// Below the spectrum (the usual request: the lowest modes), LDL' at sigma when the lowest
/// eigenvalues are separated as seen from it, else at a shift moved up to just below the
/// lowest eigenvalue by Sturm counts; inside the spectrum, UMFPACK's LU at sigma itself.
/// `counter` has factorised K - sigma M already; `below` is its count there.
ShiftedInverse shiftedInverse(SturmCounter& counter, int below, const SparseMatrix& K,
                              const SparseMatrix& M, int count, double sigma) {
  ShiftedInverse op;
  if (below == 0) {
    // When lambda_2 - sigma is over twice lambda_1 - sigma (r^2 < 1/4), the lowest
    // eigenvalues are not clustered as seen from sigma and Lanczos converges fast there: the
    // factor at sigma serves as it is, without the counts of a shift search (a plate's or a
    // grillage's spectrum). Otherwise (a long line of equal spans, a degenerate lowest pair)
    // the shift moves up to just below lambda_1.
    constexpr double kSeparated = 0.25;
    op.shift = sigma;
    const Settling settled = settling(counter.factor(), K, M);
    if (!(settled.ratio < kSeparated)) {
      op.shift = shiftBelowLowest(counter, sigma, settled.quotient, count);
      // The counter's own factor at the shift (the search's last count is often there): its
      // symbolic analysis and storage serve again. A later count overwrites it; the caller
      // refactorises it then.
      counter.below(op.shift);
    }
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

/// How many eigenvalues a Sturm count finds below the `count`-th lowest of `values` (all
/// above the shift, ascending) beyond those of `values` that lie there: modes Lanczos missed
/// (0 when none). The count is taken in the first gap above the `count`-th among the computed
/// eigenvalues and `ritzFloors` (where the unconverged Ritz values place the next ones), where
/// it cannot be off: next to an eigenvalue the inertia of a nearly singular K - tau M, and
/// the computed eigenvalue itself, are uncertain by the round-off of a solve, about 1e-9
/// relative on an ill-conditioned model (a degenerate pair at the top of the list then looked
/// like two missed modes). Without such a gap (a cluster), just below the `count`-th.
int missedBelow(SturmCounter& counter, const Eigen::VectorXd& values,
                const std::vector<double>& ritzFloors, int count, double shift) {
  if (values.size() == 0 || count <= 0) return 0;
  // Points closer than this (relative to their distance from the shift) may be one
  // eigenvalue computed twice or a pair: no gap between them.
  constexpr double kGap = 1e-6;
  const int top = std::min<int>(count, int(values.size())) - 1;
  const double highest = values[top];
  std::vector<double> points(values.begin() + top, values.end());
  for (const double floor : ritzFloors)
    if (floor >= highest) points.push_back(floor);
  std::sort(points.begin(), points.end());
  for (std::size_t j = 0; j + 1 < points.size(); ++j)
    if (points[j + 1] - points[j] > kGap * std::abs(points[j + 1] - shift)) {
      const double tau = 0.5 * (points[j] + points[j + 1]);
      const int found = int((values.array() < tau).count());
      return std::max(0, counter.below(tau) - found);
    }
  const double justBelow = highest - 1e-9 * std::abs(highest - shift) - 1e-12 * std::abs(highest);
  const int found = int((values.head(top + 1).array() < justBelow).count());
  return std::max(0, counter.below(justBelow) - found);
}

struct LanczosRun {
  EigenPairs pairs;
  /// Where the run's Ritz values, converged or not, place eigenvalues: each Ritz value's
  /// lambda less its error estimate, a point at or below an eigenvalue of the pencil's
  /// (Parlett ch. 10: a Ritz value with residual norm e lies within e of an eigenvalue).
  std::vector<double> ritzFloors;
};

/// Shift-invert Lanczos for the `nevWanted` eigenpairs nearest op.shift, in the complement of
/// the M-orthonormal columns of `locked`. With a factor M = G G' (`massFactor`), in standard
/// form on G' (K - shift M)^-1 G (ARPACK's mode 1); else on (K - shift M)^-1 M in the M inner
/// product (mode 3).
LanczosRun lanczos(const SparseMatrix& M, const MassFactor* massFactor, const ShiftedInverse& op,
                   int nevWanted, int basis, const Eigen::MatrixXd& locked) {
  const a_int n = a_int(M.rows());
  const a_int nev = nevWanted;
  const a_int ncv = std::min<a_int>(n, std::max<a_int>(basis, nev + 2));
  const a_int lworkl = ncv * (ncv + 8);
  const bool standard = massFactor != nullptr;
  const arpack::bmat form = standard ? arpack::bmat::identity : arpack::bmat::generalized;
  Eigen::VectorXd resid = fixedStart(n, kStartSeed);
  std::vector<double> v(std::size_t(n) * ncv), workd(3 * std::size_t(n)), workl(lworkl);
  std::array<a_int, 11> iparam{}, ipntr{};
  iparam[0] = 1;                 // exact shifts
  iparam[2] = kMaxRestarts;      // maximum Arnoldi restarts
  iparam[6] = standard ? 1 : 3;  // mode 1 on the symmetric operator, or 3: shift-invert
  a_int ido = 0, info = 1;       // start from resid (ARPACK's own start would vary from run to run)
  const double tol = 0.0;        // machine precision
  Eigen::VectorXd y(n), solution(n);
  const ArpackTurn turn;  // from the first dsaupd to dseupd
  // The complement of the locked X: z -= B (C' z), with B = X and C = M X (X' M z = (M X)' z),
  // or, in standard form, where the vectors are G' x, B = C = G' X.
  Eigen::MatrixXd lockedBasis(n, locked.cols());
  if (standard)
    for (Eigen::Index k = 0; k < locked.cols(); ++k)
      massFactor->multiplyTransposed(locked.col(k), lockedBasis.col(k));
  else
    lockedBasis = locked;
  const Eigen::MatrixXd lockedDual = standard ? lockedBasis : Eigen::MatrixXd(M * locked);
  auto project = [&](auto&& z) {
    if (locked.cols() > 0) z -= lockedBasis * (lockedDual.transpose() * z);
  };
  while (true) {
    arpack::saupd(ido, form, n, arpack::which::largest_magnitude, nev, tol, resid.data(), ncv,
                  v.data(), n, iparam.data(), ipntr.data(), workd.data(), workl.data(), lworkl,
                  info);
    Eigen::Map<Eigen::VectorXd> x(&workd[ipntr[0] - 1], n), out(&workd[ipntr[1] - 1], n);
    if (standard && (ido == -1 || ido == 1)) {
      massFactor->multiply(x, y);
      op.solve(y, solution);
      massFactor->multiplyTransposed(solution, out);
      project(out);
    } else if (ido == -1 || ido == 1) {
      // M x: computed at the start, from ARPACK (which keeps it) after that.
      if (ido == -1)
        y = M * x;
      else
        y = Eigen::Map<Eigen::VectorXd>(&workd[ipntr[2] - 1], n);
      op.solve(y, solution);
      project(solution);
      out = solution;
    } else if (ido == 2) {
      // M symmetric: M' x walks each stored column as a row, a dot product per entry of out,
      // where M x scatters into out (13 % faster: 152 products in 1.29 s against 1.48 s on
      // the planar bench's bending block of 1.9e6 dofs).
      out = M.transpose() * x;
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

  // The Ritz values of the operator the run ended with, mu = 1 / (lambda - shift) in either
  // form, and their error estimates (dsaupd leaves them in workl at ipntr[5] and ipntr[6]);
  // mu +- e is lambda = shift + 1/mu within about e / mu^2.
  LanczosRun run;
  for (a_int k = 0; k < ncv; ++k) {
    const double mu = workl[ipntr[5] - 1 + k], estimate = std::abs(workl[ipntr[6] - 1 + k]);
    if (std::abs(mu) > estimate) run.ritzFloors.push_back(op.shift + 1 / mu - estimate / (mu * mu));
  }

  // Ritz vectors (mode 3 returns lambda; mode 1 the operator's mu and G' x).
  std::vector<a_int> select(ncv);
  Eigen::VectorXd d(nev);
  Eigen::MatrixXd z(n, nev);
  arpack::seupd(1, arpack::howmny::ritz_vectors, select.data(), d.data(), z.data(), n, op.shift,
                form, n, arpack::which::largest_magnitude, nev, tol, resid.data(), ncv, v.data(), n,
                iparam.data(), ipntr.data(), workd.data(), workl.data(), lworkl, info);
  if (info != 0)
    throw SolveError("modal analysis: ARPACK dseupd failed with info = " + std::to_string(info));
  if (standard) {
    // x = G'^-1 (G' x): x' M x = (G' x)' (G' x) = 1 already, as ARPACK's vectors are unit.
    d = (op.shift + d.array().inverse()).matrix();
    for (int k = 0; k < nev; ++k) massFactor->solveTransposed(z.col(k));
  } else {
    for (int k = 0; k < nev; ++k) z.col(k) /= std::sqrt(z.col(k).dot(M * z.col(k)));
  }
  run.pairs.values = d;
  run.pairs.vectors = std::move(z);
  return run;
}

}  // namespace

int lanczosBasisSize(int count) {
  // Every step reorthogonalises against the whole basis, so a larger one costs more per step
  // than it saves in steps, and a smaller one restarts more often. Steps for 10 modes on the
  // planar benchmark's lines of 10^3, 3x10^3, 10^4, 3x10^4 and 10^5 spans (fixed start, shift
  // as found): 21 vectors 55-106, 24 vectors 53-72, 26 vectors 43-57, 28 vectors 46-47, 30
  // vectors 49-51 (4.5 s against 4.7 s inside ARPACK at 10^5 spans); 41 and 50 vectors took
  // 105 and 91 steps at 10^5 spans, and twice the time. With 2.8 a mode also 20 modes (56
  // vectors: 90 steps against 98 with 60) and the 3D grid benchmark's 10 (63 against 69).
  return std::max(int(std::lround(2.8 * count)), 20);
}

namespace {

/// Whether `count` eigenpairs of an n-dof pencil go to the dense solver.
bool densePathSuits(int n, int count) {
  return n <= kDenseLimit || count >= n - 1;
}

/// The pencil taken whole: a dense solve or shift-invert Lanczos.
EigenPairs wholeEigenpairs(const SparseMatrix& K, const SparseMatrix& M, int count, double sigma,
                           std::span<const int> nodeOfRow) {
  const int n = int(K.rows());
  if (densePathSuits(n, count)) {
    EigenPairs dense = denseEigenpairs(K, M, count, sigma);
    dense.shiftUsed = sigma;
    return dense;
  }

  // 1. Factorise K - shift M once, with the shift moved up to the lowest eigenvalues when
  //    sigma lies below all of them.
  //    Meanwhile, on another core, the factor of M for Lanczos in standard form (below).
  // Lanczos multiplies by M about three times per step (its M inner product): without the
  // pattern's exact zeros (in a planar beam the axial dofs never couple with the bending
  // ones, over 40 % of the entries) the products read less memory and give the same sums.
  // A copy only when M holds such zeros (modal analysis passes M without them).
  SparseMatrix pruned;
  const bool holdsZeros =
      std::find(M.valuePtr(), M.valuePtr() + M.nonZeros(), 0.0) != M.valuePtr() + M.nonZeros();
  if (holdsZeros) {
    pruned = M;
    dropExactZeros(pruned);  // the rule the counter's pattern and the statics use
  }
  const SparseMatrix& massNonzeros = holdsZeros ? pruned : M;
  std::unique_ptr<MassFactor> massFactor;
  SturmCounter counter(K, M, nodeOfRow);
  int belowSigma = 0;
  std::optional<ShiftedInverse> shifted;
  runTogether(
      std::size_t(n), [&] { massFactor = MassFactor::ofMass(massNonzeros); },
      [&] {
        belowSigma = counter.below(sigma);
        shifted = shiftedInverse(counter, belowSigma, K, M, count, sigma);
      });
  const ShiftedInverse& op = *shifted;

  // 2. Lanczos; when a Sturm count shows that it missed eigenvalues among the lowest (it can,
  //    with multiple or tightly clustered ones), again in the complement of those it found.
  const int basis = lanczosBasisSize(count);
  LanczosRun run = lanczos(massNonzeros, massFactor.get(), op, count, basis, Eigen::MatrixXd(n, 0));
  EigenPairs& all = run.pairs;
  for (int attempt = 0;; ++attempt) {
    Eigen::VectorXd ascending = all.values;
    std::sort(ascending.begin(), ascending.end());
    const int missed =
        belowSigma == 0 ? missedBelow(counter, ascending, run.ritzFloors, count, op.shift) : 0;
    const int room = n - 2 - int(all.values.size());
    if (missed == 0 || attempt == 2 || room < 1) {
      // Still missing after the retries: the caller reports it (the count itself can be off
      // by a few for a matrix this near singular, so the modes found are not thrown away).
      // The shift was only moved within [sigma, lambda_1): nearest it is still nearest sigma.
      EigenPairs out = nearest(all.values, all.vectors, count, op.shift);
      out.factorEntries = op.factorEntries;
      out.shiftUsed = op.shift;
      out.missedBySturmCount = missed;
      return out;
    }
    // The Sturm check refactorised the counter away from the shift.
    if (op.fromCounter) counter.below(op.shift);
    LanczosRun more =
        lanczos(massNonzeros, massFactor.get(), op, std::min(room, missed + 2), basis, all.vectors);
    const Eigen::Index found = all.values.size(), added = more.pairs.values.size();
    all.values.conservativeResize(found + added);
    all.values.tail(added) = more.pairs.values;
    all.vectors.conservativeResize(Eigen::NoChange, found + added);
    all.vectors.rightCols(added) = more.pairs.vectors;
    // The complement's Ritz values place the eigenvalues not yet found.
    run.ritzFloors = std::move(more.ritzFloors);
  }
}

/// `pairs` of a block, as vectors of the whole pencil's n dofs (zero outside the block).
void appendBlockPairs(const EigenPairs& pairs, const std::vector<int>& dofs, EigenPairs& all) {
  const Eigen::Index had = all.values.size(), added = pairs.values.size();
  all.values.conservativeResize(had + added);
  all.values.tail(added) = pairs.values;
  all.vectors.conservativeResize(Eigen::NoChange, had + added);
  all.vectors.rightCols(added).setZero();
  for (std::size_t k = 0; k < dofs.size(); ++k)
    all.vectors.row(dofs[k]).tail(added) = pairs.vectors.row(Eigen::Index(k));
  all.factorEntries += pairs.factorEntries;
  all.shiftUsed = had == 0 ? pairs.shiftUsed : std::min(all.shiftUsed, pairs.shiftUsed);
  all.missedBySturmCount += pairs.missedBySturmCount;
}

/// How many eigenvalues of the pencil lie within `reach` of sigma, by two Sturm counts; -1 when
/// a count fails (a shift on an eigenvalue). The reach is widened by a relative 1e-9, so that a
/// count is not taken on an eigenvalue equal to the farthest one found in another block (two
/// equal bending planes), where K - tau M is singular: such an equal one is counted instead,
/// and costs one more mode of the rest.
int countWithin(const SparseMatrix& K, const SparseMatrix& M, double sigma, double reach,
                std::span<const int> nodeOfRow) {
  SturmCounter counter(K, M, nodeOfRow);
  const double widened = reach + 1e-9 * (reach + std::abs(sigma));
  const int above = counter.below(sigma + widened), below = counter.below(sigma - widened);
  return above < 0 || below < 0 ? -1 : above - below;
}

}  // namespace

EigenPairs symmetricEigenpairs(const SparseMatrix& K, const SparseMatrix& M, int count,
                               double sigma, std::span<const int> nodeOfRow) {
  const int n = int(K.rows());
  if (count <= 0 || n == 0) return {};
  if (densePathSuits(n, count)) return wholeEigenpairs(K, M, count, sigma, nodeOfRow);
  // Blocks that do not couple are solved apart (fem/solvers/DecoupledBlocks): Lanczos on the
  // largest, where a structure's lowest modes usually all lie, and the rest only when Sturm
  // counts find eigenvalues of it nearer sigma than the farthest the largest gave. Each
  // Lanczos step then reads only its block's vectors: a straight planar line's bending block
  // is two thirds of its dofs, and its axial chains, far stiffer, cost two factorisations.
  // Small blocks (under the dense limit) or many wanted modes are not worth a split.
  const LargestBlock split = largestBlock(K, M);
  if (split.rest.empty() || int(split.dofs.size()) <= kDenseLimit ||
      2 * count > int(split.dofs.size()))
    return wholeEigenpairs(K, M, count, sigma, nodeOfRow);
  EigenPairs all;
  all.vectors.resize(n, 0);
  appendBlockPairs(
      wholeEigenpairs(principalSubmatrix(K, split.dofs), principalSubmatrix(M, split.dofs), count,
                      sigma, entriesAt(nodeOfRow, split.dofs)),
      split.dofs, all);
  const SparseMatrix restK = principalSubmatrix(K, split.rest);
  const SparseMatrix restM = principalSubmatrix(M, split.rest);
  const std::vector<int> restNodes = entriesAt(nodeOfRow, split.rest);
  int wanted = count;
  if (all.values.size() == count) {
    const double reach = (all.values.array() - sigma).abs().maxCoeff();
    const int within = countWithin(restK, restM, sigma, reach, restNodes);
    if (within >= 0) wanted = std::min(count, within);
  }
  if (wanted > 0)
    appendBlockPairs(symmetricEigenpairs(restK, restM, wanted, sigma, restNodes), split.rest, all);
  EigenPairs out = nearest(all.values, all.vectors, count, sigma);
  out.factorEntries = all.factorEntries;
  out.shiftUsed = all.shiftUsed;
  out.missedBySturmCount = all.missedBySturmCount;
  return out;
}

}  // namespace beamrotor
