// The onset speed of instability: the lowest spin speed at which a damped mode's logarithmic
// decrement falls through zero (its eigenvalue crosses into the right half-plane), typically
// from cross-coupled bearing or seal stiffness. Bracketed on a Campbell diagram's speed grid,
// then refined on the speed itself (not interpolated): the decay rate of the least stable
// mode, max Re(lambda) over the modes computed, is continuous in the speed, so a sign change
// between two speeds brackets a root, which regula falsi (Illinois variant) narrows to the
// asked tolerance.
#pragma once

#include <optional>
#include <vector>

#include "fem/rotor/Api684.hpp"
#include "fem/rotor/RotorModes.hpp"

namespace beamrotor {

struct InstabilityOnset {
  double speed = 0;              ///< rad/s, where the least stable mode's Re(lambda) = 0
  double rpm = 0;
  double frequencyHz = 0;        ///< that mode's damped frequency there
  Whirl whirl = Whirl::planar;   ///< and its whirl sense
  int evaluations = 0;           ///< eigen-solutions spent on the refinement
};

/// A log decrement as a verdict reads it: an undamped mode's decrement is 0 up to the
/// eigensolver's round-off (Re(lambda) ~ 1e-13 |lambda|, a decrement of ~1e-12), so below 1e-9
/// in size it is taken as 0, neither growing nor decaying; other values as they are.
double neutralLogDecrement(double logDecrement);

/// The least damped mode of a Campbell diagram over its speeds from `firstSpeed` on.
struct LeastDamped {
  std::size_t line = 0, speed = 0;  ///< indices into the diagram's lines and speeds
  /// neutralLogDecrement of its log decrement: -inf for a mode that grows without oscillating
  /// (a real eigenvalue > 0), the least damped of all.
  double logDecrement = 0;
};

/// The least damped mode (what decides stability: the console summary, results.json and the
/// API 684 verdict all read it from here); none without modes at those speeds. Modes whose
/// log decrement is not a number are passed over.
std::optional<LeastDamped> leastDamped(const CampbellResult& campbell, std::size_t firstSpeed = 0);

/// max Re(lambda) (1/s) over a set of modes: > 0 when one of them grows.
double leastStableDecayRate(const std::vector<RotorMode>& modes);

/// The lowest onset speed within the Campbell sweep's speeds (its lines give the brackets),
/// refined to a relative speed tolerance; none when every mode stays stable at every grid
/// speed, or the rotor is unstable already at the first one (no bracket). The options must
/// be those of the Campbell diagram.
std::optional<InstabilityOnset> instabilityOnset(const Model& model, const CampbellResult& campbell,
                                                 const RotorOptions& options,
                                                 double tolerance = 1e-10);

/// The stability half of an API 684 verdict: over an operating speed range every damped mode
/// must keep a log decrement of at least `required` (0: only a growing mode fails; API 617's
/// level I screening asks 0.1). A mode whose log decrement falls through zero inside the range
/// fails whatever the limit, the onset speed named.
struct OperatingStability {
  double required = 0;      ///< smallest log decrement allowed
  double smallest = 0;      ///< smallest log decrement of the modes at the speeds in range
  double speed = 0;         ///< rad/s, where it occurs
  double frequencyHz = 0;   ///< that mode's damped frequency there
  Whirl whirl = Whirl::planar;
  /// the lowest onset of instability between the first speed checked and the top of the range
  std::optional<InstabilityOnset> onset;
  bool pass = false;  ///< smallest >= required and no onset inside the range
};

/// Checks the modes of `options` (those of a Campbell diagram) at `inRange` + 1 equal steps
/// over the operating range and at `below` + 1 equal steps from `fromSpeed` (rad/s) up to its
/// lowest speed (the onset's brackets). Throws SolveError as solveCampbell does.
OperatingStability operatingStability(const Model& model, const RotorOptions& options,
                                      const OperatingRange& range, double fromSpeed,
                                      double required, int inRange = 10, int below = 30);

}  // namespace beamrotor
