#include "problems/output/rotor/UnwrappedPhase.hpp"

#include <numbers>

namespace beamrotor {

std::vector<double> unwrappedPhases(const std::vector<std::complex<double>>& values) {
  // A step this close to +-180 deg is a sign change (an undamped resonance), not a wrap: drawn
  // down, as a lag; round-off puts the raw phase on either side of the cut.
  constexpr double kNearHalfTurn = 0.1;
  std::vector<double> out;
  double offset = 0, previous = 0;
  for (const std::complex<double>& v : values) {
    const double raw = std::arg(v) * 180 / std::numbers::pi;
    if (out.empty()) {
      offset = raw > 180 - kNearHalfTurn ? -360 : 0;
    } else {
      const double jump = raw + offset - previous;
      if (jump > 180 - kNearHalfTurn) offset -= 360;
      else if (jump < -180 - kNearHalfTurn) offset += 360;
    }
    previous = raw + offset;
    out.push_back(previous);
  }
  return out;
}

UnbalancePhases unbalancePhases(const std::vector<Orbit>& orbits) {
  std::vector<std::complex<double>> uy, uz;
  for (const Orbit& o : orbits) {
    uy.push_back(o.uy);
    uz.push_back(o.uz);
  }
  return {unwrappedPhases(uy), unwrappedPhases(uz)};
}

}  // namespace beamrotor
