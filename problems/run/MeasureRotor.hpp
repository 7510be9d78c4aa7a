// The rotor analyses' check quantities measured in a solved rotor analysis.
#pragma once

#include "problems/deck/Quantity.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// The quantity in a solved rotor analysis; throws std::invalid_argument when it lacks it.
double measureRotor(const Quantity& q, const AnalysisOutcome& outcome);

}  // namespace beamrotor
