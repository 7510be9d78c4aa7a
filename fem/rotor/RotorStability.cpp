#include "fem/rotor/RotorStability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "fem/rotor/RotorCampbell.hpp"

namespace beamrotor {

double neutralLogDecrement(double logDecrement) {
  constexpr double kNeutral = 1e-9;
  return std::abs(logDecrement) < kNeutral ? 0 : logDecrement;
}

std::optional<LeastDamped> leastDamped(const CampbellResult& campbell, std::size_t firstSpeed) {
  std::optional<LeastDamped> least;
  for (std::size_t l = 0; l < campbell.lines.size(); ++l)
    for (std::size_t s = firstSpeed; s < campbell.lines[l].size(); ++s) {
      const double delta = neutralLogDecrement(campbell.lines[l][s].logDecrement);
      if (!std::isnan(delta) && (!least || delta < least->logDecrement)) least = {l, s, delta};
    }
  return least;
}

double leastStableDecayRate(const std::vector<RotorMode>& modes) {
  double worst = -std::numeric_limits<double>::infinity();
  for (const RotorMode& m : modes) worst = std::max(worst, m.eigenvalue.real());
  return worst;
}

std::optional<InstabilityOnset> instabilityOnset(const Model& model, const CampbellResult& campbell,
                                                 const RotorOptions& options, double tolerance) {
  const std::vector<double>& speeds = campbell.speeds;
  auto gridRate = [&](std::size_t s) {
    double worst = -std::numeric_limits<double>::infinity();
    for (const auto& line : campbell.lines) worst = std::max(worst, line[s].eigenvalue.real());
    return worst;
  };
  // 1. The first grid interval over which the least stable mode starts to grow.
  std::size_t s = 0;
  if (speeds.empty() || campbell.lines.empty() || gridRate(0) > 0) return std::nullopt;
  while (s + 1 < speeds.size() && !(gridRate(s + 1) > 0)) ++s;
  if (s + 1 == speeds.size()) return std::nullopt;

  // 2. Regula falsi on the speed, halving the retained end's value when the same end is kept
  //    twice (Illinois), so the bracket shrinks superlinearly on a smooth root.
  const RotorSystem system(model, options.damping);
  QuadraticEigenSolver solver;
  InstabilityOnset onset;
  auto solveAt = [&](double speed) {
    ++onset.evaluations;
    return solveRotorModes(system, speed, options, solver, false).modes;
  };
  double a = speeds[s], b = speeds[s + 1];
  double fa = gridRate(s), fb = gridRate(s + 1);
  int kept = 0;  // -1: a kept last time, +1: b kept
  std::vector<RotorMode> modes;
  double c = b;
  for (int i = 0; i < 200 && b - a > tolerance * b; ++i) {
    c = fa == fb ? 0.5 * (a + b) : b - fb * (b - a) / (fb - fa);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    modes = solveAt(c);
    const double fc = leastStableDecayRate(modes);
    if (fc > 0) {
      b = c, fb = fc;
      if (kept == -1) fa /= 2;
      kept = -1;
    } else {
      a = c, fa = fc;
      if (kept == 1) fb /= 2;
      kept = 1;
    }
    if (fc == 0) break;
  }
  onset.speed = c;
  if (modes.empty()) modes = solveAt(c);
  const auto worst = std::max_element(modes.begin(), modes.end(), [](const auto& x, const auto& y) {
    return x.eigenvalue.real() < y.eigenvalue.real();
  });
  onset.rpm = c * 30 / std::numbers::pi;
  onset.frequencyHz = worst->dampedFrequencyHz;
  onset.whirl = worst->whirl;
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
