// The lines `beamrotor solve` prints for a torsion analysis of a train beyond its modes: the
// shafts' speeds, where the orders cross the natural frequencies, and the vibratory torques
// and twists at the operating speed.
#pragma once

#include <ostream>

#include "problems/deck/OutputUnits.hpp"
#include "problems/run/TorsionOutcome.hpp"

namespace beamrotor::cli {

/// Numbers in the user's `units` where they set the quantity (speeds rpm, frequencies Hz,
/// torques N m, twists rad otherwise).
void printTrain(std::ostream& out, const TorsionOutcome& t, const OutputUnits& units = {});

}  // namespace beamrotor::cli
