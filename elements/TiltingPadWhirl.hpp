// A tilting-pad bearing's coefficients by speed and by the journal's motion: its operating
// points at the table's speeds (elements/TiltingPadBearing.hpp), each condensed at the
// motion's eigenvalue, linear in the speed between two table speeds, the end rows held.
#pragma once

#include <vector>

#include "elements/TiltingPadBearing.hpp"

namespace beamrotor {

class TiltingPadWhirl : public WhirlCoefficients {
 public:
  /// One point per table speed, ascending (point.speed); throws std::invalid_argument when
  /// there are none or their speeds do not ascend.
  explicit TiltingPadWhirl(std::vector<TiltingPadPoint> points);

  /// tiltingPadCoefficientsAt of the bracketing points, in the bearing's axes.
  BearingCoefficients at(double speed, std::complex<double> lambda) const override;
  const char* source() const override { return "tilting pads condensed at the eigenvalue"; }

 private:
  std::vector<TiltingPadPoint> points_;
  std::vector<double> speeds_;
};

/// Coefficients of another WhirlCoefficients with the bearing's axes turned by `angle` about
/// +x (elements/TurnedBearing.hpp): T K T^T and T C T^T.
class TurnedWhirl : public WhirlCoefficients {
 public:
  TurnedWhirl(std::shared_ptr<const WhirlCoefficients> inner, double angle)
      : inner_(std::move(inner)), angle_(angle) {}
  BearingCoefficients at(double speed, std::complex<double> lambda) const override;
  const char* source() const override { return inner_->source(); }

 private:
  std::shared_ptr<const WhirlCoefficients> inner_;
  double angle_;
};

}  // namespace beamrotor
