// A spin speed driven by a torque against the rotor's polar inertia, in place of a prescribed
// Omega(t): J Omega' = T(t, Omega) - T_unbalance, the speed a state of the run-up's integration
// (fem/runup/RunUp.hpp). The torque is a constant, a table against time, or a motor curve
// against speed, each piecewise linear (held beyond its ends).
#pragma once

#include <vector>

namespace beamrotor {

class DriveTorque {
 public:
  /// T (N m) at all times and speeds.
  static DriveTorque constant(double torque);
  /// T(t) through (time s, torque N m) points, times strictly ascending from 0.
  static DriveTorque againstTime(std::vector<double> times, std::vector<double> torques);
  /// T(Omega) through (speed rad/s, torque N m) points, speeds strictly ascending: a motor's
  /// torque-speed curve. Throws std::invalid_argument for bad points (as the others).
  static DriveTorque againstSpeed(std::vector<double> speeds, std::vector<double> torques);

  /// T (N m) at time t (s) and speed Omega (rad/s).
  double at(double t, double speed) const;
  /// dT/dOmega (N m s) there: 0 unless against speed.
  double slope(double t, double speed) const;

 private:
  enum class Kind { constant, time, speed };
  DriveTorque(Kind kind, std::vector<double> x, std::vector<double> torques);
  /// The piecewise linear value and slope at x.
  std::pair<double, double> interpolate(double x) const;
  Kind kind_;
  std::vector<double> x_, torque_;
};

/// The drive of a run-up whose speed is a state: torque, the rotor's polar inertia about its
/// axis (kg m^2, > 0: the model's spinning parts plus any extra), the start speed (rad/s) and
/// how long the run lasts (s).
struct SpeedDrive {
  DriveTorque torque = DriveTorque::constant(0);
  double inertia = 0;
  double startSpeed = 0;
  double duration = 0;
};

}  // namespace beamrotor
