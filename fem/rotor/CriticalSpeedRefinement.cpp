#include "fem/rotor/CriticalSpeedRefinement.hpp"

#include <algorithm>
#include <numbers>

#include "fem/rotor/LineFollower.hpp"
#include "fem/rotor/RotorCampbell.hpp"

namespace beamrotor {

std::vector<CriticalSpeed> refinedCriticalSpeeds(const Model& model, const CampbellResult& campbell,
                                                 const RotorOptions& options, double order,
                                                 double tolerance) {
  std::vector<CriticalSpeed> out;
  const auto& speeds = campbell.speeds;
  for (const CrossingBracket& b : crossingBrackets(campbell, order)) {
    const auto& line = campbell.lines[b.line];
    const std::size_t s = b.interval;
    // A line that changes mode across the interval (reported as a jump) changes sign there
    // without meeting the order line: no crossing.
    const auto jumpsHere = [&](const LineJump& j) { return j.line == b.line && j.speed == s + 1; };
    if (std::any_of(campbell.jumps.begin(), campbell.jumps.end(), jumpsHere)) continue;
    const auto distance = [&](const RotorMode& m, double speed) {
      return m.dampedFrequency - order * speed;
    };
    const double fa = distance(line[s], speeds[s]), fb = distance(line[s + 1], speeds[s + 1]);
    CriticalSpeed c;
    c.line = b.line;
    c.order = order;
    RotorMode mode;
    if (fa == 0 || fb == 0) {  // on a sweep speed already
      c.speed = speeds[fa == 0 ? s : s + 1];
      mode = line[fa == 0 ? s : s + 1];
    } else {
      LineFollower follow(model, campbell, options, s);
      const auto rate = [&](double speed) {
        mode = follow.at(speed)[std::size_t(b.line)];
        return distance(mode, speed);
      };
      const SpeedRoot root = speedRoot(rate, speeds[s], fa, speeds[s + 1], fb, tolerance);
      if (root.evaluations == 0) rate(root.speed);  // a bracket already narrower than asked
      c.speed = root.speed;
    }
    c.rpm = c.speed * 30 / std::numbers::pi;
    c.frequencyHz = order * c.speed / (2 * std::numbers::pi);
    c.dampingRatio = mode.dampingRatio;
    c.whirl = mode.whirl;
    out.push_back(c);
  }
  sortCriticalSpeeds(out);
  return out;
}

}  // namespace beamrotor
