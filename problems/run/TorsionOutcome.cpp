#include "problems/run/TorsionOutcome.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace beamrotor {

double peakOfHarmonics(const std::vector<std::complex<double>>& amplitudes,
                       const std::vector<double>& orders) {
  if (amplitudes.size() == 1) return std::abs(amplitudes[0]);
  const auto value = [&](double theta) {
    double sum = 0;
    for (std::size_t j = 0; j < amplitudes.size(); ++j)
      sum += std::real(amplitudes[j] * std::polar(1.0, orders[j] * theta));
    return std::abs(sum);
  };
  double highest = 0;
  for (double o : orders) highest = std::max(highest, o);
  const int samples = std::max(64, int(std::ceil(2 * 64 * highest)));
  const double span = 4 * std::numbers::pi, h = span / samples;
  double best = 0, at = 0;
  for (int i = 0; i < samples; ++i)
    if (const double v = value(i * h); v > best) {
      best = v;
      at = i * h;
    }
  // Golden-section search for the maximum within a sample either side.
  const double g = (std::sqrt(5.0) - 1) / 2;
  double a = at - h, b = at + h;
  for (int k = 0; k < 60 && b - a > 1e-14 * span; ++k) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (value(c) > value(d))
      b = d;
    else
      a = c;
  }
  return std::max(best, value((a + b) / 2));
}

double measureTorsion(const std::string& property, const std::string& target,
                      const TorsionOutcome& t) {
  if (!t.atSpeed) throw std::runtime_error("no response at an operating speed");
  const auto& traces = property == "torque" ? t.atSpeed->torques : t.atSpeed->twists;
  for (const ResponseTrace& r : traces)
    if (r.name == target) return r.peak;
  throw std::runtime_error("no " + property + " '" + target + "' in the response");
}

}  // namespace beamrotor
