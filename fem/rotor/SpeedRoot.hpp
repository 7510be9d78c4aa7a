// A root on the spin speed: where a quantity that changes sign between two sweep speeds (the
// least stable mode's growth rate, a Campbell line's frequency minus order x speed) is zero,
// found on the speed itself rather than interpolated. Regula falsi with the Illinois change
// (the end kept twice in a row has its value halved), which narrows a bracket of a smooth
// function superlinearly and never leaves it.
#pragma once

#include <functional>

namespace beamrotor {

/// The relative speed tolerance the rotor analyses refine their roots to (the onset of
/// instability, critical speeds): far below any speed that matters, above the eigensolver's
/// round-off in a mode's frequency and decay rate.
inline constexpr double kSpeedTolerance = 1e-10;

struct SpeedRoot {
  double speed = 0;     ///< the last speed evaluated: an end of the final bracket, or a zero
  int evaluations = 0;  ///< calls of the function
  /// The root lies at an end of the bracket given (within the tolerance): the function jumps
  /// there rather than passing through zero, e.g. a line of a diagram that changes mode.
  bool atBracketEnd = false;
};

/// The root of f between a and b > a, where f(a) = fa and f(b) = fb have opposite signs
/// (fa may be 0: f there counts as on a's side), until the bracket is narrower than
/// tolerance * b or f is exactly 0 at a speed tried; at most 200 evaluations.
SpeedRoot speedRoot(const std::function<double(double)>& f, double a, double fa, double b,
                    double fb, double tolerance = kSpeedTolerance);

}  // namespace beamrotor
