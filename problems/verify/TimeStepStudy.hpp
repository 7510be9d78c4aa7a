// Explicit time steps: central difference on a lumped-mass cantilever released from a smooth
// bend, just below and just above the critical step 2 / omega_max (Bathe, Finite Element
// Procedures, 9.4): below, the tip oscillates with bounded amplitude; above, it diverges.
#pragma once

#include <vector>

namespace beamrotor::verify {

struct TimeStepRun {
  double stepFactor = 0;      ///< dt / dt_crit
  double dtCritical = 0;      ///< s
  std::vector<double> times;  ///< s
  std::vector<double> tip;    ///< tip deflection (m), initial 1 mm
};

/// One run per factor of the critical step, each `steps` steps long.
std::vector<TimeStepRun> timeStepStudy(const std::vector<double>& stepFactors, int steps);

}  // namespace beamrotor::verify
