// The statistics a design study's summary reports: percentiles of a sample and the Wilson
// score interval of a proportion (Wilson 1927), which, unlike the normal approximation, stays
// inside [0, 1] and keeps its coverage when the proportion is near 0 or 1 (a rare exceedance).
#pragma once

#include <vector>

namespace beamrotor {

/// The p-quantile (0 <= p <= 1) of sorted values by linear interpolation between order
/// statistics at position p (n - 1) (Hyndman and Fan 1996, definition 7); NaN when empty.
double sortedPercentile(const std::vector<double>& sorted, double p);

struct ProportionInterval {
  double estimate = 0, low = 0, high = 0;
};

/// z for a two-sided 95 % interval: Phi^-1(0.975).
inline constexpr double kZ95 = 1.959963984540054;

/// successes out of trials (trials > 0), with the Wilson score interval for confidence z.
ProportionInterval wilsonInterval(long long successes, long long trials, double z = kZ95);

}  // namespace beamrotor
