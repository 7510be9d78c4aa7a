#include "fem/rotor/RotorResults.hpp"

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

}  // namespace beamrotor
