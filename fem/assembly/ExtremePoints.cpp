// Extreme points of a point set (see ExtremePoints.hpp).
#include "fem/assembly/ExtremePoints.hpp"

#include <cmath>

namespace beamrotor {

namespace {

/// Pivots no larger than this (in a tableau whose coordinates are scaled to at most 1) are
/// not taken: they would divide by round-off.
constexpr double kSmallestPivot = 1e-11;

/// How far (a share of the largest coordinate) a combination of the others may miss a point
/// that is called inside their hull: round-off of a few operations on numbers of that size.
/// What is then left out can exceed what is kept by no more than this share of a function's
/// gradient.
constexpr double kMiss = 1e-12;

/// Whether `target` is a convex combination of the columns of `others`, each coordinate
/// divided by `scale` (the largest of all): weights found by the first phase of the simplex
/// method (one artificial variable per equation, Bland's rule of the lowest index, so it
/// cannot cycle) and then checked in the unscaled coordinates.
bool insideHullOf(const Eigen::MatrixXd& others, const Eigen::VectorXd& target, double scale) {
  const Eigen::Index k = others.rows(), n = others.cols(), m = k + 1;
  // Rows: sum_j w_j (others_j - target) = 0 coordinate by coordinate, then sum_j w_j = 1;
  // columns: the weights, the artificial variables, the right-hand side.
  Eigen::MatrixXd tableau = Eigen::MatrixXd::Zero(m, n + m + 1);
  tableau.topLeftCorner(k, n) = (others.colwise() - target) / scale;
  tableau.row(k).head(n).setOnes();
  tableau.block(0, n, m, m).setIdentity();
  tableau(k, n + m) = 1;
  std::vector<Eigen::Index> basis(m);
  for (Eigen::Index i = 0; i < m; ++i) basis[i] = n + i;
  // The reduced costs of minimising the artificial variables' sum, and minus that sum.
  Eigen::RowVectorXd cost = Eigen::RowVectorXd::Zero(n + m + 1);
  cost.head(n) = -tableau.leftCols(n).colwise().sum();
  cost(n + m) = -1;
  for (Eigen::Index step = 0; step < 50 * (n + m); ++step) {
    Eigen::Index entering = -1;
    for (Eigen::Index j = 0; j < n + m && entering < 0; ++j)
      if (cost(j) < -kSmallestPivot) entering = j;
    if (entering < 0) break;
    Eigen::Index leaving = -1;
    double ratio = 0;
    for (Eigen::Index i = 0; i < m; ++i) {
      const double a = tableau(i, entering);
      if (a <= kSmallestPivot) continue;
      const double r = tableau(i, n + m) / a;
      if (leaving < 0 || r < ratio || (r == ratio && basis[i] < basis[leaving]))
        leaving = i, ratio = r;
    }
    if (leaving < 0) return false;  // unbounded: cannot happen in the first phase
    tableau.row(leaving) /= tableau(leaving, entering);
    for (Eigen::Index i = 0; i < m; ++i)
      if (i != leaving) tableau.row(i) -= tableau(i, entering) * tableau.row(leaving);
    cost -= cost(entering) * tableau.row(leaving);
    basis[leaving] = entering;
  }
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < m; ++i)
    if (basis[i] < n) weights(basis[i]) = std::max(0.0, tableau(i, n + m));
  const double sum = weights.sum();
  if (!(sum > 0)) return false;
  weights /= sum;
  return ((others * weights - target).cwiseAbs().maxCoeff() <= kMiss * scale);
}

}  // namespace

std::vector<bool> extremePoints(const Eigen::MatrixXd& points) {
  const Eigen::Index count = points.rows();
  std::vector<bool> kept(std::size_t(count), true);
  for (Eigen::Index i = 0; i < count; ++i)
    for (Eigen::Index j = 0; j < i && kept[std::size_t(i)]; ++j)
      if (kept[std::size_t(j)] && points.row(j) == points.row(i)) kept[std::size_t(i)] = false;
  const double scale = points.size() > 0 ? points.cwiseAbs().maxCoeff() : 0.0;
  if (!(scale > 0) || !std::isfinite(scale)) return kept;
  // Each point against those still kept: a point left out is inside the hull of the points
  // kept at the end (up to kMiss for each point left out before it).
  for (Eigen::Index c = 0; c < count; ++c) {
    if (!kept[std::size_t(c)]) continue;
    std::vector<Eigen::Index> others;
    for (Eigen::Index j = 0; j < count; ++j)
      if (j != c && kept[std::size_t(j)]) others.push_back(j);
    if (others.empty()) continue;
    Eigen::MatrixXd columns(points.cols(), Eigen::Index(others.size()));
    for (std::size_t j = 0; j < others.size(); ++j)
      columns.col(Eigen::Index(j)) = points.row(others[j]).transpose();
    if (insideHullOf(columns, points.row(c).transpose(), scale)) kept[std::size_t(c)] = false;
  }
  return kept;
}

}  // namespace beamrotor
