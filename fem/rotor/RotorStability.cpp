#include "fem/rotor/RotorStability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "fem/rotor/LineFollower.hpp"
#include "fem/rotor/RotorCampbell.hpp"

namespace beamrotor {

double neutralLogDecrement(const RotorMode& mode) {
  constexpr double kNeutral = 1e-9;
  const double band = std::max(kNeutral, 2 * std::numbers::pi * mode.roundOff);
  return std::abs(mode.logDecrement) < band ? 0 : mode.logDecrement;
}

std::optional<LeastDamped> leastDamped(const CampbellResult& campbell, std::size_t firstSpeed) {
  std::optional<LeastDamped> least;
  for (std::size_t l = 0; l < campbell.lines.size(); ++l)
    for (std::size_t s = firstSpeed; s < campbell.lines[l].size(); ++s) {
      const double delta = neutralLogDecrement(campbell.lines[l][s]);
      if (!std::isnan(delta) && (!least || delta < least->logDecrement)) least = {l, s, delta};
    }
  return least;
}

double growthRate(const RotorMode& mode) {
  return neutralLogDecrement(mode) == 0 ? 0.0 : -mode.dampingRatio;
}

double leastStableGrowth(const std::vector<RotorMode>& modes) {
  double worst = -std::numeric_limits<double>::infinity();
  for (const RotorMode& m : modes) worst = std::max(worst, growthRate(m));
  return worst;
}

std::optional<InstabilityOnset> instabilityOnset(const Model& model, const CampbellResult& campbell,
                                                 const RotorOptions& options, double tolerance) {
  const std::vector<double>& speeds = campbell.speeds;
  auto gridRate = [&](std::size_t s) {
    double worst = -std::numeric_limits<double>::infinity();
    for (const auto& line : campbell.lines) worst = std::max(worst, growthRate(line[s]));
    return worst;
  };
  // 1. The first grid interval over which the least stable line starts to grow.
  std::size_t s = 0;
  if (speeds.empty() || campbell.lines.empty() || gridRate(0) > 0) return std::nullopt;
  while (s + 1 < speeds.size() && !(gridRate(s + 1) > 0)) ++s;
  if (s + 1 == speeds.size()) return std::nullopt;

  // 2. The root of the least stable line's growth rate on the speed, the lines followed from
  //    the interval's lower speed.
  LineFollower follow(model, campbell, options, s);
  std::vector<RotorMode> modes;
  const auto rate = [&](double speed) {
    modes = follow.at(speed);
    return leastStableGrowth(modes);
  };
  const SpeedRoot root = speedRoot(rate, speeds[s], gridRate(s), speeds[s + 1], gridRate(s + 1),
                                   tolerance);
  if (root.evaluations == 0) rate(root.speed);  // a bracket already narrower than asked
  // The mode that grows there: the largest growth, then (all neutral) the largest Re(lambda).
  const auto worst = std::max_element(modes.begin(), modes.end(), [](const auto& x, const auto& y) {
    return std::pair(growthRate(x), -x.dampingRatio) < std::pair(growthRate(y), -y.dampingRatio);
  });
  InstabilityOnset onset;
  onset.speed = root.speed;
  onset.rpm = root.speed * 30 / std::numbers::pi;
  onset.frequencyHz = worst->dampedFrequencyHz;
  onset.whirl = worst->whirl;
  onset.evaluations = follow.evaluations();
  onset.atSweepSpeed = root.atBracketEnd;
  return onset;
}

OperatingStability operatingStability(const Model& model, const RotorOptions& options,
                                      const OperatingRange& range, double fromSpeed,
                                      double required, int inRange, int below) {
  std::vector<double> speeds;
  const double start = std::min(fromSpeed, range.minimum);
  if (start < range.minimum)
    for (int i = 0; i < below; ++i) speeds.push_back(start + (range.minimum - start) * i / below);
  const std::size_t firstInRange = speeds.size();
  for (int i = 0; i <= inRange; ++i)
    speeds.push_back(range.minimum + (range.maximum - range.minimum) * i / inRange);
  const CampbellResult campbell = solveCampbell(model, speeds, options);

  OperatingStability out;
  out.required = required;
  out.smallest = std::numeric_limits<double>::infinity();
  // An undamped rotor does not fail on the sign of its round-off (leastDamped reads the
  // decrements as neutralLogDecrement does).
  if (const auto least = leastDamped(campbell, firstInRange)) {
    const RotorMode& mode = campbell.lines[least->line][least->speed];
    out.smallest = least->logDecrement;
    out.speed = speeds[least->speed];
    out.frequencyHz = mode.dampedFrequencyHz;
    out.whirl = mode.whirl;
  }
  // Some mode grows at some speed checked, in the range or below it.
  const auto leastOverall = leastDamped(campbell);
  if (leastOverall && leastOverall->logDecrement < 0)
    out.onset = instabilityOnset(model, campbell, options);
  const bool onsetInRange = out.onset && out.onset->speed >= range.minimum &&
                            out.onset->speed <= range.maximum;
  out.pass = out.smallest >= required && !onsetInRange;
  return out;
}

}  // namespace beamrotor
