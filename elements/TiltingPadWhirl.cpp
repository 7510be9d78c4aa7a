#include "elements/TiltingPadWhirl.hpp"

#include <stdexcept>

#include "elements/TurnedBearing.hpp"

namespace beamrotor {

TiltingPadWhirl::TiltingPadWhirl(std::vector<TiltingPadPoint> points)
    : points_(std::move(points)) {
  if (points_.empty()) throw std::invalid_argument("tilting pads by whirl: no operating points");
  for (const TiltingPadPoint& p : points_) {
    if (!speeds_.empty() && !(p.speed > speeds_.back()))
      throw std::invalid_argument("tilting pads by whirl: the points' speeds must ascend");
    speeds_.push_back(p.speed);
  }
}

BearingCoefficients TiltingPadWhirl::at(double speed, std::complex<double> lambda) const {
  const TableBracket s = tableBracket(speeds_, speed);
  const BearingCoefficients low = tiltingPadCoefficientsAt(points_[s.low], lambda);
  if (s.t == 0) return low;
  return blend(low, tiltingPadCoefficientsAt(points_[s.low + 1], lambda), s.t);
}

BearingCoefficients TurnedWhirl::at(double speed, std::complex<double> lambda) const {
  return turnedCoefficients(inner_->at(speed, lambda), angle_);
}

}  // namespace beamrotor
