// The lines `beamrotor solve` prints for a crank-slider analysis: the mechanism's figures at
// its crank speed, the reduced masses, the inertia harmonics per crank and over all cranks
// (what cancels), the rod's inertia moment and the delivery.
#pragma once

#include <ostream>

#include "problems/deck/OutputUnits.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// Numbers in the user's `units` where they set the quantity, SI (speed in rpm) otherwise.
void printCrankSlider(std::ostream& out, const AnalysisOutcome& a, const OutputUnits& units = {});

}  // namespace beamrotor::cli
