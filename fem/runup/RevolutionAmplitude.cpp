#include "fem/runup/RevolutionAmplitude.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace beamrotor {

void RevolutionAmplitude::add(double t, double phi, double speed, double y, double z) {
  const long long turn = static_cast<long long>(std::floor(phi / (2 * std::numbers::pi)));
  if (revolution_ < 0) revolution_ = turn;
  if (turn != revolution_) {
    // The sample on the boundary belongs to both revolutions: it closes this one.
    y_.push_back(y);
    z_.push_back(z);
    speed_.push_back(speed);
    closeRevolution(t);
    revolution_ = turn;
  }
  y_.push_back(y);
  z_.push_back(z);
  speed_.push_back(speed);
}

void RevolutionAmplitude::closeRevolution(double t) {
  const double n = double(y_.size());
  // Every pair: a revolution holds tens to hundreds of samples.
  double largest = 0;
  for (std::size_t i = 0; i < y_.size(); ++i)
    for (std::size_t j = i + 1; j < y_.size(); ++j)
      largest = std::max(largest, (y_[i] - y_[j]) * (y_[i] - y_[j]) + (z_[i] - z_[j]) * (z_[i] - z_[j]));
  largest = std::sqrt(largest) / 2;
  const auto [ylo, yhi] = std::minmax_element(y_.begin(), y_.end());
  const auto [zlo, zhi] = std::minmax_element(z_.begin(), z_.end());
  out_.speed.push_back(std::accumulate(speed_.begin(), speed_.end(), 0.0) / n);
  out_.time.push_back(t);
  out_.amplitude.push_back(largest);
  out_.halfRangeY.push_back((*yhi - *ylo) / 2);
  out_.halfRangeZ.push_back((*zhi - *zlo) / 2);
  y_.clear();
  z_.clear();
  speed_.clear();
}

}  // namespace beamrotor
