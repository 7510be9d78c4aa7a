// Shared by the rotor test suites.
#pragma once

#include <complex>

#include "fem/rotor/RotorModes.hpp"

namespace beamrotor::test {

using Complex = std::complex<double>;

/// Rotor options without aggregate initialisation (which warns about the fields left out).
inline RotorOptions rotorOptions(int modes, std::complex<double> shift = 0,
                                 ProportionalDamping damping = {},
                                 EigenMethod method = EigenMethod::automatic) {
  RotorOptions o;
  o.modes = modes;
  o.shift = shift;
  o.damping = damping;
  o.method = method;
  return o;
}

}  // namespace beamrotor::test
