#include "fem/solvers/MassFactor.hpp"

#include <cmath>

#include "fem/assembly/ParallelParts.hpp"

namespace beamrotor {

std::unique_ptr<MassFactor> MassFactor::ofMass(const SparseMatrix& M) {
  // Back through G'^-1, the eigenvectors carry round-off of order eps / sqrt(rcond) of the
  // scaled M (van der Sluis: the scaled system's conditioning is what Cholesky sees). Beam
  // elements' consistent masses are far above this, and so is a tiny mass on a dof of its
  // own (scaled, it is 1); dofs tied to move nearly as one are not.
  constexpr double kWellConditioned = 1e-8;
  // Two products with the factor's triangle a step should read less than the three with M
  // they replace: at most as many entries as M. In M's own order the factor lies within the
  // lower envelope, a linear count, which a line numbered node by node keeps small (its
  // banded M fills little: equal spans leave no rotation-translation mass coupling at a
  // node, which the factor fills). Other numberings would need a fill-reducing ordering,
  // whose analysis alone cost a tenth of the solve on the 3D grid benchmark, to find out.
  if (double(lowerEnvelope(M)) > double(M.nonZeros())) return nullptr;
  SparseLDLT ldlt;
  ldlt.analyzePattern(M);
  if (ldlt.factorView().perm || ldlt.predictedFactorEntries() > double(M.nonZeros()))
    return nullptr;
  ldlt.factorize(M);
  if (ldlt.info() != Eigen::Success || ldlt.negativePivots() > 0 ||
      !(ldlt.scaledRcond() > kWellConditioned))
    return nullptr;
  // L D^1/2 as a matrix of its own, whose products are plain sparse ones.
  const SparseLDLT::FactorView f = ldlt.factorView();
  std::unique_ptr<MassFactor> factor(new MassFactor);
  SparseMatrix& G = factor->lower_;
  G.resize(M.rows(), M.cols());
  G.reserve(Eigen::VectorXi(Eigen::Map<const Eigen::VectorXi>(f.L.innerNonZeroPtr(), M.cols())));
  for (Eigen::Index j = 0; j < M.cols(); ++j) {
    const double root = std::sqrt(f.pivot(j));
    G.insert(j, j) = root;
    Eigen::Map<const SparseMatrix>::InnerIterator below(f.L, j);  // at the diagonal
    for (++below; below; ++below) G.insert(below.row(), j) = below.value() * root;
  }
  G.makeCompressed();
  factor->rows_ = G;
  return factor;
}

namespace {

/// y_i = sum over the stored entries of row (or column) i of A, in their stored order: one
/// dot product per entry of y, entries split over the cores.
template <class Compressed>
void dotPerOuter(const Compressed& A, Eigen::Ref<const Eigen::VectorXd> x,
                 Eigen::Ref<Eigen::VectorXd> y) {
  const int* start = A.outerIndexPtr();
  const int* index = A.innerIndexPtr();
  const double* value = A.valuePtr();
  forEvenParts(int(A.outerSize()), [&](int first, int end) {
    for (int i = first; i < end; ++i) {
      double sum = 0;
      for (int k = start[i]; k < start[i + 1]; ++k) sum += value[k] * x[index[k]];
      y[i] = sum;
    }
  });
}

}  // namespace

void MassFactor::multiply(Eigen::Ref<const Eigen::VectorXd> x,
                          Eigen::Ref<Eigen::VectorXd> y) const {
  dotPerOuter(rows_, x, y);
}

void MassFactor::multiplyTransposed(Eigen::Ref<const Eigen::VectorXd> x,
                                    Eigen::Ref<Eigen::VectorXd> y) const {
  // Each stored column read as a row of G'.
  dotPerOuter(lower_, x, y);
}

void MassFactor::solveTransposed(Eigen::Ref<Eigen::VectorXd> x) const {
  lower_.transpose().triangularView<Eigen::Upper>().solveInPlace(x);
}

}  // namespace beamrotor
