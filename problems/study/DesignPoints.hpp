// The points of a design study in parameter space: a grid's every combination (the first
// parameter varying slowest, as nested loops in the order given), or samples drawn from each
// parameter's distribution, randomly or by Latin hypercube (McKay, Beckman and Conover 1979:
// each parameter's probability range cut into n equal strata, one point in each, the strata
// paired across parameters by independent random permutations).
#pragma once

#include <vector>

#include "problems/deck/study/DesignStudy.hpp"

namespace beamrotor {

class DesignPoints {
 public:
  /// Samples are drawn here, once, from std::mt19937_64 seeded with spec.seed: random
  /// sampling draws point by point, each point's parameters in order; Latin-hypercube
  /// sampling draws per parameter a permutation of the strata (Fisher-Yates, from the last
  /// position down) and then one position inside each stratum, point by point.
  explicit DesignPoints(const DesignStudySpec& spec);
  long long size() const { return count_; }
  int parameters() const { return int(names_.size()); }
  const std::vector<std::string>& names() const { return names_; }
  /// The parameter values of point `index` (0-based), in the order of names().
  std::vector<double> at(long long index) const;

 private:
  long long count_ = 0;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> grid_;  ///< grid: each parameter's values
  std::vector<double> samples_;            ///< sampling: point-major, count_ x parameters
};

/// The value of `d` at probability u in (0, 1): the inverse of its distribution function,
/// truncated to [lower, upper] (u is mapped onto [F(lower), F(upper)] first).
double distributionQuantile(const StudyDistribution& d, double u);

}  // namespace beamrotor
