#include "problems/run/CampbellWarnings.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "fem/rotor/WhirlIteration.hpp"

namespace beamrotor {

namespace {

double rpmOf(double speed) { return speed * 30 / std::numbers::pi; }

}  // namespace

std::optional<std::string> onsetWarning(const std::optional<InstabilityOnset>& onset) {
  if (!onset || !onset->atSweepSpeed) return std::nullopt;
  char text[400];
  std::snprintf(text, sizeof text,
                "the onset of instability settles on the sweep speed %.6g rpm: a line changes "
                "mode there instead of passing through zero decrement, so the onset may lie "
                "elsewhere; ask for more modes (or more steps)",
                onset->rpm);
  return std::string(text);
}

std::vector<std::string> campbellWarnings(const CampbellResult& campbell,
                                          const std::optional<InstabilityOnset>& onset) {
  std::vector<std::string> out;
  const std::size_t lines = campbell.lines.size();
  for (const LineJump& j : campbell.jumps) {
    char text[400];
    std::snprintf(text, sizeof text,
                  "line %d jumps from %.4g Hz at %.6g rpm to %.4g Hz by %.6g rpm (MAC %.3g), "
                  "also in a denser local sweep: it changes mode there, and %zu modes do not "
                  "follow it; ask for more modes",
                  j.line + 1, j.fromHz, rpmOf(campbell.speeds[j.speed - 1]), j.toHz,
                  rpmOf(campbell.speeds[j.speed]), j.mac, lines);
    out.push_back(text);
  }
  if (const auto& u = campbell.untracked) {
    char text[400];
    std::snprintf(text, sizeof text,
                  "a mode no line follows grows at %.6g rpm (%.4g Hz %s whirl, log decrement "
                  "%.3g): the %zu lines' stability verdict does not see it; ask for more modes",
                  rpmOf(campbell.speeds[u->speed]), u->frequencyHz,
                  std::string(whirlName(u->whirl)).c_str(), u->logDecrement, lines);
    out.push_back(text);
  }
  if (auto w = onsetWarning(onset)) out.push_back(*w);
  for (const std::string& w : whirlWarnings(campbell.coefficients, campbell.speeds))
    out.push_back(w);
  return out;
}

std::vector<std::string> whirlWarnings(const WhirlCoefficientsUsed& used,
                                       const std::vector<double>& speeds) {
  std::vector<std::string> out;
  for (const auto& u : used.unsettled) {
    char text[400];
    std::snprintf(text, sizeof text,
                  "the mode at %.6g Hz (%.6g rpm, synchronous bearing coefficients) did not "
                  "settle with the coefficients at its own eigenvalue (in %d eigen-solutions "
                  "it did not converge, lost its shape or ended on another mode's eigenvalue): "
                  "it is reported with the synchronous set",
                  u.frequencyHz, rpmOf(speeds.at(u.speed)), kMaxWhirlIterations);
    out.push_back(text);
  }
  return out;
}

}  // namespace beamrotor
