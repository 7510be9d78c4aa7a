// Extreme points of a point set (see ExtremePoints.hpp).
#include "fem/assembly/ExtremePoints.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

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

/// The arithmetic (tableau entries updated) all the programmes of one set may take, about a
/// tenth of a second: past it the points not yet tested are kept (many points of many
/// cases, most of them corners, would otherwise cost seconds to show what saves little).
constexpr long long kBudget = 200'000'000;

/// Whether `target` is a convex combination of the columns of `others`, each coordinate
/// divided by `scale` (the largest of all): weights found by the first phase of the simplex
/// method (one artificial variable per equation, Bland's rule of the lowest index, so it
/// cannot cycle) and then checked in the unscaled coordinates. Each pivot's work is taken
/// from `budget`; false once it is spent.
bool insideHullOf(const Eigen::MatrixXd& others, const Eigen::VectorXd& target, double scale,
                  long long& budget) {
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
    budget -= (m + 1) * (n + m + 1);
    if (budget < 0) return false;
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

/// The columns of `points`' rows listed in `rows`.
Eigen::MatrixXd columnsOf(const Eigen::MatrixXd& points, const std::vector<Eigen::Index>& rows) {
  Eigen::MatrixXd out(points.cols(), Eigen::Index(rows.size()));
  for (std::size_t j = 0; j < rows.size(); ++j)
    out.col(Eigen::Index(j)) = points.row(rows[j]).transpose();
  return out;
}

/// Rows that are the largest along some direction (each coordinate's both ways and a fixed
/// set of others), ascending: most extreme points of a set, which most other points are
/// inside the hull of, so a small programme shows it.
std::vector<Eigen::Index> likelyCorners(const Eigen::MatrixXd& points) {
  const Eigen::Index k = points.cols();
  Eigen::MatrixXd directions = Eigen::MatrixXd::Zero(k, 2 * k + 8 * k);
  for (Eigen::Index j = 0; j < k; ++j) directions(j, 2 * j) = 1, directions(j, 2 * j + 1) = -1;
  std::mt19937 random(1);  // fixed: the same directions on every run
  std::normal_distribution<double> normal;
  for (Eigen::Index d = 2 * k; d < directions.cols(); ++d)
    for (Eigen::Index j = 0; j < k; ++j) directions(j, d) = normal(random);
  const Eigen::MatrixXd values = points * directions;
  std::vector<Eigen::Index> out;
  for (Eigen::Index d = 0; d < values.cols(); ++d) {
    Eigen::Index top = 0;
    values.col(d).maxCoeff(&top);
    out.push_back(top);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

std::vector<bool> extremePoints(const Eigen::MatrixXd& points) {
  const Eigen::Index count = points.rows();
  std::vector<bool> kept(std::size_t(count), true);
  std::vector<Eigen::Index> all(static_cast<std::size_t>(count));
  std::iota(all.begin(), all.end(), Eigen::Index(0));
  // Repeats: sorted by coordinates (then by index), each row after an equal one left out.
  std::vector<Eigen::Index> order = all;
  const auto less = [&](Eigen::Index a, Eigen::Index b) {
    for (Eigen::Index j = 0; j < points.cols(); ++j)
      if (points(a, j) != points(b, j)) return points(a, j) < points(b, j);
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  for (std::size_t i = 1; i < order.size(); ++i)
    if (points.row(order[i]) == points.row(order[i - 1])) kept[std::size_t(order[i])] = false;
  const double scale = points.size() > 0 ? points.cwiseAbs().maxCoeff() : 0.0;
  if (!(scale > 0) || !std::isfinite(scale)) return kept;
  // Each point against those still kept, first against the likely corners among them (a small
  // programme), then, if that does not show it inside, against all, while the budget lasts. A
  // point left out is inside the hull of the points kept at the end (up to kMiss for each
  // point left out before it).
  const std::vector<Eigen::Index> corners = likelyCorners(points);
  const auto keptBut = [&](const std::vector<Eigen::Index>& rows, Eigen::Index c) {
    std::vector<Eigen::Index> out;
    for (Eigen::Index j : rows)
      if (j != c && kept[std::size_t(j)]) out.push_back(j);
    return out;
  };
  long long budget = kBudget;
  for (Eigen::Index c = 0; c < count && budget > 0; ++c) {
    if (!kept[std::size_t(c)]) continue;
    const Eigen::VectorXd target = points.row(c).transpose();
    const std::vector<Eigen::Index> few = keptBut(corners, c);
    if (!few.empty() && insideHullOf(columnsOf(points, few), target, scale, budget)) {
      kept[std::size_t(c)] = false;
      continue;
    }
    const std::vector<Eigen::Index> others = keptBut(all, c);
    if (others.size() > few.size() &&
        insideHullOf(columnsOf(points, others), target, scale, budget))
      kept[std::size_t(c)] = false;
  }
  return kept;
}

}  // namespace beamrotor
