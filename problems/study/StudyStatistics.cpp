#include "problems/study/StudyStatistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace beamrotor {

double sortedPercentile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double position = p * double(sorted.size() - 1);
  const std::size_t below = std::size_t(std::floor(position));
  if (below + 1 >= sorted.size()) return sorted.back();
  const double fraction = position - double(below);
  return sorted[below] + fraction * (sorted[below + 1] - sorted[below]);
}

ProportionInterval wilsonInterval(long long successes, long long trials, double z) {
  const double n = double(trials);
  const double p = double(successes) / n;
  const double z2 = z * z;
  const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
  const double half = z / (1 + z2 / n) * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n));
  // At 0 (or all) successes the bound is 0 (or 1) exactly; the formula leaves round-off there.
  const double low = successes == 0 ? 0.0 : std::max(0.0, centre - half);
  const double high = successes == trials ? 1.0 : std::min(1.0, centre + half);
  return {p, low, high};
}

}  // namespace beamrotor
