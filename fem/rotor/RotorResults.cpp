#include "fem/rotor/RotorResults.hpp"

#include <algorithm>

namespace beamrotor {

std::string_view whirlName(Whirl w) {
  switch (w) {
    case Whirl::forward:
      return "forward";
    case Whirl::backward:
      return "backward";
    case Whirl::planar:
      return "planar";
  }
  return "planar";
}

double Orbit::whirlRatio() const {
  const double f = forwardRadius(), b = backwardRadius();
  return f + b > 0 ? (f - b) / (f + b) : 0.0;
}

void WhirlCoefficientsUsed::add(const WhirlCoefficientsUsed& other, std::size_t speed) {
  atOwnWhirl = atOwnWhirl || other.atOwnWhirl;
  mostIterations = std::max(mostIterations, other.mostIterations);
  for (Unsettled u : other.unsettled) {
    u.speed = speed;
    unsettled.push_back(u);
  }
}

}  // namespace beamrotor
