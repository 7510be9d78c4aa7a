#include "fem/rotor/LineFollower.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "fem/rotor/RotorCampbell.hpp"
#include "fem/solvers/Errors.hpp"

namespace beamrotor {

LineFollower::LineFollower(const Model& model, const CampbellResult& campbell,
                           const RotorOptions& options, std::size_t from)
    : system_(model, options.damping), options_(options), lines_(int(campbell.lines.size())) {
  options_.modes = std::max(campbell.candidates, firstCandidates(lines_));
  options_.everyRotorMode = true;
  // Each line's mode at the lower speed: the candidate nearest its eigenvalue there (the same
  // solve as the diagram's, to round-off), and between the two members of a repeated
  // eigenvalue the one of the line's whirl (their basis is fixed by whirl, DegenerateModes.hpp).
  constexpr double kOtherWhirl = 1e-6;  // relative distance a whirl that differs counts as
  const RotorModesResult at = solve(campbell.speeds.at(from));
  anchor_.resize(at.vectors.rows(), lines_);
  std::vector<bool> taken(at.modes.size(), false);
  for (int l = 0; l < lines_; ++l) {
    const RotorMode& mode = campbell.lines[l].at(from);
    int best = -1;
    double nearest = std::numeric_limits<double>::infinity();
    for (int c = 0; c < int(at.modes.size()); ++c) {
      const RotorMode& candidate = at.modes[c];
      const double size =
          std::max(std::abs(mode.eigenvalue), std::numeric_limits<double>::min());
      const double distance = std::abs(candidate.eigenvalue - mode.eigenvalue) / size +
          (candidate.whirl == mode.whirl ? 0 : kOtherWhirl);
      if (!taken[c] && distance < nearest) {
        nearest = distance;
        best = c;
      }
    }
    taken[best] = true;
    anchor_.col(l) = at.vectors.col(best);
  }
}

RotorModesResult LineFollower::solve(double speed) {
  ++evaluations_;
  // Once the lines are anchored, only the candidates they follow are found at their own
  // eigenvalue (whirl-dependent bearings); the anchoring solve finds every one.
  RotorModesResult at = solveRotorModes(system_, speed, options_, solver_, false, {&anchor_});
  if (int(at.modes.size()) < lines_)
    throw SolveError("Campbell diagram: only " + std::to_string(at.modes.size()) +
                     " modes found at " + std::to_string(speed) + " rad/s, " +
                     std::to_string(lines_) + " lines to follow");
  return at;
}

std::vector<RotorMode> LineFollower::at(double speed) {
  RotorModesResult at = solve(speed);
  std::vector<RotorMode> modes;
  for (const auto& [candidate, mac] : matchByMac(anchor_, at.vectors))
    modes.push_back(at.modes[candidate]);
  return modes;
}

}  // namespace beamrotor
