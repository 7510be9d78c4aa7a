#include "fem/runup/SpeedProfile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace beamrotor {

SpeedProfile SpeedProfile::ramp(double from, double to, double duration) {
  return table({0, duration}, {from, to});
}

SpeedProfile SpeedProfile::table(std::vector<double> times, std::vector<double> speeds) {
  return SpeedProfile(std::move(times), std::move(speeds));
}

SpeedProfile::SpeedProfile(std::vector<double> times, std::vector<double> speeds)
    : times_(std::move(times)), speeds_(std::move(speeds)) {
  if (times_.size() != speeds_.size())
    throw std::invalid_argument("speed profile: as many times as speeds are needed");
  if (times_.size() < 2)
    throw std::invalid_argument("speed profile: at least two (time, speed) points are needed");
  if (times_.front() != 0) throw std::invalid_argument("speed profile: the first time must be 0");
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (!std::isfinite(times_[i]) || (i > 0 && !(times_[i] > times_[i - 1])))
      throw std::invalid_argument("speed profile: times must ascend strictly (point " +
                                  std::to_string(i + 1) + ")");
    if (!std::isfinite(speeds_[i]) || speeds_[i] < 0)
      throw std::invalid_argument("speed profile: speeds must be finite and >= 0 (point " +
                                  std::to_string(i + 1) + ")");
  }
  // The trapezoid rule is exact for a piecewise linear speed.
  angles_.assign(times_.size(), 0.0);
  for (std::size_t i = 1; i < times_.size(); ++i)
    angles_[i] = angles_[i - 1] + (times_[i] - times_[i - 1]) * (speeds_[i] + speeds_[i - 1]) / 2;
}

std::size_t SpeedProfile::piece(double t) const {
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  const std::size_t after = std::size_t(it - times_.begin());
  return std::clamp<std::size_t>(after == 0 ? 0 : after - 1, 0, times_.size() - 2);
}

double SpeedProfile::speed(double t) const {
  if (t >= times_.back()) return speeds_.back();
  const std::size_t i = piece(t);
  return speeds_[i] + acceleration(t) * (t - times_[i]);
}

double SpeedProfile::acceleration(double t) const {
  if (t >= times_.back()) return 0;
  const std::size_t i = piece(t);
  return (speeds_[i + 1] - speeds_[i]) / (times_[i + 1] - times_[i]);
}

double SpeedProfile::angle(double t) const {
  if (t >= times_.back()) return angles_.back() + speeds_.back() * (t - times_.back());
  const std::size_t i = piece(t);
  const double s = t - times_[i];
  return angles_[i] + speeds_[i] * s + acceleration(t) * s * s / 2;
}

}  // namespace beamrotor
