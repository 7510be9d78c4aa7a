// Phases of a response along a sweep (unbalance response against speed, receptance against
// frequency), unwrapped as FORMAT.md promises: continuous through resonances, a lag negative,
// in every table, results.json and chart alike.
#pragma once

#include <complex>
#include <vector>

#include "fem/rotor/RotorResults.hpp"

namespace beamrotor {

/// arg(values[i]) in degrees, unwrapped point by point. A step of more than 180 deg between
/// neighbours is the wrap of (-180, 180], not the response, and is taken out; a step of
/// exactly 180 deg (an undamped resonance: the response changes sign) is a lag, down, whatever
/// side round-off put it on, so it never flickers between +180 and -180. A first value at
/// +180 deg reads as -180 (a lag).
std::vector<double> unwrappedPhases(const std::vector<std::complex<double>>& values);

/// The unwrapped phases (deg) of one point's orbit along a sweep: of uy and of uz.
struct UnbalancePhases {
  std::vector<double> uy, uz;
};
UnbalancePhases unbalancePhases(const std::vector<Orbit>& orbits);

}  // namespace beamrotor
