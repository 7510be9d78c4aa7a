#include "fem/solvers/MassFactor.hpp"

#include <cmath>

#include "fem/solvers/Tolerances.hpp"

namespace beamrotor {

std::unique_ptr<MassFactor> MassFactor::ofMass(const SparseMatrix& M) {
  // Back through G'^-1, the eigenvectors carry round-off of order eps / sqrt(rcond) of the
  // scaled M (van der Sluis: the scaled system's conditioning is what Cholesky sees). Beam
  // elements' consistent masses are far above this; a nearly massless dof is not.
  constexpr double kWellConditioned = 1e-8;
  SparseLDLT ldlt;
  ldlt.analyzePattern(M);
  // Two products with the factor's triangle a step should read less than the three with M
  // they replace: at most as many entries as M (a banded M fills little: a line of equal
  // spans has no rotation-translation mass coupling at its nodes, and its factor fills it).
  if (ldlt.predictedFactorEntries() > double(M.nonZeros())) return nullptr;
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
  if (f.perm) factor->perm_.assign(f.perm, f.perm + M.rows());
  return factor;
}

void MassFactor::multiply(Eigen::Ref<const Eigen::VectorXd> x,
                          Eigen::Ref<Eigen::VectorXd> y) const {
  if (perm_.empty()) {
    y.noalias() = lower_ * x;
    return;
  }
  const Eigen::VectorXd permuted = lower_ * x;
  for (Eigen::Index k = 0; k < x.size(); ++k) y[perm_[k]] = permuted[k];
}

void MassFactor::multiplyTransposed(Eigen::Ref<const Eigen::VectorXd> x,
                                    Eigen::Ref<Eigen::VectorXd> y) const {
  if (perm_.empty()) {
    y.noalias() = lower_.transpose() * x;
    return;
  }
  Eigen::VectorXd permuted(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) permuted[k] = x[perm_[k]];
  y.noalias() = lower_.transpose() * permuted;
}

void MassFactor::solveTransposed(Eigen::Ref<Eigen::VectorXd> x) const {
  Eigen::VectorXd v = x;
  lower_.transpose().triangularView<Eigen::Upper>().solveInPlace(v);
  for (Eigen::Index k = 0; k < x.size(); ++k) x[perm_.empty() ? k : perm_[k]] = v[k];
}

}  // namespace beamrotor
