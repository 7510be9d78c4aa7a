// The onset speed of instability: the lowest spin speed at which a damped mode's logarithmic
// decrement falls through zero (its eigenvalue crosses into the right half-plane), typically
// from cross-coupled bearing or seal stiffness. Bracketed on a Campbell diagram's speed grid,
// then refined on the speed itself (not interpolated): the growth rate of the least stable
// line, max Re(lambda) / |lambda| over the diagram's lines followed into the interval
// (LineFollower.hpp), is continuous in the speed, so a sign change between two speeds
// brackets a root, which regula falsi (Illinois variant, SpeedRoot.hpp) narrows to the asked
// tolerance. Growth is judged on each mode's own scale, Re(lambda) / |lambda|, with an
// undamped mode's round-off read as neutral (neutralLogDecrement), so that a rotor without
// damping is never unstable by the sign of its round-off.
#pragma once

#include <optional>
#include <vector>

#include "fem/rotor/Api684.hpp"
#include "fem/rotor/RotorModes.hpp"
#include "fem/rotor/SpeedRoot.hpp"

namespace beamrotor {

struct InstabilityOnset {
  double speed = 0;              ///< rad/s, where the least stable mode's Re(lambda) = 0
  double rpm = 0;
  double frequencyHz = 0;        ///< that mode's damped frequency there
  Whirl whirl = Whirl::planar;   ///< and its whirl sense
  int evaluations = 0;           ///< eigen-solutions spent on the refinement
  /// The refinement ended on a sweep speed: there a line changes mode (jumps) rather than
  /// passing through neutral, so the onset is where the tracking fails, not where a mode
  /// starts to grow
  bool atSweepSpeed = false;
};

/// A mode's log decrement as a verdict reads it: an undamped mode's decrement is 0 up to the
/// eigensolver's round-off (Re(lambda) ~ 1e-13 |lambda| near the shift, a decrement of
/// ~1e-12), so below 1e-9 in size, or below 2 pi times the mode's own roundOff where that is
/// larger (a mode far from the shift), it is taken as 0, neither growing nor decaying; other
/// values as they are.
double neutralLogDecrement(const RotorMode& mode);

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

/// How fast a mode grows as the verdicts read it: Re(lambda) / |lambda| (= -zeta), on the
/// mode's own scale, and 0 where neutralLogDecrement reads its decrement as 0; > 0 when it
/// grows.
double growthRate(const RotorMode& mode);

/// The largest growthRate of a set of modes (-inf for none): > 0 when one of them grows.
double leastStableGrowth(const std::vector<RotorMode>& modes);

/// The lowest onset speed within the Campbell sweep's speeds (its lines give the brackets),
/// refined to a relative speed tolerance; none when every line stays stable at every grid
/// speed, or one grows already at the first (no bracket). The options must be those of the
/// Campbell diagram.
std::optional<InstabilityOnset> instabilityOnset(const Model& model, const CampbellResult& campbell,
                                                 const RotorOptions& options,
                                                 double tolerance = kSpeedTolerance);

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
