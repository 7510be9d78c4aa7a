// The speed and frequency axes of the rotor charts: rpm and Hz, or the user's `speed` and
// `frequency` output units (OutputUnits.hpp), which the tables then hold.
#pragma once

#include <string>

#include "problems/deck/OutputUnits.hpp"

namespace beamrotor {

struct SpeedAxes {
  /// The unit of the speed columns (speed_rpm) and the factor from a speed in rpm (a result's
  /// critical speed, onset, operating range) into it.
  OutputUnits::Shown speed;
  /// The unit of the frequency columns and the factor from a frequency in Hz into it.
  OutputUnits::Shown frequency;

  /// The frequency (in its unit) of once per turn at a speed of 1 (in its unit): 1/60 for
  /// rpm and Hz, 1 for Hz and Hz.
  double oncePerTurn() const { return frequency.factor / (60 * speed.factor); }
  /// A speed given in rpm as the axis shows it: "3000 rpm", "50 Hz".
  std::string speedText(double rpm) const;
};

SpeedAxes speedAxes(const OutputUnits& units);

}  // namespace beamrotor
