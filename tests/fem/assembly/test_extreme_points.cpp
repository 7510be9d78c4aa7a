// The extreme points of a point set: a box's corners, a plane polygon's vertices against a
// second method (Andrew's monotone chain in exact integer arithmetic), the same polygon lifted
// into a plane of 3d, points on a line, repeated points, and the largest of linear functions
// over the points kept against the largest over all.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "fem/assembly/ExtremePoints.hpp"

using namespace beamrotor;

// Named, not anonymous: the test sources are compiled in unity batches.
namespace extreme_points {

Eigen::MatrixXd rowsOf(const std::vector<std::vector<double>>& points) {
  Eigen::MatrixXd out(Eigen::Index(points.size()), Eigen::Index(points.front().size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = 0; j < points[i].size(); ++j)
      out(Eigen::Index(i), Eigen::Index(j)) = points[i][j];
  return out;
}

std::vector<std::size_t> keptOf(const std::vector<bool>& flags) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < flags.size(); ++i)
    if (flags[i]) out.push_back(i);
  return out;
}

/// The vertices of the convex hull of integer points (indices, each point's first occurrence,
/// ascending), by Andrew's monotone chain: points on an edge between two vertices are not
/// vertices. Cross products of integers are exact.
std::vector<std::size_t> hullVertices(const std::vector<std::array<std::int64_t, 2>>& p) {
  std::vector<std::size_t> order(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  order.erase(std::unique(order.begin(), order.end(),
                          [&](std::size_t a, std::size_t b) { return p[a] == p[b]; }),
              order.end());
  const auto cross = [&](std::size_t o, std::size_t a, std::size_t b) {
    return (p[a][0] - p[o][0]) * (p[b][1] - p[o][1]) - (p[a][1] - p[o][1]) * (p[b][0] - p[o][0]);
  };
  if (order.size() < 2) return order;
  std::vector<std::size_t> chain;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = chain.size();
    for (std::size_t i : order) {
      while (chain.size() >= start + 2 && cross(chain[chain.size() - 2], chain.back(), i) <= 0)
        chain.pop_back();
      chain.push_back(i);
    }
    chain.pop_back();  // the next chain starts with it
    std::reverse(order.begin(), order.end());
  }
  std::sort(chain.begin(), chain.end());
  chain.erase(std::unique(chain.begin(), chain.end()), chain.end());
  return chain;
}

}  // namespace extreme_points

using namespace extreme_points;

TEST_SUITE("extreme points") {
  TEST_CASE("a grid of factors: the box's eight corners, the first of repeated ones") {
    // Dead 1..1.35 in 8 steps, two winds -1.5..1.5 in 7 and 5 steps (the bench deck's grid),
    // then a corner again: a box's extreme points are its corners.
    std::vector<std::vector<double>> points;
    for (int k = 0; k < 280; ++k)
      points.push_back({1 + 0.35 * (k % 8) / 7, 1.5 * ((k % 7) - 3) / 3, 1.5 * ((k % 5) - 2) / 2});
    points.push_back(points[7]);
    const std::vector<bool> kept = extremePoints(rowsOf(points));
    std::vector<std::size_t> corners;
    for (std::size_t i = 0; i < 280; ++i) {
      const auto& p = points[i];
      if ((p[0] == 1 || p[0] == 1.35) && std::abs(p[1]) == 1.5 && std::abs(p[2]) == 1.5)
        corners.push_back(i);
    }
    CHECK(corners.size() == 8);
    CHECK(keptOf(kept) == corners);
    CHECK_FALSE(kept.back());  // a repeat of a kept corner
  }

  TEST_CASE("plane polygons against the monotone chain, in 2d and lifted into a plane of 3d") {
    std::mt19937 random(20261130);
    std::uniform_int_distribution<int> coordinate(-20, 20);
    for (int trial = 0; trial < 40; ++trial) {
      CAPTURE(trial);
      const int count = 3 + trial * 3;
      std::vector<std::array<std::int64_t, 2>> integer;
      integer.resize(std::size_t(count));
      std::vector<std::vector<double>> flat, lifted;
      for (auto& p : integer) {
        p = {coordinate(random), coordinate(random)};
        flat.push_back({double(p[0]), double(p[1])});
        lifted.push_back({double(p[0]), double(p[1]), 3.0 * double(p[0]) - 2.0 * double(p[1])});
      }
      const std::vector<std::size_t> expected = hullVertices(integer);
      CHECK(keptOf(extremePoints(rowsOf(flat))) == expected);
      CHECK(keptOf(extremePoints(rowsOf(lifted))) == expected);
    }
  }

  TEST_CASE("points on a line: the two ends") {
    std::vector<std::vector<double>> points;
    for (double t : {0.3, -1.0, 0.0, 2.5, 2.5, 1.0, -1.0}) points.push_back({1 + 2 * t, -t});
    CHECK(keptOf(extremePoints(rowsOf(points))) == std::vector<std::size_t>{1, 3});
    CHECK(keptOf(extremePoints(rowsOf({{4.0}}))) == std::vector<std::size_t>{0});
  }

  TEST_CASE("the largest of linear functions over the points kept: that over all of them") {
    // 300 points in 4d with most inside (a cloud, 12 of them farther out), and 1000 in 10d,
    // most of them corners (past the programmes' budget, the points not yet tested are kept):
    // any linear function's largest value is taken at a kept point, to the round-off of the
    // dot product.
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    for (const auto& [rows, columns] : {std::pair{300, 4}, std::pair{1000, 10}}) {
      Eigen::MatrixXd points(rows, columns);
      for (Eigen::Index i = 0; i < points.rows(); ++i)
        for (Eigen::Index j = 0; j < columns; ++j)
          points(i, j) = normal(random) * (i % 25 == 0 ? 3 : 1);
      const std::vector<bool> kept = extremePoints(points);
      const std::size_t count = keptOf(kept).size();
      MESSAGE(count << " of " << rows << " points kept in " << columns << "d");
      CHECK(count < std::size_t(rows));
      for (int trial = 0; trial < 2000; ++trial) {
        Eigen::VectorXd direction(columns);
        for (int j = 0; j < columns; ++j) direction(j) = normal(random);
        const Eigen::VectorXd values = points * direction;
        double all = values.maxCoeff(), onKept = -1e300;
        for (Eigen::Index i = 0; i < points.rows(); ++i)
          if (kept[std::size_t(i)]) onKept = std::max(onKept, values(i));
        CHECK(onKept >= all - 1e-12 * (1 + std::abs(all)));
      }
    }
  }
}
