#include "problems/run/TorsionOutcome.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace beamrotor {

HarmonicPeak::HarmonicPeak(std::vector<double> orders) : orders_(std::move(orders)) {
  if (orders_.size() < 2) return;
  double highest = 0;
  for (double o : orders_) highest = std::max(highest, o);
  samples_ = std::max(64, int(std::ceil(2 * 64 * highest)));
  step_ = 4 * std::numbers::pi / samples_;
  phasors_.reserve(std::size_t(samples_) * orders_.size());
  for (int i = 0; i < samples_; ++i)
    for (double o : orders_) phasors_.push_back(std::polar(1.0, o * (i * step_)));
}

double HarmonicPeak::valueAt(const std::vector<std::complex<double>>& amplitudes,
                             double theta) const {
  double sum = 0;
  for (std::size_t j = 0; j < amplitudes.size(); ++j)
    sum += std::real(amplitudes[j] * std::polar(1.0, orders_[j] * theta));
  return std::abs(sum);
}

double HarmonicPeak::operator()(const std::vector<std::complex<double>>& amplitudes) const {
  if (amplitudes.size() != orders_.size())
    throw std::logic_error("HarmonicPeak: one amplitude per order expected");
  if (amplitudes.size() == 1) return std::abs(amplitudes[0]);
  double best = 0, at = 0;
  const std::size_t n = orders_.size();
  for (int i = 0; i < samples_; ++i) {
    const std::complex<double>* phasor = &phasors_[std::size_t(i) * n];
    double sum = 0;
    for (std::size_t j = 0; j < n; ++j) sum += std::real(amplitudes[j] * phasor[j]);
    if (const double v = std::abs(sum); v > best) {
      best = v;
      at = i * step_;
    }
  }
  // Golden-section search for the maximum within a sample either side.
  const double g = (std::sqrt(5.0) - 1) / 2, span = 4 * std::numbers::pi;
  double a = at - step_, b = at + step_;
  for (int k = 0; k < 60 && b - a > 1e-14 * span; ++k) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (valueAt(amplitudes, c) > valueAt(amplitudes, d))
      b = d;
    else
      a = c;
  }
  return std::max(best, valueAt(amplitudes, (a + b) / 2));
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
