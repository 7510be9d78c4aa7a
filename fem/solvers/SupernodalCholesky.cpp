// Supernodal Cholesky by CHOLMOD (see SupernodalCholesky.hpp).
#include "fem/solvers/SupernodalCholesky.hpp"

#include <Eigen/CholmodSupport>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace beamrotor {

SupernodalCholesky::SupernodalCholesky() {
  cholmod_start(&common_);
  common_.print = 0;  // a matrix that is not positive definite is reported, never printed
  common_.supernodal = CHOLMOD_SUPERNODAL;
  common_.final_ll = 1;
  common_.grow2 = 0;  // factors are recomputed, never updated: no room kept for updates
}

SupernodalCholesky::~SupernodalCholesky() {
  if (factor_) cholmod_free_factor(&factor_, &common_);
  cholmod_finish(&common_);
}

void SupernodalCholesky::analyse(const SparseMatrix& A, const std::vector<int>& order) {
  if (factor_) cholmod_free_factor(&factor_, &common_);
  factorised_ = false;
  common_.nmethods = 1;
  common_.method[0].ordering = CHOLMOD_GIVEN;
  common_.postorder = 1;
  cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Upper>());
  std::vector<int> perm = order;
  factor_ = cholmod_analyze_p(&view, perm.data(), nullptr, 0, &common_);
  if (!factor_) throw std::runtime_error("CHOLMOD's supernodal analysis failed");
}

bool SupernodalCholesky::factorize(const SparseMatrix& A) {
  if (!factor_) throw std::logic_error("SupernodalCholesky::factorize before analyse");
  diagonal_ = A.diagonal();
  cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Upper>());
  cholmod_factorize(&view, factor_, &common_);
  factorised_ = common_.status == CHOLMOD_OK && factor_->minor == factor_->n;
  cholmod_free_work(&common_);
  return factorised_;
}

void SupernodalCholesky::solveInto(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  if (!factorised_) throw std::logic_error("SupernodalCholesky::solveInto without a factor");
  Eigen::VectorXd rhs = b;
  cholmod_dense in{};
  in.nrow = in.d = std::size_t(rhs.size());
  in.ncol = 1;
  in.nzmax = in.nrow;
  in.x = rhs.data();
  in.xtype = CHOLMOD_REAL;
  in.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* out = cholmod_solve(CHOLMOD_A, factor_, &in, &common_);
  if (!out) throw std::runtime_error("CHOLMOD's supernodal solve failed");
  x = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(out->x), rhs.size());
  cholmod_free_dense(&out, &common_);
}

std::pair<double, double> SupernodalCholesky::scaledPivotRange() const {
  if (!factorised_ || diagonal_.size() != Eigen::Index(factor_->n)) return {0, 0};
  // Supernode s holds columns super[s] .. super[s + 1] - 1 as one dense column-major block of
  // pi[s + 1] - pi[s] rows starting at x[px[s]]; its diagonal entries lead each column.
  const auto* super = static_cast<const int*>(factor_->super);
  const auto* pi = static_cast<const int*>(factor_->pi);
  const auto* px = static_cast<const int*>(factor_->px);
  const auto* x = static_cast<const double*>(factor_->x);
  const auto* perm = static_cast<const int*>(factor_->Perm);
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for (std::size_t s = 0; s < factor_->nsuper; ++s) {
    const int rows = pi[s + 1] - pi[s];
    for (int j = super[s]; j < super[s + 1]; ++j) {
      const int k = j - super[s];
      const double l = x[px[s] + std::size_t(k) * rows + k];
      const double a = diagonal_[perm ? perm[j] : j];
      if (!(a > 0)) return {0, 0};
      const double pivot = l * l / a;
      if (!std::isfinite(pivot)) return {0, 0};
      smallest = std::min(smallest, pivot);
      largest = std::max(largest, pivot);
    }
  }
  return largest > 0 ? std::pair{smallest, largest} : std::pair{0.0, 0.0};
}

double SupernodalCholesky::factorEntries() const {
  if (!factor_) return 0;
  const auto* counts = static_cast<const int*>(factor_->ColCount);
  return std::accumulate(counts, counts + factor_->n, 0.0);
}

}  // namespace beamrotor
