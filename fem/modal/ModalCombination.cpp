#include "fem/modal/ModalCombination.hpp"

#include <cmath>

namespace beamrotor {

double cqcCorrelation(double wi, double wj, double xi) {
  const double r = wj / wi;
  const double num = 8 * xi * xi * (1 + r) * std::pow(r, 1.5);
  const double den = (1 - r * r) * (1 - r * r) + 4 * xi * xi * r * (1 + r) * (1 + r);
  return den > 0 ? num / den : 1;
}

Eigen::MatrixXd modalCorrelations(const std::vector<double>& omega, double dampingRatio,
                                  ModalRule rule) {
  const int n = int(omega.size());
  Eigen::MatrixXd rho = Eigen::MatrixXd::Identity(n, n);
  if (rule == ModalRule::cqc)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (i != j) rho(i, j) = cqcCorrelation(omega[i], omega[j], dampingRatio);
  return rho;
}

Eigen::VectorXd combineModes(const Eigen::MatrixXd& modal, const Eigen::MatrixXd& rho) {
  // rho is positive semi-definite, so each q' rho q >= 0 up to round-off: clip that at zero.
  const Eigen::MatrixXd weighted = modal * rho;
  return weighted.cwiseProduct(modal).rowwise().sum().cwiseMax(0.0).cwiseSqrt();
}

std::vector<std::vector<double>> directionalFactors(std::size_t count, DirectionalRule rule) {
  if (rule == DirectionalRule::srss) return {std::vector<double>(count, 1.0)};
  std::vector<std::vector<double>> out;
  for (std::size_t d = 0; d < count; ++d) {
    std::vector<double> factors(count, 0.3);
    factors[d] = 1;
    out.push_back(std::move(factors));
  }
  return out;
}

Eigen::VectorXd combineDirectionsAs(const Eigen::MatrixXd& perDirection,
                                    const std::vector<double>& factors, DirectionalRule rule) {
  const Eigen::VectorXd f =
      Eigen::Map<const Eigen::VectorXd>(factors.data(), Eigen::Index(factors.size()));
  if (rule == DirectionalRule::srss) return (perDirection * f.asDiagonal()).rowwise().norm();
  return perDirection * f;
}

Eigen::VectorXd combineDirections(const Eigen::MatrixXd& perDirection, DirectionalRule rule) {
  Eigen::VectorXd best = Eigen::VectorXd::Zero(perDirection.rows());
  for (const std::vector<double>& factors :
       directionalFactors(std::size_t(perDirection.cols()), rule))
    best = best.cwiseMax(combineDirectionsAs(perDirection, factors, rule));
  return best;
}

}  // namespace beamrotor
