#include "fem/runup/SpeedDrive.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace beamrotor {

DriveTorque DriveTorque::constant(double torque) {
  return DriveTorque(Kind::constant, {0}, {torque});
}

DriveTorque DriveTorque::againstTime(std::vector<double> times, std::vector<double> torques) {
  if (times.empty() || times.front() != 0)
    throw std::invalid_argument("drive torque: a table against time starts at t = 0");
  return DriveTorque(Kind::time, std::move(times), std::move(torques));
}

DriveTorque DriveTorque::againstSpeed(std::vector<double> speeds, std::vector<double> torques) {
  return DriveTorque(Kind::speed, std::move(speeds), std::move(torques));
}

DriveTorque::DriveTorque(Kind kind, std::vector<double> x, std::vector<double> torques)
    : kind_(kind), x_(std::move(x)), torque_(std::move(torques)) {
  if (x_.size() != torque_.size() || x_.empty())
    throw std::invalid_argument("drive torque: as many torques as points, at least one");
  if (kind_ != Kind::constant && x_.size() < 2)
    throw std::invalid_argument("drive torque: a table needs at least two points");
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(torque_[i]) || (i > 0 && !(x_[i] > x_[i - 1])))
      throw std::invalid_argument(
          "drive torque: points must be finite and strictly ascending "
          "(point " +
          std::to_string(i + 1) + ")");
  }
}

std::pair<double, double> DriveTorque::interpolate(double x) const {
  if (kind_ == Kind::constant) return {torque_.front(), 0};
  if (x <= x_.front()) return {torque_.front(), 0};
  if (x >= x_.back()) return {torque_.back(), 0};
  const std::size_t i = std::size_t(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
  const double slope = (torque_[i + 1] - torque_[i]) / (x_[i + 1] - x_[i]);
  return {torque_[i] + slope * (x - x_[i]), slope};
}

double DriveTorque::at(double t, double speed) const {
  return interpolate(kind_ == Kind::time ? t : speed).first;
}

double DriveTorque::slope(double t, double speed) const {
  (void)t;
  return kind_ == Kind::speed ? interpolate(speed).second : 0;
}

}  // namespace beamrotor
