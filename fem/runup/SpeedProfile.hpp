// The spin speed of a run-up or coast-down as a function of time: piecewise linear between
// given (time, speed) points (a ramp is two of them), so the angular acceleration is constant
// on each piece and the spin angle, its exact integral, is piecewise quadratic.
#pragma once

#include <vector>

namespace beamrotor {

class SpeedProfile {
 public:
  /// From `from` to `to` (rad/s, >= 0) over `duration` (s, > 0): a run-up when to > from, a
  /// coast-down when to < from. Throws std::invalid_argument for a bad ramp.
  static SpeedProfile ramp(double from, double to, double duration);
  /// Through the points (times strictly ascending from 0, s; speeds >= 0, rad/s; at least two).
  /// Throws std::invalid_argument otherwise.
  static SpeedProfile table(std::vector<double> times, std::vector<double> speeds);

  /// Omega(t) (rad/s); held at the last speed after the last time.
  double speed(double t) const;
  /// Omega'(t) (rad/s^2) of the piece t lies in (the later one at a corner); 0 after the end.
  double acceleration(double t) const;
  /// phi(t) = integral of Omega from 0 to t (rad), exact.
  double angle(double t) const;
  /// The last time of the profile (s): how long the run lasts.
  double duration() const { return times_.back(); }
  double startSpeed() const { return speeds_.front(); }
  double endSpeed() const { return speeds_.back(); }
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& speeds() const { return speeds_; }

 private:
  SpeedProfile(std::vector<double> times, std::vector<double> speeds);
  /// Index of the piece [t_i, t_i+1) holding t (the last piece for t at or past its end).
  std::size_t piece(double t) const;

  std::vector<double> times_, speeds_;
  std::vector<double> angles_;  ///< phi at each time
};

}  // namespace beamrotor
