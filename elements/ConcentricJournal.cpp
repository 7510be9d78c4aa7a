#include "elements/ConcentricJournal.hpp"

#include <cmath>
#include <numbers>

namespace beamrotor {

BearingCoefficients concentricJournalCoefficients(const PlainJournal& b, double speed) {
  const double damping = std::numbers::pi * b.viscosity * b.diameter * std::pow(b.length, 3) /
                         (4 * std::pow(b.clearance, 3));
  const double cross = speed * damping / 2;
  BearingCoefficients out;
  out.kyz = cross;
  out.kzy = -cross;
  out.cyy = damping;
  out.czz = damping;
  return out;
}

}  // namespace beamrotor
