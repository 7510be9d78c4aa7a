// Critical speeds refined on the speed: where a Campbell line's damped frequency meets the
// excitation order x speed, found as the root of omega_d(Omega) - order Omega of the line
// followed into its bracketing interval (LineFollower.hpp) by regula falsi (SpeedRoot.hpp), to
// the tolerance the onset of instability uses, rather than interpolated between sweep speeds
// (whose error falls only as the square of the step).
#pragma once

#include <vector>

#include "fem/rotor/RotorModes.hpp"
#include "fem/rotor/SpeedRoot.hpp"

namespace beamrotor {

/// Every crossing criticalSpeeds finds on `campbell` (solved with `options`), its speed
/// refined to `tolerance` relative, its damping ratio and whirl those of the line's mode
/// there; sorted by sortCriticalSpeeds. A sign change across a line's reported jump (the
/// diagram's `jumps`) is no crossing and is left out.
std::vector<CriticalSpeed> refinedCriticalSpeeds(const Model& model, const CampbellResult& campbell,
                                                 const RotorOptions& options, double order = 1,
                                                 double tolerance = kSpeedTolerance);

}  // namespace beamrotor
