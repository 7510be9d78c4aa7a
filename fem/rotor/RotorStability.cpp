#include "fem/rotor/RotorStability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace beamrotor {

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

}  // namespace beamrotor
