// The rotor charts' speed and frequency axes (see SpeedAxes.hpp).
#include "problems/output/rotor/SpeedAxes.hpp"

#include <cstdio>

namespace beamrotor {

std::string SpeedAxes::speedText(double rpm) const {
  char text[48];
  // Whole revolutions per minute read best; any other unit keeps four digits.
  std::snprintf(text, sizeof text, speed.unit == "rpm" ? "%.0f " : "%.4g ", rpm * speed.factor);
  return text + speed.unit;
}

SpeedAxes speedAxes(const OutputUnits& units) {
  return {units.valueIn("rpm", {1, "rpm"}), units.valueIn("Hz", {1, "Hz"})};
}

}  // namespace beamrotor
